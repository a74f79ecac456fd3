# check_layers.cmake must be able to fail: a small tree with one planted include per rule (a lower
# layer including a higher one, a header in no layer, GL in a GL-free layer, the manifest library
# reaching past the standard library and toml++, general code including an assignment's header, an
# assignment including another's, by its header or by a relative path to its file, a task module
# naming an assignment, a body kind's grader cases naming an assignment or GL, a framework folder
# with no layer) must fail naming each file and line, and the same tree without them, including
# every allowed kind, must pass.
#
#   cmake -DCHECK=<check_layers.cmake> -DWORK=<scratch folder> -P check_layers_selftest.cmake
cmake_minimum_required(VERSION 3.16)
file(REMOVE_RECURSE "${WORK}")

# Allowed includes, one per layer (the tree must pass with only these).
set(_good
  "framework/manifest/include/jelly/manifest.hpp|#pragma once\n#include <string>\n#include <vector>"
  "framework/manifest/src/manifest.cpp|#include \"jelly/manifest.hpp\"\n#include <toml++/toml.h>\n#include <filesystem>"
  "framework/manifest/CMakeLists.txt|add_library(jelly_manifest src/manifest.cpp)\ntarget_link_libraries(jelly_manifest PRIVATE tomlplusplus::tomlplusplus)"
  "framework/core/src/a.cpp|#include \"jelly/world.hpp\"\n#include \"jelly/manifest.hpp\""
  "framework/core/CMakeLists.txt|add_library(jelly_core a.cpp)\ntarget_link_libraries(jelly_core PUBLIC jelly::manifest)"
  "assignments/a1/include/jelly/a1/forces.hpp|#pragma once\n#include \"jelly/types.hpp\""
  "assignments/a1/forces.cpp|#include \"jelly/a1/forces.hpp\""
  "assignments/a1/bindings/task_table.cpp|#include \"jelly/task_table.hpp\"\n#include \"jelly/a1/forces.hpp\""
  "assignments/a1/grader/runner/cases_forces.cpp|#include \"harness.hpp\"\n#include \"jelly/world.hpp\"\n#include \"jelly/a1/forces.hpp\""
  "solutions/a1/springs.cpp|#include \"jelly/a1/springs.hpp\"\n#include \"jelly/spring_pass.hpp\""
  "solutions/a1/detail.hpp|#pragma once\n#include \"jelly/types.hpp\""
  "solutions/a1/engine.cpp|#include \"detail.hpp\"\n#include \"../a1/detail.hpp\""
  "solutions/tasks/mass/engine.cpp|#include \"jelly/spring.hpp\"\n#include \"engine_detail.hpp\""
  "solutions/tasks/mass/engine_detail.hpp|#pragma once\n#include \"jelly/types.hpp\""
  "solutions/tasks/mass/forces.cpp|#include \"jelly/JELLY_TASKS_NAMESPACE/forces.hpp\"\n#include \"jelly/spring_pass.hpp\""
  "assignments/a2/include/jelly/a2/cloth.hpp|#pragma once\n#include \"jelly/types.hpp\""
  "assignments/a2/cloth.cpp|#include \"jelly/a2/cloth.hpp\""
  "bench/bench_a1.cpp|#include \"jelly/a1/forces.hpp\"\n#include \"jelly/world.hpp\""
  "framework/session/src/a.cpp|#include \"jelly/session/x.hpp\"\n#include \"jelly/scene.hpp\""
  "framework/render/src/a.cpp|#include <GL/glcorearb.h>\n#include \"jelly/session/x.hpp\"\n#include \"jelly/render/y.hpp\""
  "framework/movie/src/a.cpp|#include \"jelly/render/y.hpp\"\n#include \"jelly/movie/z.hpp\"\n#include \"jelly/cli_common/c.hpp\""
  "framework/cli/a.cpp|#include \"jelly/movie/render_command.hpp\"\n#include \"jelly/cli/x.hpp\""
  "framework/app/a.cpp|#include <imgui.h>\n#include \"jelly/render/y.hpp\"\n#include \"jelly/movie/mp4.hpp\""
  "grader/src/a.cpp|#include \"jelly/scene.hpp\"\n#include \"jelly/manifest.hpp\"\n#include \"process.hpp\""
  "framework/bodies/kind/grader/kind_cases.cpp|#include \"harness.hpp\"\n#include \"jelly/world.hpp\""
  "grader/tests/hostile/x/forces.cpp|#include \"jelly/render/renderer.hpp\""
  "framework/movie/CMakeLists.txt|add_library(jelly_movie a.cpp)\ntarget_link_libraries(jelly_movie PUBLIC jelly::render jelly::session)"
  "framework/cli/CMakeLists.txt|add_executable(jelly main.cpp)\n# the `jelly-lab` viewer\nif(TARGET jelly_movie)\n  target_link_libraries(jelly PRIVATE jelly::movie)\nendif()"
  "framework/app/CMakeLists.txt|add_executable(jelly-lab main.cpp)\ntarget_link_libraries(jelly-lab PRIVATE jelly::movie jelly::render)")
