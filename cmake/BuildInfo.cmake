# Build facts recorded in every run.json: compiler, flags, commit.
# The commit is taken at build time, not configure time: vroc_build_commit runs at every build and
# rewrites generated/vroc_build_commit.h only when the commit changed (so a new commit rebuilds one
# file of core and relinks, and an unchanged one nothing). Ninja restats the byproduct.
set(VROC_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated)
add_custom_target(vroc_build_commit
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${VROC_GENERATED_DIR}/vroc_build_commit.h
          -P ${CMAKE_SOURCE_DIR}/cmake/WriteBuildCommit.cmake
  BYPRODUCTS ${VROC_GENERATED_DIR}/vroc_build_commit.h
  COMMENT "vroc: commit stamp"
  VERBATIM)
string(TOUPPER "${CMAKE_BUILD_TYPE}" _vroc_bt)
set(VROC_BUILD_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_vroc_bt}} -ffp-contract=off")
string(STRIP "${VROC_BUILD_FLAGS}" VROC_BUILD_FLAGS)
set(VROC_COMPILER "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}")
