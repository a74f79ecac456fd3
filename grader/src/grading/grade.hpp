// Running the cases against a built runner and judging the outputs against the reference.
#pragma once

#include <string>
#include <vector>

#include "build/build.hpp"
#include "inputs/cases.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

struct CaseResult {
  const CaseSpec* spec = nullptr;
  std::string status;      ///< "passed", "failed", or "skipped" (hidden data absent)
  double max_score = 0.0;  ///< scaled points
  double score = 0.0;
  std::vector<std::string> failures;  ///< what failed and why, in the student's terms
  bool not_run = false;  ///< its file could not be used (FileFailure): failures say why
  /// Why the test's program did not finish normally: "timed out", "crashed", "refused" (a
  /// forbidden system call or a sandbox limit), "ended early", "threw" (an exception left the
  /// student's code); "" when it returned its outputs.
  std::string abnormal;
  std::string printed;  ///< an excerpt of what the student's code printed
  Json outputs;         ///< the student's outputs (for plots)
  Json reference;       ///< the reference outputs
  double seconds = 0.0;
  /// The mistakes of the mutation table this failure looks like (hints.hpp): their descriptions.
  std::vector<std::string> hints;
};

struct TaskResult {
  const TaskSpec* spec = nullptr;
  double max_score = 0.0;
  double score = 0.0;
  std::vector<CaseResult*> cases;
};

struct GradeOptions {
  bool include_hidden = true;  ///< --visibility all
  double timeout_s = 10.0;     ///< per case unless the case sets its own
  int jobs = 0;                ///< parallel cases (0: all cores)
  std::size_t memory_bytes = 1ULL << 30;
  Isolation isolation;       ///< where the compiler and the tests run (choose_isolation)
  BuildLimits build_limits;  ///< limits of compiling and linking
  bool hints = true;         ///< "this looks like ..." hints from hints.json (hints.hpp)
  std::filesystem::path
      runner;  ///< --runner: a runner CMake built from the student's tasks; nothing
               ///< is compiled, and it runs without a sandbox (the self-check)
};

/// The isolation of the self-check (--runner): none, and the report says why in the student's
/// terms.
Isolation own_machine_isolation();

/// A task file replaced by its stub (it did not compile, defined a symbol it may not, or did not
/// link): what it cost.
struct FileFailure {
  std::string file;                ///< "forces.cpp"
  std::string what;                ///< "did not compile", "was refused", "did not link"
  std::string message;             ///< the compiler's (or the grader's) message
  std::vector<std::string> tasks;  ///< its tasks ("A1.T4")
  double points = 0.0;             ///< their scaled points, all lost
};

/// The task file a task's functions live in ("forces.cpp"), from the rubric's `functions`
/// ("spring_force (forces.cpp)"); "" for a task of several files (the course scene).
std::string task_file_of(const TaskSpec& task);

struct GradeReport {
  std::string submission;  ///< folder as given
  bool compiled = false;   ///< all five files compiled and linked (see failed_files otherwise)
  std::vector<FileFailure> failed_files;  ///< files replaced by their stubs, in task-file order
  bool prebuilt_runner = false;           ///< --runner: built by CMake, not compiled by the grader
  BuildResult build;
  std::vector<CaseResult> cases;        ///< in case-book order
  std::vector<TaskResult> tasks;        ///< in rubric order
  double score = 0.0, max_score = 0.0;  ///< the tasks that are not bonus tasks
  /// Bonus tasks (manifest `bonus = true`): on top of score / max_score, never part of them.
  double bonus_score = 0.0, bonus_max = 0.0;
  bool has_bonus() const { return bonus_max > 0.0; }
  std::vector<std::string> notes;
  double grading_seconds = 0.0;  ///< running the cases (not compiling)
  std::string visibility;        ///< "public" or "all"
  std::string isolation;         ///< the mechanism used: "bwrap", "user" or "none"
  std::string isolation_description;
  std::string isolation_warning;  ///< non-empty when hidden tests were not protected
  /// The handout page that explains the report's terms (tolerance names, contract sections),
  /// relative to the framework's top folder ("assignments/<id>/handout/reading-your-report.md"); ""
  /// when the assignment has none.
  std::string terms_page;
  /// The contracts its messages cite by name (the manifest's `contracts`): the report links
  /// "<name> contract §N" to the terms page's #<name>-contract-N.
  std::vector<std::string> contracts;
};

/// Builds the submission's runner and runs every selected case. Throws std::runtime_error only
/// for grader errors (missing or stale reference data, a case the runner does not know).
GradeReport grade_submission(const GradeConfig& config, const CaseBook& book,
                             const std::filesystem::path& submission,
                             const std::filesystem::path& work_dir, const GradeOptions& options);

/// Runs one case (its generator and params, plus the prepared input) with a runner binary in the
/// sandbox (also used by generate-reference, with the trusted reference runner and no isolation).
/// The request reaches the runner on its stdin, never as a file another case could read. Isolated
/// (iso given), it runs in its own empty folder with the submission's group `gid` (kind User).
ChildResult run_case(const std::filesystem::path& runner, const CaseSpec& spec, const Json* input,
                     const std::filesystem::path& work_dir, double timeout_s,
                     std::size_t memory_bytes, bool prepare = false, const Isolation* iso = nullptr,
                     int gid = -1);

/// Name of a system call number (for "your code tried to open a file").
std::string syscall_name(int nr);

}  // namespace jelly::grade
