#include "commands/commands.hpp"

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

#include "class/class_record.hpp"
#include "class/csv.hpp"
#include "grading/parallel.hpp"
#include "inputs/submissions.hpp"
#include "reports/points.hpp"
#include "reports/report.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

namespace {

/// A record --resume may keep: readable, made under the same grading fingerprint from the same
/// files, and not a grader error (which may have been the machine's, not the student's).
bool keepable(const fs::path& file, const std::string& fingerprint, const Submission& sub) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return false;
  try {
    const Json r = read_record(file);
    if (r.value("fingerprint", "") != fingerprint || r.value("status", "") == "grader error")
      return false;
    return r.value("submission_digest", "") ==
           (sub.problem.empty() ? submission_digest(sub.dir) : std::string());
  } catch (const std::exception&) {
    return false;
  }
}

/// The batch's last line but its folder: the students graded and those not graded apart (a row
/// with no points, whatever the reason: the submission's problem or the grader's error), and
/// with --resume how many this run graded and kept.
std::string last_line(const std::vector<Json>& records, std::size_t students, std::size_t run,
                      const BatchArgs& args) {
  std::size_t graded = 0;
  for (const Json& r : records)
    if (r.value("status", "") == "graded") ++graded;
  const std::size_t not_graded = students - graded;
  std::string line = "jelly-grade: " + std::to_string(graded) + " graded, " +
                     std::to_string(not_graded) + " not graded";
  if (args.shard_count > 1)
    line += " (shard " + std::to_string(args.shard_index) + "/" + std::to_string(args.shard_count) +
            ")";
  if (not_graded > 0) line += " (scores.csv's error column says why)";
  if (run < students)
    line += "; this run took " + std::to_string(run) + ", kept " + std::to_string(students - run);
  return line;
}

/// --shard I/N: every N-th submission in id order, starting at the I-th, so that each part gets
/// its share of the alphabet and the parts are disjoint and together the class.
std::vector<Submission> shard_of(const std::vector<Submission>& all, const BatchArgs& args) {
  std::vector<Submission> subs;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (static_cast<int>(k % static_cast<std::size_t>(args.shard_count)) == args.shard_index - 1)
      subs.push_back(all[k]);
  return subs;
}

/// Class files at the top of --out, each student's files under students/<id>/ (no id can collide
/// with a class file); returns students/.
fs::path prepare_out(const fs::path& out) {
  const fs::path students = out / "students";
  fs::create_directories(students);
  // batch.json is written when the batch ends: until then (and if it is stopped) the folder is
  // not a part merge accepts, even when an earlier batch into it had ended.
  fs::remove(out / "batch.json");
  // A folder left half-made by a batch that was stopped (students/.<id>.partial) is never a
  // result: it goes, and its student is graded again.
  for (const auto& e : fs::directory_iterator(students)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 9 && n[0] == '.' && n.compare(n.size() - 8, 8, ".partial") == 0)
      fs::remove_all(e.path());
  }
  return students;
}

/// User mode: while the batch runs, no sandbox user can read any submission or any report (the
/// work folders are private to each submission already: Workspace).
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
};

/// --resume: whoever has a record made under this fingerprint from the same files keeps it; the
/// others (all of them without --resume) are to grade.
std::vector<std::size_t> to_grade(const std::vector<Submission>& subs, const fs::path& out,
                                  const std::string& fingerprint, bool resume) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < subs.size(); ++i)
    if (!resume || !keepable(record_path(out, subs[i].id), fingerprint, subs[i])) todo.push_back(i);
  if (resume)
    std::cerr << "jelly-grade: resuming " << safe_text(out.string()) << ": "
              << subs.size() - todo.size() << " of " << subs.size()
              << " submissions already graded (kept), " << todo.size() << " to grade\n";
  return todo;
}

/// One student's grading in the batch: what it made and what went wrong.
struct StudentOutcome {
  GradeReport report;
  bool graded = false;
  std::string failed;  ///< why the results could not be written ("" when they were)
};

/// Grades one student. Everything of one student is made in students/.<id>.partial and renamed
/// into place when whole: a report appears whole or not at all, and the record last of all.
StudentOutcome grade_student(const GradeConfig& config, const CaseBook& book, const Submission& sub,
                             const fs::path& students, const GradeOptions& per, bool frames,
                             const std::string& fingerprint) {
  const fs::path part = students / ("." + sub.id + ".partial");
  const fs::path final_dir = students / sub.id;
  std::string error;
  StudentOutcome o;
  std::error_code ec;
  fs::remove_all(part, ec);
  fs::create_directories(part, ec);
  if (sub.problem.empty()) {
    try {
      o.report = grade_submission(config, book, sub.dir, part / "work", per);
      // The reports name the student, not this machine's path to their folder: the parts of a
      // class graded on several machines give the same reports.
      o.report.submission = sub.id;
      write_reports(o.report, book, part, {"gradescope", "markdown", "html"},
                    frames ? &config : nullptr);
      o.graded = true;
    } catch (const std::exception& e) {
      error = e.what();
    } catch (...) {
      error = "unknown error";
    }
  }
  // No half-made work folder (objects, a runner) among the reports.
  fs::remove_all(part / "work", ec);
  const Json record =
      student_record(sub, o.graded ? &o.report : nullptr, error, config, book, fingerprint);
  try {
    write_file_atomically(part / "record.json", record.dump(2) + "\n");
    fs::remove_all(final_dir);
    fs::rename(part, final_dir);
  } catch (const std::exception& e) {
    o.failed = e.what();
  }
  return o;
}

