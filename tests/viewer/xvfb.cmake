# Shared by the viewer tests: without xvfb-run or xauth, print the line the tests'
# SKIP_REGULAR_EXPRESSION reports as "skipped" and stop; otherwise run commands in a fresh
# 1280x720 virtual screen. (A macro, so its return() ends the calling script.)
macro(tv_require_xvfb)
  find_program(TV_XAUTH xauth)
  if(NOT EXISTS "${XVFB_RUN}" OR NOT TV_XAUTH)
    message("tv-skip: xvfb-run or xauth is missing (apt-get install xvfb xauth)")
    return()
  endif()
endmacro()

function(tv_xvfb_run)
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24" ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "exit ${rc}: ${ARGN}\nstdout: ${out}\nstderr: ${err}")
  endif()
endfunction()
