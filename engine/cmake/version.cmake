# Writes OUT (version.hpp) from IN with the git commit of SOURCE_DIR, at every build: a result file,
# a report or a checkpoint names the commit its program was built from, not the one CMake was
# configured at. "-modified" follows the commit when a tracked file outside reports/ (which the
# tools themselves write) differs from it: the one definition of a modified tree, which result
# files, checkpoints and the report's "Source" line (report --source's default) all say.
# configure_file rewrites OUT only when it changes, so a build at the same commit recompiles nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR NOT GIT_COMMIT)
  set(GIT_COMMIT "unknown")  # not a git checkout (a source tarball)
else()
  execute_process(COMMAND git diff --quiet HEAD -- . ":(exclude)reports" WORKING_DIRECTORY ${SOURCE_DIR}
                  RESULT_VARIABLE modified ERROR_QUIET)
  if(modified)
    string(APPEND GIT_COMMIT "-modified")
  endif()
endif()
configure_file(${IN} ${OUT} @ONLY)
