#include "class/class_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "class/class_report_fields.hpp"
#include "reports/points.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

using namespace class_fields;

namespace {

constexpr const char* kSummaryFormat = "jelly-grade class report 1";
constexpr int kBins = 11;                   // 0–9 %, 10–19 %, ..., 90–99 %, and full marks
constexpr std::size_t kMessageBytes = 300;  // of an example message

double round2(double v) { return std::round(v * 100.0) / 100.0; }

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

namespace {

// One failed test of the class: its task, whether hidden, how many students failed it and the
// first of them (by id) with their first failure.
struct Group {
  std::string task;
  bool hidden = false;
  int count = 0;
  std::string student, message;
};

// What the graded students' failed tests add up to.
struct Tally {
  std::map<std::string, Group> groups;                         // by case id
  std::map<std::string, std::map<std::string, int>> mistakes;  // task → hint → students
  std::map<std::string, int> hidden_failed;                    // task → students
  std::map<std::string, int> kinds;                            // abnormal kind → students
  Json abnormal = Json::array();
};

// The task `id` of the book (nullptr if it has none).
const TaskSpec* task_of(const CaseBook& book, const std::string& id) {
  for (const TaskSpec& t : book.rubric.tasks)
    if (t.id == id) return &t;
  return nullptr;
}

// Whether a record's file that did not compile explains its results in `task`: a task with no
// file of its own (a course scene) runs all the student's code, with the stub of the failed file.
// Its failures then follow from the compile error, which is counted once, apart.
bool follows_from_compile_error(const Json& r, const TaskSpec* task) {
  const bool compile_failed =
      !list(r, "failed_files").empty() || (r.contains("compiled") && !flag(r, "compiled"));
  return compile_failed && task && task->file.empty();
}

// Abnormal runs, one entry per student and kind (a loop in a function every test calls times out
// in every test: one entry, with how many).
void tally_abnormal(const std::string& id, const Json& c, std::vector<std::string>& kinds,
                    std::map<std::string, Json>& by_kind) {
  const std::string kind = str(c, "abnormal");
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
}

// One graded student's failed tests: grouped by test, their hints by task (each mistake once per
// student and task), their hidden failures by task, their abnormal runs by kind.
void tally_cases(const Json& r, const CaseBook& book, Tally& t) {
  const std::string id = str(r, "id");
  std::vector<std::string> kinds;
  std::map<std::string, Json> by_kind;
  std::map<std::string, std::set<std::string>> mistakes;
  std::set<std::string> hidden_tasks;
  for (const Json& c : list(r, "cases")) {
    if (str(c, "status") != "failed" || flag(c, "not_run")) continue;
    const std::string task = str(c, "task");
    if (follows_from_compile_error(r, task_of(book, task))) continue;
    if (!str(c, "abnormal").empty()) {
      tally_abnormal(id, c, kinds, by_kind);
      continue;  // listed with the abnormal runs, not among the failed checks
    }
    Group& g = t.groups[str(c, "id")];
    if (g.count++ == 0) {
      g.task = task;
      g.hidden = flag(c, "hidden");
      g.student = id;
      g.message = first_message(c);
    }
    if (flag(c, "hidden")) hidden_tasks.insert(task);
    for (const Json& h : list(c, "hints"))
      if (h.is_string()) mistakes[task].insert(safe_text(h.get<std::string>()));
  }
  for (const std::string& k : kinds) {
    t.abnormal.push_back(by_kind[k]);
    ++t.kinds[k];
  }
  for (const auto& [task, set] : mistakes)
    for (const std::string& m : set) ++t.mistakes[task][m];
  for (const std::string& task : hidden_tasks) ++t.hidden_failed[task];
}

double share_of(int count, std::size_t of) {
  return of ? std::round(1000.0 * count / static_cast<double>(of)) / 1000.0 : 0.0;
}

// A task's failed tests, most frequent first (ties in the case book's order, then by id).
Json failed_cases(const std::string& tid, const Tally& t, const CaseBook& book,
                  std::size_t graded) {
  std::map<std::string, std::size_t> order;
  for (std::size_t i = 0; i < book.cases.size(); ++i) order[book.cases[i].id] = i;
  const auto at = [&](const std::string& id) {
    return order.count(id) ? order.at(id) : book.cases.size();
  };
  std::vector<std::string> ids;
  for (const auto& [id, g] : t.groups)
    if (g.task == tid) ids.push_back(id);
  std::stable_sort(ids.begin(), ids.end(), [&](const std::string& a, const std::string& b) {
    const int na = t.groups.at(a).count, nb = t.groups.at(b).count;
    if (na != nb) return na > nb;
    return at(a) != at(b) ? at(a) < at(b) : a < b;
  });
  Json failed = Json::array();
  for (const std::string& cid : ids) {
    const Group& g = t.groups.at(cid);
    std::string title;
    for (const CaseSpec& c : book.cases)
      if (c.id == cid) title = c.title;
    failed.push_back({{"case", cid},
                      {"title", title},
                      {"hidden", g.hidden},
                      {"students", g.count},
                      {"share", share_of(g.count, graded)},
                      {"example", {{"student", g.student}, {"message", g.message}}}});
  }
  return failed;
}

// A task's known mistakes (hints.hpp), most frequent first, then by description.
Json known_mistakes(const std::string& tid, const Tally& t, std::size_t graded) {
  std::vector<std::pair<std::string, int>> m;
  if (t.mistakes.count(tid))
    for (const auto& [what, n] : t.mistakes.at(tid)) m.emplace_back(what, n);
  std::stable_sort(m.begin(), m.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  Json out = Json::array();
  for (const auto& [what, n] : m)
    out.push_back({{"mistake", what}, {"students", n}, {"share", share_of(n, graded)}});
  return out;
}

// The students of each way a submission failed as a whole, the kinds with none left out.
Json failure_kinds(const Json& s, const Tally& t, std::size_t graded) {
  std::set<std::string> compile;
  for (const Json& c : s["did_not_compile"]) compile.insert(str(c, "student"));
  Json kinds = Json::array();
  auto add = [&](const std::string& kind, int n) {
    if (n > 0) kinds.push_back({{"kind", kind}, {"students", n}, {"share", share_of(n, graded)}});
  };
  add("did not compile", static_cast<int>(compile.size()));
  for (const auto& [kind, n] : t.kinds) add(kind, n);
  add("missing task files", static_cast<int>(s["missing_files"]["students"].size()));
  add("could not be graded", static_cast<int>(s["could_not_grade"].size()));
  return kinds;
}

Json missing_by_file(const std::map<std::string, int>& missing, const CaseBook& book) {
  std::vector<std::string> order;  // the assignment's file order where the book has it
  for (const TaskSpec& t : book.rubric.tasks)
    if (missing.count(t.file) && std::find(order.begin(), order.end(), t.file) == order.end())
      order.push_back(t.file);
  for (const auto& [file, n] : missing)
    if (std::find(order.begin(), order.end(), file) == order.end()) order.push_back(file);
  Json by_file = Json::array();
  for (const std::string& f : order) by_file.push_back({{"file", f}, {"students", missing.at(f)}});
  return by_file;
}

}  // namespace

Json class_summary(const std::vector<Json>& in, const CaseBook& book, const std::string& title) {
  // In id order whatever order the records came in: the first student by id is the example.
  std::vector<Json> records = in;
  std::stable_sort(records.begin(), records.end(),
                   [](const Json& a, const Json& b) { return str(a, "id") < str(b, "id"); });
  Json s;
  s["format"] = kSummaryFormat;
  s["assignment"] = records.empty() ? "" : str(records.front(), "assignment");
  s["title"] = safe_text(title);
  s["students"] = records.size();
  std::vector<std::pair<double, double>> totals;
  std::map<std::string, std::vector<std::pair<double, double>>> task_scores;
  Tally tally;
  Json compile = Json::array(), not_graded = Json::array(), missing = Json::array();
  std::map<std::string, int> missing_files;
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
          ++missing_files[safe_text(f.get<std::string>())];
        }
      missing.push_back({{"student", id}, {"files", files}});
    }
    tally_cases(r, book, tally);
  }
  const std::size_t graded = totals.size();
  s["graded"] = graded;
  s["not_graded"] = not_graded.size();
  s["score"] = distribution(totals);

  std::vector<std::string> task_ids;
  for (const TaskSpec& t : book.rubric.tasks) task_ids.push_back(t.id);
  for (const auto& [id, scores] : task_scores)  // a task the records have and the book has not
    if (std::find(task_ids.begin(), task_ids.end(), id) == task_ids.end()) task_ids.push_back(id);
  Json tasks = Json::array();
  for (const std::string& tid : task_ids) {
    const TaskSpec* spec = task_of(book, tid);
    Json t;
    t["id"] = tid;
    t["title"] = spec ? spec->title : "";
    t["bonus"] = spec && spec->bonus;
    t["scores"] = distribution(task_scores[tid]);
    t["failed_cases"] = failed_cases(tid, tally, book, graded);
    t["known_mistakes"] = known_mistakes(tid, tally, graded);
    const int hidden = tally.hidden_failed.count(tid) ? tally.hidden_failed.at(tid) : 0;
    t["hidden_failed"] = {{"students", hidden}, {"share", share_of(hidden, graded)}};
    tasks.push_back(t);
  }
  s["tasks"] = tasks;
  s["did_not_compile"] = compile;
  s["timed_out_or_crashed"] = tally.abnormal;
  s["could_not_grade"] = not_graded;
  s["missing_files"] = {{"students", missing}, {"by_file", missing_by_file(missing_files, book)}};
  s["failure_kinds"] = failure_kinds(s, tally, graded);
  return s;
}

}  // namespace jelly::grade
