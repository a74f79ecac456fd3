#include "class/class_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "class/class_report_fields.hpp"
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
std::string hs(const Json& j, const char* key) { return html_escape(str(j, key)); }

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

constexpr const char* kStyle = R"(<style>
body{font-family:"DejaVu Sans",Arial,sans-serif;font-size:24px;line-height:1.35;margin:32px 48px;color:#111;background:#fff}
h1{font-size:46px;margin:0 0 8px}h2{font-size:36px;margin:40px 0 12px;border-bottom:3px solid #ccc}
h3{font-size:28px;margin:28px 0 8px}.note{color:#a33;font-style:italic}.lecture{color:#555;font-style:italic}
table{border-collapse:collapse;width:100%}td,th{padding:6px 12px;border-bottom:1px solid #ddd;text-align:left;vertical-align:top}
th{font-size:20px;color:#555}td.fm{white-space:nowrap}.dim{color:#777;font-style:italic}td.n{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
.bar{display:inline-block;width:220px;height:22px;background:#eee;vertical-align:middle;margin-right:10px}
.bar span{display:block;height:100%}
.big{font-size:30px}.msg{font-family:"DejaVu Sans Mono",monospace;font-size:19px;white-space:pre-wrap;overflow-wrap:anywhere;color:#333}
.tag{font-size:17px;background:#fbe3c2;color:#7a4a00;padding:1px 8px;border-radius:8px;margin-left:8px}
.warn{background:#fff3f3;border-left:8px solid #c33;padding:10px 16px;font-size:28px}
ul{padding-left:28px}li{margin:6px 0}
</style>)";

void html_scores(std::ostringstream& o, const Json& s) {
  const Json& score = s["score"];
  o << "<h2>Scores</h2>\n<p class=\"big\">Mean <b>" << pts(num(score, "mean")) << "</b>, median <b>"
    << pts(num(score, "median")) << "</b> of " << pts(num(score, "max_score"))
    << "; full marks: <b>" << score.value("full_marks", 0) << "</b> of " << score.value("count", 0)
    << " (" << percent(num(score, "full_marks_share")) << ")</p>\n"
    << svg_histogram(score["histogram"], 1100, 320, true) << "\n";
  o << "<h2>Tasks</h2>\n<table><tr><th>Task</th><th>Points</th><th>Mean</th><th>Median</th>"
       "<th>Full marks</th><th>Scores (0–100%)</th></tr>\n";
  for (const Json& t : s["tasks"]) {
    const Json& d = t["scores"];
    o << "<tr><td>" << h(task_name(t)) << "</td><td class=\"n\">" << pts(num(d, "max_score"))
      << "</td>";
    if (num(d, "max_score") <= 0.0) {  // a task of no points (a course scene): nothing to compare
      o << "<td colspan=\"4\" class=\"dim\">no points: its tests are listed below</td></tr>\n";
      continue;
    }
    o << "<td class=\"n\">" << pts(num(d, "mean")) << "</td><td class=\"n\">"
      << pts(num(d, "median")) << "</td><td class=\"fm\">"
      << css_bar(num(d, "full_marks_share"), "#2e8b57") << percent(num(d, "full_marks_share"))
      << "</td><td>" << svg_histogram(d["histogram"], 220, 44, false) << "</td></tr>\n";
  }
  o << "</table>\n";
}

void html_lecture_tasks(std::ostringstream& o, const Json& s) {
  o << "<h2>What went wrong, task by task</h2>\n<p>The mistakes the grader recognised (in the "
       "words of the hints) and the tests failed, most frequent first. Runs that did not "
       "compile, timed out or crashed are counted below.</p>\n";
  for (const Json& t : s["tasks"]) {
    if (!task_failed(t)) continue;
    o << "<h3>" << h(task_name(t)) << "</h3>\n<table>\n";
    for (const Line& l : lecture_lines(t))
      o << "<tr><td class=\"n\">" << css_bar(l.share, "#c0392b") << percent(l.share)
        << "</td><td><b>" << h(l.what) << "</b> <span class=\"dim\">("
        << students(static_cast<std::size_t>(l.students)) << ")</span>"
        << (l.example.empty() ? "" : "<div class=\"msg\">e.g. " + h(l.example) + "</div>")
        << "</td></tr>\n";
    o << "</table>\n";
  }
}

void html_instructor_tasks(std::ostringstream& o, const Json& s) {
  const double graded = std::max(1, s.value("graded", 0));
  o << "<h2>What failed, task by task</h2>\n<p>The mistakes the grader recognised (hints) and "
       "the tests that failed, most frequent first: how many students failed each, and one "
       "example (the first such student by id, their first failure). Timed-out and crashed runs "
       "and files that did not compile are listed below.</p>\n";
  for (const Json& t : s["tasks"]) {
    if (!task_failed(t)) continue;
    o << "<h3>" << h(task_name(t)) << "</h3>\n<table>\n";
    for (const Json& m : t["known_mistakes"])
      o << "<tr><td class=\"n\">" << css_bar(num(m, "share"), "#c0392b") << m.value("students", 0)
        << "</td><td><b>" << hs(m, "mistake")
        << "</b><span class=\"tag\">known mistake</span></td></tr>\n";
    for (const Json& c : t["failed_cases"]) {
      const int n = c.value("students", 0);
      o << "<tr><td class=\"n\">" << css_bar(n / graded, "#c0392b") << n << "</td><td><b>"
        << hs(c, "case") << "</b>" << (flag(c, "hidden") ? "<span class=\"tag\">hidden</span>" : "")
        << "<div class=\"msg\">" << hs(c["example"], "student") << ": "
        << hs(c["example"], "message") << "</div></td></tr>\n";
    }
    o << "</table>\n";
  }
}

void html_kinds(std::ostringstream& o, const Json& s) {
  o << "<h2>Did not compile, timed out, crashed</h2>\n";
  if (s["failure_kinds"].empty()) o << "<p>None.</p>\n";
  o << "<table>\n";
  for (const Json& k : s["failure_kinds"])
    o << "<tr><td class=\"n\">" << css_bar(num(k, "share"), "#c0392b") << percent(num(k, "share"))
      << "</td><td><b>" << hs(k, "kind") << "</b> <span class=\"dim\">("
      << students(k.value("students", 0u)) << ")</span></td></tr>\n";
  o << "</table>\n";
}

void html_instructor_lists(std::ostringstream& o, const Json& s) {
  auto none = [&](const Json& list) {
    if (list.empty()) o << "<p>None.</p>\n";
    return list.empty();
  };
  o << "<h2>Did not compile</h2>\n";
  if (!none(s["did_not_compile"])) {
    o << "<ul>\n";
    for (const Json& c : s["did_not_compile"])
      o << "<li><b>" << hs(c, "student") << "</b>: " << hs(c, "file") << " " << hs(c, "what")
        << (str(c, "message").empty() ? "" : "<div class=\"msg\">" + hs(c, "message") + "</div>")
        << "</li>\n";
    o << "</ul>\n";
  }
  o << "<h2>Timed out or crashed</h2>\n";
  if (!none(s["timed_out_or_crashed"])) {
    o << "<ul>\n";
    for (const Json& a : s["timed_out_or_crashed"])
      o << "<li><b>" << hs(a, "student") << "</b>: " << hs(a, "abnormal") << " in "
        << a.value("cases", 0) << (a.value("cases", 0) == 1 ? " test" : " tests") << ", first "
        << hs(a, "first_case") << "<div class=\"msg\">" << hs(a, "message") << "</div></li>\n";
    o << "</ul>\n";
  }
  o << "<h2>Could not be graded</h2>\n";
  if (!none(s["could_not_grade"])) {
    o << "<ul>\n";
    for (const Json& g : s["could_not_grade"])
      o << "<li><b>" << hs(g, "student") << "</b> (" << hs(g, "status") << ")<div class=\"msg\">"
        << hs(g, "error") << "</div></li>\n";
    o << "</ul>\n";
  }
  o << "<h2>Missing task files</h2>\n";
  const Json& miss = s["missing_files"];
  if (none(miss["students"])) return;
  o << "<p class=\"warn\">Missing task files: <b>" << students(miss["students"].size()) << "</b> (";
  bool first = true;
  for (const Json& f : miss["by_file"]) {
    o << (first ? "" : ", ") << hs(f, "file") << " " << f.value("students", 0);
    first = false;
  }
  o << "), graded with the unchanged stub in their place.</p>\n<ul>\n";
  for (const Json& m : miss["students"]) {
    o << "<li><b>" << hs(m, "student") << "</b>:";
    for (const Json& f : m["files"]) o << " " << h(f.get<std::string>());
    o << "</li>\n";
  }
  o << "</ul>\n";
}

}  // namespace

std::string class_html(const Json& s, ClassView view) {
  const bool lecture = view == ClassView::Lecture;
  std::ostringstream o;
  const std::string title = h(title_of(s));
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>What the class got "
       "wrong: "
    << title << "</title>\n"
    << kStyle << "</head><body>\n"
    << "<h1>What the class got wrong: " << title << "</h1>\n"
    << (lecture ? "<p class=\"lecture\">For the lecture: it names no student and shows no hidden "
                  "test. The instructor's view is class-instructor.html.</p>\n"
                : "<p class=\"note\">Instructor-only: this report names students and hidden "
                  "tests. Project class.html instead.</p>\n")
    << "<p class=\"big\">" << s.value("students", 0) << " submissions: " << s.value("graded", 0)
    << " graded, " << s.value("not_graded", 0) << " could not be graded.</p>\n";
  html_scores(o, s);
  if (lecture)
    html_lecture_tasks(o, s);
  else
    html_instructor_tasks(o, s);
  const std::string fine = tasks_without_failure(s);
  if (!fine.empty()) o << "<p><b>No test failed:</b> " << h(fine) << "</p>\n";
  html_kinds(o, s);
  if (!lecture) html_instructor_lists(o, s);
  o << "</body></html>\n";
  return o.str();
}

}  // namespace jelly::grade
