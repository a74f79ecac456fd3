# Assignments as plug-ins (docs/new-assignment.md). An assignment is a folder with a manifest,
# assignments/<id>/assignment.toml; jelly_add_assignment(<folder>) reads it and makes, for
# assignment <id> with C++ namespace <ns> (jelly::<ns>):
#   jelly_<id>_tasks_assignments  its student stubs + its bindings (always)
#   jelly_<id>_tasks_solutions    its reference + bindings (only when solutions/<id>/ exists: never in
#                                 a student release)
#   jelly_<id>_tasks              the one JELLY_TASKS chooses (or JELLY_TASKS_DIR, for the assignment
#                                 named by JELLY_TASKS_ASSIGNMENT): what the viewer and the CLI link
# with aliases jelly::<id>::tasks_assignments, jelly::<id>::tasks_solutions and jelly::<id>::tasks.
#
# Task modules: tasks that several assignments share (same signatures, same contract section) have
# one reference, solutions/tasks/<module>/*.cpp, named by no assignment. An assignment whose
# manifest lists the module (`task_modules = ["<module>"]`) compiles that reference into its own
# reference library, in its own namespace (JELLY_TASKS_NAMESPACE=<ns>). Each assignment keeps its
# own student files, headers and bindings, so that a release of one assignment is complete alone.
# A module's reference defines `void add_<module>_slots(TaskTable&)` in that namespace: the
# TaskTable slots it fills besides the tasks (mass_spring: its spring engine). The bindings call
# `add_library_slots(t)`, which the build generates for each task library: for the reference it
# calls every module's add_<module>_slots, for the stubs and a submission it does nothing, so no
# student-facing file names the reference.
# The grader (grader/CMakeLists.txt) reads the global property JELLY_ASSIGNMENTS and the
# per-assignment properties set here. A draft (`draft = true`) is in JELLY_DRAFT_ASSIGNMENTS
# instead: built and linked into the programs (so that its author can run its scenes), never
# graded, platform-checked or released. The linked-assignment registry (_jelly_make_registry)
# reads JELLY_LINKED_ASSIGNMENTS: both, in the order they were added.
# The reference and student code never go into one binary.
#
# CMake takes only the manifest's top-level keys id, namespace, files, reference_files,
# task_modules, default_scene and draft, from tools/jelly_manifest.py; the programs read the whole
# manifest (framework/manifest).

set(JELLY_ASSIGNMENTS_ROOT ${PROJECT_SOURCE_DIR}/assignments)
set(JELLY_SOLUTIONS_ROOT ${PROJECT_SOURCE_DIR}/solutions)
set(JELLY_TASK_MODULES_ROOT ${JELLY_SOLUTIONS_ROOT}/tasks)

# The manifest's keys come from one reader, tools/jelly_manifest.py (tomllib), which the tools
# import too. CMake runs it and includes the file it writes. A machine without Python 3.11 (a
# student's Windows or macOS) builds a student release all the same: the release ships each
# manifest's keys as the reader wrote them (assignments/<id>/assignment.keys.cmake, with the
# manifest's hash, which CMake checks). docs/instructor-guide.md, "The tool and Python".
find_package(Python3 3.11 COMPONENTS Interpreter QUIET)
set(JELLY_MANIFEST_READER ${PROJECT_SOURCE_DIR}/tools/jelly_manifest.py)

# _jelly_read_manifest(<manifest>): sets JELLY_MANIFEST_ID, _NAMESPACE, _FILES, _REFERENCE_FILES
# and _DEFAULT_SCENE in the caller's scope (a macro: the included file sets them there).
macro(_jelly_read_manifest manifest)
  get_filename_component(_jm_dir "${manifest}" DIRECTORY)
  get_filename_component(_jm_name "${_jm_dir}" NAME)
  if(Python3_Interpreter_FOUND AND EXISTS ${JELLY_MANIFEST_READER})
    set(_jm_keys ${CMAKE_BINARY_DIR}/jelly-manifests/${_jm_name}.cmake)
    execute_process(COMMAND ${Python3_EXECUTABLE} -B ${JELLY_MANIFEST_READER} cmake ${manifest} ${_jm_keys}
                    RESULT_VARIABLE _jm_rc ERROR_VARIABLE _jm_err)
    if(NOT _jm_rc EQUAL 0)
      message(FATAL_ERROR "${_jm_err}")
    endif()
    set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${JELLY_MANIFEST_READER})
  elseif(EXISTS ${_jm_dir}/assignment.keys.cmake)
    set(_jm_keys ${_jm_dir}/assignment.keys.cmake)
  else()
    message(FATAL_ERROR "${manifest}: reading it needs Python 3.11 or newer (python3, for "
                        "tools/jelly_manifest.py), which CMake did not find (set Python3_EXECUTABLE)")
  endif()
  include(${_jm_keys})
  file(READ ${manifest} _jm_text)
  string(REPLACE "\r" "" _jm_text "${_jm_text}")
  string(SHA256 _jm_sha "${_jm_text}")
  if(NOT _jm_sha STREQUAL JELLY_MANIFEST_SHA256)
    message(FATAL_ERROR "${manifest}: changed since ${_jm_keys} was written from it: install Python "
                        "3.11 or newer (python3) so that CMake reads it again")
  endif()
