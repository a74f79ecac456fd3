// The student's report (issue 21): per task its points and verdict, the first failed test expanded
// with its hint, the other failed tests and the passed ones folded; the same order in the terminal,
// report.md, report.html and Gradescope's results; the messages' words (tolerance 'step',
// contract §9) linked to the handout page that explains them; hostile text still escaped. And the
// hints' matching (hints.hpp) on made-up outputs. grader/src/reports/report.cpp and hints.cpp on a
// made-up report: no runner, no compiler.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "display_column.hpp"
#include "grading/grade.hpp"
#include "grading/hints.hpp"
#include "inputs/cases.hpp"
#include "report_text.hpp"
#include "reports/report.hpp"

namespace {

using namespace jelly::grade;
using jelly::testing::lines_starting;
using jelly::testing::outside_code_blocks;

const std::string kPage = "assignments/p/handout/reading-your-report.md";

// Task P.T1 with four tests in case-book order: passed, failed (a tolerance, a contract section,
// a hint), failed (hostile text), hidden and failed; task P.T2 with one passed test.
struct Fixture {
  CaseBook book;
  std::vector<CaseSpec> specs;
  GradeReport report;

  Fixture() {
    book.rubric.autograded_total = 80.0;
    book.rubric.tasks = {{"P.T1", "Integrator", "integrators", "f (a.cpp)", "a.cpp", 60.0, false},
                         {"P.T2", "Forces", "forces", "g (a.cpp)", "a.cpp", 20.0, false}};
    const struct {
      const char *id, *task, *title;
      bool hidden;
    } cases[] = {{"p.one.passes", "P.T1", "the first test", false},
                 {"p.one.step", "P.T1", "one step (contract §9)", false},
                 {"p.one.hostile", "P.T1", "a <b>hostile</b> [title](javascript:x)", false},
                 {"p.one.hidden", "P.T1", "a hidden test", true},
                 {"p.two.passes", "P.T2", "forces pass", false}};
    for (const auto& c : cases) {
      CaseSpec s;
      s.id = c.id, s.task = c.task, s.title = c.title, s.hidden = c.hidden;
      s.tolerance = "step";
      specs.push_back(s);
    }
    report.submission = "sub";
    report.visibility = "all";
    report.compiled = true;
    report.build.ok = true;
    report.terms_page = kPage;
    report.cases.resize(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
      CaseResult& c = report.cases[i];
      c.spec = &specs[i];
      c.max_score = 10.0;
      c.status = c.spec->id.find("passes") != std::string::npos ? "passed" : "failed";
      c.score = c.status == "passed" ? 10.0 : 0.0;
    }
    report.cases[1].failures = {
        "x [particle 0, y] — height after 500 steps (contract §9): expected 1, got 2 (difference "
        "1, allowed 1e-12 by tolerance 'step')",
        "v: expected 0, got 1 (difference 1, allowed 1e-12 by tolerance 'force')",
        "a third reason"};
    report.cases[1].hints = {"RK4 with equal weights (h/4 each)"};
    report.cases[2].failures = {
        "<script>alert(1)</script> by tolerance 'a\"><script>' and "
        "[link](javascript:alert(1)) by tolerance 'step'"};
    report.cases[3].failures = {"the hidden test's secret message"};
    for (const TaskSpec& t : book.rubric.tasks) {
      TaskResult tr;
      tr.spec = &t;
      for (CaseResult& c : report.cases)
        if (c.spec->task == t.id) tr.cases.push_back(&c), tr.score += c.score, tr.max_score += 10;
      report.tasks.push_back(tr);
      report.score += tr.score, report.max_score += tr.max_score;
    }
  }
};

// The ids of `ids` in the order they first appear in `text`.
std::vector<std::string> order_in(const std::string& text, const std::vector<std::string>& ids) {
  std::vector<std::pair<std::size_t, std::string>> at;
  for (const std::string& id : ids) {
    const std::size_t p = text.find("[" + id);
    if (p != std::string::npos) at.emplace_back(p, id);
  }
  std::sort(at.begin(), at.end());
  std::vector<std::string> out;
  for (const auto& a : at) out.push_back(a.second);
  return out;
}

const std::vector<std::string> kIds = {"p.one.passes", "p.one.step", "p.one.hostile",
                                       "p.one.hidden", "p.two.passes"};
// Per task: the failed tests first (case-book order), then the passed ones.
const std::vector<std::string> kOrder = {"p.one.step", "p.one.hostile", "p.one.hidden",
                                         "p.one.passes", "p.two.passes"};

TEST(GraderReport, EveryFormatListsTheTestsInTheSameOrder) {
  const Fixture f;
  EXPECT_EQ(order_in(markdown_report(f.report), kIds), kOrder);
  EXPECT_EQ(order_in(html_report(f.report), kIds), kOrder);
  const Json gs = gradescope_results(f.report, f.book);
  std::string names;
  for (const Json& t : gs["tests"]) names += t["name"].get<std::string>() + "\n";
  EXPECT_EQ(order_in(names, kIds), kOrder);
  const Json pl = prairielearn_results(f.report);
  names.clear();
  for (const Json& t : pl["tests"]) names += t["name"].get<std::string>() + "\n";
  EXPECT_EQ(order_in(names, kIds), kOrder);
  // The terminal names the failed tests (the passed ones only with --verbose, by title).
  const std::vector<std::string> failed(kOrder.begin(), kOrder.begin() + 3);
  EXPECT_EQ(order_in(terminal_summary(f.report, false), kIds), failed);
  EXPECT_EQ(order_in(terminal_summary(f.report, true), kIds), failed);
}

TEST(GraderReport, TheFirstFailureIsExpandedTheRestFolded) {
  const Fixture f;
  const std::string html = html_report(f.report);
  const std::size_t first = html.find("allowed 1e-12 by ");
  const std::size_t more = html.find("<details><summary>2 more failed tests</summary>");
  const std::size_t hostile = html.find("[p.one.hostile]");
  const std::size_t passed = html.find("<details><summary>1 passed test</summary>");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(more, std::string::npos) << html;
  ASSERT_NE(passed, std::string::npos);
  EXPECT_LT(first, more);
  EXPECT_LT(more, hostile);
  EXPECT_LT(hostile, passed);
  EXPECT_LT(passed, html.find("[p.one.passes]"));
  // The summary table comes before every task's section, one row per task.
  EXPECT_LT(html.find("<h2>Summary</h2>"), html.find("<section id=\"task-p-t1\">"));
  EXPECT_NE(html.find("<a href=\"#task-p-t1\">P.T1 Integrator</a>"), std::string::npos);
  const std::string md = markdown_report(f.report);
  EXPECT_LT(md.find("allowed 1e-12 by "), md.find("<details><summary>2 more failed tests"));
  EXPECT_NE(md.find("| [P.T1 Integrator](#task-p-t1) | 10.00 / 40.00 | **fail** | 1/4 |"),
            std::string::npos)
      << md;
  // The terminal: the first failure's two reasons, the second failure one line, passed counted.
  const std::string term = terminal_summary(f.report, false);
  EXPECT_NE(term.find("(1 more: --verbose"), std::string::npos) << term;
  EXPECT_EQ(term.find("<script>alert"), std::string::npos) << "a folded failure's message";
  EXPECT_NE(term.find("✗ a <b>hostile</b>"), std::string::npos);
  EXPECT_NE(term.find("✓ 1 passed (--verbose lists them)"), std::string::npos);
  EXPECT_NE(terminal_summary(f.report, true).find("a third reason"), std::string::npos);
}

TEST(GraderReport, TheHintIsInEveryFormat) {
  const Fixture f;
  const std::string hint = "this looks like RK4 with equal weights (h/4 each)";
  EXPECT_NE(terminal_summary(f.report, false).find("hint: " + hint), std::string::npos);
  EXPECT_NE(html_report(f.report).find("<b>Hint:</b> " + hint), std::string::npos);
  EXPECT_NE(markdown_report(f.report).find("**Hint:** this looks like RK4"), std::string::npos);
  const Json gs = gradescope_results(f.report, f.book);
  EXPECT_NE(gs["output"].get<std::string>().find("hint: " + hint), std::string::npos);
  EXPECT_NE(gs["tests"][1]["output"].get<std::string>().find("Hint: " + hint), std::string::npos);
}

TEST(GraderReport, TheWordsOfTheMessagesLinkToTheHandout) {
  const Fixture f;
  const std::string html = html_report(f.report);
  EXPECT_NE(html.find("<a href=\"" + kPage + "#tolerance-step\">tolerance &#39;step&#39;</a>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<a href=\"" + kPage + "#contract-9\">contract §9</a>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"" + kPage + "\">reading your report</a>"), std::string::npos);
  const std::string md = markdown_report(f.report);
  EXPECT_NE(md.find("](" + kPage + "#tolerance-step)"), std::string::npos) << md;
  EXPECT_NE(md.find("[contract §9](" + kPage + "#contract-9)"), std::string::npos) << md;
  // A link target given by write_reports (relative to the report's folder) wins.
  EXPECT_NE(markdown_report(f.report, nullptr, "../x.md").find("](../x.md#tolerance-step)"),
            std::string::npos);
  const std::string term = terminal_summary(f.report, false);
  EXPECT_NE(term.find("words: see " + kPage + "#tolerance-step"), std::string::npos) << term;
  EXPECT_NE(term.find("words: see " + kPage + "#contract-9"), std::string::npos);
  EXPECT_NE(term.find("words: see " + kPage + "#tolerance-force"), std::string::npos);
  const Json gs = gradescope_results(f.report, f.book);
  EXPECT_NE(
      gs["tests"][1]["output"].get<std::string>().find("Words: see " + kPage + "#tolerance-step"),
      std::string::npos);
  // A contract the manifest names (`contracts`) links to its own anchors; one it does not name
  // links as the general "contract §N".
  Fixture named;
  named.report.contracts = {"drag"};
  named.report.cases[1].failures = {"speed (drag contract §4, ballistics contract §2)"};
  const std::string named_md = markdown_report(named.report);
  EXPECT_NE(named_md.find("[drag contract §4](" + kPage + "#drag-contract-4)"), std::string::npos)
      << named_md;
  EXPECT_NE(named_md.find("ballistics [contract §2](" + kPage + "#contract-2)"), std::string::npos)
      << named_md;
  // Without the page (an assignment without one), no links and no pointers.
  Fixture bare;
  bare.report.terms_page.clear();
  EXPECT_EQ(html_report(bare.report).find("#tolerance-"), std::string::npos);
  EXPECT_EQ(terminal_summary(bare.report, false).find("words: see"), std::string::npos);
}

TEST(GraderReport, HostileTextStaysEscapedAndMakesNoLink) {
  const Fixture f;
  const std::string html = html_report(f.report);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<b>hostile</b>"), std::string::npos);
  EXPECT_EQ(html.find("#tolerance-a"), std::string::npos) << "not a tolerance name: no anchor";
  EXPECT_NE(html.find("&lt;script&gt;alert(1)"), std::string::npos);
  const std::string md = markdown_report(f.report);
  EXPECT_EQ(md.find("<script>"), std::string::npos);
  // The student's brackets are escaped: "\\[link\\](javascript:" is text, not a link.
  EXPECT_NE(md.find("\\[link\\](javascript:"), std::string::npos) << md;
  EXPECT_EQ(md.find("[link](javascript:"), std::string::npos) << md;
  EXPECT_EQ(md.find("#tolerance-a"), std::string::npos);
}

// Every line of `text` that holds `needle` has the gutter "│ " before it (student text set apart).
bool only_behind_the_gutter(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find(needle);
    if (at == std::string::npos) continue;
    const std::size_t gutter = line.find("\xE2\x94\x82 ");
    if (gutter == std::string::npos || gutter > at || line.find_first_not_of(' ') != gutter)
      return false;
  }
  return true;
}