# Planted violations: file|text|expected "FILE:LINE:" of the message.
set(_bad
  "framework/core/src/bad.cpp|// one\n\n#include \"jelly/session/scene_catalog.hpp\"|framework/core/src/bad.cpp:3:"
  "framework/core/include/jelly/bad.hpp|#pragma once\n#include <GLFW/glfw3.h>|framework/core/include/jelly/bad.hpp:2:"
  "solutions/a1/bad.cpp|#include \"jelly/session/simulation_run.hpp\"|solutions/a1/bad.cpp:1:"
  "framework/manifest/src/bad.cpp|#include \"jelly/manifest.hpp\"\n#include \"jelly/world.hpp\"|framework/manifest/src/bad.cpp:2:"
  "framework/manifest/src/eigen.cpp|#include <vector>\n#include <Eigen/Dense>|framework/manifest/src/eigen.cpp:2:"
  "framework/manifest/src/CMakeLists.txt|add_library(m a.cpp)\ntarget_link_libraries(m PUBLIC jelly::core)|framework/manifest/src/CMakeLists.txt:2:"
  "framework/core/src/a1.cpp|#include \"jelly/a1/forces.hpp\"|framework/core/src/a1.cpp:1:"
  "framework/session/src/a1.cpp|#include \"jelly/a2/cloth.hpp\"|framework/session/src/a1.cpp:1:"
  "grader/src/a1.cpp|#include \"jelly/manifest.hpp\"\n#include \"jelly/a1/forces.hpp\"|grader/src/a1.cpp:2:"
  "grader/runner/a1.cpp|#include \"harness.hpp\"\n#include \"jelly/a1/forces.hpp\"|grader/runner/a1.cpp:2:"
  "framework/bodies/kind/grader/a1.cpp|#include \"harness.hpp\"\n#include \"jelly/a1/forces.hpp\"|framework/bodies/kind/grader/a1.cpp:2:"
  "framework/bodies/kind/grader/gl.cpp|#include <GL/glcorearb.h>|framework/bodies/kind/grader/gl.cpp:1:"
  "assignments/a2/bindings/bad.cpp|#include \"jelly/a1/forces.hpp\"|assignments/a2/bindings/bad.cpp:1:"
  "assignments/a2/include/jelly/a2/bad.hpp|#pragma once\n#include \"jelly/a1/forces.hpp\"|assignments/a2/include/jelly/a2/bad.hpp:2:"
  "solutions/a2/cloth.cpp|#include \"jelly/a2/cloth.hpp\"\n#include \"jelly/a1/forces.hpp\"|solutions/a2/cloth.cpp:2:"
  "solutions/a2/engine.cpp|#include \"jelly/a2/cloth.hpp\"\n#define NS a2\n#include \"../a1/engine.cpp\"|solutions/a2/engine.cpp:3:"
  "assignments/a2/grader/runner/reuse.cpp|#include \"../../../a1/grader/runner/cases_forces.cpp\"|assignments/a2/grader/runner/reuse.cpp:1:"
  "solutions/tasks/mass/named.cpp|#include \"jelly/a1/forces.hpp\"|solutions/tasks/mass/named.cpp:1:"
  "solutions/tasks/mass/reach.cpp|#include \"../../a1/springs.cpp\"|solutions/tasks/mass/reach.cpp:1:"
  "solutions/a1/placeholder.cpp|#include \"jelly/JELLY_TASKS_NAMESPACE/forces.hpp\"|solutions/a1/placeholder.cpp:1:"
  "framework/core/src/reach.cpp|#include \"../../../assignments/a1/forces.cpp\"|framework/core/src/reach.cpp:1:"
  "framework/core/src/up.cpp|#include \"../../session/src/a.cpp\"|framework/core/src/up.cpp:1:"
  "assignments/a2/grader/runner/cases.cpp|#include \"harness.hpp\"\n#include \"jelly/a1/forces.hpp\"|assignments/a2/grader/runner/cases.cpp:2:"
  "assignments/a1/bindings/session.cpp|#include \"jelly/session/simulation_run.hpp\"|assignments/a1/bindings/session.cpp:1:"
  "assignments/a1/grader/runner/gl.cpp|#include <GL/glcorearb.h>|assignments/a1/grader/runner/gl.cpp:1:"
  "framework/tasks/task_table.cpp|#include \"jelly/a1/forces.hpp\"|framework/tasks/task_table.cpp:1:"
  "framework/session/src/bad.cpp|#include \"jelly/scene.hpp\"\n#include \"jelly/render/renderer.hpp\"|framework/session/src/bad.cpp:2:"
  "framework/session/src/gl.cpp|#include <GL/glcorearb.h>|framework/session/src/gl.cpp:1:"
  "framework/render/src/bad.cpp|#include \"jelly/movie/render_command.hpp\"|framework/render/src/bad.cpp:1:"
  "framework/movie/src/bad.cpp|#include \"jelly/cli/x.hpp\"|framework/movie/src/bad.cpp:1:"
  "framework/movie/src/gl.cpp|#include <GL/glcorearb.h>|framework/movie/src/gl.cpp:1:"
  "framework/cli/draws.cpp|#include \"jelly/render/renderer.hpp\"|framework/cli/draws.cpp:1:"
  "framework/cli/bad.cpp|#  include <jelly/app/app.hpp>|framework/cli/bad.cpp:1:"
  "framework/app/bad.cpp|#include \"jelly/cli/cli_args.hpp\"|framework/app/bad.cpp:1:"
  "framework/app/sideways.cpp|#include \"jelly/cli/render_command.hpp\"|framework/app/sideways.cpp:1:"
  "grader/src/bad.cpp|#include \"jelly/render/frame.hpp\"|grader/src/bad.cpp:1:"
  "framework/render/src/nolayer.cpp|#include \"jelly/newthing/x.hpp\"|framework/render/src/nolayer.cpp:1:"
  "framework/render/CMakeLists.txt|add_library(jelly_render a.cpp)\n# The CLI forwards `jelly render` here:\nif(TARGET jelly)\n  target_link_libraries(jelly PRIVATE jelly::render)\nendif()|framework/render/CMakeLists.txt:3:"
  "framework/session/CMakeLists.txt|add_library(jelly_session a.cpp)\ntarget_link_libraries(jelly_session PUBLIC jelly::core\n  jelly::render)|framework/session/CMakeLists.txt:3:"
  "framework/render/src/CMakeLists.txt|add_library(x a.cpp)\ntarget_link_libraries(x PRIVATE jelly::movie)|framework/render/src/CMakeLists.txt:2:"
  "framework/movie/src/CMakeLists.txt|add_library(y a.cpp)\ntarget_link_libraries(y PRIVATE jelly)|framework/movie/src/CMakeLists.txt:2:")

