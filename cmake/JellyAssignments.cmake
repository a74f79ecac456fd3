# Assignments as plug-ins (docs/new-assignment.md). An assignment is a folder with a manifest,
# assignments/<id>/assignment.toml; jelly_add_assignment(<folder>) reads it and makes, for
# assignment <id> with C++ namespace <ns> (jelly::<ns>):
#   jelly_<id>_tasks_assignments  its student stubs + its bindings (always)
#   jelly_<id>_tasks_solutions    its reference + bindings (only when the tree holds the reference
#                                 of every file: never in a student release)
#   jelly_<id>_tasks              the one JELLY_TASKS chooses (or JELLY_TASKS_DIR, for the assignment
#                                 named by JELLY_TASKS_ASSIGNMENT): what the viewer and the CLI link
# with aliases jelly::<id>::tasks_assignments, jelly::<id>::tasks_solutions and jelly::<id>::tasks.
#
# Task modules: tasks that several assignments share (same signatures, same contract section) have
# one reference, solutions/tasks/<module>/*.cpp, named by no assignment (mass_spring: forces.cpp,
# integrators.cpp and the spring engine, for A1 and A2; kinematics: kinematics.cpp, for A3 and A4).
# An assignment whose manifest lists the module (`task_modules = ["<module>"]`) builds that
# reference into its own reference library, in its own namespace. Each assignment keeps its own
# student files, headers and bindings, so that a release of one assignment is complete alone.
# The reference of each file of `files` is explicit (_jelly_reference_sources): either
# solutions/<id>/<file> or the file of one listed module, never both; CMake stops naming the file
# otherwise.
#   - A module's task file (named like a student file) is written with the word
#     JELLY_TASKS_NAMESPACE where the assignment's namespace goes (its include of the assignment's
#     header, "jelly/JELLY_TASKS_NAMESPACE/<file>.hpp", and its namespace). For each assignment the
#     build writes it out with <ns> there (_jelly_module_task_file), into
#     build/assignments/<id>/reference/: the file the assignment would hold itself. It includes the
#     assignment's own header, so a signature drift is a compile error (no previous declaration).
#   - A module's other files (its machinery) are compiled as they are, with
#     JELLY_TASKS_NAMESPACE=<ns> defined, and define `void add_<module>_slots(TaskTable&)` in that
#     namespace: the TaskTable slots the module fills besides the tasks (mass_spring: the engine).
#   - build/assignments/<id>/reference/ also gets a copy of solutions/<id>/'s files of `files`: the
#     reference as a submission (property JELLY_ASSIGNMENT_<id>_REFERENCE_DIR), which the grader
#     grades and mutates as the reference (grade-config.json's reference_dir).
# The bindings call `add_library_slots(t)`, which the build generates for each task library: for
# the reference it calls the add_<module>_slots of every module with machinery, for the stubs and a
# submission it does nothing, so no student-facing file names the reference.
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

# _jelly_module_task_file(<out> <module file> <id> <ns>): a task module's task file written out for
# assignment <id> in the build tree (build/assignments/<id>/reference/<file>): the module's text
# with the word JELLY_TASKS_NAMESPACE replaced by <ns> everywhere, so that it includes the
# assignment's own header (jelly/<ns>/<file's stem>.hpp) and defines the tasks in the assignment's
# namespace: exactly the file the assignment would hold itself. Rewritten only when it changes;
# an edit of the module's file reconfigures (CMAKE_CONFIGURE_DEPENDS).
function(_jelly_module_task_file out module_file id ns)
  get_filename_component(name ${module_file} NAME)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${module_file})
  file(READ ${module_file} text)
  string(REPLACE "JELLY_TASKS_NAMESPACE" "${ns}" text "${text}")
  set(file ${CMAKE_BINARY_DIR}/assignments/${id}/reference/${name})
  file(WRITE ${file}.tmp "// Generated by cmake/JellyAssignments.cmake for ${id} from ${rel}:\n// edit that file.\n${text}")
  configure_file(${file}.tmp ${file} COPYONLY)
  file(REMOVE ${file}.tmp)
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${module_file})
  # A task whose signature drifted from the assignment's header is a compile error here (a
  # definition with no previous declaration), not a link error in the bindings.
  set_source_files_properties(${file} PROPERTIES COMPILE_OPTIONS
    "$<$<CXX_COMPILER_ID:GNU>:-Werror=missing-declarations>;$<$<CXX_COMPILER_ID:Clang,AppleClang>:-Werror=missing-prototypes>")
  set(${out} ${file} PARENT_SCOPE)
