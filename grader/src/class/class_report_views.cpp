#include "class/class_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "class/class_report_fields.hpp"
#include "reports/html_page.hpp"
#include "reports/points.hpp"
#include "reports/text_safety.hpp"

// The two views of the class summary (class_report.hpp), in Markdown and in HTML: the lecture's
// (no student, no hidden test: what was commonly wrong, counted) and the instructor's (all of it).
namespace jelly::grade {

using namespace class_fields;

// ---- what both views say -----------------------------------------------------------------------

namespace {

std::string students(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " student" : " students");
}

std::string task_name(const Json& t) {
  return str(t, "id") + (str(t, "title").empty() ? "" : " " + str(t, "title")) +
         (flag(t, "bonus") ? " (bonus)" : "");
}

std::string title_of(const Json& s) {
  return str(s, "title").empty() ? str(s, "assignment") : str(s, "title");
}

std::string dist_line(const Json& d) {
  const int n = d.value("count", 0);
  return "mean " + pts(num(d, "mean")) + ", median " + pts(num(d, "median")) + " of " +
         pts(num(d, "max_score")) + "; full marks: " + std::to_string(d.value("full_marks", 0)) +
         " of " + std::to_string(n) + " (" + percent(num(d, "full_marks_share")) + ")";
}

// One line of a task's "what went wrong": how many students (and their share of the graded
// class), what (a known mistake in the hints' words, a test by its title), and an example of the
// grader's message (a public test's only).
struct Line {
  int students = 0;
  double share = 0.0;
  std::string what, example;
};

// What a task's failures come to, naming no student and no hidden test: the known mistakes, the
// public tests failed, and how many failed a hidden test.
std::vector<Line> lecture_lines(const Json& t) {
  std::vector<Line> lines;
  for (const Json& m : t["known_mistakes"])
    lines.push_back({m.value("students", 0), num(m, "share"), str(m, "mistake"), ""});
  for (const Json& c : t["failed_cases"]) {
    if (flag(c, "hidden")) continue;
    const std::string title = str(c, "title").empty() ? str(c, "case") : str(c, "title");
    lines.push_back({c.value("students", 0), num(c, "share"), "failed the test “" + title + "”",
                     str(c["example"], "message")});
  }
  const Json& hidden = t["hidden_failed"];
  if (hidden.value("students", 0) > 0)
    lines.push_back({hidden.value("students", 0), num(hidden, "share"),
                     "failed a hidden test of this task", ""});
  return lines;
}

std::string share_text(const Line& l) {
  return percent(l.share) + " of the class (" + students(static_cast<std::size_t>(l.students)) +
         ")";
}

bool task_failed(const Json& t) {
  return !t["failed_cases"].empty() || !t["known_mistakes"].empty() ||
         t["hidden_failed"].value("students", 0) > 0;
}

// The tasks nobody failed, as one line: "HW.T1 First task, HW.T2 Second task".
std::string tasks_without_failure(const Json& s) {
  std::string names;
  for (const Json& t : s["tasks"])
    if (!task_failed(t)) names += (names.empty() ? "" : ", ") + task_name(t);
  return names;
}

std::string kind_text(const Json& k) {
  return str(k, "kind") + ": " + students(static_cast<std::size_t>(k.value("students", 0))) + " (" +
         percent(num(k, "share")) + ")";
}

}  // namespace

// ---- class.md, class-instructor.md -------------------------------------------------------------