endmacro()

# _jelly_task_slots(<out> <id> <ns> <origin> <modules...>): the generated add_library_slots() of
# one task library of assignment <id>: for the reference (origin "solutions"), every module's
# add_<module>_slots; for the stubs and a submission, nothing.
function(_jelly_task_slots out id ns origin)
  set(decls "")
  set(calls "")
  if(origin STREQUAL "solutions")
    foreach(m IN LISTS ARGN)
      string(APPEND decls "void add_${m}_slots(TaskTable& t);\n")
      string(APPEND calls "  add_${m}_slots(t);\n")
    endforeach()
  endif()
  set(param "TaskTable& t")
  if(calls STREQUAL "")
    set(param "TaskTable& /*t*/")
  endif()
  set(file ${CMAKE_BINARY_DIR}/assignments/${id}/task_table_slots_${origin}.cpp)
  set(content "// Generated by cmake/JellyAssignments.cmake: add_library_slots() of the ${origin} task library of ${id}.\n")
  string(APPEND content "#include \"jelly/task_table.hpp\"\n\nnamespace jelly::${ns} {\n\n${decls}")
  string(APPEND content "void add_library_slots(TaskTable& t);\n\nvoid add_library_slots(${param}) {\n${calls}}\n\n}  // namespace jelly::${ns}\n")
  file(WRITE ${file}.tmp "${content}")
  configure_file(${file}.tmp ${file} COPYONLY)
  set(${out} ${file} PARENT_SCOPE)
endfunction()

