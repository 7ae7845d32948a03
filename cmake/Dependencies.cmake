# System dependencies, all from Debian 12 packages (see setup.sh for the list).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
find_package(GTest REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(assimp REQUIRED)
# tinyxml2: the case files (case_generator); the shared-library CONFIG package.
find_package(tinyxml2 REQUIRED)

# Bullet: module mode only. The CONFIG package shipped by Debian has relative
# paths and names a BulletInverseDynamics library that is not installed.
find_package(Bullet REQUIRED MODULE)
if(NOT TARGET colonosim::bullet)
  add_library(colonosim::bullet INTERFACE IMPORTED)
  target_include_directories(colonosim::bullet INTERFACE ${BULLET_INCLUDE_DIRS})
  target_link_libraries(colonosim::bullet INTERFACE ${BULLET_LIBRARIES})
endif()

if(COLONOSIM_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# zstd: compression of the recorded input traces. No CMake package in Debian 12.
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)

# OpenIGTLink: the protocol between the Haptic Device Controller and the
# simulator. Debian's CONFIG package sets variables only; wrap them in a target.
find_package(OpenIGTLink REQUIRED NO_MODULE)
if(NOT TARGET colonosim::openigtlink)
  add_library(colonosim::openigtlink INTERFACE IMPORTED)
  target_include_directories(colonosim::openigtlink SYSTEM INTERFACE ${OpenIGTLink_INCLUDE_DIRS})
  target_link_directories(colonosim::openigtlink INTERFACE ${OpenIGTLink_LIBRARY_DIRS})
  target_link_libraries(colonosim::openigtlink INTERFACE ${OpenIGTLink_LIBRARIES})
endif()

# SDL2: gamepads through its game-controller API.
pkg_check_modules(SDL2 REQUIRED IMPORTED_TARGET sdl2)

# Qt enters at db (QtCore, QtSql) and trainer_ui (QtGui for the PDF reports).
find_package(Qt6 REQUIRED COMPONENTS Core Sql Gui)
# SQLite itself: the online backup API (db); the same library the QSQLITE driver uses.
pkg_check_modules(SQLITE3 REQUIRED IMPORTED_TARGET sqlite3)
# libsodium: Argon2id password hashes (db) and Ed25519 report signatures (trainer_ui).
pkg_check_modules(SODIUM REQUIRED IMPORTED_TARGET libsodium)
