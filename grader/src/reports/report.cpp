#include "reports/report.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "inputs/files.hpp"
#include "jelly/cli_common/text_table.hpp"
#include "reports/html_page.hpp"
#include "reports/plot.hpp"
#include "reports/points.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

namespace {

// "72.50 / 80.00", and with a bonus task "72.50 / 80.00 + bonus 5.00 / 5.00": the bonus is never
// part of the total it is added to (an assignment without one reads as before).
std::string total_text(const GradeReport& r) {
  std::string t = pts(r.score) + " / " + pts(r.max_score);
  if (r.has_bonus()) t += " + bonus " + pts(r.bonus_score) + " / " + pts(r.bonus_max);
  return t;
}

// A bonus task's points in a table: "+5.00 / 5.00 bonus".
std::string task_points(const TaskResult& t) {
  if (t.spec->bonus) return "+" + pts(t.score) + " / " + pts(t.max_score) + " bonus";
  return pts(t.score) + " / " + pts(t.max_score);
}

std::string case_name(const CaseResult& c, const TaskSpec* t) {
  return c.spec->task + (t ? " " + t->title : std::string()) + ": " + c.spec->title + " [" +
         c.spec->id + "]";
}

// "forces.cpp did not compile: its tasks A1.T4, A1.T5 (20.00 points) score 0; ..."
std::string file_failure_headline(const GradeReport& r, const FileFailure& f) {
  std::string tasks;
  for (const std::string& t : f.tasks) tasks += (tasks.empty() ? "" : ", ") + t;
  return f.file + " " + f.what + ": its tasks " + tasks + " (" + pts(f.points) +
         " points) score 0" +
         (r.build.ok ? "; the other files' tasks were graded with the stub of " + f.file +
                           " in its place, and keep their points"
                     : "");
}

// What the compile step says, for the plain-text formats (terminal, Gradescope, PrairieLearn,
// JUnit): each unusable file with its cost, then the compiler's messages about it set apart (they
// quote the student's code: no line of them may pass for the report's own).
std::string compile_summary(const GradeReport& r) {
  if (r.compiled) return "Your code compiled.\n";
  std::string o;
  for (const FileFailure& f : r.failed_files)
    o += file_failure_headline(r, f) + ".\n  the compiler's messages:\n" +
         set_apart(f.message, "    ");
  if (r.build.ok && r.build.runner.empty())
    o += "Your files do not link together; each file was graded alone with the other files' "
         "stubs. The linker's messages:\n" +
         set_apart(r.build.link_errors, "    ");
  if (o.empty())
    o = "Your code did not compile. The compiler's messages:\n" + set_apart(r.build.errors, "    ");
  return o;
}

// Tests whose output is shown in the reports: the failed ones first, at most `n`.
std::vector<const CaseResult*> printed_cases(const GradeReport& r, std::size_t n) {
  std::vector<const CaseResult*> out;
  for (int pass = 0; pass < 2; ++pass)
    for (const CaseResult& c : r.cases)
      if (!c.printed.empty() && (c.status == "failed") == (pass == 0) && out.size() < n)
        out.push_back(&c);
  return out;
}

// XML and HTML text and attributes (the report's text is valid UTF-8 already: make_safe).
std::string xml_escape(const std::string& s) { return html_escape(s); }

// ---- The report's layout, shared by every format: tasks in rubric order; in each task its failed
// tests first (the first one expanded, with its hint), then its passed tests (collapsed).

// The cases of a task that ran, failed ones first, each group in case-book order.
std::vector<const CaseResult*> ordered_cases(const TaskResult& t) {
  std::vector<const CaseResult*> out;
  for (int pass = 0; pass < 2; ++pass)
    for (const CaseResult* c : t.cases)
      if (c->status != "skipped" && (c->status == "failed") == (pass == 0)) out.push_back(c);
  return out;
}

// Every case that ran, in the report's order (the order of every format's list of tests).
std::vector<const CaseResult*> report_order(const GradeReport& r) {
  std::vector<const CaseResult*> out;
  for (const TaskResult& t : r.tasks)
    for (const CaseResult* c : ordered_cases(t)) out.push_back(c);
  return out;
}

// The anchor of a task's section: "task-<id>-t13" for task <ID>.T13 (ids are letters, digits and
// dots).
std::string task_anchor(const TaskResult& t) {
  std::string a = "task-";
  for (const char ch : t.spec->id)
    a += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : '-';
  return a;
}

// The task whose test records the course scene's centre-of-mass curve (its section holds the plot
// and the frames), or nullptr.
const TaskResult* course_scene_task(const GradeReport& r) {
  for (const TaskResult& t : r.tasks)
    for (const CaseResult* c : t.cases)
      if (c->status != "skipped" && c->reference.is_object() && c->reference.contains("com_time"))
        return &t;
  return nullptr;
}

struct TaskCount {
  std::size_t run = 0, passed = 0;
};
TaskCount count(const TaskResult& t) {
  TaskCount n;
  for (const CaseResult* c : t.cases)
    if (c->status != "skipped") ++n.run, n.passed += c->status == "passed";
  return n;
}

// "this looks like A" / "this looks like A, or B": the hint of a failed test (hints.hpp).
std::string hint_text(const CaseResult& c) {
  if (c.hints.empty()) return "";
  std::string h = "this looks like ";
  for (std::size_t i = 0; i < c.hints.size(); ++i) h += (i ? ", or " : "") + c.hints[i];
  return h + " (a mistake the grader knows; check that part of your code)";
}

// The handout page that explains a report's terms, and the contracts its messages cite by name.
struct TermsPage {
  std::string path;                    ///< "" when the assignment has none
  std::vector<std::string> contracts;  ///< the manifest's `contracts`
};

TermsPage terms_page_of(const GradeReport& r) { return {r.terms_page, r.contracts}; }

// A term of a message that the handout page explains: its text in the message, its anchor there.
struct Term {
  std::size_t at = 0, size = 0;
  std::string anchor;
};

// The terms in `text`: "tolerance 'force'" (a tolerance's name: lower-case letters and _ only, so
// a student's text cannot make an anchor of anything else) and "contract §9" (with "physics "
// before it: the physics contract, anchor contract-9; with the name of one of the assignment's
// `contracts` before it: that contract, anchor <name>-contract-9).
std::vector<Term> find_terms(const std::string& text, const std::vector<std::string>& contracts) {
  std::vector<Term> out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    static const std::string tol = "tolerance '";
    if (text.compare(i, tol.size(), tol) == 0) {
      std::size_t e = i + tol.size();
      while (e < text.size() && e - i - tol.size() < 32 &&
             ((text[e] >= 'a' && text[e] <= 'z') || text[e] == '_'))
        ++e;
      if (e < text.size() && text[e] == '\'' && e > i + tol.size()) {
        out.push_back(
            {i, e + 1 - i, "tolerance-" + text.substr(i + tol.size(), e - i - tol.size())});
        i = e;
        continue;
      }
    }
    static const std::string con = "contract §";
    if (text.compare(i, con.size(), con) == 0) {
      std::size_t e = i + con.size();
      while (e < text.size() && e - i - con.size() < 2 && text[e] >= '0' && text[e] <= '9') ++e;
      if (e > i + con.size()) {
        std::string prefix = "contract-";
        std::size_t start = i;
        for (const std::string& name : contracts) {
          const std::string who = name + " ";
          if (i >= who.size() && text.compare(i - who.size(), who.size(), who) == 0) {
            start = i - who.size();
            prefix = name + "-contract-";
          }
        }
        static const std::string physics = "physics ";
        if (i >= physics.size() && text.compare(i - physics.size(), physics.size(), physics) == 0)
          start = i - physics.size();
        out.push_back({start, e - start, prefix + text.substr(i + con.size(), e - i - con.size())});
        i = e - 1;
      }
    }
  }
  return out;
}

