// Building a submission's runner: its five task files (found by name anywhere in the folder,
// everything else ignored) compiled with the framework's exact flags and linked with the
// precompiled framework and grading harness.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "config.hpp"

namespace jelly::grade {

struct BuildResult {
  bool ok = false;
  std::filesystem::path runner;          ///< the per-submission runner (when ok)
  std::string errors;                    ///< compiler/linker messages, paths relative to the submission
  std::vector<std::string> notes;        ///< e.g. "forces.cpp not found: graded as the stub"
  std::map<std::string, std::string> used;  ///< task file → where it came from (relative path or "stub")
  double seconds = 0.0;
};

/// Builds into `work_dir` (created). `jobs` compiler processes at once. Objects are cached by
/// content in config.cache_dir(), so an unchanged file is never compiled twice.
BuildResult build_submission(const GradeConfig& config, const std::filesystem::path& submission,
                             const std::filesystem::path& work_dir, int jobs);

}  // namespace jelly::grade
