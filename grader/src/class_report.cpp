#include "class_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "commands/common.hpp"
#include "text_safety.hpp"

namespace jelly::grade {

namespace {

constexpr const char* kSummaryFormat = "jelly-grade class report 1";
constexpr int kBins = 11;                   // 0–9 %, 10–19 %, ..., 90–99 %, and full marks
constexpr std::size_t kMessageBytes = 300;  // of an example message

// Record fields read defensively: a record is our own file, but one edited by hand must not turn
// the class report into a crash, and its text is shown only through safe_text.
std::string str(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? safe_text(it->get<std::string>()) : std::string();
}
double num(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : 0.0;
}
bool flag(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}
const Json& list(const Json& j, const char* key) {
  static const Json empty = Json::array();
  const auto it = j.find(key);
  return it != j.end() && it->is_array() ? *it : empty;
}

double round2(double v) { return std::round(v * 100.0) / 100.0; }

std::string percent(double share) {
  char b[16];
  std::snprintf(b, sizeof b, "%.0f%%", share * 100.0);
  return b;
}

std::string bin_label(int k) {
  return k == kBins - 1 ? "100%" : std::to_string(10 * k) + "–" + std::to_string(10 * k + 9) + "%";
}

// The distribution of scores out of their maxima: count, mean, median, min, max, full marks and
// the 11 bins (floor of the percentage by tens, full marks alone).
Json distribution(const std::vector<std::pair<double, double>>& scores) {
  std::vector<double> s;
  std::vector<int> bins(kBins, 0);
  int full = 0;
  double max_score = 0.0;
  for (const auto& [score, max] : scores) {
    s.push_back(score);
    max_score = std::max(max_score, max);
    int k = 0;
    if (max > 0.0 && score >= max - 1e-9) {
      k = kBins - 1;
      ++full;
    } else if (max > 0.0) {
      k = std::clamp(static_cast<int>(std::floor(score / max * 10.0 + 1e-9)), 0, kBins - 2);
    }
    ++bins[k];
  }
  std::sort(s.begin(), s.end());
  double sum = 0.0;
  for (double v : s) sum += v;
  const std::size_t n = s.size();
  Json d;
  d["count"] = n;
  d["max_score"] = round2(max_score);
  d["mean"] = n ? round2(sum / static_cast<double>(n)) : 0.0;
  d["median"] = n ? round2(n % 2 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2.0) : 0.0;
  d["min"] = n ? round2(s.front()) : 0.0;
  d["max"] = n ? round2(s.back()) : 0.0;
  d["full_marks"] = full;
  d["full_marks_share"] = n ? std::round(1000.0 * full / static_cast<double>(n)) / 1000.0 : 0.0;
  Json h = Json::array();
  for (int k = 0; k < kBins; ++k) h.push_back({{"label", bin_label(k)}, {"count", bins[k]}});
  d["histogram"] = h;
  return d;
}

// The line of a compiler's message worth showing: its first error line (else its first line).
std::string first_error_line(const std::string& message) {
  std::istringstream in(message);
  std::string line, first;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.find("error") != std::string::npos) return safe_excerpt(line, kMessageBytes);
  }
  return safe_excerpt(first, kMessageBytes);
}

std::string first_message(const Json& c) {
  for (const Json& f : list(c, "failures"))
    if (f.is_string()) return safe_excerpt(f.get<std::string>(), kMessageBytes);
  return "failed";
}

}  // namespace

