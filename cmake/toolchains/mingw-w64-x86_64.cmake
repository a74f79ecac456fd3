# Cross-compile Jelly Lab for 64-bit Windows with MinGW-w64 (Debian: g++-mingw-w64-x86-64-posix).
#
#   cmake --preset windows-mingw          (or: cmake -S . -B build-win
#                                            -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64-x86_64.cmake)
#
# The "posix" thread model is required: std::thread and std::mutex (used by the core and the tests)
# need winpthreads with MinGW-w64's GCC. libgcc, libstdc++ and winpthread are linked statically so
# that the .exe files run on a plain Windows (and under wine) without any MinGW DLL next to them.
# Run the results with `wine jelly.exe ...` (Debian: /usr/lib/wine/wine64).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(_jelly_mingw x86_64-w64-mingw32)
find_program(CMAKE_C_COMPILER NAMES ${_jelly_mingw}-gcc-posix)
find_program(CMAKE_CXX_COMPILER NAMES ${_jelly_mingw}-g++-posix)
find_program(CMAKE_RC_COMPILER NAMES ${_jelly_mingw}-windres)
if(NOT CMAKE_CXX_COMPILER)
  message(FATAL_ERROR "MinGW-w64 (posix threads) not found: install the Debian package "
                      "g++-mingw-w64-x86-64-posix (x86_64-w64-mingw32-g++-posix)")
endif()

# Only the MinGW sysroot (and folders the user adds, e.g. bundled third-party builds) are searched
# for libraries and headers: never the Linux host's /usr/include or /usr/lib.
list(APPEND CMAKE_FIND_ROOT_PATH /usr/${_jelly_mingw})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Programs run by the build or by CTest (gtest_discover_tests, the platform tests) go through wine.
find_program(JELLY_WINE NAMES wine64 wine PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(JELLY_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${JELLY_WINE})
endif()

# No DLLs from MinGW next to the programs: static libgcc, libstdc++ and winpthread.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
# FindOpenMP would pick libgomp.dll.a (a DLL import library) even with -static: point it at the
# static archive (only the reference solution's spring pass uses OpenMP).
if(CMAKE_CXX_COMPILER)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libgomp.a
                  OUTPUT_VARIABLE _jelly_gomp OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(IS_ABSOLUTE "${_jelly_gomp}" AND EXISTS "${_jelly_gomp}")
    set(OpenMP_gomp_LIBRARY "${_jelly_gomp}" CACHE FILEPATH "libgomp (static, MinGW)")
  endif()
endif()
