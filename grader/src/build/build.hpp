// Building a submission's runner: its five task files (found by name anywhere in the folder,
// everything else ignored) compiled with the framework's exact flags and linked with the
// precompiled framework and grading harness.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "inputs/config.hpp"
#include "sandbox/isolation.hpp"

namespace jelly::grade {

/// A task file that does not compile (or defines a symbol it may not, or does not link) costs only
/// its own tasks: the runner is linked with that file's stub (assignments/) in its place.
struct BuildResult {
  bool ok = false;  ///< at least one runner was built (some tasks can be graded)
  std::filesystem::path
      runner;  ///< all five files (or their stubs) linked together, when they link
  std::map<std::string, std::filesystem::path>
      runners;  ///< usable task file → the runner its tasks run with (`runner`, or when the files
                ///< do not link together, one linked with that file alone and the other stubs)
  std::map<std::string, std::string>
      failed_files;  ///< task file → why it was replaced by its stub (compiler, symbols, linker)
  std::map<std::string, std::string>
      failed_what;          ///< task file → "did not compile", "was refused", "did not link", ...
  std::string errors;       ///< every failed file's messages, paths relative to the submission
  std::string warnings;     ///< the compiler's warnings about the files that compiled
  std::string link_errors;  ///< why the files did not link together (then `runner` is empty)
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
/// compiled twice. Task files that are symbolic or hard links, FIFOs or devices are refused, as are
/// objects that define symbols they may not (symbols.hpp); a refused or broken file is replaced by
/// its stub from assignments/, so that only its own tasks are lost. Throws std::runtime_error when
/// the stubs themselves do not compile (a grader error).
BuildResult build_submission(const GradeConfig& config, const std::filesystem::path& submission,
                             const std::filesystem::path& work_dir, int jobs, const Isolation& iso,
                             const BuildLimits& limits = {}, int gid = -1);

/// Compiler messages with every diagnostic located in a file outside `allowed` (folders) reduced
/// to its location: no text of any other file reaches a student. Paths in the messages are
/// relative to `cwd` or absolute.
std::string filter_diagnostics(const std::string& messages, const std::filesystem::path& cwd,
                               const std::vector<std::filesystem::path>& allowed);

}  // namespace jelly::grade