Json class_summary(const std::vector<Json>& in, const CaseBook& book) {
  // In id order whatever order the records came in: the first student by id is the example.
  std::vector<Json> records = in;
  std::stable_sort(records.begin(), records.end(),
                   [](const Json& a, const Json& b) { return str(a, "id") < str(b, "id"); });
  std::map<std::string, std::size_t> case_order;
  for (std::size_t i = 0; i < book.cases.size(); ++i) case_order[book.cases[i].id] = i;

  Json s;
  s["format"] = kSummaryFormat;
  s["assignment"] = records.empty() ? "" : str(records.front(), "assignment");
  s["students"] = records.size();
  std::vector<std::pair<double, double>> totals;
  std::map<std::string, std::vector<std::pair<double, double>>> task_scores;
  struct Group {
    std::string task;
    bool hidden = false;
    int count = 0;
    std::string student, message;
  };
  std::map<std::string, Group> groups;
  Json compile = Json::array(), abnormal = Json::array(), not_graded = Json::array(),
       missing = Json::array();
  std::map<std::string, int> missing_by_file;
  for (const Json& r : records) {
    const std::string id = str(r, "id");
    if (str(r, "status") != "graded") {
      not_graded.push_back({{"student", id},
                            {"name", str(r, "name")},
                            {"status", str(r, "status")},
                            {"error", safe_excerpt(str(r, "error"), kMessageBytes)}});
      continue;
    }
    totals.emplace_back(num(r, "score"), num(r, "max_score"));
    for (const Json& t : list(r, "tasks"))
      task_scores[str(t, "id")].emplace_back(num(t, "score"), num(t, "max_score"));
    for (const Json& f : list(r, "failed_files"))
      compile.push_back({{"student", id},
                         {"file", str(f, "file")},
                         {"what", str(f, "what")},
                         {"message", first_error_line(str(f, "message"))}});
    if (r.contains("compiled") && !flag(r, "compiled") && list(r, "failed_files").empty())
      compile.push_back(
          {{"student", id}, {"file", ""}, {"what", "did not compile"}, {"message", ""}});
    if (!list(r, "missing_files").empty()) {
      Json files = Json::array();
      for (const Json& f : list(r, "missing_files"))
        if (f.is_string()) {
          files.push_back(safe_text(f.get<std::string>()));
          ++missing_by_file[safe_text(f.get<std::string>())];
        }
      missing.push_back({{"student", id}, {"files", files}});
    }
    // Abnormal runs, one line per student and kind (a loop in a function every test calls
    // times out in every test: one line, with how many).
    std::vector<std::string> kinds;
    std::map<std::string, Json> by_kind;
    for (const Json& c : list(r, "cases")) {
      if (str(c, "status") != "failed" || flag(c, "not_run")) continue;
      const std::string kind = str(c, "abnormal");
      if (!kind.empty()) {
        if (!by_kind.count(kind)) {
          kinds.push_back(kind);
          by_kind[kind] = {{"student", id},
                           {"abnormal", kind},
                           {"cases", 0},
                           {"first_case", str(c, "id")},
                           {"task", str(c, "task")},
                           {"message", first_message(c)}};
        }
        by_kind[kind]["cases"] = by_kind[kind]["cases"].get<int>() + 1;
        continue;  // listed with the abnormal runs, not among the failed checks
      }
      Group& g = groups[str(c, "id")];
      if (g.count++ == 0) {
        g.task = str(c, "task");
        g.hidden = flag(c, "hidden");
        g.student = id;
        g.message = first_message(c);
      }
    }
    for (const std::string& k : kinds) abnormal.push_back(by_kind[k]);
  }
  s["graded"] = totals.size();
  s["not_graded"] = not_graded.size();
  s["score"] = distribution(totals);

  // Failed cases most frequent first, ties in the case book's order (then by id).
  std::vector<std::string> ids;
  for (const auto& [id, g] : groups) ids.push_back(id);
  std::stable_sort(ids.begin(), ids.end(), [&](const std::string& a, const std::string& b) {
    if (groups[a].count != groups[b].count) return groups[a].count > groups[b].count;
    const std::size_t oa = case_order.count(a) ? case_order[a] : book.cases.size();
    const std::size_t ob = case_order.count(b) ? case_order[b] : book.cases.size();
    return oa != ob ? oa < ob : a < b;
  });
  Json tasks = Json::array();
  std::vector<std::string> task_ids;
  for (const TaskSpec& t : book.rubric.tasks) task_ids.push_back(t.id);
  for (const auto& [id, scores] : task_scores)  // a task the records have and the book has not
    if (std::find(task_ids.begin(), task_ids.end(), id) == task_ids.end()) task_ids.push_back(id);
  for (const std::string& tid : task_ids) {
    const TaskSpec* spec = nullptr;
    for (const TaskSpec& t : book.rubric.tasks)
      if (t.id == tid) spec = &t;
    Json t;
    t["id"] = tid;
    t["title"] = spec ? spec->title : "";
    t["bonus"] = spec && spec->bonus;
    t["scores"] = distribution(task_scores[tid]);
    Json failed = Json::array();
    for (const std::string& cid : ids) {
      const Group& g = groups[cid];
      if (g.task != tid) continue;
      std::string title;
      for (const CaseSpec& c : book.cases)
        if (c.id == cid) title = c.title;
      failed.push_back({{"case", cid},
                        {"title", title},
                        {"hidden", g.hidden},
                        {"students", g.count},
                        {"example", {{"student", g.student}, {"message", g.message}}}});
    }
    t["failed_cases"] = failed;
    tasks.push_back(t);
  }
  s["tasks"] = tasks;
  s["did_not_compile"] = compile;
  s["timed_out_or_crashed"] = abnormal;
  s["could_not_grade"] = not_graded;
  Json by_file = Json::array();
  for (const std::string& f : [&] {
         std::vector<std::string> order;  // the assignment's file order where the book has it
         for (const TaskSpec& t : book.rubric.tasks)
           if (missing_by_file.count(t.file) &&
               std::find(order.begin(), order.end(), t.file) == order.end())
             order.push_back(t.file);
         for (const auto& [file, n] : missing_by_file)
           if (std::find(order.begin(), order.end(), file) == order.end()) order.push_back(file);
         return order;
       }())
    by_file.push_back({{"file", f}, {"students", missing_by_file[f]}});
  s["missing_files"] = {{"students", missing}, {"by_file", by_file}};
  return s;
}

