# ccache as the compiler launcher when it is installed (Debian package `ccache`, in `make deps`),
# so that a rebuild of unchanged sources, in this or another build directory, is a cache hit.
# CCACHE_BASEDIR=<source dir> makes ccache rewrite absolute paths under the source tree to relative
# ones before hashing, so a fresh clone in another folder (what CI builds) hits the cache filled by
# an earlier clone. Builds with debug info (the -g1 sanitizer build, the fuzzing build) would still
# miss, because ccache hashes the working directory that debug info records; -fdebug-prefix-map
# records the build directory as "." instead (source paths in debug info are then relative to it),
# which ccache recognises (its manual, "Compiling in different directories").
# Off with -DVROC_CCACHE=OFF; an explicit -DCMAKE_CXX_COMPILER_LAUNCHER=... wins. The cache
# (~/.cache/ccache, 5 GB) persists across builds only where the home directory does.
option(VROC_CCACHE "Use ccache as the compiler launcher when it is installed" ON)
if(VROC_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER AND NOT CMAKE_C_COMPILER_LAUNCHER)
  find_program(VROC_CCACHE_PROGRAM ccache)
  find_program(VROC_ENV_PROGRAM env)
  if(VROC_CCACHE_PROGRAM AND VROC_ENV_PROGRAM)
    set(_vroc_launcher ${VROC_ENV_PROGRAM} CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} ${VROC_CCACHE_PROGRAM})
    set(CMAKE_C_COMPILER_LAUNCHER ${_vroc_launcher})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${_vroc_launcher})
    unset(_vroc_launcher)
    add_compile_options(-fdebug-prefix-map=${CMAKE_BINARY_DIR}=.)
    message(STATUS "vroc: compiling through ${VROC_CCACHE_PROGRAM} (CCACHE_BASEDIR=${PROJECT_SOURCE_DIR})")
  endif()
endif()
