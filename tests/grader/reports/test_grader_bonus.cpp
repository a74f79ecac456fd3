// A bonus task (manifest `bonus = true`, A2's friction): its points come on top of
// autograded_total. The rubric's scale ignores it, and every report shows it apart — the total
// and its maximum unchanged, "+ bonus" after them — while a report without a bonus task reads
// exactly as before (A1).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grading/grade.hpp"
#include "inputs/cases.hpp"
#include "reports/report.hpp"

namespace {

using jelly::grade::CaseBook;
using jelly::grade::CaseResult;
using jelly::grade::CaseSpec;
using jelly::grade::GradeReport;
using jelly::grade::TaskResult;
using jelly::grade::TaskSpec;

// Two tasks of 60 and 20 raw points plus, when `bonus`, a bonus task of 5; one passed case each
// (the bonus's too), as grade_submission leaves them.
struct Fixture {
  CaseBook book;
  std::vector<CaseSpec> specs;
  GradeReport report;

  explicit Fixture(bool bonus) {
    book.rubric.autograded_total = 80.0;
    book.rubric.tasks = {{"P.T1", "Springs", "springs", "f (a.cpp)", "a.cpp", 60.0, false},
                         {"P.T2", "Forces", "forces", "g (a.cpp)", "a.cpp", 20.0, false}};
    if (bonus)
      book.rubric.tasks.push_back(
          {"P.T3", "Friction (bonus)", "bonus", "h (a.cpp)", "a.cpp", 5.0, true});
    for (const TaskSpec& t : book.rubric.tasks) {
      CaseSpec c;
      c.id = "p." + t.id;
      c.task = t.id;
      c.title = "a test of " + t.title;
      specs.push_back(c);
    }
    report.submission = "sub";
    report.visibility = "all";
    report.compiled = true;
    report.build.ok = true;
    report.cases.resize(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
      CaseResult& c = report.cases[i];
      c.spec = &specs[i];
      c.status = "passed";
      const TaskSpec& t = book.rubric.tasks[i];
      c.max_score = c.score = t.points * book.rubric.scale();
      TaskResult tr;
      tr.spec = &t;
      tr.cases = {&c};
      tr.score = tr.max_score = c.max_score;
      report.tasks.push_back(tr);
      (t.bonus ? report.bonus_score : report.score) += c.score;
      (t.bonus ? report.bonus_max : report.max_score) += c.max_score;
    }
  }
};

TEST(GraderBonus, TheScaleCountsTheRegularTasksOnly) {
  const Fixture plain(false), bonus(true);
  EXPECT_DOUBLE_EQ(plain.book.rubric.raw_total(), 80.0);
  EXPECT_DOUBLE_EQ(bonus.book.rubric.raw_total(), 80.0) << "the bonus is on top";
  EXPECT_DOUBLE_EQ(bonus.book.rubric.scale(), 1.0);
  EXPECT_FALSE(plain.report.has_bonus());
  EXPECT_TRUE(bonus.report.has_bonus());
}

TEST(GraderBonus, ReportsShowTheBonusApartWithTheMaximumUnchanged) {
  const Fixture f(true);
  const std::string terminal = jelly::grade::terminal_summary(f.report, false);
  EXPECT_NE(terminal.find("Total: 80.00 / 80.00 + bonus 5.00 / 5.00"), std::string::npos)
      << terminal;
  EXPECT_NE(terminal.find("+5.00 / 5.00"), std::string::npos) << terminal;
  const jelly::grade::Json gs = jelly::grade::gradescope_results(f.report, f.book);
  EXPECT_DOUBLE_EQ(gs["score"].get<double>(), 85.0) << "Gradescope: the bonus on top of 80";
  double max = 0.0;
  for (const auto& t : gs["tests"])
    if (t.contains("max_score")) max += t["max_score"].get<double>();
  EXPECT_DOUBLE_EQ(max, 80.0) << "the tests' maximum stays the assignment's total";
  const auto& last = gs["tests"].back();
  EXPECT_DOUBLE_EQ(last["score"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(last["max_score"].get<double>(), 0.0);
  EXPECT_NE(last["name"].get<std::string>().find("(bonus: 5.00)"), std::string::npos);
  EXPECT_DOUBLE_EQ(gs["extra_data"]["bonus_score"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(gs["extra_data"]["bonus_max"].get<double>(), 5.0);
  const jelly::grade::Json pl = jelly::grade::prairielearn_results(f.report);
  EXPECT_DOUBLE_EQ(pl["score"].get<double>(), 1.0);
  EXPECT_NE(pl["message"].get<std::string>().find("+ bonus 5.00 / 5.00"), std::string::npos);
  const std::string md = jelly::grade::markdown_report(f.report);
  EXPECT_NE(md.find("**80.00 / 80.00 + bonus 5.00 / 5.00**"), std::string::npos) << md;
  EXPECT_NE(md.find("| +5.00 / 5.00 bonus |"), std::string::npos) << md;
  EXPECT_NE(jelly::grade::html_report(f.report).find("80.00 / 80.00 + bonus 5.00 / 5.00"),
            std::string::npos);
}

TEST(GraderBonus, WithoutABonusTaskNothingChanges) {
  const Fixture f(false);
  const std::string terminal = jelly::grade::terminal_summary(f.report, false);
  EXPECT_NE(terminal.find("Total: 80.00 / 80.00   ("), std::string::npos) << terminal;
  EXPECT_EQ(terminal.find("bonus"), std::string::npos) << terminal;
  const jelly::grade::Json gs = jelly::grade::gradescope_results(f.report, f.book);
  EXPECT_DOUBLE_EQ(gs["score"].get<double>(), 80.0);
  EXPECT_FALSE(gs["extra_data"].contains("bonus_score"));
  EXPECT_EQ(gs.dump().find("bonus"), std::string::npos);
  EXPECT_EQ(jelly::grade::markdown_report(f.report).find("bonus"), std::string::npos);
}

}  // namespace
