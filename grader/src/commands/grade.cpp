#include <cstdlib>
#include <iostream>

#include "commands/commands.hpp"
#include "jelly/cli_common/exit_codes.hpp"
#include "reports/report.hpp"

namespace jelly::grade {

int grade_one(const GradeConfig& config, const CaseBook& book, const GradeOneArgs& args,
              const GradeOptions& options) {
  const fs::path out_dir = args.out.empty() ? fs::path("grade-results") : args.out;
  const fs::path work = out_dir / ".work";
  fs::remove_all(work);
  const GradeReport r = grade_submission(config, book, args.submission, work, options);
  std::set<std::string> files = args.formats;
  files.erase("terminal");
  if (!files.empty()) write_reports(r, book, out_dir, files, args.frames ? &config : nullptr);
  // JELLY_GRADE_KEEP_WORK=1 keeps the built runner (out/.work/build/runner) for experiments
  // such as the tolerance measurements of docs/tolerances.md.
  if (!std::getenv("JELLY_GRADE_KEEP_WORK")) fs::remove_all(work);
  if (args.formats.count("terminal")) std::cout << terminal_summary(r, args.verbose);
  // Full marks include a bonus task's (every public test passed).
  return args.strict && !(r.compiled && r.max_score > 0 && r.score >= r.max_score - 1e-9 &&
                          r.bonus_score >= r.bonus_max - 1e-9)
             ? cli::kExitFailure
             : cli::kExitOk;
}

}  // namespace jelly::grade
