#!/usr/bin/env bash
# fresh-machine-check.sh: prove the README's two commands on a fresh Debian 12 root.
#
# Usage: tools/fresh-machine-check.sh [--keep] [--ci] [--run-timeout SECONDS] WORKDIR
#   e.g. sudo tools/fresh-machine-check.sh /var/tmp/colonosim-fresh
#
# 1. Builds (once, then reuses) WORKDIR/base-bookworm-minbase.tar.zst: a minimal
#    `debootstrap --variant=minbase bookworm` root from the Debian mirror this machine's apt uses.
# 2. For each check, extracts a fresh copy of that root, copies a fresh `git clone` of this
#    repository (the committed HEAD; uncommitted changes are left out) into /root/colonosim,
#    bind-mounts proc, sys and dev, and runs the command in a chroot as root with no stdin:
#       ./setup.sh test     -> WORKDIR/setup-test.log
#       ./setup.sh run      -> WORKDIR/setup-run.log
# 3. Unmounts everything on exit and prints a summary with the minutes each step took.
#
# --keep keeps the extracted roots (WORKDIR/root-test, WORKDIR/root-run) for inspection.
# --ci also runs the CI job, `CI=true bash .ci/run`, in a third fresh root (WORKDIR/ci-run.log).
# --run-timeout stops `./setup.sh run` after SECONDS (default 3600) and reports it as TIMEOUT.
# MIRROR=http://... overrides the mirror. Needs root, debootstrap, git, tar and zstd.
set -euo pipefail

KEEP=0
CI_CHECK=0
RUN_TIMEOUT=3600
while (($# > 0)); do
    case "$1" in
        --keep) KEEP=1 ;;
        --ci) CI_CHECK=1 ;;
        --run-timeout)
            RUN_TIMEOUT="$2"
            shift
            ;;
        -h | --help)
            sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
            exit 0
            ;;
        -*)
            echo "fresh-machine-check: unknown option $1" >&2
            exit 2
            ;;
        *) break ;;
    esac
    shift