# _jelly_add_task_library(<target> <dir> <origin> <slots file> <sources...>): one implementation of
# an assignment's tasks, with the assignment's bindings compiled for it.
function(_jelly_add_task_library target dir origin slots)
  file(GLOB bindings CONFIGURE_DEPENDS ${dir}/bindings/*.cpp)
  add_library(${target} STATIC ${ARGN} ${bindings} ${slots})
  target_include_directories(${target} PUBLIC ${dir}/include)
  target_link_libraries(${target} PUBLIC jelly::core)
  target_compile_definitions(${target} PRIVATE JELLY_TASKS_ORIGIN="${origin}")
  jelly_target_defaults(${target})
endfunction()

# jelly_add_assignment(<folder>): the folder holds assignment.toml.
function(jelly_add_assignment dir)
  get_filename_component(dir "${dir}" ABSOLUTE)
  set(manifest ${dir}/assignment.toml)
  if(NOT EXISTS ${manifest})
    message(FATAL_ERROR "${dir}: no assignment.toml (every assignment folder has a manifest; "
                        "docs/new-assignment.md)")
  endif()
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${manifest})
  _jelly_read_manifest(${manifest})
  set(id "${JELLY_MANIFEST_ID}")
  set(ns "${JELLY_MANIFEST_NAMESPACE}")
  set(files "${JELLY_MANIFEST_FILES}")
  set(reference_files "${JELLY_MANIFEST_REFERENCE_FILES}")
  set(modules "${JELLY_MANIFEST_TASK_MODULES}")
  get_filename_component(folder_name "${dir}" NAME)
  if(NOT id STREQUAL folder_name)
    message(FATAL_ERROR "${manifest}: id: expected the folder's name \"${folder_name}\", not \"${id}\"")
  endif()
  get_property(known GLOBAL PROPERTY JELLY_ASSIGNMENTS)
  get_property(known_drafts GLOBAL PROPERTY JELLY_DRAFT_ASSIGNMENTS)
  if(id IN_LIST known OR id IN_LIST known_drafts)
    message(FATAL_ERROR "${manifest}: id: \"${id}\" is already an assignment")
  endif()
  foreach(f IN LISTS files)
    if(NOT EXISTS ${dir}/${f})
      message(FATAL_ERROR "${manifest}: files: ${dir}/${f} does not exist")
    endif()
  endforeach()

  set(stub_sources)
  foreach(f IN LISTS files)
    list(APPEND stub_sources ${dir}/${f})
  endforeach()
  _jelly_task_slots(stub_slots ${id} ${ns} assignments)
  _jelly_add_task_library(jelly_${id}_tasks_assignments ${dir} assignments ${stub_slots} ${stub_sources})
  add_library(jelly::${id}::tasks_assignments ALIAS jelly_${id}_tasks_assignments)

  # The reference: solutions/<id>/ with every file of the manifest, and the reference of every task
  # module the manifest uses (absent in a student release).
  set(solutions_dir ${JELLY_SOLUTIONS_ROOT}/${id})
  set(have_solutions ON)
  set(ref_sources)
  foreach(f IN LISTS files reference_files)
    if(NOT EXISTS ${solutions_dir}/${f})
      set(have_solutions OFF)
    endif()
    list(APPEND ref_sources ${solutions_dir}/${f})
  endforeach()
  foreach(m IN LISTS modules)
    if(NOT m MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "${manifest}: task_modules: expected module names (lower-case letters, "
                          "digits, '_'), not \"${m}\"")
    endif()
    file(GLOB module_sources CONFIGURE_DEPENDS ${JELLY_TASK_MODULES_ROOT}/${m}/*.cpp)
    if(NOT module_sources)
      set(have_solutions OFF)
    endif()
    list(APPEND ref_sources ${module_sources})
  endforeach()
  if(id STREQUAL "tasks")
    message(FATAL_ERROR "${manifest}: id: \"tasks\" is the folder of the task modules "
                        "(solutions/tasks/); choose another id")
  endif()
  if(have_solutions)
    _jelly_task_slots(ref_slots ${id} ${ns} solutions ${modules})
    list(APPEND ref_sources ${ref_slots})
    _jelly_add_task_library(jelly_${id}_tasks_solutions ${dir} solutions "" ${ref_sources})
    # A task module's reference is compiled in the assignment's namespace.
    target_compile_definitions(jelly_${id}_tasks_solutions PRIVATE JELLY_TASKS_NAMESPACE=${ns})
    add_library(jelly::${id}::tasks_solutions ALIAS jelly_${id}_tasks_solutions)
    # A reference may split its work among threads (same bits for any count).
    if(JELLY_OPENMP)
      find_package(OpenMP)
      if(OpenMP_CXX_FOUND)
        target_link_libraries(jelly_${id}_tasks_solutions PUBLIC OpenMP::OpenMP_CXX)
      endif()
    endif()
  endif()

  add_library(jelly_${id}_tasks INTERFACE)
  add_library(jelly::${id}::tasks ALIAS jelly_${id}_tasks)
  if(JELLY_TASKS_DIR AND JELLY_TASKS_ASSIGNMENT STREQUAL id)
    set(custom)
    foreach(f IN LISTS files)
      list(APPEND custom ${JELLY_TASKS_DIR}/${f})
    endforeach()
    _jelly_task_slots(custom_slots ${id} ${ns} submission)
    _jelly_add_task_library(jelly_${id}_tasks_custom ${dir} submission ${custom_slots} ${custom})
    target_link_libraries(jelly_${id}_tasks INTERFACE jelly_${id}_tasks_custom)
    set(chosen ${JELLY_TASKS_DIR})
  elseif(JELLY_TASKS STREQUAL "solutions")
    if(NOT have_solutions)
      message(FATAL_ERROR "JELLY_TASKS=solutions, but ${solutions_dir} does not hold the reference of "
                          "${id} (a student release has no solutions/). Use JELLY_TASKS=assignments.")
    endif()
    target_link_libraries(jelly_${id}_tasks INTERFACE jelly_${id}_tasks_solutions)
    set(chosen ${solutions_dir})
  elseif(JELLY_TASKS STREQUAL "assignments")
    target_link_libraries(jelly_${id}_tasks INTERFACE jelly_${id}_tasks_assignments)
    set(chosen ${dir})
  else()
    message(FATAL_ERROR "JELLY_TASKS must be 'assignments' or 'solutions', not '${JELLY_TASKS}'")
  endif()
  file(RELATIVE_PATH chosen_rel ${PROJECT_SOURCE_DIR} ${chosen})
  message(STATUS "Jelly Lab: assignment ${id}, student tasks from ${chosen_rel}")

  if(JELLY_MANIFEST_DRAFT)
    # A draft (`draft = true`, docs/new-assignment.md "A draft"): its task libraries are built and
    # its own tests link them and the programs' registry lists it (its author runs its scenes), but
    # the grader, the platform checks and the student release leave it out (they read
    # JELLY_ASSIGNMENTS).
    set_property(GLOBAL APPEND PROPERTY JELLY_DRAFT_ASSIGNMENTS ${id})
    message(STATUS "Jelly Lab: assignment ${id} is a draft: built, linked into the programs and "
                   "its own tests run; not graded or released")
  else()
    set_property(GLOBAL APPEND PROPERTY JELLY_ASSIGNMENTS ${id})
  endif()
  set_property(GLOBAL APPEND PROPERTY JELLY_LINKED_ASSIGNMENTS ${id})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_DIR ${dir})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_NAMESPACE ${ns})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_FILES "${files}")
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_REFERENCE_FILES "${reference_files}")
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_DEFAULT_SCENE "${JELLY_MANIFEST_DEFAULT_SCENE}")
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_TASK_MODULES "${modules}")
  # Every source of the reference library but the bindings (its files, its modules' references and
  # the generated slots), for targets that compile the reference themselves (tests/determinism),
  # with the definition a module's reference needs.
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_REFERENCE_SOURCES "${ref_sources}")
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_REFERENCE_DEFINITIONS JELLY_TASKS_NAMESPACE=${ns})
  # add_library_slots() for a submission's link (grader/CMakeLists.txt).
  _jelly_task_slots(submission_slots ${id} ${ns} submission)
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_SUBMISSION_SLOTS ${submission_slots})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_HAVE_SOLUTIONS ${have_solutions})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_SOLUTIONS_DIR ${solutions_dir})
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_CHOSEN_DIR ${chosen})
endfunction()

# jelly_add_assignments(): every folder under assignments/ with a manifest, plus the folders in
# JELLY_EXTRA_ASSIGNMENTS. Then the registry of linked assignments (jelly::assignments): the
# viewer and the CLI link it and run any assignment's scenes with that assignment's tasks.
function(jelly_add_assignments)
  file(GLOB manifests CONFIGURE_DEPENDS ${JELLY_ASSIGNMENTS_ROOT}/*/assignment.toml)
  list(SORT manifests)
  set(dirs)
  foreach(m IN LISTS manifests)
    get_filename_component(d ${m} DIRECTORY)
    list(APPEND dirs ${d})
  endforeach()
  list(APPEND dirs ${JELLY_EXTRA_ASSIGNMENTS})
  if(NOT dirs)
    message(FATAL_ERROR "${JELLY_ASSIGNMENTS_ROOT}: no assignment (a folder with an assignment.toml)")
  endif()
  foreach(d IN LISTS dirs)
    jelly_add_assignment(${d})
  endforeach()
  if(JELLY_TASKS_DIR)
    get_property(ids GLOBAL PROPERTY JELLY_ASSIGNMENTS)
    if(NOT JELLY_TASKS_ASSIGNMENT IN_LIST ids)
      message(FATAL_ERROR "JELLY_TASKS_DIR is set: JELLY_TASKS_ASSIGNMENT must name its assignment "
                          "(one of: ${ids}), not '${JELLY_TASKS_ASSIGNMENT}'")
    endif()
  endif()
  _jelly_make_registry()
