# The body kinds (docs/architecture.md "Bodies"): every framework/bodies/<folder>/body.cmake is read
# here, from jelly::core's CMakeLists. A body.cmake adds its folder's sources to jelly_core (the
# modules are core code: no GL, the core's flags) and names the kind it registers, if any:
#
#   jelly_body_module(SOURCES a.cpp b.cpp)                 # shared code (mass_spring/)
#   jelly_body_kind(cube ORDER 10 MODULE cube_kind SOURCES cube_kind.cpp)
#
# MODULE is a function `const jelly::BodyKindModule& jelly::bodies::<MODULE>()`; ORDER places the
# kind in the registry (the parameter table lists the kinds' keys in that order). From the kinds
# found, CMake writes BUILD/bodies/linked_body_kinds.cpp: the list of the kinds this build links,
# so that a new kind is a new folder and no general file changes.
set_property(GLOBAL PROPERTY JELLY_BODY_KINDS "")

function(jelly_body_module)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  foreach(src IN LISTS ARG_SOURCES)
    target_sources(jelly_core PRIVATE "${CMAKE_CURRENT_LIST_DIR}/${src}")
  endforeach()
  if(IS_DIRECTORY "${CMAKE_CURRENT_LIST_DIR}/include")
    target_include_directories(jelly_core PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_LIST_DIR}/include>)
  endif()
endfunction()

function(jelly_body_kind name)
  cmake_parse_arguments(ARG "" "ORDER;MODULE" "SOURCES" ${ARGN})
  if(NOT name MATCHES "^[a-z][a-z0-9_]*$" OR NOT ARG_MODULE MATCHES "^[A-Za-z_][A-Za-z0-9_]*$"
     OR NOT ARG_ORDER MATCHES "^[0-9]+$")
    message(FATAL_ERROR "${CMAKE_CURRENT_LIST_FILE}: jelly_body_kind(NAME ORDER n MODULE fn SOURCES ...) "
                        "expects a lower-case name, a whole-number ORDER and a C++ function name; got "
                        "'${name}', ORDER '${ARG_ORDER}', MODULE '${ARG_MODULE}'")
  endif()
  jelly_body_module(SOURCES ${ARG_SOURCES})
  # Sorted by ORDER then name: "0010 cube cube_kind".
  string(LENGTH "${ARG_ORDER}" len)
  set(order "${ARG_ORDER}")
  while(len LESS 6)
    string(PREPEND order "0")
    math(EXPR len "${len} + 1")
  endwhile()
  set_property(GLOBAL APPEND PROPERTY JELLY_BODY_KINDS "${order}|${name}|${ARG_MODULE}")
endfunction()

file(GLOB _jelly_body_files CONFIGURE_DEPENDS "${CMAKE_CURRENT_LIST_DIR}/*/body.cmake")
list(SORT _jelly_body_files)
foreach(_file IN LISTS _jelly_body_files)
  include("${_file}")
endforeach()

get_property(_kinds GLOBAL PROPERTY JELLY_BODY_KINDS)
list(SORT _kinds)
set(_decls "")
set(_items "")
set(_names "")
foreach(_kind IN LISTS _kinds)
  string(REPLACE "|" ";" _parts "${_kind}")
  list(GET _parts 1 _name)
  list(GET _parts 2 _module)
  if(_name IN_LIST _names)
    message(FATAL_ERROR "two body modules register the body kind '${_name}' (framework/bodies/*/body.cmake)")
  endif()
  list(APPEND _names ${_name})
  string(APPEND _decls "const BodyKindModule& ${_module}();  // body.type = \"${_name}\"\n")
  string(APPEND _items "      &bodies::${_module}(),\n")
endforeach()
set(_linked "${PROJECT_BINARY_DIR}/bodies/linked_body_kinds.cpp")
set(_text
"// Written by CMake (framework/bodies/bodies.cmake) from framework/bodies/*/body.cmake: the body
// kinds this build links, in their ORDER. Do not edit.
#include \"jelly/body_kind.hpp\"

namespace jelly {
namespace bodies {
${_decls}}  // namespace bodies

std::vector<const BodyKindModule*> linked_body_kinds() {
  return {
${_items}  };
}

}  // namespace jelly
")
# Written only when it changes, so a configure does not rebuild the core.
file(WRITE "${_linked}.new" "${_text}")
configure_file("${_linked}.new" "${_linked}" COPYONLY)
target_sources(jelly_core PRIVATE "${_linked}")
string(REPLACE ";" ", " _names_text "${_names}")
message(STATUS "Jelly Lab body kinds: ${_names_text}")