endfunction()

# _jelly_reference_of(<out> <manifest> <id> <file> <modules>): the reference of the student file
# <file> of assignment <id>: solutions/<id>/<file>, or solutions/tasks/<module>/<file> of the one
# module of <modules> that holds it (a module's task file), never both; "" when the tree has
# neither and no solutions/<id>/ (a student release). Two references, or none where solutions/<id>/
# exists, stop the configuration naming the file.
function(_jelly_reference_of out manifest id f modules)
  set(solutions_dir ${JELLY_SOLUTIONS_ROOT}/${id})
  set(holders)
  if(EXISTS ${solutions_dir}/${f})
    list(APPEND holders ${solutions_dir}/${f})
  endif()
  set(where "")
  foreach(m IN LISTS modules)
    string(APPEND where " or solutions/tasks/${m}/${f}")
    if(EXISTS ${JELLY_TASK_MODULES_ROOT}/${m}/${f})
      list(APPEND holders ${JELLY_TASK_MODULES_ROOT}/${m}/${f})
    endif()
  endforeach()
  list(LENGTH holders n)
  if(n GREATER 1)
    set(names "")
    foreach(h IN LISTS holders)
      file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${h})
      list(APPEND names ${rel})
    endforeach()
    string(REPLACE ";" " and " names "${names}")
    message(FATAL_ERROR "${manifest}: files: ${f} has two references, ${names}: a student file has "
                        "one (keep the task module's, or drop the module from task_modules)")
  elseif(n EQUAL 0 AND IS_DIRECTORY ${solutions_dir})
    message(FATAL_ERROR "${manifest}: files: ${f} has no reference: expected "
                        "solutions/${id}/${f}${where}")
  endif()
  set(${out} "${holders}" PARENT_SCOPE)
endfunction()

