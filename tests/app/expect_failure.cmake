# Runs a command that must fail: a non-zero exit, and stderr matching EXPECT.
#   cmake -DCOMMAND="prog|arg|arg" -DEXPECT="regex" -P expect_failure.cmake
# ('|' separates the arguments: a ';' would be split by CMake before we see it.)
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit from: ${COMMAND}\nstdout: ${out}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}':\n${err}")
endif()
message(STATUS "exit ${rc}: ${err}")
