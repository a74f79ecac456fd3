#include "class/class_record.hpp"

#include <algorithm>
#include <stdexcept>

#include "class/class_report.hpp"
#include "class/csv.hpp"
#include "inputs/files.hpp"
#include "reports/points.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRecordFormat = "jelly-grade student record 1";

std::string file_text(const fs::path& p) { return read_file(p); }

}  // namespace

std::string grading_fingerprint(const GradeConfig& config, const CaseBook& book,
                                const GradeOptions& options) {
  std::string all = config.assignment().id + "\n" + harness_digest(config) + "\n" +
                    (options.include_hidden ? "all" : "public") + "\n" +
                    std::to_string(options.timeout_s) + "\n" +
                    std::to_string(book.rubric.autograded_total) + "\n";
  for (const TaskSpec& t : book.rubric.tasks)
    all += t.id + " " + std::to_string(t.points) + (t.bonus ? " bonus" : "") + "\n";
  for (const CaseSpec& c : book.cases) {
    if (c.hidden && !options.include_hidden) continue;
    all += c.id + " " + c.task + " " + std::to_string(c.weight) + " " + c.params.dump() + "\n";
    const fs::path data = reference_path(config, c);
    std::error_code ec;
    if (fs::is_regular_file(data, ec)) all += fnv_hex(file_text(data)) + "\n";
  }
  return fnv_hex(all);
}

std::string submission_digest(const fs::path& dir) {
  std::vector<std::string> entries;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_symlink(ec) || !it->is_regular_file(ec)) continue;
    entries.push_back(fs::relative(it->path(), dir, ec).generic_string() + "\n" +
                      fnv_hex(file_text(it->path())));
  }
  std::sort(entries.begin(), entries.end());
  std::string all;
  for (const std::string& e : entries) all += e + "\n";
  return fnv_hex(all);
}

Json student_record(const Submission& sub, const GradeReport* report, const std::string& error,
                    const GradeConfig& config, const CaseBook& book,
                    const std::string& fingerprint) {
  Json r;
  r["format"] = kRecordFormat;
  r["assignment"] = config.assignment().id;
  r["fingerprint"] = fingerprint;
  r["submission_digest"] = sub.problem.empty() ? submission_digest(sub.dir) : "";
  r["id"] = safe_text(sub.id);
  r["name"] = safe_text(sub.name);
  r["email"] = safe_text(sub.email);
  Json notes = Json::array();
  for (const std::string& n : sub.notes) notes.push_back(safe_text(n));
  if (!report) {
    r["status"] = sub.problem.empty() ? "grader error" : "not graded";
    r["error"] = safe_text(sub.problem.empty() ? error : sub.problem);
    r["notes"] = notes;
    return r;
  }
  r["status"] = "graded";
  r["error"] = "";
  for (const std::string& n : report->notes) notes.push_back(safe_text(n));
  r["notes"] = notes;
  r["score"] = report->score;
  r["max_score"] = report->max_score;
  r["bonus_score"] = report->bonus_score;
  r["bonus_max"] = report->bonus_max;
  r["compiled"] = report->compiled;
  Json missing = Json::array();
  for (const std::string& file : config.task_files())
    if (const auto u = report->build.used.find(file);
        u != report->build.used.end() && u->second == "stub")
      missing.push_back(file);
  r["missing_files"] = missing;
  Json failed = Json::array();
  for (const FileFailure& f : report->failed_files)
    failed.push_back({{"file", f.file}, {"what", f.what}, {"message", safe_text(f.message)}});
  r["failed_files"] = failed;
  Json tasks = Json::array();
  for (const TaskResult& t : report->tasks)
    tasks.push_back({{"id", t.spec->id},
                     {"score", t.score},
                     {"max_score", t.max_score},
                     {"bonus", t.spec->bonus}});
  r["tasks"] = tasks;
  Json cases = Json::array();
  for (const CaseResult& c : report->cases) {
    Json failures = Json::array(), hints = Json::array();
    for (const std::string& f : c.failures) failures.push_back(safe_text(f));
    for (const std::string& h : c.hints) hints.push_back(safe_text(h));
    cases.push_back({{"id", c.spec->id},
                     {"task", c.spec->task},
                     {"hidden", c.spec->hidden},
                     {"status", c.status},
                     {"score", c.score},
                     {"max_score", c.max_score},
                     {"abnormal", c.abnormal},
                     {"not_run", c.not_run},
                     {"failures", failures},
                     {"hints", hints}});
  }
  r["cases"] = cases;
  (void)book;
  return r;
}