namespace {

std::string md(const Json& j, const char* key) { return markdown_inline(str(j, key)); }

std::string md_bar(int count, int most) {
  const int width = most > 0 ? static_cast<int>(std::lround(30.0 * count / most)) : 0;
  std::string bar;
  for (int i = 0; i < width; ++i) bar += "█";
  return bar;
}

void md_scores(std::ostringstream& o, const Json& s) {
  const Json& score = s["score"];
  o << "## Scores\n\n"
    << "Of the " << score.value("count", 0) << " graded: " << dist_line(score) << "; lowest "
    << pts(num(score, "min")) << ", highest " << pts(num(score, "max")) << ".\n\n"
    << "| Score | Students | |\n|---|---:|---|\n";
  int most = 0;
  for (const Json& b : score["histogram"]) most = std::max(most, b.value("count", 0));
  for (const Json& b : score["histogram"])
    o << "| " << str(b, "label") << " | " << b.value("count", 0) << " | "
      << md_bar(b.value("count", 0), most) << " |\n";
  o << "\n## Tasks\n\n| Task | Points | Mean | Median | Full marks |\n|---|---:|---:|---:|---:|\n";
  for (const Json& t : s["tasks"]) {
    const Json& d = t["scores"];
    if (num(d, "max_score") <= 0.0) {
      o << "| " << markdown_inline(task_name(t)) << " | 0.00 | | | no points |\n";
      continue;
    }
    o << "| " << markdown_inline(task_name(t)) << " | " << pts(num(d, "max_score")) << " | "
      << pts(num(d, "mean")) << " | " << pts(num(d, "median")) << " | " << d.value("full_marks", 0)
      << " (" << percent(num(d, "full_marks_share")) << ") |\n";
  }
}

void md_lecture_tasks(std::ostringstream& o, const Json& s) {
  o << "\n## What went wrong, task by task\n\n"
    << "The mistakes the grader recognised (in the words of the hints) and the tests failed, "
       "most frequent first. Runs that did not compile, timed out or crashed are counted "
       "below.\n";
  for (const Json& t : s["tasks"]) {
    if (!task_failed(t)) continue;
    o << "\n### " << markdown_inline(task_name(t)) << "\n\n";
    for (const Line& l : lecture_lines(t))
      o << "- **" << share_text(l) << "**: " << markdown_inline(l.what)
        << (l.example.empty() ? "" : " (e.g. " + markdown_inline(l.example) + ")") << "\n";
  }
}

void md_instructor_tasks(std::ostringstream& o, const Json& s) {
  o << "\n## What failed, task by task\n\n"
    << "The mistakes the grader recognised (hints) and the tests that failed, most frequent "
       "first, with how many students failed each and one example (the first such student by "
       "id, their first failure). Timed-out and crashed runs and files that did not compile are "
       "listed below, not here.\n";
  for (const Json& t : s["tasks"]) {
    if (!task_failed(t)) continue;
    o << "\n### " << markdown_inline(task_name(t)) << "\n\n";
    for (const Json& m : t["known_mistakes"])
      o << "- Known mistake, " << students(m.value("students", 0u)) << " ("
        << percent(num(m, "share")) << "): " << md(m, "mistake") << "\n";
    if (!t["known_mistakes"].empty()) o << "\n";
    if (t["failed_cases"].empty()) continue;
    o << "| Test | Students | Example |\n|---|---:|---|\n";
    for (const Json& c : t["failed_cases"])
      o << "| " << md(c, "case") << (flag(c, "hidden") ? " (hidden)" : "") << " | "
        << c.value("students", 0) << " | " << md(c["example"], "student") << ": "
        << md(c["example"], "message") << " |\n";
  }
}

void md_kinds(std::ostringstream& o, const Json& s) {
  o << "\n## Did not compile, timed out, crashed\n\n";
  if (s["failure_kinds"].empty()) o << "None.\n";
  for (const Json& k : s["failure_kinds"]) o << "- " << markdown_inline(kind_text(k)) << "\n";
}

void md_instructor_lists(std::ostringstream& o, const Json& s) {
  auto none = [&](const Json& list) {
    if (list.empty()) o << "None.\n";
    return list.empty();
  };
  o << "\n## Did not compile\n\n";
  if (!none(s["did_not_compile"]))
    for (const Json& c : s["did_not_compile"])
      o << "- " << md(c, "student") << ": " << (str(c, "file").empty() ? "" : md(c, "file") + " ")
        << md(c, "what") << (str(c, "message").empty() ? "" : ": " + md(c, "message")) << "\n";
  o << "\n## Timed out or crashed\n\n";
  if (!none(s["timed_out_or_crashed"]))
    for (const Json& a : s["timed_out_or_crashed"])
      o << "- " << md(a, "student") << ": " << md(a, "abnormal") << " in " << a.value("cases", 0)
        << (a.value("cases", 0) == 1 ? " test" : " tests") << ", first " << md(a, "first_case")
        << ": " << md(a, "message") << "\n";
  o << "\n## Could not be graded\n\n";
  if (!none(s["could_not_grade"]))
    for (const Json& g : s["could_not_grade"])
      o << "- " << md(g, "student") << " (" << md(g, "status") << "): " << md(g, "error") << "\n";
  o << "\n## Missing task files\n\n";
  const Json& miss = s["missing_files"];
  if (none(miss["students"])) return;
  o << "**Missing task files: " << students(miss["students"].size()) << "** (";
  bool first = true;
  for (const Json& f : miss["by_file"]) {
    o << (first ? "" : ", ") << md(f, "file") << " " << f.value("students", 0);
    first = false;
  }
  o << "); graded with the unchanged stub in their place.\n\n";
  for (const Json& m : miss["students"]) {
    o << "- " << md(m, "student") << ":";
    for (const Json& f : m["files"]) o << " " << markdown_inline(f.get<std::string>());
    o << "\n";
  }
}

}  // namespace

