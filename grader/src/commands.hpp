// The jelly-grade subcommands beyond grading one submission.
#pragma once

#include <string>

#include "cases.hpp"
#include "grade.hpp"

namespace jelly::grade {

/// Regenerates grader/data/{public,hidden}/*.json from solutions/ with the reference runner.
int generate_reference(const GradeConfig& config, const CaseBook& book);

/// Grades every folder in `dir` (one per student) in parallel; results per student and scores.csv.
int batch(const GradeConfig& config, const CaseBook& book, const std::string& dir,
          const std::string& out, int jobs, const GradeOptions& options, bool frames = true);

/// Shell lines (setup.sh, run_autograder, a PrairieLearn image) that create the unprivileged user
/// of the "user" sandbox and make the grader's secrets under `source` readable by root only.
std::string sandbox_setup_lines(const std::string& source);

/// Builds the Gradescope autograder zip (setup.sh, run_autograder, the framework without solutions/
/// but with the hidden data).
int gradescope_zip(const GradeConfig& config, const std::string& zip_path);

/// Applies every grader/mutants/*.toml to a copy of solutions/, grades each, checks that the
/// reference scores full marks, the stubs zero, and every mutant loses points in its own task only.
/// Writes the table (Markdown) to `table_path` when given. Returns 0 when every check holds.
int mutants(const GradeConfig& config, const CaseBook& book, const std::string& table_path,
            const std::string& work, int jobs, const GradeOptions& options);

}  // namespace jelly::grade
