# A LÖVE game shipped as core/lua/README.md says: tests/lua/fused (with the shim
# tunnelvision/bump.lua) zipped into game.love; the module beside it; `love game.love` run, then
# the love executable fused with game.love (cat love game.love > game) run — both must load the
# module from beside the game and stop a bullet at a wall.
#   cmake -DLOVE=love -DMODULE=tunnelvision.so -DSOURCE=repo -DWORK=dir -P fused_game.cmake
foreach(v LOVE MODULE SOURCE WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "fused_game.cmake needs -D${v}=")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/game/tunnelvision ${WORK}/ship)
file(COPY ${SOURCE}/tests/lua/fused/main.lua ${SOURCE}/tests/lua/fused/conf.lua
     DESTINATION ${WORK}/game)
file(COPY ${SOURCE}/core/lua/tunnelvision/bump.lua DESTINATION ${WORK}/game/tunnelvision)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${WORK}/ship/game.love --format=zip
                        main.lua conf.lua tunnelvision/bump.lua
                WORKING_DIRECTORY ${WORK}/game RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not zip the game")
endif()
file(COPY ${MODULE} DESTINATION ${WORK}/ship)

# The fused executable: love's binary with the .love appended (LÖVE finds the zip at its end).
execute_process(COMMAND cat ${LOVE} ${WORK}/ship/game.love OUTPUT_FILE ${WORK}/ship/game
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not fuse ${LOVE} with game.love")
endif()
file(CHMOD ${WORK}/ship/game PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)

foreach(run "${LOVE};${WORK}/ship/game.love" "${WORK}/ship/game")
  execute_process(COMMAND ${run} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "bullet stopped at x=96")
    message(FATAL_ERROR "${run} (exit ${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${run}: ${out}")
endforeach()
