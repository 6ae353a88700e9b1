# Cross-compiling for 64-bit Windows with MinGW-w64 from Debian (g++-mingw-w64-x86-64,
# libz-mingw-w64-dev):
#   cmake -S . -B build/windows -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64-x86_64.cmake \
#         -DTV_BUILD_APP=OFF -DTV_BUILD_TESTS=OFF -DTV_BUILD_LEVEL=OFF
#   cmake --build build/windows --target tv_lua        # build/windows/lua/tunnelvision.dll
# The posix thread model: the libraries use no threads, but it is the variant whose standard
# library is complete in GCC 12.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(TV_MINGW_PREFIX x86_64-w64-mingw32)
find_program(CMAKE_CXX_COMPILER NAMES ${TV_MINGW_PREFIX}-g++-posix ${TV_MINGW_PREFIX}-g++ REQUIRED)
find_program(CMAKE_RC_COMPILER NAMES ${TV_MINGW_PREFIX}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${TV_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# zlib linked in, so a DLL built here needs no zlib1.dll beside it.
set(ZLIB_USE_STATIC_LIBS ON)