// `text` escaped by `escape`, each term a link to `page`#anchor made by `link(shown, href)`.
template <class Escape, class Link>
std::string with_links(const std::string& text, const TermsPage& page, Escape escape, Link link) {
  if (page.path.empty()) return escape(text);
  std::string out;
  std::size_t from = 0;
  for (const Term& t : find_terms(text, page.contracts)) {
    out += escape(text.substr(from, t.at - from));
    out += link(escape(text.substr(t.at, t.size)), page.path + "#" + t.anchor);
    from = t.at + t.size;
  }
  return out + escape(text.substr(from));
}

std::string html_with_links(const std::string& text, const TermsPage& page) {
  return with_links(text, page, xml_escape, [](const std::string& shown, const std::string& href) {
    return "<a href=\"" + xml_escape(href) + "\">" + shown + "</a>";
  });
}

std::string markdown_with_links(const std::string& text, const TermsPage& page) {
  return with_links(text, page, markdown_inline,
                    [](const std::string& shown, const std::string& href) {
                      return "[" + shown + "](" + href + ")";
                    });
}

// The plain-text pointers to the handout for the terms of `lines` (terminal, Gradescope): one
// "see PAGE#anchor" per distinct term.
std::vector<std::string> term_pointers(const std::vector<std::string>& lines,
                                       const TermsPage& page) {
  std::vector<std::string> out;
  if (page.path.empty()) return out;
  std::set<std::string> seen;
  for (const std::string& l : lines)
    for (const Term& t : find_terms(l, page.contracts))
      if (seen.insert(t.anchor).second) out.push_back(page.path + "#" + t.anchor);
  return out;
}

