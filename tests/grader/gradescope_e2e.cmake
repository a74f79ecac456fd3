# The Gradescope autograder end to end, as far as one machine can take it: build the zip, unpack
# it where /autograder would be, configure and build it exactly as its setup.sh does but WITHOUT
# the toml++ package (Gradescope's Ubuntu image may lack it; the zip's bundled headers must do),
# then grade the reference's five files and the stubs as run_autograder does, and check
# results.json. apt-get is the one step not exercised.
#   cmake -DGRADE=jelly-grade -DSOURCE=<repo> -DWORK=<dir> -P gradescope_e2e.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/autograder")
execute_process(COMMAND "${GRADE}" gradescope-zip "${WORK}/autograder.zip" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gradescope-zip failed (${rc}): ${out}${err}")
endif()
execute_process(COMMAND unzip -q "${WORK}/autograder.zip" -d "${WORK}/autograder" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "unzip failed (${rc})")
endif()
set(src "${WORK}/autograder/source")
if(NOT EXISTS "${src}/third_party/tomlplusplus/include/toml++/toml.h" OR NOT EXISTS "${src}/third_party/tomlplusplus/LICENSE")
  message(FATAL_ERROR "the zip has no bundled toml++ headers and licence under source/third_party/tomlplusplus")
endif()
# setup.sh's configure line, plus: pretend the distribution has no toml++ package.
file(READ "${WORK}/autograder/setup.sh" setup)
string(FIND "${setup}" "-DJELLY_TASKS=assignments" at)
if(at EQUAL -1)
  message(FATAL_ERROR "setup.sh no longer configures as this test assumes:\n${setup}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${src}" -B "${src}/build" -DCMAKE_BUILD_TYPE=Release
                        -DJELLY_TASKS=assignments -DJELLY_BUILD_TESTS=OFF -DJELLY_BUILD_BENCHMARKS=OFF
                        -DJELLY_BUILD_VIEWER=OFF -DCMAKE_DISABLE_FIND_PACKAGE_tomlplusplus=ON
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configure failed (${rc}):\n${out}${err}")
endif()
string(FIND "${out}" "third_party/tomlplusplus" used)
if(used EQUAL -1)
  message(FATAL_ERROR "the build did not use the bundled toml++:\n${out}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${src}/build" -j2 --target jelly-grade
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "build failed (${rc}):\n${out}${err}")
endif()
# run_autograder on two submissions: the reference's files (full marks) and the stubs (zero).
set(grade "${src}/build/grader/jelly-grade")
file(MAKE_DIRECTORY "${WORK}/reference-submission")
foreach(f springs.cpp forces.cpp collision.cpp contact.cpp integrators.cpp)
  file(COPY "${SOURCE}/solutions/${f}" DESTINATION "${WORK}/reference-submission")
endforeach()
foreach(case reference stubs)
  if(case STREQUAL "reference")
    set(sub "${WORK}/reference-submission")
  else()
    set(sub "${src}/assignments")
  endif()
  execute_process(COMMAND "${grade}" grade "${sub}" --visibility all --out "${WORK}/results-${case}"
                          --format gradescope WORKING_DIRECTORY "${src}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT EXISTS "${WORK}/results-${case}/results.json")
    message(FATAL_ERROR "${case}: no results.json (${rc}):\n${out}${err}")
  endif()
  file(READ "${WORK}/results-${case}/results.json" json)
  string(JSON score GET "${json}" score)
  string(JSON tests LENGTH "${json}" tests)
  message(STATUS "${case}: score ${score}, ${tests} tests")
  if(case STREQUAL "reference" AND NOT score MATCHES "^80(\\.0*)?$")
    message(FATAL_ERROR "the reference scored ${score}, expected 80:\n${out}")
  endif()
  if(case STREQUAL "stubs" AND NOT score MATCHES "^0(\\.0*)?$")
    message(FATAL_ERROR "the stubs scored ${score}, expected 0")
  endif()
endforeach()