// Issue 28: what a submission controls (an exception's message, what its tests printed, the
// compiler's messages, its notes) never passes for the grader's own text: no line of it in the
// plain-text formats starts where the summary's lines do ("Total: 80.00 / 80.00"), and in
// Markdown and HTML its markup stays text.
TEST(GraderReport, StudentTextCannotPassForTheGradersSummary) {
  Fixture f;
  const std::string fake = "Total: 80.00 / 80.00";
  const std::string img = "<img src=x onerror=alert(1)>";
  f.report.cases[1].failures.insert(f.report.cases[1].failures.begin(),
                                    "an exception was thrown: oops\n" + fake + "\n" + img);
  f.report.cases[1].printed = fake + "\n" + img + "\n```\n~~~\n" + img + "\n";
  f.report.notes.push_back("a note naming\n" + fake);
  f.report.submission = "sub\n" + fake;
  for (const bool verbose : {false, true}) {
    const std::string term = terminal_summary(f.report, verbose);
    EXPECT_EQ(lines_starting(term, "Total:"), 1) << term;
    // (the first line names the submission: its folder's name on that one line)
    EXPECT_TRUE(only_behind_the_gutter(term.substr(term.find('\n') + 1), fake)) << term;
    EXPECT_EQ(term.rfind("Jelly Lab autograder — sub\xE2\x90\xA4Total: 80.00", 0), 0u) << term;
  }
  const Json gs = gradescope_results(f.report, f.book);
  EXPECT_EQ(gs.value("output_format", ""), "text");
  EXPECT_EQ(gs.value("test_output_format", ""), "text");
  std::string plain = gs["output"].get<std::string>();
  for (const Json& t : gs["tests"]) plain += t["output"].get<std::string>();
  for (const Json& t : prairielearn_results(f.report)["tests"])
    plain += t["output"].get<std::string>();
  EXPECT_EQ(lines_starting(plain, "Total:"), 0) << plain;
  EXPECT_TRUE(only_behind_the_gutter(plain, fake)) << plain;
  const std::string md = markdown_report(f.report);
  EXPECT_EQ(outside_code_blocks(md).find("<img"), std::string::npos) << md;
  EXPECT_EQ(lines_starting(outside_code_blocks(md), "Total:"), 0) << md;
  const std::string html = html_report(f.report);
  EXPECT_EQ(html.find(img), std::string::npos);
  EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
}

