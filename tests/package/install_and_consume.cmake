# ctest -R package: installs the build into a fresh prefix, then builds and runs a tiny game
# against it twice — with find_package(tunnelvision 0.2) and with pkg-config.
#   -DBUILD_DIR=  the build tree to install      -DWORK=  a scratch directory (emptied)
#   -DSOURCE=     tests/package                  -DCXX=   the compiler   -DFLAGS= extra flags
#   -DSHARED_FROM= the repository: first build it alone as shared libraries (BUILD_SHARED_LIBS)
#                  into WORK/lib-build, and install that instead of BUILD_DIR
#   -DEXAMPLES=   examples/: also build examples/fixed-step against the install and run it
#   -DPROGRAMS=   the programs BUILD_DIR built (a|b|c): each must be installed, and runs there
if(DEFINED SHARED_FROM)
  set(BUILD_DIR ${WORK}/lib-build)
endif()
foreach(v BUILD_DIR WORK SOURCE CXX)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "install_and_consume.cmake needs -D${v}=")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " cmd)
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK}/prefix ${WORK}/cmake-build ${WORK}/example-build ${WORK}/run)
set(prefix ${WORK}/prefix)
if(DEFINED SHARED_FROM)
  # The library alone, as a game's build would add it: no programs, no tests.
  run(${CMAKE_COMMAND} -S ${SHARED_FROM} -B ${BUILD_DIR} -G Ninja -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_CXX_COMPILER=${CXX} -DBUILD_SHARED_LIBS=ON -DTV_BUILD_APP=OFF -DTV_BUILD_TESTS=OFF
      -DTV_INSTALL=ON)
  run(${CMAKE_COMMAND} --build ${BUILD_DIR})
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# 1. CMake: find_package from the prefix.
run(${CMAKE_COMMAND} -S ${SOURCE}/consumer -B ${WORK}/cmake-build -G Ninja
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_CXX_FLAGS=${FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK}/cmake-build)
run(${WORK}/cmake-build/game)
if(NOT last_output MATCHES "consumer: ok")
  message(FATAL_ERROR "the find_package consumer printed: ${last_output}")
endif()

# 2. pkg-config: one compiler command.
find_program(PKG_CONFIG pkg-config REQUIRED)
file(GLOB_RECURSE pc_files ${prefix}/*/tunnelvision.pc)
list(GET pc_files 0 pc)
get_filename_component(pc_dir ${pc} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run(${PKG_CONFIG} --cflags --libs --static tunnelvision)
string(STRIP "${last_output}" pc_flags)
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
separate_arguments(extra UNIX_COMMAND "${FLAGS}")
# Every library is in the one .pc file (tv_record and tv_level are installed with the rest).
run(${CXX} -std=c++20 ${extra} -DGAME_HAS_LEVEL -DGAME_HAS_RECORD ${SOURCE}/consumer/game.cpp ${pc_flags}
    -o ${WORK}/game-pkgconfig)
# Outside the system's library path a shared install needs the loader told where it is
# (CMake's consumer has an RPATH; a plain compiler command does not).
set(ENV{LD_LIBRARY_PATH} ${prefix}/lib)
run(${WORK}/game-pkgconfig)
if(NOT last_output MATCHES "consumer: ok")
  message(FATAL_ERROR "the pkg-config consumer printed: ${last_output}")
endif()
unset(ENV{LD_LIBRARY_PATH})

# 3. The fixed-step example (examples/fixed-step), as a user builds it against the install.
if(DEFINED EXAMPLES)
  run(${CMAKE_COMMAND} -S ${EXAMPLES}/fixed-step -B ${WORK}/example-build -G Ninja
      -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
      "-DCMAKE_CXX_FLAGS=${FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}")
  run(${CMAKE_COMMAND} --build ${WORK}/example-build)
  file(MAKE_DIRECTORY ${WORK}/run)
  execute_process(COMMAND ${WORK}/example-build/fixed-step-game --frames 240
                          --record ${WORK}/run/example.tvrec
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "bullet stopped at x = [0-9.]+, before the wall")
    message(FATAL_ERROR "the fixed-step example (exit ${rc}): ${out}\n${err}")
  endif()
endif()

# 4. The programs, run from the prefix in a folder far from the source tree: what a user has
#    after `cmake --install` of a build with the programs (TV_BUILD_APP=ON).
set(bin ${prefix}/bin)
if(PROGRAMS)
  string(REPLACE "|" ";" PROGRAMS "${PROGRAMS}")
  foreach(program ${PROGRAMS})
    if(NOT EXISTS ${bin}/${program})
      message(FATAL_ERROR "cmake --install put no ${program} in ${bin}")
    endif()
  endforeach()
endif()
if(EXISTS ${bin}/tv-run)
  set(share ${prefix}/share/tunnelvision)
  execute_process(COMMAND ${bin}/tv-run --map ${share}/levels/meadow.tmj --mover continuous
                  WORKING_DIRECTORY ${WORK}/run RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\\| continuous \\| 600 \\| 10 \\|")
    message(FATAL_ERROR "installed tv-run on the installed map (exit ${rc}): ${out}\n${err}")
  endif()
  if(EXISTS ${WORK}/run/example.tvrec)
    execute_process(COMMAND ${bin}/tv-replay example.tvrec --validate
                    WORKING_DIRECTORY ${WORK}/run RESULT_VARIABLE rc OUTPUT_VARIABLE out
                    ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "^ok: 241 frames")
      message(FATAL_ERROR "installed tv-replay --validate (exit ${rc}): ${out}\n${err}")
    endif()
    if(EXISTS ${bin}/tv-render)
      execute_process(COMMAND ${bin}/tv-render --open example.tvrec --frame 30 --out frame.png
                      WORKING_DIRECTORY ${WORK}/run RESULT_VARIABLE rc OUTPUT_VARIABLE out
                      ERROR_VARIABLE err)
      if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/run/frame.png)
        message(FATAL_ERROR "installed tv-render --open (exit ${rc}): ${out}\n${err}")
      endif()
    endif()
  endif()
  if(EXISTS ${bin}/tv-debugger)
    # No display needed for its command line; a bad flag fails naming it.
    execute_process(COMMAND ${bin}/tv-debugger --help RESULT_VARIABLE rc OUTPUT_VARIABLE out)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: tv-debugger")
      message(FATAL_ERROR "installed tv-debugger --help (exit ${rc}): ${out}")
    endif()
  endif()
  message(STATUS "the installed programs ran from ${bin}")
endif()
message(STATUS "installed to ${prefix}; find_package and pkg-config consumers both ran")