done
if (($# != 1)); then
    echo "usage: $0 [--keep] [--ci] [--run-timeout SECONDS] WORKDIR" >&2
    exit 2
fi
((EUID == 0)) || {
    echo "fresh-machine-check: must run as root (debootstrap, chroot, mount)" >&2
    exit 2
}
for tool in debootstrap git tar zstd chroot mount; do
    command -v "$tool" >/dev/null || {
        echo "fresh-machine-check: $tool not found" >&2
        exit 2
    }
done

REPO="$(git -C "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" rev-parse --show-toplevel)"
mkdir -p "$1"
WORKDIR="$(readlink -f "$1")"
case "$WORKDIR/" in
    "$REPO"/*)
        echo "fresh-machine-check: WORKDIR must lie outside the repository" >&2
        exit 2
        ;;
esac
BASE_TAR="$WORKDIR/base-bookworm-minbase.tar.zst"
SUMMARY=()

say()
{
    echo "fresh-machine-check: $*"
}

# "1.5 min (90 s)" for a number of seconds.
duration()
{
    awk -v x="$1" 'BEGIN { printf "%.1f min (%d s)", x / 60, x }'
}

minutes_since()
{
    duration "$(($(date +%s) - $1))"
}

# Print the URI of the host's apt source that serves the given suite (deb822 and one-line formats).
host_mirror_for()
{
    local suite="$1" f
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [[ -f "$f" ]] || continue
        awk -v s="$suite" '$1 == "deb" { i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
                            if ($(i + 1) == s) { print $i; exit } }' "$f"
    done
    for f in /etc/apt/sources.list.d/*.sources; do
        [[ -f "$f" ]] || continue
        awk -v s="$suite" 'BEGIN { RS = ""; FS = "\n" }
            { uri = ""; ok = 0; deb = 0
              for (i = 1; i <= NF; i++) {
                  if ($i ~ /^URIs:/) { split($i, a, /[ \t]+/); uri = a[2] }
                  if ($i ~ /^Types:/ && $i ~ /[ \t]deb([ \t]|$)/) deb = 1
                  if ($i ~ /^Suites:/) { n = split($i, a, /[ \t]+/); for (j = 2; j <= n; j++) if (a[j] == s) ok = 1 }
              }
              if (ok && deb && uri ~ /^https?:/) { print uri; exit } }' "$f"
    done
}

# Prefix each line with the seconds since the command started.
stamp()
{
    local start="$EPOCHSECONDS" line
    while IFS= read -r line; do
        printf '[%5d s] %s\n' "$((EPOCHSECONDS - start))" "$line"
    done
}

# Seconds at the first log line matching a pattern (empty when none matches).
seconds_at()
{
    { grep -m1 -E "^\[ *[0-9]+ s\] ($2)" "$1" || true; } | sed -E 's/^\[ *([0-9]+) s\].*/\1/'
}

# Remove an extracted root, refusing while anything is still mounted beneath it.
remove_root()
{
    local root="$1"
    [[ -e "$root" ]] || return 0
    if awk -v r="$root/" 'index($2 "/", r) == 1 { found = 1 } END { exit !found }' /proc/self/mounts; then
        echo "fresh-machine-check: $root still has mounts; not removing it" >&2
        exit 1
    fi
    rm -rf --one-file-system "$root"
}

MOUNTED=()
cleanup()
{
    local i
    for ((i = ${#MOUNTED[@]} - 1; i >= 0; i--)); do
        umount -l "${MOUNTED[$i]}" 2>/dev/null || true
    done
    MOUNTED=()
}
trap cleanup EXIT
trap 'exit 130' INT TERM

make_base()
{
    if [[ -f "$BASE_TAR" ]]; then
        say "reusing $BASE_TAR"
        SUMMARY+=("debootstrap: cached")
        return
    fi
    local mirror security
    mirror="${MIRROR:-$(host_mirror_for bookworm | head -n1)}"
    security="$(host_mirror_for bookworm-security | head -n1)"
    [[ -n "$mirror" ]] || {
        echo "fresh-machine-check: no http(s) mirror for bookworm in the host's apt sources; set MIRROR" >&2
        exit 2
    }
    local stage="$WORKDIR/base-stage" t0
    rm -rf "$stage"
    say "debootstrap --variant=minbase bookworm from $mirror"
    t0="$(date +%s)"
    debootstrap --variant=minbase bookworm "$stage" "$mirror" >"$WORKDIR/debootstrap.log" 2>&1 || {
        tail -n 20 "$WORKDIR/debootstrap.log" >&2
        exit 1
    }
    # The sources of a plain Debian 12 install: main, updates and security.
    {
        echo "deb $mirror bookworm main"
        echo "deb $mirror bookworm-updates main"
        [[ -z "$security" ]] || echo "deb $security bookworm-security main"
    } >"$stage/etc/apt/sources.list"
    # Only the mirror may be reachable: carry over any apt proxy settings.
    local f
    for f in /etc/apt/apt.conf /etc/apt/apt.conf.d/*; do
        [[ -f "$f" ]] && grep -qi 'proxy' "$f" && cp "$f" "$stage/etc/apt/apt.conf.d/"
    done
    rm -rf "$stage/var/cache/apt/archives/"*.deb "$stage/var/lib/apt/lists/"* 2>/dev/null || true
    tar -C "$stage" --numeric-owner -cf - . | zstd -q -T0 -o "$BASE_TAR.tmp"
    mv "$BASE_TAR.tmp" "$BASE_TAR"
    rm -rf "$stage"
    SUMMARY+=("debootstrap: $(minutes_since "$t0")")
}

# check NAME COMMAND...: run COMMAND in /root/colonosim of a fresh root, logging to WORKDIR/NAME.log.
check()
{
    local name="$1"
    shift
    local root="$WORKDIR/root-${name#setup-}" log="$WORKDIR/$name.log" t0 rc
    [[ "$name" != ci-run ]] || root="$WORKDIR/root-ci"
    remove_root "$root"
    mkdir -p "$root"
    zstd -q -d -c "$BASE_TAR" | tar -C "$root" --numeric-owner -xf -
    cp /etc/resolv.conf "$root/etc/resolv.conf"
    git clone -q --no-checkout "$REPO" "$root/root/colonosim"
    git -C "$root/root/colonosim" checkout -q "$(git -C "$REPO" rev-parse HEAD)"
    local m
    for m in proc sys dev; do
        mount --rbind "/$m" "$root/$m"
        mount --make-rslave "$root/$m"
        MOUNTED+=("$root/$m")
    done

    say "$name: running '$*' in a fresh root (log: $log)"
    t0="$(date +%s)"
    set +e
    chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb LANG=C.UTF-8 \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        /bin/bash -c 'cd /root/colonosim && exec "$@"' bash "$@" </dev/null 2>&1 | stamp >"$log"
    rc="${PIPESTATUS[0]}"
    set -e
    local took
    took="$(minutes_since "$t0")"
    cleanup
    local verdict=PASS
    ((rc == 0)) || verdict="FAIL (exit $rc)"
    ((rc != 124)) || verdict="TIMEOUT"
    SUMMARY+=("$name: $verdict, $took")
    say "$name: $verdict after $took; last lines:"
    tail -n 5 "$log" | sed 's/^/    /'
    phases "$log"
    ((KEEP == 1)) || remove_root "$root"
    return 0
}

# Split a setup.sh log into apt install, configure + build, and tests (or the main job).
phases()
{
    local log="$1" a b c d e
    a="$(seconds_at "$log" 'setup: installing')"
    b="$(seconds_at "$log" 'setup: configuring|ninja:|\[[0-9]+/[0-9]+\]')"
    c="$(seconds_at "$log" 'setup: build (done|up to date)')"
    d="$(seconds_at "$log" 'setup: running')"
    e="$(tail -n1 "$log" | sed -nE 's/^\[ *([0-9]+) s\].*/\1/p')"
    [[ -n "$d" ]] || d="$c"
    local parts=()
    [[ -z "$a" || -z "$b" ]] || parts+=("apt install $(duration "$((b - a))")")
    [[ -z "$b" || -z "$c" ]] || parts+=("configure+build $(duration "$((c - b))")")
    [[ -z "$d" || -z "$e" ]] || parts+=("tests or main job $(duration "$((e - d))")")
    if ((${#parts[@]} > 0)); then
        local joined
        joined="$(printf '%s, ' "${parts[@]}")"
        SUMMARY+=("    ${joined%, }")
    fi
}

T_START="$(date +%s)"
make_base
check setup-test ./setup.sh test
check setup-run timeout "$RUN_TIMEOUT" ./setup.sh run
((CI_CHECK == 0)) || check ci-run env CI=true bash .ci/run

echo
say "summary ($(git -C "$REPO" rev-parse --short HEAD), $(minutes_since "$T_START") in all)"
printf '  %s\n' "${SUMMARY[@]}"
for s in "${SUMMARY[@]}"; do
    [[ "$s" != *FAIL* && "$s" != *TIMEOUT* ]] || exit 1
done
