#include <fstream>
#include <iostream>

#include "commands/commands.hpp"
#include "jelly/cli_common/exit_codes.hpp"
#include "reports/report.hpp"

namespace jelly::grade {

int prairielearn(const GradeConfig& config, const CaseBook& book, const std::string& student,
                 const std::string& results, const GradeOptions& options) {
  const fs::path s = student.empty() ? fs::path("/grade/student") : fs::path(student);
  const fs::path res = results.empty() ? fs::path("/grade/results") : fs::path(results);
  fs::create_directories(res);
  const fs::path work = res / ".work";
  const GradeReport r = grade_submission(config, book, s, work, options);
  fs::remove_all(work);
  std::ofstream(res / "results.json") << prairielearn_results(r).dump(2) << "\n";
  std::cout << terminal_summary(r, false);
  return cli::kExitOk;
}

}  // namespace jelly::grade
