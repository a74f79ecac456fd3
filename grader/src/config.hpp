// Where jelly-grade finds the framework, the compiler recipe and its data.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jelly::grade {

namespace fs = std::filesystem;

/// The recipe CMake wrote (build/grader/grade-config.json) plus paths derived from it.
struct GradeConfig {
  std::string compiler;
  std::string compiler_id;
  std::vector<std::string> compile_flags;  ///< includes -O level and -ffp-contract=off
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;
  std::vector<std::string> link_objects;    ///< runner main + task_table for a submission
  std::vector<std::string> link_libraries;  ///< harness, core, seccomp
  std::vector<std::string> link_flags;
  fs::path source_dir;  ///< the framework checkout (grader/, assignments/, solutions/?)
  fs::path binary_dir;
  fs::path reference_runner;  ///< empty in a student release
  /// The `jelly` CLI with `render --replay` (report frames); empty when built without the viewer.
  /// $JELLY_GRADE_JELLY overrides it.
  fs::path jelly_cli;
  fs::path config_path;

  fs::path grader_dir() const { return source_dir / "grader"; }
  fs::path cases_dir() const { return grader_dir() / "cases"; }
  fs::path data_dir() const { return grader_dir() / "data"; }
  fs::path rubric_path() const { return grader_dir() / "rubric.toml"; }
  fs::path assignments_dir() const { return source_dir / "assignments"; }
  fs::path solutions_dir() const { return source_dir / "solutions"; }
  /// Compiled-object cache (content-addressed), so a mutant recompiles only the file it changes.
  fs::path cache_dir() const;
};

/// Reads the config: `path` if given, else $JELLY_GRADE_CONFIG, else the path compiled in.
/// Throws std::runtime_error naming the file and key on a problem.
GradeConfig load_config(const std::string& path);

/// The five files a student edits, in build order.
const std::vector<std::string>& task_files();

}  // namespace jelly::grade
