# The Lua module cross-compiled for Windows with MinGW-w64 (cmake/toolchains/mingw-w64-x86_64.cmake):
# it builds, it exports luaopen_tunnelvision and luaopen_tunnelvision_bump and nothing else, and
# it imports its Lua API from lua51.dll (what LÖVE ships beside love.exe) and otherwise only
# from Windows itself — the C runtime, the kernel, and Winsock 2 (WS2_32.dll, the live stream's
# sockets): no MinGW runtime DLL to ship beside it. Not run: there is no Windows here.
#   cmake -DSOURCE=repo -DWORK=dir -P windows_dll.cmake
foreach(v SOURCE WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "windows_dll.cmake needs -D${v}=")
  endif()
endforeach()
find_program(MINGW_CXX NAMES x86_64-w64-mingw32-g++-posix x86_64-w64-mingw32-g++)
find_program(OBJDUMP x86_64-w64-mingw32-objdump)
if(NOT MINGW_CXX OR NOT OBJDUMP OR NOT EXISTS /usr/x86_64-w64-mingw32/include/zlib.h)
  message(STATUS "tv-skip: the MinGW-w64 cross-compiler or its zlib is not installed "
                 "(apt-get install g++-mingw-w64-x86-64 libz-mingw-w64-dev; scripts/deps.sh all)")
  return()
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " cmd)
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK} -G Ninja -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_TOOLCHAIN_FILE=${SOURCE}/cmake/toolchains/mingw-w64-x86_64.cmake
    -DTV_BUILD_APP=OFF -DTV_BUILD_TESTS=OFF -DTV_BUILD_LEVEL=OFF -DTV_INSTALL=OFF)
run(${CMAKE_COMMAND} --build ${WORK} --target tv_lua)
set(dll ${WORK}/lua/tunnelvision.dll)
run(${OBJDUMP} -p ${dll})
set(headers "${last_output}")

string(REGEX MATCHALL "DLL Name: [^\n]+" imports "${headers}")
string(REPLACE "DLL Name: " "" imports "${imports}")
list(SORT imports)
if(NOT imports STREQUAL "KERNEL32.dll;WS2_32.dll;lua51.dll;msvcrt.dll")
  message(FATAL_ERROR "tunnelvision.dll imports ${imports}; expected KERNEL32.dll, WS2_32.dll, "
                      "lua51.dll and msvcrt.dll only")
endif()
string(REGEX MATCH "\\[Ordinal/Name Pointer\\] Table\n(([ \t]+\\[[ 0-9]+\\] [^\n]+\n)+)" _ "${headers}")
string(REGEX MATCHALL "\\] [A-Za-z_0-9]+" exports "${CMAKE_MATCH_1}")
string(REPLACE "] " "" exports "${exports}")
if(NOT exports STREQUAL "luaopen_tunnelvision;luaopen_tunnelvision_bump")
  message(FATAL_ERROR "tunnelvision.dll exports '${exports}'; expected luaopen_tunnelvision and "
                      "luaopen_tunnelvision_bump only")
endif()
file(SIZE ${dll} size)
message(STATUS "tunnelvision.dll (${size} bytes): imports ${imports}; exports ${exports}")