// The compiler's messages quote the student's code: set apart in every plain-text format.
TEST(GraderReport, CompilerMessagesAreSetApart) {
  Fixture f;
  const std::string fake = "Total: 80.00 / 80.00";
  f.report.compiled = false;
  f.report.failed_files.push_back(
      {"a.cpp", "did not compile", "a.cpp:1:2: error: #error\n" + fake + "\n", {"P.T1"}, 60.0});
  const std::string term = terminal_summary(f.report, false);
  EXPECT_EQ(lines_starting(term, "Total:"), 1) << term;
  EXPECT_TRUE(only_behind_the_gutter(term, fake)) << term;
  EXPECT_NE(term.find("a.cpp did not compile"), std::string::npos) << term;
  const std::string compile = gradescope_results(f.report, f.book)["tests"][0]["output"];
  EXPECT_TRUE(only_behind_the_gutter(compile, fake)) << compile;
  EXPECT_TRUE(only_behind_the_gutter(junit_xml(f.report), fake));
  f.report.failed_files.clear();
  f.report.build.ok = false;
  f.report.build.errors = "x.cpp:1: error\n" + fake + "\n";
  EXPECT_TRUE(only_behind_the_gutter(terminal_summary(f.report, false), fake));
}

using jelly::test::column_of;

// Issue 28: the summary's rows line up by display width ("Cloth–sphere" has a three-byte en dash)
// and a long title widens its column instead of pushing its row out of line.
TEST(GraderReport, TheSummaryTableLinesUpByDisplayWidth) {
  Fixture f;
  f.book.rubric.tasks[0].title = "Implicit Euler (predictor-corrector)";
  f.book.rubric.tasks[1].title = "Cloth–sphere collision";
  for (const std::string& text :
       {terminal_summary(f.report, false),
        gradescope_results(f.report, f.book)["output"].get<std::string>()}) {
    std::istringstream in(text);
    std::vector<std::string> rows;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("P.T", 0) == 0) rows.push_back(line);
    ASSERT_EQ(rows.size(), 2u) << text;
    EXPECT_EQ(column_of(rows[0], " / "), column_of(rows[1], " / ")) << text;
    EXPECT_EQ(column_of(rows[0], "FAIL"), column_of(rows[1], "PASS")) << text;
    EXPECT_EQ(column_of(rows[0], "Implicit"), column_of(rows[1], "Cloth")) << text;
    EXPECT_NE(rows[0].find("(predictor-corrector) "), std::string::npos) << text;
  }
}

