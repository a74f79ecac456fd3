# Cross-compile Jelly Lab for 64-bit ARM Linux (aarch64) with Debian's g++-aarch64-linux-gnu: the
# stand-in here for Apple silicon (an ARM64 CPU with FMA always available), run under qemu-user.
#
#   cmake -S . -B build-arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake \
#         -DJELLY_DEPS=bundled
#   qemu-aarch64 -L /usr/aarch64-linux-gnu build-arm64/framework/cli/jelly run scenes/course-2023.toml
#
# Only the aarch64 sysroot (and the bundled third-party sources) are searched for libraries and
# headers, never the host's. tests/platform/check_platform.sh (platform.same_bits_aarch64) uses it.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(_jelly_arm64 aarch64-linux-gnu)
find_program(CMAKE_C_COMPILER NAMES ${_jelly_arm64}-gcc)
find_program(CMAKE_CXX_COMPILER NAMES ${_jelly_arm64}-g++)
if(NOT CMAKE_CXX_COMPILER)
  message(FATAL_ERROR "aarch64 cross-compiler not found: install the Debian package "
                      "g++-aarch64-linux-gnu (aarch64-linux-gnu-g++)")
endif()

list(APPEND CMAKE_FIND_ROOT_PATH /usr/${_jelly_arm64})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Programs run by the build or by CTest (gtest_discover_tests, the selfcheck target) go through
# qemu-user with the cross toolchain's libraries.
find_program(JELLY_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static NO_CMAKE_FIND_ROOT_PATH)
if(JELLY_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${JELLY_QEMU_AARCH64} -L /usr/${_jelly_arm64})
endif()
