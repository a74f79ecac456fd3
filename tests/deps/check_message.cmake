cmake_minimum_required(VERSION 3.16)
# Configures the source tree in a way that must fail, and checks the message names the fix.
#   CASE=missing_system   JELLY_DEPS=system with Eigen hidden: names libeigen3-dev and the bundled way
#   CASE=missing_cli11    JELLY_DEPS=system with CLI11 hidden (package and headers): names libcli11-dev.
#                         Eigen, toml++ and nlohmann/json, checked before it, come from a fake
#                         prefix made here, so the first missing package is CLI11 whatever this
#                         machine has installed (Ubuntu 24.04 has no libtomlplusplus-dev, say)
#   CASE=missing_bundled  JELLY_DEPS=bundled with no third_party/: names tools/fetch-third-party
#   CASE=no_compiler      CXX points nowhere: names what to install per OS
#   CASE=x11_missing      bundled GLFW with X11 hidden: the configure SUCCEEDS with the viewer off
#                         and a warning naming the packages for Debian/Ubuntu, Fedora and Arch (the
#                         bundled libraries are stand-in headers made here: configure only)
file(REMOVE_RECURSE "${WORK}")
set(args -S "${SRC}" -B "${WORK}" -DJELLY_BUILD_VIEWER=OFF -DJELLY_BUILD_TESTS=OFF
         -DJELLY_BUILD_BENCHMARKS=OFF -DJELLY_BUILD_GRADER=OFF)
set(env)
set(must_fail TRUE)
set(forbid)
if(CASE STREQUAL "missing_system")
  list(APPEND args -DJELLY_DEPS=system -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)
  set(expect "Eigen not found (JELLY_DEPS=system): install the Debian package libeigen3-dev"
             "or use the student release / -DJELLY_DEPS=bundled")
elseif(CASE STREQUAL "missing_cli11")
  # A package config for each library checked before CLI11 (the version files accept any request).
  set(prefix "${WORK}/fake-prefix")
  foreach(pkg Eigen3 tomlplusplus nlohmann_json)
    set(target ${pkg}::${pkg})
    if(pkg STREQUAL "Eigen3")
      set(target Eigen3::Eigen)
    endif()
    set(name ${pkg})
    file(WRITE "${prefix}/share/${name}/${name}Config.cmake"
         "if(NOT TARGET ${target})\n  add_library(${target} INTERFACE IMPORTED)\nendif()\n")
    file(WRITE "${prefix}/share/${name}/${name}ConfigVersion.cmake"
         "set(PACKAGE_VERSION 99.0)\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n")
  endforeach()
  list(APPEND args -DJELLY_DEPS=system -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
                   "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_FIND_PACKAGE_PREFER_CONFIG=ON)
  set(expect "CLI11 not found (JELLY_DEPS=system): install the Debian package libcli11-dev")
elseif(CASE STREQUAL "missing_bundled")
  list(APPEND args -DJELLY_DEPS=bundled -DJELLY_THIRD_PARTY_DIR=${WORK}/no-third-party)
  set(expect "Eigen: JELLY_DEPS=bundled, but ${WORK}/no-third-party/eigen does not exist"
             "tools/fetch-third-party")
elseif(CASE STREQUAL "no_compiler")
  set(env CXX=${WORK}/no-such-compiler)
  set(expect "No C++17 compiler found" "xcode-select --install" "Visual Studio 2019" "apt-get install g++")
elseif(CASE STREQUAL "x11_missing")
  set(tp "${WORK}/third_party")
  foreach(f eigen/Eigen/Core tomlplusplus/include/toml++/toml.h nlohmann_json/include/nlohmann/json.hpp
            cli11/include/CLI/CLI.hpp glfw/include/GLFW/glfw3.h)
    file(WRITE "${tp}/${f}" "")
  endforeach()
  file(WRITE "${tp}/glfw/CMakeLists.txt" "message(FATAL_ERROR \"GLFW's CMakeLists.txt was reached\")\n")
  list(REMOVE_ITEM args -DJELLY_BUILD_VIEWER=OFF)
  list(APPEND args -DJELLY_DEPS=bundled "-DJELLY_THIRD_PARTY_DIR=${tp}" -DCMAKE_DISABLE_FIND_PACKAGE_X11=ON)
  set(must_fail FALSE)
  set(expect "Jelly Lab: the viewer is OFF for this build"
             "Debian/Ubuntu: sudo apt-get install libx11-dev libxrandr-dev libxinerama-dev libxcursor-dev libxi-dev"
             "Fedora: sudo dnf install libX11-devel libXrandr-devel libXinerama-devel libXcursor-devel libXi-devel"
             "Arch: sudo pacman -S libx11 libxrandr libxinerama libxcursor libxi"
             "-DJELLY_BUILD_VIEWER=OFF" "Jelly Lab: built WITHOUT the viewer")
  set(forbid "Could NOT find X11" "GLFW's CMakeLists.txt was reached")
else()
  message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${CMAKE_COMMAND} ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \t\r\n]+" " " text "${out}${err}")   # CMake wraps long messages
if(must_fail AND rc EQUAL 0)
  message(FATAL_ERROR "the configure succeeded; it must fail (${CASE}):\n${out}${err}")
elseif(NOT must_fail AND NOT rc EQUAL 0)
  message(FATAL_ERROR "the configure failed; it must succeed (${CASE}):\n${out}${err}")
endif()
foreach(f IN LISTS forbid)
  string(FIND "${text}" "${f}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the output has '${f}' (${CASE}):\n${out}${err}")
  endif()
endforeach()
if(CASE STREQUAL "x11_missing" AND EXISTS "${WORK}/framework/app")
  message(FATAL_ERROR "the viewer is said to be off, but framework/app (jelly-lab) was configured")
endif()
foreach(e IN LISTS expect)
  string(REGEX REPLACE "[ \t\r\n]+" " " e "${e}")
  string(FIND "${text}" "${e}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the message lacks '${e}' (${CASE}):\n${out}${err}")
  endif()
endforeach()
if(must_fail)
  message("${CASE}: the configure stops with the expected message")
else()
  message("${CASE}: the configure succeeds with the expected notice")
endif()