TEST(GraderReport, GradescopesSummaryLeavesTheHiddenTestsOut) {
  Fixture f;
  f.book.rubric.hidden_visibility = "after_due_date";
  const std::string out = gradescope_results(f.report, f.book)["output"].get<std::string>();
  EXPECT_EQ(out.find("hidden"), std::string::npos) << out;
  EXPECT_NE(out.find("(1/3 public tests)"), std::string::npos) << out;
  EXPECT_NE(out.find("P.T1"), std::string::npos);
  f.book.rubric.hidden_visibility = "visible";
  const std::string all = gradescope_results(f.report, f.book)["output"].get<std::string>();
  EXPECT_NE(all.find("(1/4 tests)"), std::string::npos) << all;
}

TEST(GraderReport, TheCourseScenesPlotIsInItsTasksSection) {
  Fixture f;
  f.report.cases[4].reference =
      Json::parse(R"({"com_time": {"value": [0, 1]}, "com_y": {"value": [2, 1]}})");
  const std::string html = html_report(f.report);
  const std::size_t section = html.find("<section id=\"task-p-t2\">");
  const std::size_t plot = html.find("<h3>Course scene</h3>");
  ASSERT_NE(plot, std::string::npos);
  EXPECT_LT(section, plot);
  EXPECT_LT(plot, html.find("</section>", section));
  const std::string md = markdown_report(f.report);
  EXPECT_LT(md.find("## P.T2 Forces"), md.find("### Course scene"));
}