// A test's output in Gradescope, PrairieLearn and JUnit: its messages (at most six), its hint, the
// handout's words, what it printed.
std::string case_output(const CaseResult& c, const TermsPage& terms_page) {
  std::string o;
  if (c.status == "passed") o = "Passed.\n";
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < c.failures.size() && i < 6; ++i)
    o += "- " + hanging(c.failures[i], "  ") + "\n", shown.push_back(c.failures[i]);
  if (c.failures.size() > 6) o += "- … and " + std::to_string(c.failures.size() - 6) + " more\n";
  if (!c.hints.empty()) o += "Hint: " + hint_text(c) + "\n";
  for (const std::string& p : term_pointers(shown, terms_page)) o += "Words: see " + p + "\n";
  if (!c.printed.empty())
    o += "\nYour code printed (first lines):\n" + set_apart(cut_utf8(c.printed, 1500), "  ");
  return o;
}

// A task's row in the plain-text summary (terminal and Gradescope's output): id, title, points,
// verdict, tests passed; none when none of its tests ran. With `public_only` (Gradescope's output
// while hidden tests are not yet visible) the points and counts are those of the public tests.
std::vector<std::string> task_row(const TaskResult& t, bool public_only) {
  TaskCount n;
  double score = 0.0, max_score = 0.0;
  for (const CaseResult* c : ordered_cases(t))
    if (!public_only || !c->spec->hidden)
      ++n.run, n.passed += c->status == "passed", score += c->score, max_score += c->max_score;
  if (n.run == 0) return {};
  if (!public_only) score = t.score, max_score = t.max_score;
  const bool full = max_score == 0 ? n.passed == n.run : score >= max_score - 1e-9;
  return {t.spec->id,
          t.spec->title,
          (t.spec->bonus ? "+" : "") + pts(score),
          "/",
          pts(max_score),
          full ? (max_score == 0 ? "ok" : "PASS") : "FAIL",
          "(" + std::to_string(n.passed) + "/" + std::to_string(n.run) +
              (public_only ? " public tests)" : " tests)")};
}

// A failed test's messages in the plain-text summary: the first line after the indent, every
// further line (the student's text, an exception's message) set apart below it.
void failure_lines(std::ostream& o, const std::string& message) {
  const std::string indent = "               ";
  o << indent << hanging(message, indent + "  ") << "\n";
}

// The tests of one task under its row: its first failed test expanded (at most two messages
// unless `verbose`, its hint, the handout's words), its other failed tests one line each
// (expanded with `verbose`), its passed tests only with `verbose`.
void task_details(std::ostream& o, const GradeReport& r, const TaskResult& t, bool verbose,
                  bool public_only) {
  std::size_t passed = 0;
  bool first = true;
  for (const CaseResult* c : ordered_cases(t)) {
    if (public_only && c->spec->hidden) continue;
    if (c->status == "failed") {
      o << "           ✗ " << c->spec->title << " [" << c->spec->id << "]\n";
      if (!first && !verbose) continue;  // collapsed: the report files show its messages
      std::vector<std::string> shown;
      for (std::size_t i = 0; i < c->failures.size() && (verbose || i < 2); ++i)
        failure_lines(o, c->failures[i]), shown.push_back(c->failures[i]);
      // Every way this summary is made takes --verbose (jelly-grade grade, tools/selfcheck), and
      // the IDE's selfcheck target (which takes no options) has its twin selfcheck-verbose. One
      // text for every path: the self-check's report is the grader's, line for line.
      if (!verbose && c->failures.size() > 2)
        o << "               (" << c->failures.size() - 2
          << " more: --verbose, or the selfcheck-verbose target)\n";
      if (!c->hints.empty()) o << "               hint: " << hint_text(*c) << "\n";
      for (const std::string& p : term_pointers(shown, terms_page_of(r)))
        o << "               words: see " << p << "\n";
      first = false;
    } else {
      passed += c->status == "passed";
      if (verbose) o << "           ✓ " << c->spec->title << "\n";
    }
  }
  if (!verbose && !first && passed > 0)
    o << "           ✓ " << passed << " passed (--verbose lists them)\n";
}

// The summary of the tasks as text (terminal and Gradescope's output): a row per task, its
// columns as wide as their widest cell (by display width: a title with an en dash, "A–B", lines
// up with one of plain letters), each followed by its tests (task_details).
void task_blocks(std::ostream& o, const GradeReport& r, bool verbose, bool public_only = false) {
  jelly::cli::TextTable table(" ");
  table.align_right(2);
  std::vector<const TaskResult*> shown;
  for (const TaskResult& t : r.tasks) {
    std::vector<std::string> row = task_row(t, public_only);
    if (row.empty()) continue;
    table.add_row(std::move(row));
    shown.push_back(&t);
  }
  for (std::size_t i = 0; i < shown.size(); ++i) {
    o << table.row(i) << "\n";
    task_details(o, r, *shown[i], verbose, public_only);
  }
}

