# Every third-party library, found the way ../shared/notes/debian-packages.md documents for Debian 12.
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(assimp REQUIRED)
find_package(ccd REQUIRED)
find_package(GTest REQUIRED)
if(VROC_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
find_package(PNG REQUIRED)
find_package(Threads REQUIRED)
find_package(OpenSSL REQUIRED)        # SHA-256 of scene files (libcrypto)
# Bullet in double precision only: the pkg-config target carries -DBT_USE_DOUBLE_PRECISION.
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
# ODE 0.16 in double precision (the Debian build: pkg-config variable precision=dDOUBLE).
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
# DART 6.12 (libdart-dev; config in /usr/share/dart/cmake): libdart only, which collides with FCL. Never
# dart-collision-bullet: it links single-precision Bullet beside this project's double one.
find_package(DART 6.12 REQUIRED COMPONENTS dart CONFIG)
# MuJoCo 2.2.2. Debian's mujoco::mujoco names /usr/include/libqhull_r/ as an include directory;
# libqhull-dev provides it (installed by `make deps`), and the path is dropped if it is missing.
find_package(mujoco REQUIRED)
get_target_property(_vroc_mj_inc mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
if(_vroc_mj_inc)
  list(FILTER _vroc_mj_inc EXCLUDE REGEX "libqhull_r")
  set_target_properties(mujoco::mujoco PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_vroc_mj_inc}")
endif()
# qhull's reentrant C library (libqhull_r); the C++ wrapper is not needed.
find_library(QHULL_R_LIBRARY NAMES qhull_r REQUIRED)
find_path(QHULL_R_INCLUDE_DIR libqhull_r/libqhull_r.h REQUIRED)
add_library(vroc_qhull INTERFACE)
target_link_libraries(vroc_qhull INTERFACE ${QHULL_R_LIBRARY})
target_include_directories(vroc_qhull SYSTEM INTERFACE ${QHULL_R_INCLUDE_DIR})
# OSMesa for the offscreen renderer. Never link libGL into the same binary (see the notes).
if(VROC_BUILD_RENDERER)
  pkg_check_modules(OSMESA IMPORTED_TARGET osmesa)
  if(NOT OSMESA_FOUND)
    message(FATAL_ERROR "vroc: OSMesa not found: install libosmesa6-dev (`make deps`) or configure with -DVROC_BUILD_RENDERER=OFF")
  endif()
endif()