// ---- hints.hpp: the matching, on made-up outputs.

struct HintFixture {
  CaseBook book;
  CaseSpec spec;
  GradeReport report;
  HintBook hints;
  const std::string digest = "d";

  HintFixture() {
    book.tolerances["step"] = {"step", 1e-12, 1e-12, ""};
    spec.id = "p.step";
    spec.task = "P.T1";
    spec.tolerance = "step";
    spec.rules.push_back({"order", Rule{Rule::Kind::Range, "", 0.7, 1.3}});
    spec.rules.push_back({"com", Rule{Rule::Kind::Info, "", 0, 0}});
    HintSignature s;
    s.mutant = "m";
    s.description = "a known mistake";
    // JSON stores a NaN of the mutant's outputs as null.
    s.cases[spec.id] = {
        case_hash(spec, digest),
        Json::parse(R"({"x": {"value": [1.0, 2.0, null]}, "order": {"value": 1.25}})")};
    hints.signatures.push_back(s);
    CaseResult c;
    c.spec = &spec;
    c.status = "failed";
    c.outputs = Json::object();
    c.outputs["x"]["value"] = Json::array({1.0 + 1e-13, 2.0, std::nan("")});
    c.outputs["order"]["value"] = 1.25;
    c.outputs["com"]["value"] = 7.0;  // informational: never compared
    report.cases.push_back(c);
  }
  std::vector<std::string> hinted() {
    for (CaseResult& c : report.cases) c.hints.clear();
    apply_hints(hints, book, digest, report);
    return report.cases[0].hints;
  }
};

