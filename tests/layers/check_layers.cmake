# The layers of docs/architecture.md ("Layers"), kept true: every `#include "jelly/..."` (or <...>)
# in the framework, the tasks, the grader and the benchmarks must name a header of the file's own
# layer or of one below it, and the layers without GL must include no GL, GLFW or ImGui header.
# Prints every violation as FILE:LINE and fails; passes silently otherwise.
#
#   cmake -DROOT=<source tree> -P check_layers.cmake
#
# A file's layer is its folder; a header's layer is its folder under jelly/ (a header straight in
# jelly/, or in jelly/tasks/, is the core's). A new folder under jelly/ must be given a layer here
# and in docs/architecture.md, or this check fails naming it.
cmake_minimum_required(VERSION 3.16)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_layers.cmake")
endif()

# Folder of a source file (relative to ROOT) -> its layer. Checked in order; the first match wins.
set(_folders
  "framework/core/"    core
  "framework/tasks/"   tasks
  "assignments/"       tasks
  "solutions/"         tasks
  "framework/session/" session
  "framework/cli_common/" cli_common
  "framework/render/"  render
  "framework/movie/"   movie
  "framework/cli/"     cli
  "framework/app/"     app
  "grader/tests/"      ""        # hostile submissions: student code, deliberately anything
  "grader/"            grader
  "bench/"             bench)
# What each layer may include (its own layer and those below it).
set(_may_core    core)
set(_may_tasks   core)
set(_may_session core session)
set(_may_cli_common cli_common)
set(_may_render  core session render)
set(_may_movie   core session render movie cli_common)
set(_may_cli     core session movie cli cli_common)
set(_may_app     core session render movie app cli_common)
set(_may_grader  core grader cli_common)
set(_may_bench   core)
# Layers that must stay free of GL (and of windowing and GUI libraries).
set(_no_gl core tasks session cli_common movie cli grader bench)
set(_gl_regex "^(GL|GLFW|KHR|EGL|OpenGL)/|^imgui|osmesa")

# Layer of an included header path "jelly/..."; "?" when no layer owns its folder.
function(_header_layer header out)
  if(header MATCHES "^jelly/[^/]+$" OR header MATCHES "^jelly/tasks/")
    set(${out} core PARENT_SCOPE)
  elseif(header MATCHES "^jelly/(session|render|movie|cli_common|cli|app|grader)/")
    set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
  else()
    set(${out} "?" PARENT_SCOPE)
  endif()
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

set(_problems "")
set(_scanned 0)
file(GLOB_RECURSE _files RELATIVE "${ROOT}"
     "${ROOT}/framework/*" "${ROOT}/assignments/*" "${ROOT}/solutions/*" "${ROOT}/grader/*" "${ROOT}/bench/*")
list(FILTER _files INCLUDE REGEX "\\.(c|cc|cpp|cxx|h|hh|hpp|hxx|inl|ipp)$")
list(SORT _files)
foreach(f IN LISTS _files)
  set(layer "")
  set(found FALSE)
  set(i 0)
  list(LENGTH _folders n)
  while(i LESS n)
    list(GET _folders ${i} prefix)
    math(EXPR j "${i} + 1")
    list(GET _folders ${j} candidate)
    string(FIND "${f}" "${prefix}" at)
    if(at EQUAL 0)
      set(layer "${candidate}")
      set(found TRUE)
      break()
    endif()
    math(EXPR i "${i} + 2")
  endwhile()
  if(NOT found OR layer STREQUAL "")
    continue()
  endif()
  math(EXPR _scanned "${_scanned} + 1")
  file(READ "${ROOT}/${f}" text)
  string(REGEX MATCHALL "#[ \t]*include[ \t]*[<\"][^\">\n]*[\">]" includes "${text}")
  foreach(inc IN LISTS includes)
    string(REGEX REPLACE "^#[ \t]*include[ \t]*[<\"]([^\">\n]*)[\">]$" "\\1" header "${inc}")
    set(why "")
    if(header MATCHES "^jelly/")
      _header_layer("${header}" to)
      if(to STREQUAL "?")
        set(why "${header} is in no layer (give its folder one in tests/layers/check_layers.cmake and docs/architecture.md)")
      elseif(NOT to IN_LIST _may_${layer})
        string(REPLACE ";" ", " may "${_may_${layer}}")
        set(why "${layer} includes ${header} (layer ${to}), but ${layer} may include only: ${may}")
      endif()
    elseif(layer IN_LIST _no_gl AND header MATCHES "${_gl_regex}")
      set(why "${layer} includes ${header}: the ${layer} layer has no GL, window or GUI code")
    endif()
    if(why)
      _line_of("${text}" "${inc}" line)
      list(APPEND _problems "${f}:${line}: ${why}")
    endif()
  endforeach()
endforeach()

# CMake: the build files of a framework layer must not name a target of a layer they may not use
# (render/CMakeLists.txt once linked itself into the `jelly` CLI target; now the CLI links render).
set(_targets_core    jelly_core jelly::core)
set(_targets_session jelly_session jelly::session)
set(_targets_render  jelly_render jelly::render)
set(_targets_movie   jelly_movie jelly::movie)
set(_targets_cli     jelly)
set(_targets_app     jelly-lab)
file(GLOB_RECURSE _cmake_files RELATIVE "${ROOT}" "${ROOT}/framework/*CMakeLists.txt" "${ROOT}/framework/*.cmake")
list(SORT _cmake_files)
foreach(f IN LISTS _cmake_files)
  if(NOT f MATCHES "^framework/([a-z]+)/")
    continue()
  endif()
  set(layer ${CMAKE_MATCH_1})
  if(NOT DEFINED _may_${layer})
    continue()
  endif()
  math(EXPR _scanned "${_scanned} + 1")
  file(READ "${ROOT}/${f}" text)
  string(REGEX REPLACE "#[^\n]*" "" code "${text}")  # comments may name anything
  foreach(other core session render movie cli app)
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
