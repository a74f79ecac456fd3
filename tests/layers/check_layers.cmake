# The layers of docs/architecture.md ("Layers"), kept true: every `#include "jelly/..."` (or <...>)
# in the framework, the assignments, their references, the grader and the benchmarks must name a
# header of the file's own layer or of one below it, and the layers without GL must include no GL,
# GLFW or ImGui header. Prints every violation as FILE:LINE and fails; passes silently otherwise.
#
#   cmake -DROOT=<source tree> -P check_layers.cmake
#
# A file's layer is its folder; a header's layer is its folder under jelly/ (a header straight in
# jelly/ is the core's, except the manifest library's headers, framework/manifest/include/jelly/*).
# A new folder under jelly/ must be given a layer here and in docs/architecture.md, or this check
# fails naming it.
#
# The assignments: the files of assignments/<id>/ (stubs, bindings/, include/) and of
# solutions/<id>/ are layer `assignment`, those of assignments/<id>/grader/ (case generators) layer
# `assignment_grader`; both may include the core and their OWN assignment's headers
# (assignments/<id>/include/jelly/<folder>/), never another assignment's. General code (the
# framework, grader/src, grader/runner) includes no assignment's header at all. The manifest
# library (framework/manifest) is layer 0: its own headers, the standard library and toml++ only.
# A task module's reference (solutions/tasks/<module>/: tasks that several assignments share,
# compiled for each assignment that uses it) is layer `task_module`: it names no assignment, so it
# includes the core and, in a task file, the assignment's own header by the word that stands for
# the assignment's namespace (`jelly/JELLY_TASKS_NAMESPACE/<file>.hpp`, layer
# `task_header`: the build writes the file out for each assignment with that word replaced).
#
# A quoted include the compiler finds next to the including file (`#include "../a1/x.cpp"`,
# `#include "detail.hpp"`) is checked by the file it reaches: that file's layer must be one the
# includer may include, and a file of another assignment (assignments/<x>/, solutions/<x>/) is
# never included.
cmake_minimum_required(VERSION 3.16)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_layers.cmake")
endif()

# Folder of a source file (relative to ROOT) -> its layer. Checked in order; the first match wins.
# (assignments/<id>/ and solutions/<id>/ are matched before this list; see _file_layer.)
set(_folders
  "framework/manifest/" manifest
  "framework/core/"    core
  "framework/bodies/"  core      # the body modules are core code (docs/architecture.md "Bodies")
  "framework/session/" session
  "framework/cli_common/" cli_common
  "framework/process/" process
  "framework/render/"  render
  "framework/movie/"   movie
  "framework/cli/"     cli
  "framework/app/"     app
  "grader/tests/"      ""        # hostile submissions: student code, deliberately anything
  "grader/"            grader
  "bench/"             bench)
# What each layer may include (its own layer and those below it).
# `assignment` stands for the file's own assignment's headers (never another assignment's).
set(_may_manifest manifest)
set(_may_core    manifest core)
set(_may_assignment core assignment)
set(_may_assignment_grader core assignment)
set(_may_task_module core task_header)
set(_may_session manifest core session)
set(_may_cli_common cli_common)
set(_may_process process)
set(_may_render  manifest core session render)
set(_may_movie   manifest core session render movie cli_common process)
set(_may_cli     manifest core session movie cli cli_common process)
set(_may_app     manifest core session render movie app cli_common)
# A body kind's view module (framework/bodies/<kind>/view/, headers jelly/bodies/<kind>/view/):
# the kind's GL side, on top of the renderer, whose registered list the renderer walks.
set(_may_body_view manifest core session render body_view)
# A body kind's grader cases (framework/bodies/<kind>/grader/: the slot-level cases of the kind's
# own slots, on the grader's harness, `harness.hpp` by its folder): the core and the grader.
set(_may_body_grader manifest core body_grader grader)
set(_may_grader  manifest core grader cli_common process)
set(_may_bench   manifest core assignment)
# General code: it names no assignment, so it includes no assignment's header.
set(_general manifest core session cli_common process render movie cli app grader)
# Layers that must stay free of GL (and of windowing and GUI libraries).
set(_no_gl manifest core assignment assignment_grader task_module body_grader session cli_common process movie cli grader bench)
set(_gl_regex "^(GL|GLFW|KHR|EGL|OpenGL)/|^imgui|osmesa")
# Layer 0 includes, besides its own headers, only the standard library (<vector>, <cstdio>) and
# toml++ (<toml++/toml.h>).
set(_manifest_external_regex "^([a-z_0-9]+|toml\\+\\+/.*)$")