TEST(GraderHints, OutputsWithinTheCasesToleranceOfAMutantsGetItsDescription) {
  HintFixture f;
  EXPECT_EQ(f.hinted(), std::vector<std::string>{"a known mistake"});
}

TEST(GraderHints, DifferentOutputsGetNoHint) {
  HintFixture f;
  f.report.cases[0].outputs["x"]["value"][0] = 1.0 + 1e-9;  // outside 'step'
  EXPECT_TRUE(f.hinted().empty());
  HintFixture g;
  g.report.cases[0].outputs["order"]["value"] = 1.26;  // a range output: the mutant's value only
  EXPECT_TRUE(g.hinted().empty());
  HintFixture h;
  h.report.cases[0].outputs["x"]["value"][2] = 3.0;  // a number where the mutant has NaN
  EXPECT_TRUE(h.hinted().empty());
  HintFixture m;
  m.report.cases[0].outputs.erase("order");  // an output missing
  EXPECT_TRUE(m.hinted().empty());
}

TEST(GraderHints, OnlyFailedPublicTestsOfTheSameCaseVersionGetHints) {
  HintFixture passed;
  passed.report.cases[0].status = "passed";
  EXPECT_TRUE(passed.hinted().empty());
  HintFixture hidden;
  hidden.spec.hidden = true;
  EXPECT_TRUE(hidden.hinted().empty());
  HintFixture changed;  // the case's parameters changed since the signature was made
  changed.spec.params["n"] = 3;
  EXPECT_TRUE(changed.hinted().empty());
  HintFixture not_run;
  not_run.report.cases[0].not_run = true;
  EXPECT_TRUE(not_run.hinted().empty());
}

TEST(GraderHints, TwoMutantsWithTheSameOutputsAreBothNamed) {
  HintFixture f;
  HintSignature twin = f.hints.signatures[0];
  twin.mutant = "twin";
  twin.description = "another known mistake";
  f.hints.signatures.push_back(twin);
  EXPECT_EQ(f.hinted(), (std::vector<std::string>{"a known mistake", "another known mistake"}));
  Fixture r;
  r.report.cases[1].hints = {"A", "B"};
  EXPECT_NE(terminal_summary(r.report, false).find("hint: this looks like A, or B"),
            std::string::npos);
}

TEST(GraderHints, AMalformedHintsFileIsAnErrorNamingIt) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "jelly-hints-test";
  std::filesystem::create_directories(dir);
  EXPECT_TRUE(load_hints(dir / "absent.json").empty()) << "a student release has none";
  const auto write = [&](const std::string& text) {
    std::ofstream(dir / "hints.json") << text;
    return dir / "hints.json";
  };
  EXPECT_THROW(load_hints(write("not json")), std::runtime_error);
  EXPECT_THROW(load_hints(write(R"({"format": 2, "mutants": []})")), std::runtime_error);
  EXPECT_THROW(load_hints(write(R"({"format": 1, "mutants": [{"name": "m"}]})")),
               std::runtime_error);
  try {
    load_hints(write(R"({"format": 1})"));
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("hints.json: mutants"), std::string::npos) << e.what();
  }
  EXPECT_EQ(load_hints(write(R"({"format": 1, "mutants": []})")).signatures.size(), 0u);
  std::filesystem::remove_all(dir);
}

}  // namespace