fs::path record_path(const fs::path& out, const std::string& id) {
  return out / "students" / id / "record.json";
}

Json read_record(const fs::path& file) {
  Json r;
  try {
    r = Json::parse(file_text(file));
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": not a student record (" + e.what() + ")");
  }
  if (!r.is_object() || r.value("format", "") != kRecordFormat || !r.contains("id") ||
      !r["id"].is_string() || !r.contains("status"))
    throw std::runtime_error(file.string() + ": not a student record (expected \"format\": \"" +
                             kRecordFormat + "\" with an id and a status)");
  return r;
}

std::string scores_csv(const std::vector<Json>& records, const CaseBook& book) {
  // What an LMS import takes (docs/instructor-guide.md, "Import the scores"): the id; the
  // autograded points out of max_points (autograded_total: the bonus is not in it) and as a
  // percentage; the bonus, for an assignment with a bonus task; `total`, what the student earned
  // with the bonus included (the column to import); an empty column for the hand-graded part and
  // its maximum (the manifest's hand_graded_points); then each task's points. No column for a
  // task worth nothing (A1's course scene, which would always read 0).
  bool bonus = false;
  std::vector<const TaskSpec*> tasks;
  for (const TaskSpec& t : book.rubric.tasks) {
    bonus = bonus || t.bonus;
    if (t.bonus || t.points != 0.0) tasks.push_back(&t);
  }
  std::vector<std::string> header = {"student", "points", "max_points", "percent"};
  if (bonus) header.push_back("bonus");
  for (const char* h : {"total", "hand_graded", "hand_graded_max", "compiled"}) header.push_back(h);
  for (const TaskSpec* t : tasks) header.push_back(csv_field(t->id));
  // The task files not found in the submission (graded as the unchanged stubs): a student who
  // submitted nothing usable shows here, not only inside their own report.
  for (const char* h : {"name", "email", "missing_files", "error"}) header.push_back(h);
  std::string csv = csv_row(header);
  for (const Json& r : records) {
    std::vector<std::string> row = {csv_field(r.value("id", ""))};
    const bool graded = r.value("status", "") == "graded";
    if (!graded) {
      // No points at all, not 0: an import then leaves the student's grade as it was.
      while (row.size() < header.size() - 4) row.push_back("");
    } else {
      const double score = r["score"].get<double>(), max = r["max_score"].get<double>();
      const double extra = bonus ? r["bonus_score"].get<double>() : 0.0;
      row.push_back(pts(score));
      row.push_back(pts(max));
      row.push_back(max > 0.0 ? pts(100.0 * score / max) : "");
      if (bonus) row.push_back(pts(extra));
      row.push_back(pts(score + extra));
      row.push_back("");  // hand_graded: the instructor's
      row.push_back(pts(book.rubric.hand_graded_points));
      row.push_back(r["compiled"].get<bool>() ? "1" : "0");
      for (const TaskSpec* t : tasks) {
        std::string cell;
        for (const Json& rt : r["tasks"])
          if (rt.value("id", "") == t->id) cell = pts(rt["score"].get<double>());
        row.push_back(cell);
      }
    }
    row.push_back(csv_field(r.value("name", "")));
    row.push_back(csv_field(r.value("email", "")));
    std::string missing;
    if (graded)
      for (const Json& f : r["missing_files"])
        missing += (missing.empty() ? "" : " ") + f.get<std::string>();
    row.push_back(csv_field(missing));
    row.push_back(csv_field(graded ? "" : r.value("error", "")));
    csv += csv_row(row);
  }
  return csv;
}

void write_class_files(const fs::path& out, const std::vector<Json>& records, const CaseBook& book,
                       const std::string& title) {
  write_file_atomically(out / "scores.csv", scores_csv(records, book));
  const Json summary = class_summary(records, book, title);
  write_file_atomically(out / "class.json", summary.dump(1) + "\n");
  write_file_atomically(out / "class.md", class_markdown(summary, ClassView::Lecture));
  write_file_atomically(out / "class.html", class_html(summary, ClassView::Lecture));
  write_file_atomically(out / "class-instructor.md",
                        class_markdown(summary, ClassView::Instructor));
  write_file_atomically(out / "class-instructor.html", class_html(summary, ClassView::Instructor));
}

}  // namespace jelly::grade
