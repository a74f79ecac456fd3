// Where jelly-grade finds the framework, the compiler recipe and its data.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "jelly/manifest.hpp"

namespace jelly::grade {

namespace fs = std::filesystem;

/// One assignment as the build knows it (grade-config.json's "assignments") and its manifest.
struct AssignmentConfig {
  std::string id;
  AssignmentManifest manifest;
  fs::path dir;            ///< assignments/<id>/ (stubs, manifest, public grader data)
  fs::path solutions_dir;  ///< solutions/<id>/ (absent in a student release)
  /// The reference as a submission: every file of the manifest's `files`, from solutions/<id>/ or
  /// from a task module, in one folder the build makes (absent in a student release). Graded and
  /// mutated as "the reference"; solutions_dir is what reports call it.
  fs::path reference_dir;
  std::vector<std::string> include_dirs;    ///< for a submission's files
  std::vector<std::string> link_objects;    ///< runner main + the assignment's bindings
  std::vector<std::string> link_libraries;  ///< its cases, the harness, the core, seccomp
  fs::path reference_runner;                ///< empty in a student release
  fs::path student_runner;                  ///< the self-check's runner (jelly::<id>::tasks)
  bool draft = false;                       ///< from "draft_assignments": graded only with --draft
  /// " --draft" for a draft, else "": what a command that names this assignment adds.
  std::string draft_option() const { return draft ? " --draft" : ""; }
};

/// The recipe CMake wrote (build/grader/grade-config.json) plus paths derived from it. The
/// assignment-specific fields are those of the assignment select_assignment() chose.
struct GradeConfig {
  std::string compiler;
  std::string compiler_id;
  std::vector<std::string> compile_flags;  ///< includes -O level and -ffp-contract=off
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;    ///< of the selected assignment
  std::vector<std::string> link_objects;    ///< of the selected assignment
  std::vector<std::string> link_libraries;  ///< of the selected assignment
  std::vector<std::string> link_flags;
  fs::path source_dir;  ///< the framework checkout (grader/, assignments/, solutions/?)
  fs::path binary_dir;
  fs::path reference_runner;  ///< of the selected assignment; empty in a student release
  /// The `jelly` CLI with `render --replay` (report frames); empty when built without the viewer.
  /// $JELLY_GRADE_JELLY overrides it.
  fs::path jelly_cli;
  fs::path config_path;
  /// Every assignment of the build, sorted by id.
  std::vector<AssignmentConfig> assignments;
  /// The build's drafts (`draft = true` in their manifests): built, not graded unless asked for
  /// with --draft. Named so that --assignment of one says why it is not graded without it.
  std::vector<std::string> drafts;
  /// The drafts that have a grader (grade-config.json's "draft_assignments"), sorted by id: graded
  /// only by their author's request (select_assignment's `draft`).
  std::vector<AssignmentConfig> draft_assignments;
  /// The one the command works on (select_assignment); nullptr before.
  const AssignmentConfig* selected = nullptr;

  /// The selected assignment; throws std::logic_error when none was selected.
  const AssignmentConfig& assignment() const;
  fs::path grader_dir() const { return source_dir / "grader"; }
  /// The selected assignment's grader folder: assignments/<id>/grader.
  fs::path assignment_grader_dir() const { return assignment().dir / "grader"; }
  fs::path cases_dir() const { return assignment_grader_dir() / "cases"; }
  fs::path mutants_dir() const { return assignment_grader_dir() / "mutants"; }
  fs::path runner_dir() const { return assignment_grader_dir() / "runner"; }
  /// Reference data: "public" is in the assignment's folder (it ships to students), "hidden" in
  /// grader/data/<id>/hidden (it never does).
  fs::path data_dir(const std::string& visibility) const;
  /// The rubric: the manifest (its [grading] table and [[task]] points).
  fs::path rubric_path() const { return assignment().dir / "assignment.toml"; }
  fs::path assignments_dir() const { return assignment().dir; }
  fs::path solutions_dir() const { return assignment().solutions_dir; }
  fs::path reference_dir() const { return assignment().reference_dir; }
  /// The files a student edits, in build order (the manifest's `files`).
  const std::vector<std::string>& task_files() const { return assignment().manifest.files; }
  /// Compiled-object cache (content-addressed), so a mutant recompiles only the file it changes.
  fs::path cache_dir() const;
};

/// Reads the config: `path` if given, else $JELLY_GRADE_CONFIG, else the path compiled in, and
/// every assignment's manifest. Throws std::runtime_error naming the file and key on a problem.
GradeConfig load_config(const std::string& path);

/// Selects the assignment a command works on: `id` if given; else the one whose files a
/// submission folder holds (`submission`, may be empty); else the only one of the build. With
/// `draft` (--draft), `id` must name a draft that has a grader: its author tries that grader.
/// Throws std::runtime_error naming the choices when it cannot tell.
void select_assignment(GradeConfig& config, const std::string& id, const fs::path& submission,
                       bool draft = false);

/// A file name as a learning-management system's bulk download gives it: Canvas prefixes the
/// student and two numbers (`dave_12345_67890_forces.cpp`, `dave_LATE_12345_67890_…`) and numbers
/// a resubmission (`…_forces-1.cpp`); Moodle, downloading without folders, the student's name, id
/// and `assignsubmission_file` (`Dave Smith_12345_assignsubmission_file_forces.cpp`).
struct LmsName {
  std::string file;       ///< the name it stands for: "forces.cpp"
  long resubmission = 0;  ///< Canvas's -N (0 without)
};
/// The name `file_name` stands for, when it is an LMS bulk-download name.
std::optional<LmsName> lms_name(const std::string& file_name);

/// The files called `name` under `root`, shallowest first (then by path; symbolic links included,
/// so that the build refuses them with a message rather than silently ignoring them).
std::vector<fs::path> find_named(const fs::path& root, const std::string& name);

/// The file to grade as `name` under an LMS bulk-download name (lms_name): the latest
/// resubmission of the shallowest ones, or an empty path.
fs::path find_lms_named(const fs::path& root, const std::string& name);

}  // namespace jelly::grade
