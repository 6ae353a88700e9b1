# The whole debugger draws a few frames of a scene and writes what it showed.
#   cmake -DXVFB_RUN=... -DDEBUGGER=... -DOUT=file.png -DARGS="..." -P app_smoke.cmake
include(${CMAKE_CURRENT_LIST_DIR}/xvfb.cmake)
tv_require_xvfb()
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
file(REMOVE ${OUT})
tv_xvfb_run(${DEBUGGER} ${ARGS} --no-settings --frames 4 --app-screenshot ${OUT})
if(NOT EXISTS ${OUT})
  message(FATAL_ERROR "tv-debugger exited 0 but wrote no ${OUT}")
endif()