# The manifest library's headers, and each assignment's header folders (jelly/<folder>/ under
# assignments/<id>/include) with the assignment that owns them.
file(GLOB _manifest_headers RELATIVE "${ROOT}/framework/manifest/include"
     "${ROOT}/framework/manifest/include/jelly/*")
file(GLOB _assignment_header_dirs LIST_DIRECTORIES true RELATIVE "${ROOT}/assignments"
     "${ROOT}/assignments/*/include/jelly/*")
set(_assignment_folders "")
foreach(d IN LISTS _assignment_header_dirs)
  if(IS_DIRECTORY "${ROOT}/assignments/${d}" AND d MATCHES "^([^/]+)/include/jelly/([^/]+)$")
    set(_owner_of_${CMAKE_MATCH_2} ${CMAKE_MATCH_1})
    list(APPEND _assignment_folders ${CMAKE_MATCH_2})
  endif()
endforeach()

# A body module's header folders (jelly/<folder>/ under framework/bodies/<module>/include): core
# code, as the module's sources are.
file(GLOB _body_header_dirs LIST_DIRECTORIES true RELATIVE "${ROOT}/framework/bodies"
     "${ROOT}/framework/bodies/*/include/jelly/*")
set(_body_folders "")
foreach(d IN LISTS _body_header_dirs)
  if(IS_DIRECTORY "${ROOT}/framework/bodies/${d}" AND d MATCHES "^[^/]+/include/jelly/([^/]+)$")
    list(APPEND _body_folders ${CMAKE_MATCH_1})
  endif()
endforeach()

# Layer of an included header path "jelly/..."; "?" when no layer owns its folder. For an
# assignment's header, `owner` is the assignment's id.
function(_header_layer header out owner)
  set(${owner} "" PARENT_SCOPE)
  if(header IN_LIST _manifest_headers)
    set(${out} manifest PARENT_SCOPE)
  elseif(header MATCHES "^jelly/JELLY_TASKS_NAMESPACE/[^/]+$")
    set(${out} task_header PARENT_SCOPE)
  elseif(header MATCHES "^jelly/bodies/[^/]+/view/")
    set(${out} body_view PARENT_SCOPE)
  elseif(header MATCHES "^jelly/[^/]+$")
    set(${out} core PARENT_SCOPE)
  elseif(header MATCHES "^jelly/([^/]+)/" AND CMAKE_MATCH_1 IN_LIST _body_folders)
    set(${out} core PARENT_SCOPE)
  elseif(header MATCHES "^jelly/(session|render|movie|cli_common|process|cli|app|grader)/")
    set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
  elseif(header MATCHES "^jelly/([^/]+)/" AND CMAKE_MATCH_1 IN_LIST _assignment_folders)
    set(${out} assignment PARENT_SCOPE)
    set(${owner} ${_owner_of_${CMAKE_MATCH_1}} PARENT_SCOPE)
  else()
    set(${out} "?" PARENT_SCOPE)
  endif()
endfunction()

# Layer of a source file (relative to ROOT), "" for files no layer checks; `own` is the id of the
# assignment the file belongs to (assignments/<id>/..., solutions/<id>/...).
function(_file_layer f out own)
  set(${own} "" PARENT_SCOPE)
  if(f MATCHES "^solutions/tasks/")
    set(${out} task_module PARENT_SCOPE)
    return()
  elseif(f MATCHES "^assignments/([^/]+)/grader/")
    set(${out} assignment_grader PARENT_SCOPE)
    set(${own} ${CMAKE_MATCH_1} PARENT_SCOPE)
    return()
  elseif(f MATCHES "^(assignments|solutions)/([^/]+)/")
    set(${out} assignment PARENT_SCOPE)
    set(${own} ${CMAKE_MATCH_2} PARENT_SCOPE)
    return()
  endif()
  if(f MATCHES "^framework/bodies/[^/]+/view/")
    set(${out} body_view PARENT_SCOPE)
    return()
  elseif(f MATCHES "^framework/bodies/[^/]+/grader/")
    set(${out} body_grader PARENT_SCOPE)
    return()
  endif()
  list(LENGTH _folders n)
  set(i 0)
  while(i LESS n)
    list(GET _folders ${i} prefix)
    math(EXPR j "${i} + 1")
    list(GET _folders ${j} candidate)
    string(FIND "${f}" "${prefix}" at)
    if(at EQUAL 0)
      set(${out} "${candidate}" PARENT_SCOPE)
      return()
    endif()
    math(EXPR i "${i} + 2")
  endwhile()
  set(${out} "" PARENT_SCOPE)
