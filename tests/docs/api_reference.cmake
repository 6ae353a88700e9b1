# Builds the API reference with Doxygen, warnings as errors: fails naming every undocumented
# public symbol (file:line), passes when the reference builds clean.
#   cmake -DDOXYGEN=path -DDOXYFILE=build/docs/Doxyfile -DOUT=build/docs/api [-DNEGATIVE=ON]
#         -P api_reference.cmake
if(NOT DOXYGEN)
  message(STATUS "tv-skip: doxygen is not installed, so the API reference was not checked "
                 "(scripts/deps.sh installs it)")
  return()
endif()
if(NEGATIVE)
  # The negative control: the same settings over a header with one undocumented function must
  # fail, naming it, or the check above could pass without checking anything.
  set(dir ${OUT}/negative-control)
  file(REMOVE_RECURSE ${dir})
  file(MAKE_DIRECTORY ${dir})
  file(WRITE ${dir}/probe.hpp "#pragma once\n/// @file\n/// A probe.\nnamespace probe {\n"
                              "/// Documented.\nint documented();\nint undocumentedProbe();\n}\n")
  file(WRITE ${dir}/Doxyfile "@INCLUDE = ${DOXYFILE}\nINPUT = ${dir}/probe.hpp\n"
                             "USE_MDFILE_AS_MAINPAGE =\nOUTPUT_DIRECTORY = ${dir}/out\n")
  execute_process(COMMAND ${DOXYGEN} ${dir}/Doxyfile RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "undocumentedProbe")
    message(FATAL_ERROR "an undocumented function passed the check (exit ${rc}):\n${err}")
  endif()
  message(STATUS "an undocumented function fails the check, as it must: ${err}")
  return()
endif()
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
  message(FATAL_ERROR "the API reference has warnings (exit ${rc}):\n${err}")
endif()
if(NOT EXISTS ${OUT}/html/index.html)
  message(FATAL_ERROR "doxygen wrote no ${OUT}/html/index.html")
endif()
message(STATUS "API reference: ${OUT}/html/index.html, no warnings")
