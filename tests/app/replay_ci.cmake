# What a game's CI does with its recordings, through the programs (ctest -R replay.ci):
#   1. a whole recording validates (exit 0);
#   2. a recording cut short — inside a frame, or after a whole frame with no end mark, as a
#      game that crashed leaves it — fails --validate (exit 1, saying so) unless --allow-truncated;
#   3. --what-if MOVER --fail-on tunnel exits 1 with the report when the re-run tunnels, and the
#      count it prints is the one the game itself printed; 0 when it does not (the control);
#   4. a naive game's recording (bodies moved by update) re-run with --updates-as-moves explains
#      its counts: the recorded run's tunnelled moves are the bullets the game saw go through the
#      wall, plus those that then passed a tile, listed by what they passed.
#   cmake -DGAME=tv-example-platformer -DREPLAY=tv-replay -DWORK=dir -P replay_ci.cmake
foreach(v GAME REPLAY WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "replay_ci.cmake needs -D${v}=")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Runs a command; `rc`, `out` and `err` are set in the caller.
macro(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK})
endmacro()
function(expect what want_rc pattern)
  if(NOT rc EQUAL want_rc)
    message(FATAL_ERROR "${what}: expected exit ${want_rc}, got ${rc}\nstdout: ${out}\nstderr: ${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: output does not match '${pattern}'\nstdout: ${out}\nstderr: ${err}")
  endif()
  message(STATUS "${what}: exit ${rc}, as expected")
endfunction()

# 1. The game's own recording, whole.
run(${GAME} --frames 600 --record game.tvrec)
expect("the game" 0 "through the wall: [0-9]+")
string(REGEX MATCH "fired: ([0-9]+)" _ "${out}")
set(fired ${CMAKE_MATCH_1})
run(${REPLAY} game.tvrec --validate)
expect("a whole recording" 0 "ok: 601 frames")

# 2. Cut short. `head -c` copies the first bytes: inside a frame, and everything but the end mark.
file(SIZE ${WORK}/game.tvrec size)
math(EXPR mid "${size} / 2 + 3")
math(EXPR whole "${size} - 8")
execute_process(COMMAND head -c ${mid} game.tvrec OUTPUT_FILE ${WORK}/cut.tvrec
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
execute_process(COMMAND head -c ${whole} game.tvrec OUTPUT_FILE ${WORK}/unclosed.tvrec
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
run(${REPLAY} cut.tvrec --validate)
expect("a recording cut inside a frame" 1
       "CUT SHORT: frames 0[.][.][0-9]+ .*replay bit for bit, but the file is cut or damaged at byte.*--allow-truncated")
run(${REPLAY} cut.tvrec --validate --allow-truncated)
expect("the same, --allow-truncated" 0 "ok: [0-9]+ frames.*only frames 0[.][.][0-9]+ were checked")
run(${REPLAY} unclosed.tvrec --validate)
expect("a recording with no end mark" 1 "CUT SHORT: frames 0[.][.]600 .*no end mark")
run(${REPLAY} unclosed.tvrec --validate --allow-truncated)
expect("the same, --allow-truncated" 0 "ok: 601 frames.*no end mark \\(allowed\\)")

# 3. What-if with --fail-on: under discrete the bullets continuous stopped go through the wall.
run(${REPLAY} game.tvrec --what-if discrete --fail-on tunnel,overlap)
expect("discrete under --fail-on" 1
       "discrete, tunnelled: ([0-9]+) bullet through wall.*FAILED under discrete: [0-9]+ moves tunnelled")
run(${REPLAY} game.tvrec --what-if continuous --fail-on tunnel,overlap)
expect("continuous under --fail-on (the control)" 0 "passed under continuous")
run(${REPLAY} game.tvrec --what-if sweep --fail-on differ)
expect("sweep under --fail-on differ" 0 "passed under sweep")

# 4. The naive game's own recording: its counts, explained.
run(${GAME} --frames 600 --naive --record naive.tvrec)
expect("the naive game" 0 "bullets fired: ${fired}, stopped by the wall: [0-9]+, through the wall: [0-9]+")
string(REGEX MATCH "through the wall: ([0-9]+)" _ "${out}")
set(naive_through ${CMAKE_MATCH_1})
run(${REPLAY} naive.tvrec --what-if continuous --updates-as-moves --fail-on tunnel)
expect("the naive recording" 0
       "recorded run, tunnelled: ${naive_through} bullet through wall, [0-9]+ bullet through tile.*recorded run, ended inside: [0-9]+ player inside.*Counted in moves, not bodies.*first updates them into what they hit.*passed under continuous")
