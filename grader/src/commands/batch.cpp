#include "commands.hpp"

#include <algorithm>
#include <iostream>
#include <mutex>

#ifdef _WIN32
#include <io.h>
#define JELLY_STDERR_IS_TTY() (_isatty(2) != 0)
#else
#include <unistd.h>
#define JELLY_STDERR_IS_TTY() (isatty(2) != 0)
#endif

#include "commands/common.hpp"
#include "csv.hpp"
#include "parallel.hpp"
#include "report.hpp"
#include "text_safety.hpp"

namespace jelly::grade {

int batch(const GradeConfig& config, const CaseBook& book, const std::string& dir,
          const std::string& out, int jobs, const GradeOptions& options, bool frames,
          double similarity_threshold) {
  std::vector<fs::path> subs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory()) subs.push_back(e.path());
  std::sort(subs.begin(), subs.end());
  // Class files at the top of --out, each student's files under students/<folder>/: no folder
  // name can collide with a class file.
  const fs::path students = fs::path(out) / "students";
  fs::create_directories(students);
  // User mode: while the batch runs, no sandbox user can read any submission or any report (the
  // work folders are private to each submission already: Workspace).
  struct CloseToOthers {
    std::vector<std::pair<fs::path, fs::perms>> saved;
    void close(const fs::path& p) {
      std::error_code ec;
      const fs::perms was = fs::status(p, ec).permissions();
      if (ec) return;
      fs::permissions(p, fs::perms::others_all, fs::perm_options::remove, ec);
      if (!ec) saved.emplace_back(p, was);
    }
    ~CloseToOthers() {
      for (const auto& [p, was] : saved) {
        std::error_code ec;
        fs::permissions(p, was, fs::perm_options::replace, ec);
      }
    }
  } closed;
  if (options.isolation.kind == IsolationKind::User) {
    closed.close(dir);
    closed.close(out);
  }
  std::vector<GradeReport> reports(subs.size());
  std::vector<std::string> errors(subs.size());
  std::size_t done = 0;
  std::mutex mutex;
  // On a terminal one progress line is rewritten in place; into a file or a pipe (a log, CI) each
  // submission gets its own line.
  const bool tty = JELLY_STDERR_IS_TTY();
  GradeOptions per = options;
  per.jobs = 1;  // parallel across students, serial within one
  parallel_for(subs.size(), jobs, [&](std::size_t i) {
    const std::string name = subs[i].filename().string();
    try {
      reports[i] = grade_submission(config, book, subs[i], students / name / "work", per);
      write_reports(reports[i], book, students / name, {"gradescope", "markdown", "html"},
                    frames ? &config : nullptr);
      fs::remove_all(students / name / "work");
    } catch (const std::exception& e) {
      errors[i] = e.what();
    } catch (...) {
      errors[i] = "unknown error";
    }
    if (!errors[i].empty()) {  // no half-made work folder (objects, a runner) among the reports
      std::error_code ec;
      fs::remove_all(students / name / "work", ec);
    }
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    std::cerr << (tty ? "\r[" : "[") << done << "/" << subs.size() << "] " << safe_text(name)
              << ": "
              << (errors[i].empty()
                      ? pts(reports[i].score) + " / " + pts(reports[i].max_score) +
                            (reports[i].has_bonus() ? " + bonus " + pts(reports[i].bonus_score)
                                                    : "")
                      : "grader error")
              << (tty ? "            " : "\n") << std::flush;
  });
  if (tty) std::cerr << "\n";
  // A bonus column only for an assignment with a bonus task (A1's file is as it always was).
  bool bonus = false;
  for (const TaskSpec& t : book.rubric.tasks) bonus = bonus || t.bonus;
  std::vector<std::string> header = {"student", "score", "max_score", "compiled"};
  if (bonus) header.insert(header.begin() + 3, "bonus");
  for (const TaskSpec& t : book.rubric.tasks) header.push_back(csv_field(t.id));
  // The task files not found in the submission (graded as the unchanged stubs): a student who
  // submitted nothing usable shows here, not only inside their own report.
  header.push_back("missing_files");
  header.push_back("error");
  std::string csv = csv_row(header);
  int status = 0;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    std::vector<std::string> row = {csv_field(safe_text(subs[i].filename().string()))};
    if (!errors[i].empty()) {
      for (std::size_t k = 0; k < (bonus ? 5 : 4) + book.rubric.tasks.size(); ++k)
        row.push_back("");
      row.push_back(csv_field(safe_text(errors[i])));
      status = 1;
    } else {
      row.push_back(pts(reports[i].score));
      row.push_back(pts(reports[i].max_score));
      if (bonus) row.push_back(pts(reports[i].bonus_score));
      row.push_back(reports[i].compiled ? "1" : "0");
      for (const TaskResult& t : reports[i].tasks) row.push_back(pts(t.score));
      std::string missing;
      for (const std::string& file : config.task_files())
        if (const auto u = reports[i].build.used.find(file);
            u != reports[i].build.used.end() && u->second == "stub")
          missing += (missing.empty() ? "" : " ") + file;
      row.push_back(csv_field(missing));
      row.push_back("");
    }
    csv += csv_row(row);
  }
  write_file_atomically(fs::path(out) / "scores.csv", csv);
  std::cout << "jelly-grade: graded " << subs.size() << " submissions into " << out
            << " (scores.csv; each student's reports in students/)\n";
  if (similarity_threshold >= 0.0) {  // --similarity: who copied, over the same folders
    std::vector<SimilarityInput> inputs;
    for (const fs::path& s : subs) inputs.push_back({s.filename().string(), s});
    similarity(config, inputs, out, similarity_threshold);
  }
  return status;
}

}  // namespace jelly::grade