function(_plant entries)
  foreach(entry IN LISTS entries)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 0 path)
    list(GET parts 1 text)
    string(REPLACE "\\n" "\n" text "${text}")
    file(WRITE "${WORK}/${path}" "${text}\n")
  endforeach()
endfunction()

function(_check expect_ok out)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "check_layers failed on a tree that follows the layers:\n${o}${e}")
  elseif(NOT expect_ok AND rc EQUAL 0)
    message(FATAL_ERROR "check_layers passed a tree with planted violations:\n${o}${e}")
  endif()
  set(${out} "${o}${e}" PARENT_SCOPE)
endfunction()

_plant("${_good}")
_check(TRUE output)

_plant("${_bad}")
_check(FALSE output)
list(LENGTH _bad expected)
foreach(entry IN LISTS _bad)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 2 where)
  string(FIND "${output}" "${where}" at)
  if(at LESS 0)
    message(FATAL_ERROR "check_layers did not report ${where}\n${output}")
  endif()
endforeach()
string(REGEX MATCHALL "(^|\n)[a-z]+/[^\n:]*:[0-9]+: " reported "${output}")
list(LENGTH reported count)
if(NOT count EQUAL expected)
  message(FATAL_ERROR "check_layers reported ${count} problems, ${expected} were planted (the allowed "
                      "includes must not be reported):\n${output}")
endif()
message(STATUS "check_layers: all ${expected} planted violations reported with file and line; the allowed tree passes")
