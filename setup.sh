#!/usr/bin/env bash
# setup.sh: set up a Debian 12 machine for colonosim, build it, then run the main job or the tests.
#
# Every step is idempotent: packages already installed are not touched, the build directory is
# configured once and then built incrementally.
set -euo pipefail

cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")"

# System dependencies, all from Debian 12 (bookworm) packages.
# libqt6opengl6-dev and xauth are only Recommends of other packages, so they are named here.
# zlib1g-dev: assimp's CMake targets link /usr/lib/x86_64-linux-gnu/libz.so, but libassimp-dev
# does not depend on the package that ships it.
# libxml2-utils: xmllint, with which the tests validate generated case files against their XSD.
# libopenigtlink-dev: the OpenIGTLink protocol between the Haptic Device Controller and the simulator.
# libsdl2-dev: gamepads, through SDL2's game-controller API.
PACKAGES=(
    build-essential cmake ninja-build pkg-config git ccache
    libeigen3-dev libbullet-dev libsqlite3-dev
    qt6-base-dev libqt6opengl6-dev libqt6sql6-sqlite qt6-charts-dev qt6-svg-dev
    libtinyxml2-dev libosmesa6-dev libassimp-dev zlib1g-dev nlohmann-json3-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    libsodium-dev libzstd-dev
    xvfb xauth poppler-utils libxml2-utils
    libopenigtlink-dev libsdl2-dev
)

BUILD_DIR=build
SANITIZE_BUILD_DIR=build-sanitize
JOBS="${COLONOSIM_JOBS:-$(nproc)}"

log()
{
    echo "setup: $*"
}

die()
{
    local code="$1"
    shift
    echo "setup: error: $*" >&2
    exit "$code"
}

usage()
{
    cat <<'EOF'
Usage: ./setup.sh COMMAND [ARGS...]

Set up this Debian 12 machine for colonosim (system packages via apt-get), build it, and:

  run [ARGS...]    build, then run the main job: build/trainer_ui/colonosim ARGS...
  test             build, then run every test (ctest in build/)
  test-sanitize    build with AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/
                   (-O2 with line tables, benchmarks off), then run every test there except those
                   labelled "slow" (whole procedures; `test` runs them)
  build            install what is missing and build, nothing else
  -h, --help       show this help

Packages are installed only when missing (checked with dpkg-query). The build directory is
configured once (Release, Ninja) and then built incrementally with $(nproc) jobs;
set COLONOSIM_JOBS to change that. Compiled objects are kept by ccache (one of the packages), so
a fresh clone compiles only what changed since an earlier build on the same machine;
COLONOSIM_CCACHE=0 configures new build directories without it.
EOF
}

# Install the packages of PACKAGES that dpkg does not report as installed.
ensure_packages()
{
    if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
        die 2 "this script needs a Debian 12 system (apt-get and dpkg-query not found)"
    fi

    local missing=() pkg status
    for pkg in "${PACKAGES[@]}"; do
        status="$(dpkg-query -W -f='${db:Status-Status}' "$pkg" 2>/dev/null || true)"
        [[ "$status" == installed ]] || missing+=("$pkg")
    done
    if ((${#missing[@]} == 0)); then
        log "all ${#PACKAGES[@]} system packages present"
        return
    fi

    local -a as_root
    if ((EUID == 0)); then
        as_root=(env DEBIAN_FRONTEND=noninteractive)
    elif command -v sudo >/dev/null; then
        as_root=(sudo env DEBIAN_FRONTEND=noninteractive)
    else
        echo "setup: ${#missing[@]} packages are missing and this is neither root nor has sudo." >&2
        echo "setup: as root, run:" >&2
        echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
        exit 2
    fi

    log "installing ${#missing[@]} missing packages: ${missing[*]}"
    "${as_root[@]}" apt-get update -q
    "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# The compiler cache: ccache keeps compiled objects between builds, so a fresh clone (CI's) or
# a second build directory compiles only what changed since any earlier build on this machine.
# Paths under the clone are rewritten relative to it (CCACHE_BASEDIR) and the working directory
# is left out of the hash (CCACHE_NOHASHDIR: the sanitizer build's line tables would otherwise
# tie each object to its clone's path), so clones at different paths share the cache.
# COLONOSIM_CCACHE=0 builds without it.
export CCACHE_BASEDIR="$PWD"
export CCACHE_NOHASHDIR=1

COMPILER_CACHE=()
if [[ "${COLONOSIM_CCACHE:-1}" != 0 ]]; then
    COMPILER_CACHE=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

# configure_and_build DIR [CMAKE ARGS...]: configure DIR once, then build it incrementally.
configure_and_build()
{
    local dir="$1"
    shift
    if [[ ! -f "$dir/CMakeCache.txt" || ! -f "$dir/build.ninja" ]]; then
        log "configuring $dir"
        local -a cache=()
        command -v ccache >/dev/null && cache=("${COMPILER_CACHE[@]}")
        cmake -S . -B "$dir" -G Ninja "${cache[@]}" "$@"
    fi

    local out
    out="$(mktemp)"
    # Keep ninja's output visible and look for its "no work to do" line afterwards.
    if ! cmake --build "$dir" --parallel "$JOBS" 2>&1 | tee "$out"; then
        rm -f "$out"
        die 1 "build failed in $dir"
    fi
    if grep -q '^ninja: no work to do' "$out"; then
        log "build up to date ($dir)"
    else
        log "build done ($dir)"
    fi
    rm -f "$out"
}

build_release()
{
    configure_and_build "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
}

cmd="${1:-}"
case "$cmd" in
    -h | --help | help)
        usage
        exit 0
        ;;
    "")
        usage >&2
        exit 2
        ;;
    run | test | test-sanitize | build) shift ;;
    *)
        echo "setup: unknown command '$cmd' (expected run, test, test-sanitize or build; see --help)" >&2
        exit 2
        ;;
esac

ensure_packages

case "$cmd" in
    build)
        build_release
        ;;
    run)
        build_release
        exe="$BUILD_DIR/trainer_ui/colonosim"
        [[ -x "$exe" ]] || die 1 "$exe was not built"
        log "running $exe $*"
        exec "$exe" "$@"
        ;;
    test)
        build_release
        log "running the tests in $BUILD_DIR"
        ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$JOBS"
        ;;
    test-sanitize)
        # -g1: line tables only, which is all a sanitizer report's file:line needs; full debug
        # information (-g) made the objects 3.6 times larger and a compile about 40% longer.
        configure_and_build "$SANITIZE_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
            "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
            -DCOLONOSIM_SANITIZE=ON -DCOLONOSIM_BUILD_BENCH=OFF -DCOLONOSIM_SLOW_TESTS=OFF
        log "running the tests in $SANITIZE_BUILD_DIR (ASan + UBSan)"
        export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_init_order=1}"
        export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
        # Mesa's OSMesa keeps a few hundred bytes of per-process state to exit; that leak
        # is inside the library (tests/sanitizers/lsan.supp), ours are still reported.
        export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}"
        # Tests labelled "slow" (whole procedures through the CLI, the records or the HDC
        # link) run in `test`; under the sanitizers they would take hours (tests/CMakeLists.txt),
        # so they are not built here (COLONOSIM_SLOW_TESTS=OFF); the label filter stays for
        # the slow test that shares its binary with fast ones (HardCases.TenMinuteRun).
        ctest --test-dir "$SANITIZE_BUILD_DIR" --output-on-failure --parallel "$JOBS" --label-exclude slow
        ;;
esac
