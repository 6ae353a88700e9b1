# The debugger's --screenshot of a scene at a tick must equal tv-render's image of it.
#   cmake -DXVFB_RUN=... -DDEBUGGER=... -DRENDER=... -DCHECK=tv_golden_check -DOUT_DIR=...
#         -DNAME=... -DARGS="flag;value;..." -P screenshot_equal.cmake
# Skipped where there is no X server to be had (see xvfb.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/xvfb.cmake)
tv_require_xvfb()
file(MAKE_DIRECTORY ${OUT_DIR})
set(shot ${OUT_DIR}/${NAME}.debugger.png)
file(REMOVE ${shot})
tv_xvfb_run(${DEBUGGER} ${ARGS} --no-settings --screenshot ${shot})
# tv_golden_check renders with tv-render and compares exactly (or within TV_GOLDEN_TOLERANCE),
# leaving a diff image on a mismatch.
execute_process(COMMAND ${CHECK} ${RENDER} ${shot} ${OUT_DIR} ${NAME} -- ${ARGS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tv-render could not draw the same picture as the debugger (${shot}): see above")
endif()
file(REMOVE ${shot})