std::string class_markdown(const Json& s, ClassView view) {
  const bool lecture = view == ClassView::Lecture;
  std::ostringstream o;
  o << "# What the class got wrong: " << markdown_inline(title_of(s)) << "\n\n"
    << (lecture ? "*For the lecture: it names no student and shows no hidden test. The "
                  "instructor's view is class-instructor.md.*\n\n"
                : "*Instructor-only: this report names students and hidden tests. Project "
                  "class.md or class.html instead.*\n\n")
    << s.value("students", 0) << " submissions: " << s.value("graded", 0) << " graded, "
    << s.value("not_graded", 0) << " could not be graded.\n\n";
  md_scores(o, s);
  if (lecture)
    md_lecture_tasks(o, s);
  else
    md_instructor_tasks(o, s);
  const std::string fine = tasks_without_failure(s);
  if (!fine.empty()) o << "\n**No test failed:** " << markdown_inline(fine) << "\n";
  md_kinds(o, s);
  if (!lecture) md_instructor_lists(o, s);
  return o.str();
}

// ---- class.html, class-instructor.html ---------------------------------------------------------

namespace {

std::string h(const std::string& s) { return html_escape(s); }

// A histogram as inline SVG: one bar per bin, its count above, its label below; the full-marks
// bin in green.
std::string svg_histogram(const Json& histogram, int width, int height, bool labels) {
  const int n = static_cast<int>(histogram.size());
  int most = 0;
  for (const Json& b : histogram) most = std::max(most, b.value("count", 0));
  const int top = labels ? 34 : 2, bottom = labels ? 40 : 2;
  const double slot = static_cast<double>(width) / std::max(n, 1);
  const double plot = height - top - bottom;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << " " << height << "\" role=\"img\">";
  o << "<line x1=\"0\" y1=\"" << height - bottom << "\" x2=\"" << width << "\" y2=\""
    << height - bottom << "\" stroke=\"#888\"/>";
  for (int k = 0; k < n; ++k) {
    const int count = histogram[k].value("count", 0);
    const double bh = most > 0 ? plot * count / most : 0.0;
    char rect[256];
    std::snprintf(rect, sizeof rect,
                  "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>",
                  k * slot + slot * 0.1, height - bottom - bh, slot * 0.8, bh,
                  k == n - 1 ? "#2e8b57" : "#3b6fb6");
    o << rect;
    if (labels) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"24\">%d</text>",
                    k * slot + slot / 2, height - bottom - bh - 8, count);
      o << text;
      std::snprintf(text, sizeof text,
                    "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\" font-size=\"20\">",
                    k * slot + slot / 2, height - 10);
      o << text << h(str(histogram[k], "label")) << "</text>";
    }
  }
  o << "</svg>";
  return o.str();
}

// A horizontal bar as wide as `share` of its box.
std::string css_bar(double share, const char* colour) {
  char b[160];
  std::snprintf(b, sizeof b,
                "<span class=\"bar\"><span style=\"width:%.1f%%;background:%s\"></span></span>",
                std::clamp(share, 0.0, 1.0) * 100.0, colour);
  return b;
}

// The scores: the class's, and each task's (a task of no points has none to compare).
void html_scores(HtmlData& page, const Json& s) {
  const Json& score = s["score"];
  page.set("mean", pts(num(score, "mean")));
  page.set("median", pts(num(score, "median")));
  page.set("max_score", pts(num(score, "max_score")));
  page.set("full_marks", std::to_string(score.value("full_marks", 0)));
  page.set("count", std::to_string(score.value("count", 0)));
  page.set("full_marks_share", percent(num(score, "full_marks_share")));
  page.set("histogram", svg_histogram(score["histogram"], 1100, 320, true));
  HtmlList tasks;
  for (const Json& t : s["tasks"]) {
    const Json& d = t["scores"];
    tasks.push_back(HtmlObject{{"name", task_name(t)},
                               {"max_score", pts(num(d, "max_score"))},
                               {"has_points", num(d, "max_score") > 0.0},
                               {"mean", pts(num(d, "mean"))},
                               {"median", pts(num(d, "median"))},
                               {"full_marks_bar", css_bar(num(d, "full_marks_share"), "#2e8b57")},
                               {"full_marks_share", percent(num(d, "full_marks_share"))},
                               {"histogram", svg_histogram(d["histogram"], 220, 44, false)}});
  }
  page.set("tasks", tasks);
}

// The lecture's view of a failed task: what went wrong, naming no student and no hidden test.
HtmlData html_lecture_task(const Json& t) {
  HtmlList lines;
  for (const Line& l : lecture_lines(t))
    lines.push_back(HtmlObject{{"bar", css_bar(l.share, "#c0392b")},
                               {"share", percent(l.share)},
                               {"what", l.what},
                               {"students", students(static_cast<std::size_t>(l.students))},
                               {"has_example", !l.example.empty()},
                               {"example", l.example}});
  return HtmlObject{{"name", task_name(t)}, {"lines", lines}};
}

