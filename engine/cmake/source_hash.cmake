# Writes OUT with a hash of every engine source file (run at each build; the file is rewritten only
# when the hash changes). The pipeline keys its reuse of results on this hash, so a change to
# documentation or to the pipeline does not invalidate finished runs, but any engine change does.
file(GLOB_RECURSE sources ${ENGINE_DIR}/*.cpp ${ENGINE_DIR}/*.hpp ${ENGINE_DIR}/*.inc ${ENGINE_DIR}/*.in)
list(FILTER sources EXCLUDE REGEX "/bench/")  # the benchmark does not change any result
list(SORT sources)
set(all "")
foreach(f IN LISTS sources)
  file(SHA256 ${f} h)
  string(APPEND all "${h}")
endforeach()
string(SHA256 hash "${all}")
string(SUBSTRING ${hash} 0 16 hash)
set(content "#pragma once\n// Generated: hash of the engine's sources (engine/cmake/source_hash.cmake).\nnamespace dem {\ninline constexpr const char* engine_source_hash = \"${hash}\";\n}  // namespace dem\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL content)
  file(WRITE ${OUT} "${content}")
endif()