// ---- class.md ----------------------------------------------------------------------------------

namespace {

std::string md(const Json& j, const char* key) { return markdown_inline(str(j, key)); }

std::string md_bar(int count, int most) {
  const int width = most > 0 ? static_cast<int>(std::lround(30.0 * count / most)) : 0;
  std::string bar;
  for (int i = 0; i < width; ++i) bar += "█";
  return bar;
}

std::string students(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " student" : " students");
}

std::string task_name(const Json& t) {
  return str(t, "id") + (str(t, "title").empty() ? "" : " " + str(t, "title")) +
         (flag(t, "bonus") ? " (bonus)" : "");
}

std::string dist_line(const Json& d) {
  const int n = d.value("count", 0);
  return "mean " + pts(num(d, "mean")) + ", median " + pts(num(d, "median")) + " of " +
         pts(num(d, "max_score")) + "; full marks: " + std::to_string(d.value("full_marks", 0)) +
         " of " + std::to_string(n) + " (" + percent(num(d, "full_marks_share")) + ")";
}

}  // namespace

std::string class_markdown(const Json& s) {
  std::ostringstream o;
  const Json& score = s["score"];
  o << "# What the class got wrong: " << md(s, "assignment") << "\n\n"
    << "*Instructor-only: this report names hidden tests. Do not hand it to students.*\n\n"
    << s.value("students", 0) << " submissions: " << s.value("graded", 0) << " graded, "
    << s.value("not_graded", 0) << " could not be graded.\n\n";

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

  o << "\n## What failed, task by task\n\n"
    << "The tests that failed, most frequent first, with how many students failed each and one "
       "example (the first such student by id, their first failure). Timed-out and crashed runs "
       "and files that did not compile are listed below, not here.\n";
  for (const Json& t : s["tasks"]) {
    o << "\n### " << markdown_inline(task_name(t)) << "\n\n";
    if (t["failed_cases"].empty()) {
      o << "No test failed.\n";
      continue;
    }
    o << "| Test | Students | Example |\n|---|---:|---|\n";
    for (const Json& c : t["failed_cases"])
      o << "| " << md(c, "case") << (flag(c, "hidden") ? " (hidden)" : "") << " | "
        << c.value("students", 0) << " | " << md(c["example"], "student") << ": "
        << md(c["example"], "message") << " |\n";
  }

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
  if (!none(miss["students"])) {
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
  return o.str();
}

// ---- class.html --------------------------------------------------------------------------------

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
h3{font-size:28px;margin:28px 0 8px}.note{color:#a33;font-style:italic}
table{border-collapse:collapse;width:100%}td,th{padding:6px 12px;border-bottom:1px solid #ddd;text-align:left;vertical-align:top}
th{font-size:20px;color:#555}td.fm{white-space:nowrap}.dim{color:#777;font-style:italic}td.n{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
.bar{display:inline-block;width:220px;height:22px;background:#eee;vertical-align:middle;margin-right:10px}
.bar span{display:block;height:100%}
.big{font-size:30px}.msg{font-family:"DejaVu Sans Mono",monospace;font-size:19px;white-space:pre-wrap;overflow-wrap:anywhere;color:#333}
.tag{font-size:17px;background:#fbe3c2;color:#7a4a00;padding:1px 8px;border-radius:8px;margin-left:8px}
.warn{background:#fff3f3;border-left:8px solid #c33;padding:10px 16px;font-size:28px}
ul{padding-left:28px}li{margin:6px 0}
</style>)";

}  // namespace

std::string class_html(const Json& s) {
  std::ostringstream o;
  const Json& score = s["score"];
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>What the class got "
       "wrong: "
    << hs(s, "assignment") << "</title>\n"
    << kStyle << "</head><body>\n"
    << "<h1>What the class got wrong: " << hs(s, "assignment") << "</h1>\n"
    << "<p class=\"note\">Instructor-only: this report names hidden tests. Do not hand it to "
       "students.</p>\n"
    << "<p class=\"big\">" << s.value("students", 0) << " submissions: " << s.value("graded", 0)
    << " graded, " << s.value("not_graded", 0) << " could not be graded.</p>\n";

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
    if (num(d, "max_score") <= 0.0) {  // a task of no points (A1.COURSE): nothing to compare
      o << "<td colspan=\"4\" class=\"dim\">no points: its tests are listed below</td></tr>\n";
      continue;
    }
    o << "<td class=\"n\">" << pts(num(d, "mean")) << "</td><td class=\"n\">"
      << pts(num(d, "median")) << "</td><td class=\"fm\">"
      << css_bar(num(d, "full_marks_share"), "#2e8b57") << percent(num(d, "full_marks_share"))
      << "</td><td>" << svg_histogram(d["histogram"], 220, 44, false) << "</td></tr>\n";
  }
  o << "</table>\n";

  const double graded = std::max(1, s.value("graded", 0));
  o << "<h2>What failed, task by task</h2>\n<p>The tests that failed, most frequent first: how "
       "many students failed each, and one example (the first such student by id, their first "
       "failure). Timed-out and crashed runs and files that did not compile are listed "
       "below.</p>\n";
  for (const Json& t : s["tasks"]) {
    o << "<h3>" << h(task_name(t)) << "</h3>\n";
    if (t["failed_cases"].empty()) {
      o << "<p>No test failed.</p>\n";
      continue;
    }
    o << "<table>\n";
    for (const Json& c : t["failed_cases"]) {
      const int n = c.value("students", 0);
      o << "<tr><td class=\"n\">" << css_bar(n / graded, "#c0392b") << n << "</td><td><b>"
        << hs(c, "case") << "</b>" << (flag(c, "hidden") ? "<span class=\"tag\">hidden</span>" : "")
        << "<div class=\"msg\">" << hs(c["example"], "student") << ": "
        << hs(c["example"], "message") << "</div></td></tr>\n";
    }
    o << "</table>\n";
  }

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
  if (!none(miss["students"])) {
    o << "<p class=\"warn\">Missing task files: <b>" << students(miss["students"].size())
      << "</b> (";
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
  o << "</body></html>\n";
  return o.str();
}

}  // namespace jelly::grade
