# Configures the source tree in a way that must fail, and checks the message names the fix.
#   CASE=missing_system   JELLY_DEPS=system with Eigen hidden: names libeigen3-dev and the bundled way
#   CASE=missing_cli11    JELLY_DEPS=system with CLI11 hidden (package and headers): names libcli11-dev
#   CASE=missing_bundled  JELLY_DEPS=bundled with no third_party/: names tools/fetch-third-party
#   CASE=no_compiler      CXX points nowhere: names what to install per OS
file(REMOVE_RECURSE "${WORK}")
set(args -S "${SRC}" -B "${WORK}" -DJELLY_BUILD_VIEWER=OFF -DJELLY_BUILD_TESTS=OFF
         -DJELLY_BUILD_BENCHMARKS=OFF -DJELLY_BUILD_GRADER=OFF)
set(env)
if(CASE STREQUAL "missing_system")
  list(APPEND args -DJELLY_DEPS=system -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)
  set(expect "Eigen not found (JELLY_DEPS=system): install the Debian package libeigen3-dev"
             "or use the student release / -DJELLY_DEPS=bundled")
elseif(CASE STREQUAL "missing_cli11")
  list(APPEND args -DJELLY_DEPS=system -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON)
  set(expect "CLI11 not found (JELLY_DEPS=system): install the Debian package libcli11-dev")
elseif(CASE STREQUAL "missing_bundled")
  list(APPEND args -DJELLY_DEPS=bundled -DJELLY_THIRD_PARTY_DIR=${WORK}/no-third-party)
  set(expect "Eigen: JELLY_DEPS=bundled, but ${WORK}/no-third-party/eigen does not exist"
             "tools/fetch-third-party")
elseif(CASE STREQUAL "no_compiler")
  set(env CXX=${WORK}/no-such-compiler)
  set(expect "No C++17 compiler found" "xcode-select --install" "Visual Studio 2019" "apt-get install g++")
else()
  message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${CMAKE_COMMAND} ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \t\r\n]+" " " text "${out}${err}")   # CMake wraps long messages
if(rc EQUAL 0)
  message(FATAL_ERROR "the configure succeeded; it must fail (${CASE}):\n${out}${err}")
endif()
foreach(e IN LISTS expect)
  string(REGEX REPLACE "[ \t\r\n]+" " " e "${e}")
  string(FIND "${text}" "${e}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the message lacks '${e}' (${CASE}):\n${out}${err}")
  endif()
endforeach()
message("${CASE}: the configure stops with the expected message")