# _jelly_module_machinery(<out> <manifest> <files> <module>): the module's files that are not the
# reference of a file of `files` (its machinery, e.g. the spring engine), compiled as they are. A
# task file (one that includes the assignment's header by the placeholder word) that `files` does
# not list stops the configuration.
function(_jelly_module_machinery out manifest files m)
  file(GLOB module_sources CONFIGURE_DEPENDS ${JELLY_TASK_MODULES_ROOT}/${m}/*.cpp)
  set(machinery)
  foreach(src IN LISTS module_sources)
    get_filename_component(name ${src} NAME)
    if(name IN_LIST files)
      continue()
    endif()
    file(STRINGS ${src} task_file REGEX "#include \"jelly/JELLY_TASKS_NAMESPACE/")
    if(task_file)
      file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${src})
      message(FATAL_ERROR "${manifest}: task_modules: ${rel} is the reference of a student file (it "
                          "includes the assignment's header), but files does not list ${name}")
    endif()
    list(APPEND machinery ${src})
  endforeach()
  set(${out} "${machinery}" PARENT_SCOPE)
endfunction()

# _jelly_reference_sources(<id> <ns> <manifest> <files> <reference_files> <modules>): the reference
# of assignment <id>. Each file of `files` has one reference (_jelly_reference_of): a module's task
# file is written out for the assignment (_jelly_module_task_file), a file of solutions/<id>/ is
# compiled as it is and copied. A module's machinery is compiled as it is, with
# JELLY_TASKS_NAMESPACE defined, and defines add_<module>_slots. Sets in the caller's scope:
#   ref_have          whether the tree holds the whole reference (a student release has none)
#   ref_sources       the reference library's sources but the bindings and the generated slots
#   ref_slot_modules  the modules with machinery (whose add_<module>_slots the reference calls)
#   ref_dir           build/assignments/<id>/reference/: every file of `files` as a student would
#                     hand it in, which the grader grades and mutates as "the reference"
function(_jelly_reference_sources id ns manifest files reference_files modules)
  set(solutions_dir ${JELLY_SOLUTIONS_ROOT}/${id})
  set(ref_dir ${CMAKE_BINARY_DIR}/assignments/${id}/reference)
  set(have ON)
  set(sources)
  set(slot_modules)
  foreach(m IN LISTS modules)
    if(NOT m MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "${manifest}: task_modules: expected module names (lower-case letters, "
                          "digits, '_'), not \"${m}\"")
    endif()
  endforeach()
  foreach(f IN LISTS files)
    _jelly_reference_of(reference ${manifest} ${id} ${f} "${modules}")
    if(NOT reference)
      set(have OFF)
    elseif(reference STREQUAL "${solutions_dir}/${f}")
      list(APPEND sources ${reference})
      configure_file(${reference} ${ref_dir}/${f} COPYONLY)
    else()
      _jelly_module_task_file(written ${reference} ${id} ${ns})
      list(APPEND sources ${written})
    endif()
  endforeach()
  foreach(f IN LISTS reference_files)
    if(NOT EXISTS ${solutions_dir}/${f})
      set(have OFF)
    endif()
    list(APPEND sources ${solutions_dir}/${f})
  endforeach()
  foreach(m IN LISTS modules)
    if(NOT IS_DIRECTORY ${JELLY_TASK_MODULES_ROOT}/${m})
      set(have OFF)
    endif()
    _jelly_module_machinery(machinery ${manifest} "${files}" ${m})
    if(machinery)
      list(APPEND sources ${machinery})
      list(APPEND slot_modules ${m})
    endif()
  endforeach()
  set(ref_have ${have} PARENT_SCOPE)
  set(ref_sources "${sources}" PARENT_SCOPE)
  set(ref_slot_modules "${slot_modules}" PARENT_SCOPE)
  set(ref_dir ${ref_dir} PARENT_SCOPE)
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

  # The reference: each file of `files` from solutions/<id>/ or from a task module the manifest
  # uses, the manifest's reference_files, and every module's sources (absent in a student release).
  if(id STREQUAL "tasks")
    message(FATAL_ERROR "${manifest}: id: \"tasks\" is the folder of the task modules "
                        "(solutions/tasks/); choose another id")
  endif()
  set(solutions_dir ${JELLY_SOLUTIONS_ROOT}/${id})
  _jelly_reference_sources(${id} ${ns} ${manifest} "${files}" "${reference_files}" "${modules}")
  set(have_solutions ${ref_have})
  if(have_solutions)
    _jelly_task_slots(ref_slots ${id} ${ns} solutions ${ref_slot_modules})
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
    set(chosen_label ${chosen})
  elseif(JELLY_TASKS STREQUAL "solutions")
    if(NOT have_solutions)
      message(FATAL_ERROR "JELLY_TASKS=solutions, but ${solutions_dir} does not hold the reference of "
                          "${id} (a student release has no solutions/). Use JELLY_TASKS=assignments.")
    endif()
    target_link_libraries(jelly_${id}_tasks INTERFACE jelly_${id}_tasks_solutions)
    set(chosen ${ref_dir})  # solutions/<id>/ and the modules' files, as one folder
    set(chosen_label ${solutions_dir})
  elseif(JELLY_TASKS STREQUAL "assignments")
    target_link_libraries(jelly_${id}_tasks INTERFACE jelly_${id}_tasks_assignments)
    set(chosen ${dir})
    set(chosen_label ${chosen})
  else()
    message(FATAL_ERROR "JELLY_TASKS must be 'assignments' or 'solutions', not '${JELLY_TASKS}'")
  endif()
  file(RELATIVE_PATH chosen_rel ${PROJECT_SOURCE_DIR} ${chosen_label})
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
  # The reference as a submission (every file of `files`; whole only when have_solutions).
  set_property(GLOBAL PROPERTY JELLY_ASSIGNMENT_${id}_REFERENCE_DIR ${ref_dir})
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
