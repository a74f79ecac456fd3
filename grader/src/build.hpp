// Building a submission's runner: its five task files (found by name anywhere in the folder,
// everything else ignored) compiled with the framework's exact flags and linked with the
// precompiled framework and grading harness.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "config.hpp"
#include "isolation.hpp"

namespace jelly::grade {

struct BuildResult {
  bool ok = false;
  std::filesystem::path runner;    ///< the per-submission runner (when ok)
  std::string errors;              ///< compiler/linker messages, paths relative to the submission
  std::vector<std::string> notes;  ///< e.g. "forces.cpp not found: graded as the stub"
  std::map<std::string, std::string>
      used;  ///< task file → where it came from (relative path or "stub")
  double seconds = 0.0;
};

/// Limits of one compiler or linker run (each process of it: driver, cc1plus, as, ld). A run that
/// hits one is a failed compilation whose message says which ("compiling forces.cpp used more
/// than 2 GiB of memory"); the grader goes on.
struct BuildLimits {
  std::size_t memory_bytes = 2ULL << 30;  ///< RLIMIT_AS
  double cpu_s = 120.0;                   ///< RLIMIT_CPU
  double timeout_s = 300.0;               ///< wall clock
  std::size_t file_bytes = 256ULL << 20;  ///< RLIMIT_FSIZE: objects, the runner, temporary files
  std::size_t output_bytes = 8ULL << 20;  ///< compiler messages (more kills the compiler)
  std::size_t open_files = 256;           ///< RLIMIT_NOFILE
  std::size_t source_bytes = 1ULL << 20;  ///< a task file larger than this is refused
};

/// Builds into `work_dir` (created) inside the sandbox `iso`. `jobs` compiler processes at once.
/// `gid`: the submission's group (Workspace::gid(), kind User); the folder is read-only to it
/// after. Objects are cached by content in config.cache_dir(), so an unchanged file is never
/// compiled twice. Task files that are symbolic or hard links, FIFOs or devices are refused.
BuildResult build_submission(const GradeConfig& config, const std::filesystem::path& submission,
                             const std::filesystem::path& work_dir, int jobs, const Isolation& iso,
                             const BuildLimits& limits = {}, int gid = -1);

/// Compiler messages with every diagnostic located in a file outside `allowed` (folders) reduced
/// to its location: no text of any other file reaches a student. Paths in the messages are
/// relative to `cwd` or absolute.
std::string filter_diagnostics(const std::string& messages, const std::filesystem::path& cwd,
                               const std::vector<std::filesystem::path>& allowed);

}  // namespace jelly::grade
