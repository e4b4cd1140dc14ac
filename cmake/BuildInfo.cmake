# Build facts recorded in every run.json: compiler, flags, commit.
execute_process(COMMAND git rev-parse --short=12 HEAD
                WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                OUTPUT_VARIABLE VROC_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT VROC_GIT_COMMIT)
  set(VROC_GIT_COMMIT "unknown")
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" _vroc_bt)
set(VROC_BUILD_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_vroc_bt}} -ffp-contract=off")
string(STRIP "${VROC_BUILD_FLAGS}" VROC_BUILD_FLAGS)
set(VROC_COMPILER "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}")