const TaskSpec* task_of(const GradeReport& r, const CaseResult& c) {
  for (const TaskResult& t : r.tasks)
    if (t.spec->id == c.spec->task) return t.spec;
  return nullptr;
}

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) |
                       (static_cast<unsigned char>(in[i + 1]) << 8) |
                       static_cast<unsigned char>(in[i + 2]);
    out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += t[v & 63];
  }
  if (i < in.size()) {
    unsigned v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    out += t[v >> 18], out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// Every text in the report is valid UTF-8 (make_safe); should one not be, it is replaced, never a
// grader error.
std::string dump_json(const Json& j) {
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace

std::string terminal_summary(const GradeReport& r, bool verbose) {
  std::ostringstream o;
  o << "Jelly Lab autograder — " << one_line(r.submission) << " (" << r.visibility << " tests)\n";
  // "none" alone unless the description says more than the name (the self-check says why).
  const bool plain =
      r.isolation_description.empty() || r.isolation_description.rfind("none", 0) == 0;
  o << "  sandbox: " << r.isolation << (plain ? "" : " — ")
    << (plain ? "" : r.isolation_description) << "\n";
  for (const std::string& n : r.notes) o << "  note: " << hanging(n, "        ") << "\n";
  if (!r.compiled) o << "\n" << compile_summary(r);
  o << "\n";
  task_blocks(o, r, verbose);
  o << "\nTotal: " << total_text(r);
  if (r.build.ok) {
    char t[64];
    if (r.prebuilt_runner)
      std::snprintf(t, sizeof t, "   (tests ran in %.1f s; built by CMake)", r.grading_seconds);
    else
      std::snprintf(t, sizeof t, "   (tests ran in %.1f s, compiling took %.1f s)",
                    r.grading_seconds, r.build.seconds);
    o << t;
  }
  o << "\n";
  return o.str();
}

namespace {

// "five" for A1's five files: the number of distinct files the rubric's tasks are in, in words up
// to twelve.
std::string task_file_count(const CaseBook& book) {
  std::set<std::string> files;
  for (const TaskSpec& t : book.rubric.tasks)
    if (!t.file.empty()) files.insert(t.file);
  static const char* const words[] = {"no",    "one",   "two",  "three", "four",   "five",  "six",
                                      "seven", "eight", "nine", "ten",   "eleven", "twelve"};
  return files.size() < std::size(words) ? words[files.size()] : std::to_string(files.size());
}

}  // namespace

Json gradescope_results(const GradeReport& r, const CaseBook& book) {
  Json j;
  // Gradescope's total is the assignment's points (max scores add up to autograded_total); a
  // bonus test has max_score 0 and its score on top, so the score may exceed the total.
  j["score"] = r.has_bonus() ? std::round((r.score + r.bonus_score) * 1e9) / 1e9 : r.score;
  j["execution_time"] = static_cast<long>(std::lround(r.grading_seconds + r.build.seconds));
  std::string out = "Jelly Lab autograder: " + total_text(r) + "\n";
  out += "Sandbox: " + r.isolation + "\n";
  for (const std::string& n : r.notes) out += "Note: " + hanging(n, "      ") + "\n";
  // The summary first, in the terminal's words and order (the tests below follow the same order).
  std::ostringstream tasks;
  const bool public_only = book.rubric.hidden_visibility != "visible";
  task_blocks(tasks, r, false, public_only);
  out += "\n" + tasks.str();
  j["output"] = out;
  // Shown as plain text, whatever Gradescope's default: the outputs quote the student's code and
  // what it printed, which must never be rendered as markup.
  j["output_format"] = "text";
  j["test_output_format"] = "text";
  j["stdout_visibility"] = "hidden";
  j["extra_data"] = {{"isolation", r.isolation},
                     {"isolation_description", r.isolation_description}};
  if (r.has_bonus())
    j["extra_data"]["bonus_score"] = r.bonus_score, j["extra_data"]["bonus_max"] = r.bonus_max;
  Json tests = Json::array();
  Json compile;
  compile["name"] = "Compilation of your " + task_file_count(book) + " task files";
  compile["status"] = r.compiled ? "passed" : "failed";
  compile["output"] = compile_summary(r);
  compile["visibility"] = "visible";
  tests.push_back(compile);
  for (const CaseResult* cp : report_order(r)) {
    const CaseResult& c = *cp;
    Json t;
    const bool bonus = task_of(r, c) && task_of(r, c)->bonus;
    t["name"] = case_name(c, task_of(r, c)) + (bonus ? " (bonus: " + pts(c.max_score) + ")" : "");
    t["score"] = std::round(c.score * 1e6) / 1e6;
    t["max_score"] = bonus ? 0.0 : std::round(c.max_score * 1e6) / 1e6;
    t["status"] = c.status;
    t["output"] = case_output(c, terms_page_of(r));
    t["visibility"] = c.spec->hidden ? book.rubric.hidden_visibility : std::string("visible");
    const TaskSpec* ts = task_of(r, c);
    t["tags"] = Json::array({c.spec->task, ts ? ts->category : std::string()});
    tests.push_back(t);
  }
  j["tests"] = tests;
  return j;
}

Json prairielearn_results(const GradeReport& r) {
  Json j;
  j["gradable"] = r.build.ok;
  j["score"] = r.max_score > 0 ? r.score / r.max_score : 0.0;
  // PrairieLearn's score is a fraction of the question's points; the bonus is named in the
  // message and per test (max_points 0), not folded into the fraction.
  j["message"] = r.build.ok ? "Graded " + total_text(r) : std::string("Your code did not compile.");
  std::string out = "Sandbox: " + r.isolation + "\n";
  for (const std::string& n : r.notes) out += "Note: " + hanging(n, "      ") + "\n";
  if (!r.compiled) out += compile_summary(r);
  j["output"] = out;
  j["isolation"] = r.isolation;
  Json tests = Json::array();
  for (const CaseResult* cp : report_order(r)) {
    const CaseResult& c = *cp;
    Json t;
    const bool bonus = task_of(r, c) && task_of(r, c)->bonus;
    t["name"] = case_name(c, task_of(r, c)) + (bonus ? " (bonus: " + pts(c.max_score) + ")" : "");
    t["description"] = c.spec->title;
    t["points"] = std::round(c.score * 1e6) / 1e6;
    t["max_points"] = bonus ? 0.0 : std::round(c.max_score * 1e6) / 1e6;
    t["message"] = c.status == "passed"
                       ? std::string("Passed")
                       : (c.failures.empty() ? std::string("Failed") : c.failures.front());
    t["output"] = case_output(c, terms_page_of(r));
    tests.push_back(t);
  }
  j["tests"] = tests;
  const std::string svg = com_plot_svg(r);
  j["images"] = Json::array();
  if (!svg.empty())
    j["images"].push_back(
        {{"label", "Centre-of-mass height, course scene: yours and the reference"},
         {"url", "data:image/svg+xml;base64," + base64(svg)}});
  return j;
}

std::string junit_xml(const GradeReport& r) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"jelly-grade\">\n";
  o << "  <testsuite name=\"compile\" tests=\"1\" failures=\"" << (r.compiled ? 0 : 1) << "\">\n"
    << "    <testcase classname=\"compile\" name=\"compilation\">";
  if (!r.compiled)
    o << "<failure message=\"did not compile\">" << xml_escape(compile_summary(r)) << "</failure>";
  o << "</testcase>\n  </testsuite>\n";
  for (const TaskResult& t : r.tasks) {
    std::size_t n = 0, failed = 0;
    for (const CaseResult* c : t.cases)
      if (c->status != "skipped") ++n, failed += c->status == "failed";
    if (n == 0) continue;
    o << "  <testsuite name=\"" << xml_escape(t.spec->id + " " + t.spec->title) << "\" tests=\""
      << n << "\" failures=\"" << failed << "\">\n";
    for (const CaseResult* c : t.cases) {
      if (c->status == "skipped") continue;
      o << "    <testcase classname=\"" << xml_escape(t.spec->id) << "\" name=\""
        << xml_escape(c->spec->id) << "\">";
      if (c->status == "failed")
        o << "<failure message=\""
          << xml_escape(c->failures.empty() ? "failed" : c->failures.front()) << "\">"
          << xml_escape(case_output(*c, terms_page_of(r))) << "</failure>";
      o << "</testcase>\n";
    }
    o << "  </testsuite>\n";
  }
  o << "</testsuites>\n";
  return o.str();
}

std::string com_plot_svg(const GradeReport& r) {
  for (const CaseResult& c : r.cases) {
    // The scene case: the first whose reference records the centre-of-mass height over time.
    if (!c.reference.is_object() || !c.reference.contains("com_time") ||
        !c.reference.contains("com_y"))
      continue;
    // The student's outputs come from the result channel: any shape (a forged result).
    auto vec = [](const Json& out, const char* key) {
      std::vector<double> v;
      if (out.is_object() && out.contains(key) && out[key].is_object() &&
          out[key].contains("value") && out[key]["value"].is_array())
        for (const Json& e : out[key]["value"]) v.push_back(e.is_number() ? e.get<double>() : NAN);
      return v;
    };
    std::vector<Series> s;
    s.push_back(
        {"reference", "#1f77b4", vec(c.reference, "com_time"), vec(c.reference, "com_y"), false});
    if (!c.outputs.is_null())
      s.push_back({"yours", "#d62728", vec(c.outputs, "com_time"), vec(c.outputs, "com_y"), true});
    return svg_plot("Course scene: centre-of-mass height", "time [s]", "height [m]", s);
  }
  return "";
}

namespace {

// report.md's title, sandbox and the grader's notes.
void markdown_header(std::ostream& o, const GradeReport& r) {
  o << "# Jelly Lab grading report\n\nSubmission: " << markdown_inline(r.submission) << " — **"
    << total_text(r) << "** (" << r.visibility << " tests)\n\nSandbox: `" << r.isolation << "` — "
    << markdown_inline(r.isolation_description) << "\n\n";
  for (const std::string& n : r.notes) o << "> " << markdown_inline(n) << "\n\n";
}

// Why the submission did not build: each file that failed, else the link or the compile errors.
void markdown_build_failures(std::ostream& o, const GradeReport& r) {
  for (const FileFailure& f : r.failed_files)
    o << "## " << markdown_inline(f.file + " " + f.what) << "\n\n"
      << markdown_inline(file_failure_headline(r, f)) << ".\n\n"
      << markdown_code_block(f.message) << "\n";
  if (r.build.ok && r.build.runner.empty())
    o << "## Your files do not link together\n\n"
      << markdown_code_block(r.build.link_errors) << "\n";
  if (r.failed_files.empty() && !r.build.ok)
    o << "## Your code did not compile\n\n" << markdown_code_block(r.build.errors) << "\n";
}

// The summary: one row per task, its points and verdict, linked to its section below.
void markdown_summary(std::ostream& o, const GradeReport& r, const TermsPage& page) {
  o << "| Task | Points | Result | Tests passed |\n|---|---|---|---|\n";
  for (const TaskResult& t : r.tasks) {
    const TaskCount n = count(t);
    if (n.run)
      o << "| [" << markdown_inline(t.spec->id + " " + t.spec->title) << "](#" << task_anchor(t)
        << ") | " << task_points(t) << " | " << (n.passed == n.run ? "pass" : "**fail**") << " | "
        << n.passed << "/" << n.run << " |\n";
  }
  if (!page.path.empty())
    o << "\nThe words of the messages (tolerances, contract sections) are explained in [reading "
         "your report]("
      << page.path << ").\n";
  o << "\n";
}

// The frames table (or why there is none) and the notes on the frames.
void markdown_frames(std::ostream& o, const CourseFrames& frames) {
  o << "### Frames: yours beside the reference\n\n";
  if (!frames.unavailable.empty()) {
    o << "Frames not available: " << markdown_inline(frames.unavailable) << "\n\n";
  } else {
    o << "| t [s] | yours | reference |\n|---|---|---|\n";
    for (const FrameRow& row : frames.rows)
      o << "| " << pts(row.time) << " | "
        << (row.yours.empty() ? std::string("—")
                              : "![yours at t = " + pts(row.time) + " s](" + row.yours + ")")
        << " | "
        << (row.reference.empty()
                ? std::string("—")
                : "![reference at t = " + pts(row.time) + " s](" + row.reference + ")")
        << " |\n";
    o << "\n";
  }
  for (const std::string& n : frames.notes) o << "- " << markdown_inline(n) << "\n";
  if (!frames.notes.empty()) o << "\n";
}

// The course scene's plot and frames, in the section of the task whose test records them.
void markdown_course_scene(std::ostream& o, const GradeReport& r, const CourseFrames* frames) {
  if (!com_plot_svg(r).empty())
    o << "### Course scene\n\n![centre-of-mass height, yours against the "
         "reference](com-height.svg)\n\n";
  if (frames && frames->shown) markdown_frames(o, *frames);
}

std::string markdown_failed_test(const CaseResult& c, const TermsPage& page) {
  std::string f =
      "✗ **" + markdown_inline(c.spec->title) + "** \\[" + markdown_inline(c.spec->id) + "\\]\n\n";
  for (const std::string& m : c.failures) {
    if (m.find('\n') == std::string::npos)
      f += "- " + markdown_with_links(m, page) + "\n";
    else
      f += "\n" + markdown_code_block(m) + "\n";
  }
  if (!c.hints.empty()) f += "- **Hint:** " + markdown_inline(hint_text(c)) + "\n";
  return f + "\n";
}

// A task's section: the first failed test expanded, the other failed ones and the passed ones
// folded.
void markdown_task(std::ostream& o, const TaskResult& t, const TaskCount& n,
                   const TermsPage& page) {
  o << "<a id=\"" << task_anchor(t) << "\"></a>\n\n## " << markdown_inline(t.spec->id) << " "
    << markdown_inline(t.spec->title) << " — " << task_points(t) << ", "
    << (n.passed == n.run ? "passed" : "failed") << " (" << n.passed << "/" << n.run
    << " tests)\n\n";
  const std::vector<const CaseResult*> cases = ordered_cases(t);
  std::size_t failed = 0;
  for (const CaseResult* c : cases) failed += c->status == "failed";
  if (failed) o << markdown_failed_test(*cases[0], page);
  if (failed > 1) {
    o << "<details><summary>" << failed - 1 << " more failed test" << (failed > 2 ? "s" : "")
      << "</summary>\n\n";
    for (std::size_t i = 1; i < failed; ++i) o << markdown_failed_test(*cases[i], page);
    o << "</details>\n\n";
  }
  if (n.passed) {
    o << "<details><summary>" << n.passed << " passed test" << (n.passed > 1 ? "s" : "")
      << "</summary>\n\n";
    for (std::size_t i = failed; i < cases.size(); ++i)
      o << "- ✓ " << markdown_inline(cases[i]->spec->title) << " \\["
        << markdown_inline(cases[i]->spec->id) << "\\]\n";
    o << "\n</details>\n\n";
  }
}

// What the first failing tests printed.
void markdown_printed(std::ostream& o, const GradeReport& r) {
  const std::vector<const CaseResult*> printed = printed_cases(r, 5);
  if (printed.empty()) return;
  o << "## What your code printed\n\n";
  for (const CaseResult* c : printed)
    o << "### " << c->spec->id << " (" << c->status << ")\n\n"
      << markdown_code_block(cut_utf8(c->printed, 1500)) << "\n";
}

}  // namespace

std::string markdown_report(const GradeReport& r, const CourseFrames* frames,
                            const std::string& terms_link) {
  std::ostringstream o;
  markdown_header(o, r);
  if (!r.compiled) markdown_build_failures(o, r);
  const TermsPage page{terms_link.empty() ? r.terms_page : terms_link, r.contracts};
  markdown_summary(o, r, page);
  const TaskResult* scene_task = course_scene_task(r);
  for (const TaskResult& t : r.tasks) {
    const TaskCount n = count(t);
    if (!n.run) continue;
    markdown_task(o, t, n, page);
    if (&t == scene_task) markdown_course_scene(o, r, frames);
  }
  markdown_printed(o, r);
  if (!scene_task) markdown_course_scene(o, r, frames);
  return o.str();
}

namespace {

// report.html's course scene: the plot, and the frames beside the reference when they were made.
HtmlData html_course_scene(const GradeReport& r, const CourseFrames* frames,
                           const std::filesystem::path& dir) {
  HtmlData scene;
  const std::string svg = com_plot_svg(r);
  scene.set("has_svg", !svg.empty());
  scene.set("svg", svg);
  const bool shown = frames && frames->shown;
  scene.set("frames_shown", shown);
  if (!shown) return scene;
  scene.set("has_unavailable", !frames->unavailable.empty());
  scene.set("unavailable", frames->unavailable);
  const auto cell = [&](const std::string& file, const std::string& alt) {
    const std::string bytes = file.empty() ? std::string() : read_file(dir / file);
    return HtmlObject{{"has_image", !bytes.empty()}, {"alt", alt}, {"base64", base64(bytes)}};
  };
  HtmlList rows;
  for (const FrameRow& row : frames->rows) {
    HtmlList cells;
    cells.push_back(cell(row.yours, "yours at t = " + pts(row.time) + " s"));
    cells.push_back(cell(row.reference, "reference at t = " + pts(row.time) + " s"));
    rows.push_back(HtmlObject{{"time", pts(row.time)}, {"cells", cells}});
  }
  scene.set("rows", rows);
  scene.set("has_frame_notes", !frames->notes.empty());
  HtmlList notes;
  for (const std::string& n : frames->notes) notes.push_back(n);
  scene.set("frame_notes", notes);
  return scene;
}

// One failed test: its messages (terms linked to `page`), its hint.
HtmlData html_failed_test(const CaseResult& c, const TermsPage& page) {
  HtmlList failures;
  for (const std::string& f : c.failures) {
    const bool pre = f.find('\n') != std::string::npos;
    failures.push_back(
        HtmlObject{{"pre", pre}, {"text", f}, {"html", pre ? "" : html_with_links(f, page)}});
  }
  return HtmlObject{{"title", c.spec->title},
                    {"id", c.spec->id},
                    {"failures", failures},
                    {"has_hint", !c.hints.empty()},
                    {"hint", c.hints.empty() ? std::string() : hint_text(c)}};
}

// One task's row of the summary (and the head of its section).
HtmlData html_task_row(const TaskResult& t) {
  const TaskCount n = count(t);
  return HtmlObject{
      {"anchor", task_anchor(t)},           {"name", t.spec->id + " " + t.spec->title},
      {"points", task_points(t)},           {"ok", n.passed == n.run},
      {"passed", std::to_string(n.passed)}, {"run", std::to_string(n.run)}};
}

// One task's section: its failed tests (the first shown, the others folded), its passed ones.
HtmlData html_task_section(const TaskResult& t, const TermsPage& page, bool scene_here) {
  const TaskCount n = count(t);
  HtmlData section = html_task_row(t);
  section.set("id", t.spec->id);
  section.set("title", t.spec->title);
  section.set("scene_here", scene_here);
  const std::vector<const CaseResult*> cases = ordered_cases(t);
  std::size_t failed = 0;
  for (const CaseResult* c : cases) failed += c->status == "failed";
  section.set("first_failure", failed ? html_failed_test(*cases[0], page) : HtmlData(false));
  HtmlList more;
  for (std::size_t i = 1; i < failed; ++i) more.push_back(html_failed_test(*cases[i], page));
  section.set("more_failed", failed > 1 ? HtmlData(HtmlObject{{"count", std::to_string(failed - 1)},
                                                              {"plural", failed > 2},
                                                              {"tests", more}})
                                        : HtmlData(false));
  HtmlList passed;
  for (std::size_t i = failed; i < cases.size(); ++i)
    passed.push_back(HtmlObject{{"title", cases[i]->spec->title}, {"id", cases[i]->spec->id}});
  section.set("passed_tests", n.passed ? HtmlData(HtmlObject{{"count", std::to_string(n.passed)},
                                                             {"plural", n.passed > 1},
                                                             {"tests", passed}})
                                       : HtmlData(false));
  return section;
}

}  // namespace

std::string html_report(const GradeReport& r, const CourseFrames* frames,
                        const std::filesystem::path& dir, const std::string& terms_link) {
  const TermsPage page{terms_link.empty() ? r.terms_page : terms_link, r.contracts};
  HtmlData d;
  d.set("report_failed_test",
        kainjow::mustache::partial{[] { return std::string(report_failed_test_template()); }});
  d.set("report_course_scene",
        kainjow::mustache::partial{[] { return std::string(report_course_scene_template()); }});
  d.set("submission", r.submission);
  d.set("total", total_text(r));
  d.set("isolation", r.isolation);
  d.set("isolation_description", r.isolation_description);
  HtmlList notes;
  for (const std::string& n : r.notes) notes.push_back(n);
  d.set("notes", notes);
  HtmlList failed_files;
  if (!r.compiled)
    for (const FileFailure& f : r.failed_files)
      failed_files.push_back(HtmlObject{{"heading", f.file + " " + f.what},
                                        {"headline", file_failure_headline(r, f)},
                                        {"message", f.message}});
  d.set("failed_files", failed_files);
  d.set("has_link_errors", !r.compiled && r.build.ok && r.build.runner.empty());
  d.set("link_errors", r.build.link_errors);
  d.set("has_compile_errors", !r.compiled && r.failed_files.empty() && !r.build.ok);
  d.set("compile_errors", r.build.errors);
  d.set("has_terms_page", !page.path.empty());
  d.set("terms_page", page.path);
  const TaskResult* scene_task = course_scene_task(r);
  HtmlList summary, sections;
  for (const TaskResult& t : r.tasks) {
    if (!count(t).run) continue;
    summary.push_back(html_task_row(t));
    sections.push_back(html_task_section(t, page, &t == scene_task));
  }
  d.set("summary", summary);
  d.set("sections", sections);
  d.set("scene", html_course_scene(r, frames, dir));
  d.set("scene_alone", !scene_task);
  HtmlList printed;
  for (const CaseResult* c : printed_cases(r, 5))
    printed.push_back(HtmlObject{
        {"id", c->spec->id}, {"status", c->status}, {"text", cut_utf8(c->printed, 1500)}});
  d.set("has_printed", !printed.empty());
  d.set("printed", printed);
  return render_html(report_html_template(), "report.html.mustache", d);
}

void write_reports(const GradeReport& r, const CaseBook& book, const std::filesystem::path& out,
                   const std::set<std::string>& formats, const GradeConfig* config) {
  std::filesystem::create_directories(out);
  CourseFrames frames;
  if (config && (formats.count("markdown") || formats.count("html"))) {
    try {
      frames = render_course_frames(*config, r, out, out / ".frames-work");
    } catch (const std::exception& e) {
      frames = CourseFrames();
      frames.shown = true;
      frames.unavailable = std::string("the frames could not be made: ") + e.what();
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(out / ".frames-work", ec);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream f(out / name, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + (out / name).string());
  };
  if (formats.count("gradescope")) write("results.json", dump_json(gradescope_results(r, book)));
  if (formats.count("prairielearn")) write("prairielearn.json", dump_json(prairielearn_results(r)));
  if (formats.count("junit")) write("junit.xml", junit_xml(r));
  // The handout page of the report's words, as a link from the report's folder when that is in
  // the framework's tree (the self-check's build folder); else the page's path in the tree, which
  // names it in the student's own copy (a report sent on from a batch).
  std::string terms_link;
  if (config && !r.terms_page.empty()) {
    const fs::path top = fs::absolute(config->source_dir).lexically_normal();
    const fs::path here = fs::absolute(out).lexically_normal();
    const fs::path inside = here.lexically_relative(top);
    if (!inside.empty() && *inside.begin() != "..")
      terms_link = (top / r.terms_page).lexically_relative(here).generic_string();
  }
  if (formats.count("markdown")) {
    write("report.md", markdown_report(r, config ? &frames : nullptr, terms_link));
    const std::string svg = com_plot_svg(r);
    if (!svg.empty()) write("com-height.svg", svg);
  }
  if (formats.count("html"))
    write("report.html", html_report(r, config ? &frames : nullptr, out, terms_link));
}

}  // namespace jelly::grade