// The instructor's view of a failed task: its known mistakes and failed tests, with an example.
HtmlData html_instructor_task(const Json& t, double graded) {
  HtmlList mistakes, cases;
  for (const Json& m : t["known_mistakes"])
    mistakes.push_back(HtmlObject{{"bar", css_bar(num(m, "share"), "#c0392b")},
                                  {"students", std::to_string(m.value("students", 0))},
                                  {"mistake", str(m, "mistake")}});
  for (const Json& c : t["failed_cases"]) {
    const int n = c.value("students", 0);
    cases.push_back(HtmlObject{{"bar", css_bar(n / graded, "#c0392b")},
                               {"students", std::to_string(n)},
                               {"case", str(c, "case")},
                               {"hidden", flag(c, "hidden")},
                               {"student", str(c["example"], "student")},
                               {"message", str(c["example"], "message")}});
  }
  return HtmlObject{{"name", task_name(t)}, {"mistakes", mistakes}, {"cases", cases}};
}

// Did not compile, timed out, crashed: how many of each kind.
HtmlList html_kinds(const Json& s) {
  HtmlList kinds;
  for (const Json& k : s["failure_kinds"])
    kinds.push_back(HtmlObject{{"bar", css_bar(num(k, "share"), "#c0392b")},
                               {"share", percent(num(k, "share"))},
                               {"kind", str(k, "kind")},
                               {"students", students(k.value("students", 0u))}});
  return kinds;
}

// The instructor's lists: who did not compile, timed out or crashed, could not be graded, or
// handed in without a task file.
void html_instructor_lists(HtmlData& page, const Json& s) {
  HtmlList compile, timed_out, not_graded, missing;
  for (const Json& c : s["did_not_compile"])
    compile.push_back(HtmlObject{{"student", str(c, "student")},
                                 {"file", str(c, "file")},
                                 {"what", str(c, "what")},
                                 {"has_message", !str(c, "message").empty()},
                                 {"message", str(c, "message")}});
  for (const Json& a : s["timed_out_or_crashed"])
    timed_out.push_back(HtmlObject{{"student", str(a, "student")},
                                   {"abnormal", str(a, "abnormal")},
                                   {"cases", std::to_string(a.value("cases", 0))},
                                   {"tests", a.value("cases", 0) == 1 ? "test" : "tests"},
                                   {"first_case", str(a, "first_case")},
                                   {"message", str(a, "message")}});
  for (const Json& g : s["could_not_grade"])
    not_graded.push_back(HtmlObject{
        {"student", str(g, "student")}, {"status", str(g, "status")}, {"error", str(g, "error")}});
  const Json& miss = s["missing_files"];
  for (const Json& m : miss["students"]) {
    HtmlList files;
    for (const Json& f : m["files"]) files.push_back(f.get<std::string>());
    missing.push_back(HtmlObject{{"student", str(m, "student")}, {"files", files}});
  }
  std::string by_file;
  for (const Json& f : miss["by_file"])
    by_file += (by_file.empty() ? "" : ", ") + str(f, "file") + " " +
               std::to_string(f.value("students", 0));
  page.set("has_did_not_compile", !compile.empty());
  page.set("did_not_compile", compile);
  page.set("has_timed_out", !timed_out.empty());
  page.set("timed_out", timed_out);
  page.set("has_could_not_grade", !not_graded.empty());
  page.set("could_not_grade", not_graded);
  page.set("has_missing", !missing.empty());
  page.set("missing", missing);
  page.set("missing_students", students(miss["students"].size()));
  page.set("missing_by_file", by_file);
}

}  // namespace

std::string class_html(const Json& s, ClassView view) {
  const bool lecture = view == ClassView::Lecture;
  HtmlData page;
  page.set("title", title_of(s));
  page.set("lecture", lecture);
  page.set("students", std::to_string(s.value("students", 0)));
  page.set("graded", std::to_string(s.value("graded", 0)));
  page.set("not_graded", std::to_string(s.value("not_graded", 0)));
  html_scores(page, s);
  const double graded = std::max(1, s.value("graded", 0));
  HtmlList failed;
  for (const Json& t : s["tasks"])
    if (task_failed(t))
      failed.push_back(lecture ? html_lecture_task(t) : html_instructor_task(t, graded));
  page.set("failed_tasks", failed);
  const std::string fine = tasks_without_failure(s);
  page.set("has_fine", !fine.empty());
  page.set("fine", fine);
  page.set("kinds", html_kinds(s));
  if (!lecture) html_instructor_lists(page, s);
  return render_html(class_html_template(), "class.html.mustache", page);
}

}  // namespace jelly::grade
