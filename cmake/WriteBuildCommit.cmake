# Run at every build (cmake -P, from the vroc_build_commit target in cmake/BuildInfo.cmake):
# writes OUTPUT, a header defining VROC_GIT_COMMIT as the short commit of SOURCE_DIR, and rewrites
# it only when the commit changed, so an unchanged commit rebuilds nothing. Outside a git clone
# (a tarball), or inside some other repository, the commit is "unknown".
#   cmake -DSOURCE_DIR=<vroc source> -DOUTPUT=<header> -P WriteBuildCommit.cmake
if(NOT SOURCE_DIR OR NOT OUTPUT)
  message(FATAL_ERROR "WriteBuildCommit.cmake: pass -DSOURCE_DIR=... -DOUTPUT=...")
endif()

set(commit "unknown")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE)
  # The top level must be SOURCE_DIR itself: a tarball unpacked inside another clone would
  # otherwise take that clone's commit.
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --show-toplevel
                  WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE top_rc
                  OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(top_rc EQUAL 0)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
    if(top STREQUAL source)
      execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
                      WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc
                      OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      if(rc EQUAL 0 AND head MATCHES "^[0-9a-f]+$")
        set(commit "${head}")
      endif()
    endif()
  endif()
endif()

set(content "// Generated at build time by cmake/WriteBuildCommit.cmake; do not edit.\n#define VROC_GIT_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL content)
  file(WRITE "${OUTPUT}" "${content}")
endif()