endfunction()

# 1-based line of the first occurrence of `needle` in `text`.
function(_line_of text needle out)
  string(FIND "${text}" "${needle}" at)
  string(SUBSTRING "${text}" 0 ${at} before)
  string(REGEX MATCHALL "\n" newlines "${before}")
  list(LENGTH newlines n)
  math(EXPR n "${n} + 1")
  set(${out} ${n} PARENT_SCOPE)
endfunction()

# A quoted include that reaches a file beside the includer (the compiler looks there first): the
# reached file's layer must be one `layer` may include, and never another assignment's file.
function(_relative_include f header layer own out)
  set(${out} "" PARENT_SCOPE)
  get_filename_component(dir "${f}" DIRECTORY)
  get_filename_component(reached "${ROOT}/${dir}/${header}" ABSOLUTE)
  if(NOT EXISTS "${reached}" OR IS_DIRECTORY "${reached}")
    return()
  endif()
  file(RELATIVE_PATH rel "${ROOT}" "${reached}")
  if(rel MATCHES "^\\.\\./")
    set(${out} "${layer} includes ${header}, outside the source tree" PARENT_SCOPE)
    return()
  endif()
  _file_layer("${rel}" to to_own)
  if(to STREQUAL "")
    return()
  endif()
  if(to_own AND NOT to_own STREQUAL own)
    set(${out} "${f} includes ${header} (${rel}), a file of assignment ${to_own}: an assignment includes only its own files and the core (code that two assignments share is a task module, solutions/tasks/)" PARENT_SCOPE)
  elseif(to MATCHES "^assignment" AND layer IN_LIST _general)
    set(${out} "${layer} includes ${header} (${rel}), a file of assignment ${to_own}: general code names no assignment" PARENT_SCOPE)
  elseif(NOT to STREQUAL layer AND NOT to IN_LIST _may_${layer}
         AND NOT (layer STREQUAL "assignment_grader" AND to STREQUAL "assignment"))
    string(REPLACE ";" ", " may "${_may_${layer}}")
    set(${out} "${layer} includes ${header} (${rel}, layer ${to}), but ${layer} may include only: ${may}" PARENT_SCOPE)
  endif()
endfunction()

set(_problems "")
set(_scanned 0)
file(GLOB_RECURSE _files RELATIVE "${ROOT}"
     "${ROOT}/framework/*" "${ROOT}/assignments/*" "${ROOT}/solutions/*" "${ROOT}/grader/*" "${ROOT}/bench/*")
