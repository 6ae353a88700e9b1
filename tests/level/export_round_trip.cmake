# tv-run --export-scene writes every built-in scene; tv-run --scene-file runs each file to the
# same state hash as the built-in scene (the unit test checks the library; this, the programs).
#   -DRUN=tv-run  -DWORK=scratch directory
file(MAKE_DIRECTORY ${WORK})
foreach(scene bullets-wall rest-floor seam-walk platformer crowd)
  execute_process(COMMAND ${RUN} --export-scene ${scene} ${WORK}/${scene}.json --mover adaptive
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--export-scene ${scene} failed: ${err}")
  endif()
  execute_process(COMMAND ${RUN} --scene ${scene} --mover adaptive --ticks 600
                  OUTPUT_VARIABLE builtin RESULT_VARIABLE rc1)
  execute_process(COMMAND ${RUN} --scene-file ${WORK}/${scene}.json --mover adaptive --ticks 600
                  OUTPUT_VARIABLE fromFile RESULT_VARIABLE rc2)
  # The table's last row: the mover and every counter, hash included (the time column differs).
  string(REGEX MATCH "\\| adaptive \\|[^\n]*" a "${builtin}")
  string(REGEX MATCH "\\| adaptive \\|[^\n]*" b "${fromFile}")
  string(REGEX REPLACE "\\| [0-9.]+ \\|$" "" a "${a}")
  string(REGEX REPLACE "\\| [0-9.]+ \\|$" "" b "${b}")
  if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0 OR a STREQUAL "" OR NOT a STREQUAL b)
    message(FATAL_ERROR "${scene}: the file does not run like the scene\n  built-in: ${a}\n  file:     ${b}")
  endif()
  message(STATUS "${scene}: ${a}")
endforeach()