/// The progress line of one student (on a terminal rewritten in place; into a file or a pipe, a
/// log or CI, a line each).
void print_progress(const Submission& sub, const StudentOutcome& o, std::size_t done,
                    std::size_t total, bool tty) {
  if (!o.failed.empty())
    std::cerr << (tty ? "\n" : "") << "jelly-grade: " << safe_text(sub.id)
              << ": the results could not be written: " << safe_text(o.failed) << "\n";
  const GradeReport& report = o.report;
  std::cerr << (tty ? "\r[" : "[") << done << "/" << total << "] " << safe_text(sub.id) << ": "
            << (o.graded ? pts(report.score) + " / " + pts(report.max_score) +
                               (report.has_bonus() ? " + bonus " + pts(report.bonus_score) : "")
                : !sub.problem.empty() ? "not graded: " + safe_text(sub.problem)
                                       : "grader error")
            << (tty ? "            " : "\n") << std::flush;
}

/// The class files come from the records alone, those of this run and those it kept; batch.json
/// last but one, then the class files. Sets `status` to 1 when a record is missing or not graded.
std::vector<Json> write_class(const GradeConfig& config, const CaseBook& book,
                              const std::vector<Submission>& all,
                              const std::vector<Submission>& subs, const fs::path& out,
                              const std::string& fingerprint, const BatchArgs& args, int& status) {
  std::vector<Json> records;
  Json ids = Json::array(), mine = Json::array();
  for (const Submission& s : all) ids.push_back(s.id);
  for (const Submission& s : subs) {
    mine.push_back(s.id);
    try {
      records.push_back(read_record(record_path(out, s.id)));
      if (records.back().value("status", "") != "graded") status = 1;
    } catch (const std::exception& e) {
      std::cerr << "jelly-grade: " << safe_text(e.what()) << "\n";
      status = 1;
    }
  }
  const Json manifest = {{"format", "jelly-grade batch 1"},
                         {"assignment", config.assignment().id},
                         {"fingerprint", fingerprint},
                         {"shard", shard_label(args.shard_index, args.shard_count)},
                         {"class", ids},
                         {"students", mine}};
  write_file_atomically(out / "batch.json", manifest.dump(2) + "\n");
  write_class_files(out, records, book, config.assignment().manifest.title);
  return records;
}

}  // namespace

std::string shard_label(int index, int count) {
  return std::to_string(index) + "/" + std::to_string(count);
}

int batch(const GradeConfig& config, const CaseBook& book, const BatchArgs& args,
          const GradeOptions& options) {
  // Absolute: the compiler and the tests run in other working folders.
  const fs::path out = fs::absolute(args.out);
  // A zip (a Gradescope export) is extracted into --out/.submissions (no id starts with '.').
  std::vector<std::string> warnings;
  std::vector<Submission> all =
      find_submissions(fs::absolute(args.in), out / ".submissions", &warnings);
  for (const std::string& w : warnings) std::cerr << "jelly-grade: " << safe_text(w) << "\n";
  const std::vector<Submission> subs = shard_of(all, args);
  const fs::path students = prepare_out(out);
  CloseToOthers closed;
  if (options.isolation.kind == IsolationKind::User) {
    closed.close(fs::absolute(args.in));
    closed.close(out);
  }
  // Frames or not changes the reports, not the scores: a part graded --no-frames is not resumed
  // or merged as one with frames.
  const std::string fingerprint =
      args.frames ? grading_fingerprint(config, book, options)
                  : fnv_hex(grading_fingerprint(config, book, options) + " --no-frames");
  const std::vector<std::size_t> todo = to_grade(subs, out, fingerprint, args.resume);
  std::size_t done = 0;
  int status = warnings.empty() ? 0 : 1;
  std::mutex mutex;
  const bool tty = JELLY_STDERR_IS_TTY();
  GradeOptions per = options;
  per.jobs = 1;  // parallel across students, serial within one
  parallel_for(todo.size(), args.jobs, [&](std::size_t t) {
    const Submission& sub = subs[todo[t]];
    const StudentOutcome o =
        grade_student(config, book, sub, students, per, args.frames, fingerprint);
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (!o.failed.empty() || !o.graded) status = 1;
    print_progress(sub, o, done, todo.size(), tty);
  });
  if (tty && !todo.empty()) std::cerr << "\n";
  const std::vector<Json> records =
      write_class(config, book, all, subs, out, fingerprint, args, status);
  std::cout << last_line(records, subs.size(), todo.size(), args) << " into " << out.string()
            << " (scores.csv, the class report class.html; each student's reports in students/)\n";
  // --similarity: who copied, over the whole class (every shard has the same class; the first
  // writes the report, and merge takes it from there).
  if (args.similarity >= 0.0 && args.shard_index == 1) {
    similarity(config, similarity_inputs(all), out.string(), args.similarity);
  }
  return status;
}

}  // namespace jelly::grade