list(FILTER _files INCLUDE REGEX "\\.(c|cc|cpp|cxx|h|hh|hpp|hxx|inl|ipp)$")
list(SORT _files)
foreach(f IN LISTS _files)
  _file_layer("${f}" layer own)
  if(layer STREQUAL "" AND f MATCHES "^framework/([^/]+)/")
    math(EXPR _scanned "${_scanned} + 1")
    list(APPEND _problems "${f}:1: framework/${CMAKE_MATCH_1}/ is in no layer (give it one in tests/layers/check_layers.cmake and docs/architecture.md)")
    continue()
  elseif(layer STREQUAL "")
    continue()
  endif()
  math(EXPR _scanned "${_scanned} + 1")
  file(READ "${ROOT}/${f}" text)
  string(REGEX MATCHALL "#[ \t]*include[ \t]*[<\"][^\">\n]*[\">]" includes "${text}")
  foreach(inc IN LISTS includes)
    string(REGEX REPLACE "^#[ \t]*include[ \t]*[<\"]([^\">\n]*)[\">]$" "\\1" header "${inc}")
    set(why "")
    if(header MATCHES "^jelly/")
      _header_layer("${header}" to owner)
      if(to STREQUAL "?")
        set(why "${header} is in no layer (give its folder one in tests/layers/check_layers.cmake and docs/architecture.md)")
      elseif(to STREQUAL "assignment" AND layer IN_LIST _general)
        set(why "${layer} includes ${header}, a header of assignment ${owner}: general code names no assignment (it reaches an assignment through the TaskTable and the manifest)")
      elseif(to STREQUAL "assignment" AND own AND NOT owner STREQUAL own)
        set(why "${f} of assignment ${own} includes ${header}, a header of assignment ${owner}: an assignment includes only its own headers and the core")
      elseif(NOT to IN_LIST _may_${layer})
        string(REPLACE ";" ", " may "${_may_${layer}}")
        string(REPLACE "assignment" "its own assignment's headers" may "${may}")
        set(why "${layer} includes ${header} (layer ${to}), but ${layer} may include only: ${may}")
      endif()
    elseif(inc MATCHES "\"$")
      _relative_include("${f}" "${header}" "${layer}" "${own}" why)
      if(NOT why AND layer IN_LIST _no_gl AND header MATCHES "${_gl_regex}")
        set(why "${layer} includes ${header}: the ${layer} layer has no GL, window or GUI code")
      endif()
    elseif(layer IN_LIST _no_gl AND header MATCHES "${_gl_regex}")
      set(why "${layer} includes ${header}: the ${layer} layer has no GL, window or GUI code")
    elseif(layer STREQUAL "manifest" AND inc MATCHES "<" AND NOT header MATCHES "${_manifest_external_regex}")
      set(why "manifest includes ${header}: layer 0 includes only its own headers, the standard library and toml++")
    endif()
    if(why)
      _line_of("${text}" "${inc}" line)
      list(APPEND _problems "${f}:${line}: ${why}")
    endif()
  endforeach()
endforeach()

# CMake: the build files of a framework layer must not name a target of a layer they may not use
# (render/CMakeLists.txt once linked itself into the `jelly` CLI target; now the CLI links render).
set(_targets_manifest jelly_manifest jelly::manifest)
set(_targets_core    jelly_core jelly::core)
set(_targets_session jelly_session jelly::session)
set(_targets_render  jelly_render jelly::render)
set(_targets_movie   jelly_movie jelly::movie)
set(_targets_cli     jelly)
set(_targets_app     jelly-lab)
file(GLOB_RECURSE _cmake_files RELATIVE "${ROOT}" "${ROOT}/framework/*CMakeLists.txt" "${ROOT}/framework/*.cmake")
list(SORT _cmake_files)
foreach(f IN LISTS _cmake_files)
  if(f MATCHES "^framework/bodies/[^/]+/view/")
    set(layer body_view)
  elseif(f MATCHES "^framework/([a-z]+)/")
    set(layer ${CMAKE_MATCH_1})
  else()
    continue()
  endif()
  if(NOT DEFINED _may_${layer})
    continue()
  endif()
  math(EXPR _scanned "${_scanned} + 1")
  file(READ "${ROOT}/${f}" text)
  string(REGEX REPLACE "#[^\n]*" "" code "${text}")  # comments may name anything
  foreach(other manifest core session render movie cli app)
    if(other IN_LIST _may_${layer})
      continue()
    endif()
    foreach(t IN LISTS _targets_${other})
      string(REGEX MATCH "(^|[\n( \t])${t}([) \t\n]|$)" hit "${code}")
      if(hit)
        # The line in the comment-free text: comments never span lines, so the count is the same.
        string(REGEX REPLACE "^\n" "" needle "${hit}")
        _line_of("${code}" "${needle}" line)
        string(REPLACE ";" ", " may "${_may_${layer}}")
        list(APPEND _problems "${f}:${line}: ${layer} build names the ${other} target ${t}, but ${layer} may use only: ${may}")
      endif()
    endforeach()
  endforeach()
endforeach()

if(_scanned EQUAL 0)
  message(FATAL_ERROR "check_layers: no source files under ${ROOT} (wrong ROOT?)")
endif()
if(_problems)
  foreach(p IN LISTS _problems)
    message("${p}")  # unformatted, one line each, to stderr
  endforeach()
  list(LENGTH _problems count)
  message(FATAL_ERROR "${count} problem(s) above break the layers (docs/architecture.md, \"Layers\")")
endif()
message(STATUS "check_layers: ${_scanned} files follow the layers")
