# ctest -R package.fetchcontent: examples/fetchcontent with FetchContent_Declare(GIT_REPOSITORY
# <this repository> GIT_TAG <the commit checked out>), configured, built and run.
#   -DSOURCE= the repository   -DWORK= a scratch directory (emptied)   -DCXX=   -DFLAGS=
foreach(v SOURCE WORK CXX)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "fetchcontent.cmake needs -D${v}=")
  endif()
endforeach()
find_program(GIT git)
if(NOT GIT)
  message(STATUS "tv-skip: git is not installed, so FetchContent cannot clone")
  return()
endif()
execute_process(COMMAND ${GIT} -C ${SOURCE} rev-parse HEAD RESULT_VARIABLE rc
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT rc EQUAL 0)
  message(STATUS "tv-skip: ${SOURCE} is not a git checkout, so FetchContent has nothing to clone")
  return()
endif()
execute_process(COMMAND ${GIT} -C ${SOURCE} status --porcelain --untracked-files=no
                OUTPUT_VARIABLE dirty)
if(dirty)
  message(STATUS "note: uncommitted changes are not in the clone; commit ${commit} is built")
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " cmd)
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
run(${CMAKE_COMMAND} -S ${SOURCE}/examples/fetchcontent -B ${WORK}/build -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_CXX_FLAGS=${FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}" -DTUNNELVISION_GIT=${SOURCE}
    -DTUNNELVISION_TAG=${commit})
# Only what the game needs: tv::core and tv::record (the subproject builds no programs).
run(${CMAKE_COMMAND} --build ${WORK}/build --target fetchcontent-game)
run(${WORK}/build/fetchcontent-game --frames 120)
if(NOT last_output MATCHES "bullet stopped at x = [0-9.]+, before the wall")
  message(FATAL_ERROR "the FetchContent game printed: ${last_output}")
endif()
message(STATUS "FetchContent cloned ${SOURCE} at ${commit}, built and ran the game")