endfunction()

# _jelly_default_scene(<out> <name> <folder>): the file of the manifest's optional
# `default_scene = "name"`: <folder>/scenes/name.toml, else the top-level scenes/name.toml; "" when
# the manifest names none. A name that is in neither folder stops the configuration.
function(_jelly_default_scene out name dir)
  set(${out} "" PARENT_SCOPE)
  if(name STREQUAL "")
    return()
  endif()
  foreach(candidate IN ITEMS ${dir}/scenes/${name}.toml ${PROJECT_SOURCE_DIR}/scenes/${name}.toml)
    if(EXISTS ${candidate})
      set(${out} ${candidate} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "${dir}/assignment.toml: default_scene: no scene \"${name}\" (expected "
                      "${dir}/scenes/${name}.toml or ${PROJECT_SOURCE_DIR}/scenes/${name}.toml)")
endfunction()

# The registry: a generated source that lists each assignment's id, its manifest (compiled in) and
# its task table, linked with the task library JELLY_TASKS chooses, in the order the assignments
# were added. The drafts are in it too (JELLY_LINKED_ASSIGNMENTS), so that an author can
# `jelly run` a draft's scenes (docs/new-assignment.md, "A draft").
function(_jelly_make_registry)
  get_property(ids GLOBAL PROPERTY JELLY_LINKED_ASSIGNMENTS)
  set(decls "")
  set(entries "")
  set(manifests "")
  foreach(id IN LISTS ids)
    get_property(ns GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_NAMESPACE)
    get_property(dir GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_DIR)
    file(READ ${dir}/assignment.toml text)
    # A raw string literal whose delimiter cannot occur in a manifest.
    string(APPEND manifests "const char kManifest_${id}[] = R\"jelly-manifest(${text})jelly-manifest\";\n")
    # Its default scene's file, compiled in: the programs' built-in copy of that scene (used when
    # the scenes folder lacks it, and by name as builtin:<scene>).
    get_property(scene_name GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_DEFAULT_SCENE)
    _jelly_default_scene(scene_file "${scene_name}" ${dir})
    set(scene_text "")
    if(scene_file)
      set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${scene_file})
      file(READ ${scene_file} scene_text)
    endif()
    string(APPEND manifests "const char kDefaultScene_${id}[] = R\"jelly-scene(${scene_text})jelly-scene\";\n")
    string(APPEND decls "namespace jelly::${ns} {\nTaskTable task_table();\n}\n")
    string(APPEND entries "      {\"${id}\", kManifest_${id}, \"${dir}/assignment.toml\", &jelly::${ns}::task_table, kDefaultScene_${id}, \"${scene_file}\"},\n")
  endforeach()
  set(out ${CMAKE_BINARY_DIR}/assignments/linked_assignments.cpp)
  set(content "// Generated by cmake/JellyAssignments.cmake: the assignments this build links.\n")
  string(APPEND content "#include \"jelly/linked_assignments.hpp\"\n\n${decls}\nnamespace {\n${manifests}}  // namespace\n\n")
  string(APPEND content "namespace jelly {\n\nconst std::vector<LinkedAssignment>& linked_assignments() {\n")
  string(APPEND content "  static const std::vector<LinkedAssignment> all = {\n${entries}  };\n  return all;\n}\n\n}  // namespace jelly\n")
  # Rewritten only when it changes (configure_file COPYONLY), so a reconfigure rebuilds nothing.
  file(WRITE ${out}.tmp "${content}")
  configure_file(${out}.tmp ${out} COPYONLY)
  # One registry library per implementation: the one JELLY_TASKS chose (the viewer, the CLI), every
  # assignment's stubs, and every reference (when the tree has them all; tests and benchmarks).
  set(all_solutions ON)
  foreach(id IN LISTS ids)
    get_property(have GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_HAVE_SOLUTIONS)
    if(NOT have)
      set(all_solutions OFF)
    endif()
  endforeach()
  foreach(variant IN ITEMS ":tasks" "_stubs:tasks_assignments" "_solutions:tasks_solutions")
    string(REPLACE ":" ";" parts "${variant}")
    list(GET parts 0 suffix)
    list(GET parts 1 lib)
    if(suffix STREQUAL "_solutions" AND NOT all_solutions)
      continue()
    endif()
    add_library(jelly_assignments${suffix} STATIC ${out})
    add_library(jelly::assignments${suffix} ALIAS jelly_assignments${suffix})
    target_link_libraries(jelly_assignments${suffix} PUBLIC jelly::core)
    foreach(id IN LISTS ids)
      target_link_libraries(jelly_assignments${suffix} PUBLIC jelly_${id}_${lib})
    endforeach()
    jelly_target_defaults(jelly_assignments${suffix})
  endforeach()
  set(JELLY_HAVE_SOLUTIONS ${all_solutions} CACHE INTERNAL "Every assignment's reference is here")
endfunction()
