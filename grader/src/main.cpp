// jelly-grade: the headless autograder (docs/grader.md).
//
//   jelly-grade grade SUBMISSION_DIR [--visibility public|all] [--out DIR]
//               [--format terminal,gradescope,prairielearn,junit,markdown,html] [--timeout S]
//               [--jobs N] [--verbose] [--no-frames] [--runner FILE] [--strict]
//   (grade, batch, prairielearn, mutants) [--isolation auto|bwrap|user|none]
//               [--compile-memory MIB] [--compile-cpu S]
//   jelly-grade batch SUBMISSIONS_DIR --out DIR [--jobs N] [--visibility public|all] [--timeout S]
//               [--no-frames] [--resume] [--shard I/N] [--similarity [--threshold P]]
//   jelly-grade merge BATCH_OUT... --out DIR
//   jelly-grade similarity SUBMISSIONS_DIR --out DIR [--threshold P]
//   jelly-grade generate-reference
//   jelly-grade gradescope-zip OUT.zip
//   jelly-grade prairielearn [--student DIR] [--results DIR] [--visibility ...] [--timeout S]
//               [--jobs N]
//   jelly-grade mutants [--table FILE] [--out DIR] [--check-hints [--controls DIR]] [--jobs N]
//                       [--visibility ...] [--timeout S]
//   jelly-grade hints [--check | --check-digest] [--controls DIR] [--out FILE] [--work DIR]
// Common: [--config grade-config.json] [--rubric rubric.toml]
// (grade, mutants, hints, generate-reference) [--draft]: the --assignment is a draft
//               (`draft = true`), graded only so that its author can try its grader.
//
// --runner FILE grades a runner CMake built from the student's tasks (target
// jelly-grade-student-runner) instead of compiling SUBMISSION_DIR: the self-check on Windows and
// macOS (target `selfcheck`), without a sandbox. --strict: exit status 1 unless the score is full.
//
// The command line is read by CLI11 (jelly/cli_common/command_line.hpp): each command accepts only
// its own options, and a bad one is reported by name with what it expects.
// Exit status (jelly/cli_common/exit_codes.hpp): 0 when grading ran, whatever the score (1 with
// --strict when it is not full); 1 when a self-test (mutants) fails or a batch had a grader error;
// 2 on grader errors (bad arguments, missing or stale reference data).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "commands/commands.hpp"
#include "inputs/submissions.hpp"
#include "jelly/cli_common/command_line.hpp"
#include "reports/points.hpp"

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#endif

namespace {

using namespace jelly::grade;
using jelly::cli::Command;
using jelly::cli::kExitOk;
using jelly::cli::kExitUsage;

constexpr const char* kUsage =
    "usage:\n"
    "  jelly-grade grade SUBMISSION_DIR [--visibility public|all] [--out DIR]\n"
    "                    [--format terminal,gradescope,prairielearn,junit,markdown,html]\n"
    "                    [--timeout S] [--jobs N] [--verbose] [--no-frames]\n"
    "                    [--runner FILE (a prebuilt runner: the self-check, no sandbox)] "
    "[--strict]\n"
    "  jelly-grade batch SUBMISSIONS_DIR --out DIR [--jobs N] [--visibility public|all] [--timeout "
    "S] [--no-frames]\n"
    "                    [--resume (keep what a stopped batch graded)] [--shard I/N (the I-th of "
    "N parts)]\n"
    "                    [--similarity [--threshold P] (also the similarity report)]\n"
    "  jelly-grade merge BATCH_OUT... --out DIR (join the parts of a sharded batch)\n"
    "  jelly-grade similarity SUBMISSIONS_DIR --out DIR [--threshold P (percent, default 50)]\n"
    "  jelly-grade generate-reference\n"
    "  jelly-grade gradescope-zip OUT.zip\n"
    "  jelly-grade prairielearn [--student DIR] [--results DIR] [--visibility public|all] "
    "[--timeout S] [--jobs N]\n"
    "  jelly-grade mutants [--table FILE] [--out DIR] [--check-hints [--controls DIR]] [--jobs N] "
    "[--visibility public|all] [--timeout S]\n"
    "  jelly-grade hints [--check | --check-digest] [--controls DIR] [--out FILE] [--work DIR] "
    "[--jobs N]\n"
    "  common options: --config FILE (grade-config.json), --rubric FILE,\n"
    "    --assignment ID (which assignment; inferred from a submission's files, or the build's "
    "only one)\n"
    "  grade, mutants, hints, generate-reference: --draft (the --assignment is a draft: its "
    "author tries its grader)\n"
    "  sandbox (grade, batch, prairielearn, mutants): --isolation auto|bwrap|user|none (default "
    "auto),\n"
    "    --compile-memory MIB (default 2048, at least 64), --compile-cpu S (default 120)\n"
    "exit status: 0 grading ran, whatever the score (similarity: whatever it finds; 1 with "
    "--strict when it is not full); 1 a "
    "self-test\n"
    "(mutants) failed or a batch had a grader error; 2 bad arguments, missing or stale reference "
    "data.\n";

/// Every option of every command; each command declares the ones it takes.
struct Options {
  std::string positional, config_path, rubric_path, assignment, out, visibility = "all", table,
                                                                     student, results;
  std::vector<std::string> formats{"terminal", "gradescope"};
  double timeout = 10.0, compile_memory_mib = 2048, compile_cpu = 120;
  std::string isolation = "auto", runner;
  std::vector<std::string> parts;  // merge: the batches' --out folders
  std::string shard;               // batch --shard I/N
  bool resume = false;             // batch --resume
  int jobs = 0;                    // 0: one per core
  bool strict = false;  // --strict: exit 1 unless full marks (the selfcheck target's pass/fail)
  bool verbose = false;
  bool no_frames = false;   // --no-frames: no rendered frames in report.md / report.html
  bool similarity = false;  // batch --similarity: also the similarity report
  double threshold = SimilarityOptions{}.threshold;  // --threshold P (similarity)
  HintsArgs hints;                                   // jelly-grade hints
  bool draft = false;  // --draft: grade the draft --assignment names (its author's try)
};

/// A percentage > 0 and ≤ 100.
CLI::Validator percentage() {
  return CLI::Validator(
      [](std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        return !text.empty() && end == text.c_str() + text.size() && v > 0.0 && v <= 100.0
                   ? std::string()
                   : "expected a percentage > 0 and ≤ 100, got '" + text + "'";
      },
      "");
}

/// The options COMMAND takes, declared on `cmd`.
void declare(const std::string& command, Command& cmd, Options& o) {
  using namespace jelly::cli;
  cmd.add_option("--config", o.config_path)->type_name("FILE");
  cmd.add_option("--rubric", o.rubric_path)->type_name("FILE");
  cmd.add_option("--assignment", o.assignment)->type_name("ID");
  if (command == "grade" || command == "mutants" || command == "hints" ||
      command == "generate-reference")
    cmd.add_flag("--draft", o.draft);
  const bool grades = command == "grade" || command == "batch" || command == "prairielearn" ||
                      command == "mutants" || command == "hints";
  if (grades) {
    cmd.add_option("--isolation", o.isolation)->type_name("auto|bwrap|user|none");
    cmd.add_option("--compile-memory", o.compile_memory_mib)
        ->type_name("MIB")
        ->check(number_at_least(64));
    cmd.add_option("--compile-cpu", o.compile_cpu)->type_name("S")->check(positive_number());
    cmd.add_option("--timeout", o.timeout)->type_name("S")->check(positive_number());
    cmd.add_option("--jobs", o.jobs)->type_name("N")->check(whole_number(0, 1024));
    cmd.add_option("--visibility", o.visibility)->check(one_of({"public", "all"}));
  }
  if (command == "grade") {
    cmd.add_option("SUBMISSION_DIR", o.positional)->required();
    cmd.add_option("--out", o.out)->type_name("DIR");
    cmd.add_option("--format", o.formats)
        ->type_name("F1,F2")
        ->delimiter(',')
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(one_of({"terminal", "gradescope", "prairielearn", "junit", "markdown", "html"}));
    cmd.add_flag("--verbose", o.verbose);
    cmd.add_flag("--no-frames", o.no_frames);
    cmd.add_option("--runner", o.runner)->type_name("FILE");
    cmd.add_flag("--strict", o.strict);
  } else if (command == "batch") {
    cmd.add_option("SUBMISSIONS_DIR", o.positional)->required();
    cmd.add_option("--out", o.out)->type_name("DIR")->required();
    cmd.add_flag("--no-frames", o.no_frames);
    cmd.add_flag("--resume", o.resume);
    cmd.add_option("--shard", o.shard)->type_name("I/N");
    CLI::Option* similarity_flag = cmd.add_flag("--similarity", o.similarity);
    cmd.add_option("--threshold", o.threshold)
        ->type_name("P")
        ->check(percentage())
        ->needs(similarity_flag);
  } else if (command == "merge") {
    cmd.add_option("BATCH_OUT", o.parts)->required();
    cmd.add_option("--out", o.out)->type_name("DIR")->required();
  } else if (command == "similarity") {
    cmd.add_option("SUBMISSIONS_DIR", o.positional)->required();
    cmd.add_option("--out", o.out)->type_name("DIR")->required();
    cmd.add_option("--threshold", o.threshold)->type_name("P")->check(percentage());
  } else if (command == "gradescope-zip") {
    cmd.add_option("OUT.zip", o.positional)->required();
  } else if (command == "prairielearn") {
    cmd.add_option("--student", o.student)->type_name("DIR");
    cmd.add_option("--results", o.results)->type_name("DIR");
  } else if (command == "mutants") {
    cmd.add_option("--table", o.table)->type_name("FILE");
    cmd.add_option("--out", o.out)->type_name("DIR");
    cmd.add_flag("--check-hints", o.hints.check);
    cmd.add_option("--controls", o.hints.controls)->type_name("DIR");
  } else if (command == "hints") {
    cmd.add_flag("--check", o.hints.check);
    cmd.add_flag("--check-digest", o.hints.digest);
    cmd.add_option("--controls", o.hints.controls)->type_name("DIR");
    cmd.add_option("--out", o.hints.out)->type_name("FILE");
    cmd.add_option("--work", o.hints.work)->type_name("DIR");
  }
}

/// The folder whose files name the assignment when --assignment is not given.
fs::path submission_of(const std::string& command, const Options& o) {
  fs::path submission;
  if (command == "grade")
    submission = o.positional;
  else if (command == "prairielearn")
    submission = o.student.empty() ? fs::path("/grade/student") : fs::path(o.student);
  else if (command == "batch" || command == "similarity") {
    for (const Submission& s : find_submissions(o.positional, fs::path(o.out) / ".submissions"))
      if (s.problem.empty()) {
        submission = s.dir;
        break;
      }
  }
  return submission;
}

/// The tasks' points do not add up to autograded_total: every task is scaled. Says what each one
/// is worth now, so that changing one task's points cannot silently move the others.
void say_scaled_rubric(const GradeConfig& config, const CaseBook& book, const Options& o) {
  const double scale = book.rubric.scale();
  if (!(std::abs(scale - 1.0) > 1e-12 && scale > 0.0)) return;
  std::ostringstream say;
  say << "jelly-grade: " << (o.rubric_path.empty() ? config.rubric_path().string() : o.rubric_path)
      << ": the tasks' points add up to " << pts(book.rubric.raw_total())
      << ", not autograded_total = " << pts(book.rubric.autograded_total)
      << ", so every task is scaled by " << pts(book.rubric.autograded_total) << "/"
      << pts(book.rubric.raw_total()) << ". Each task is graded out of:";
  for (const TaskSpec& t : book.rubric.tasks)
    say << "\n  " << t.id << " " << pts(t.points * scale) << " (written " << pts(t.points)
        << (t.bonus ? ", bonus" : "") << ")";
  std::cerr << say.str() << "\n";
}

/// The grading options of the command line (the sandbox is chosen in run()).
GradeOptions grade_options(const Options& o) {
  GradeOptions options;
  options.include_hidden = o.visibility == "all";
  options.timeout_s = o.timeout;
  options.jobs = o.jobs;
  options.build_limits.memory_bytes = static_cast<std::size_t>(o.compile_memory_mib * (1 << 20));
  options.build_limits.cpu_s = o.compile_cpu;
  return options;
}

/// --shard I/N with 1 <= I <= N into `args`; false when it is not that.
bool read_shard(const std::string& shard, BatchArgs& args) {
  const auto slash = shard.find('/');
  const auto whole = [](const std::string& t) {
    return !t.empty() && t.size() <= 6 && t.find_first_not_of("0123456789") == std::string::npos;
  };
  const std::string i = slash == std::string::npos ? "" : shard.substr(0, slash);
  const std::string n = slash == std::string::npos ? "" : shard.substr(slash + 1);
  if (!whole(i) || !whole(n) || std::stoi(i) < 1 || std::stoi(i) > std::stoi(n)) return false;
  args.shard_index = std::stoi(i);
  args.shard_count = std::stoi(n);
  return true;
}

int run_grade(const GradeConfig& config, const CaseBook& book, const Options& o,
              const GradeOptions& options) {
  GradeOneArgs args;
  args.submission = o.positional;
  args.out = o.out;
  args.formats = std::set<std::string>(o.formats.begin(), o.formats.end());
  args.verbose = o.verbose;
  args.frames = !o.no_frames;
  args.strict = o.strict;
  return grade_one(config, book, args, options);
}

int run_batch(const GradeConfig& config, const CaseBook& book, const Options& o,
              const GradeOptions& options, const Command& cmd) {
  BatchArgs args;
  args.in = o.positional;
  args.out = o.out;
  args.jobs = o.jobs;
  args.frames = !o.no_frames;
  args.resume = o.resume;
  if (!o.shard.empty() && !read_shard(o.shard, args))
    return cmd.error("--shard " + o.shard +
                     ": expected I/N, the I-th of N parts with 1 <= I <= N (e.g. 2/4)");
  if (o.similarity) {
    similarity_tool();  // missing: say so before grading
    args.similarity = o.threshold;
  }
  // Every grading run says which sandbox it grades in (grade: its summary's second line).
  const Isolation& iso = options.isolation;
  std::cout << "jelly-grade: sandbox: "
            << (iso.description.rfind("none", 0) == 0 || iso.description.empty()
                    ? (iso.description.empty() ? iso.name : iso.description)
                    : iso.name + " — " + iso.description)
            << "\n"
            << std::flush;
  return batch(config, book, args, options);
}

int run(const std::string& command, const Options& o, const Command& cmd) {
  GradeConfig config = load_config(o.config_path);
  const fs::path submission = submission_of(command, o);
  // merge: the assignment the batches were graded for.
  select_assignment(
      config,
      command == "merge" && o.assignment.empty() ? batch_assignment(o.parts.front()) : o.assignment,
      submission, o.draft);
  // Compares source text: no reference data, no sandbox.
  if (command == "similarity") return similarity_command(config, o.positional, o.out, o.threshold);
  // A rubric change reaches this grader at once, Gradescope and the self-check only when remade.
  if (const std::string notice = stale_gradescope_zip_notice(config);
      !notice.empty() && command != "gradescope-zip")
    std::cerr << notice << "\n";
  const CaseBook book = load_case_book(config, o.rubric_path);
  say_scaled_rubric(config, book, o);
  GradeOptions options = grade_options(o);
  // Student code is compiled and run only by these commands: the sandbox is chosen once for them.
  if (!o.runner.empty() && o.isolation != "auto" && o.isolation != "none")
    return cmd.error(
        "--runner runs your own code without a sandbox: --isolation must be auto or none");
  options.runner = o.runner;
  if (!o.runner.empty())
    options.isolation = own_machine_isolation();
  else if (command == "grade" || command == "batch" || command == "prairielearn" ||
           command == "mutants" || (command == "hints" && !o.hints.digest))
    options.isolation = choose_isolation(config, o.isolation);
  if (command == "grade") return run_grade(config, book, o, options);
  if (command == "batch") return run_batch(config, book, o, options, cmd);
  if (command == "merge") return merge(config, book, o.parts, o.out);
  if (command == "generate-reference") return generate_reference(config, book);
  if (command == "gradescope-zip") return gradescope_zip(config, o.positional);
  if (command == "prairielearn") return prairielearn(config, book, o.student, o.results, options);
  if (command == "hints") return hints(config, book, o.hints, o.jobs, options);
  return mutants(config, book, o.table, o.out, o.jobs, options, o.hints.check ? &o.hints : nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  const std::set<std::string> commands{
      "grade",          "batch",        "merge",   "similarity", "generate-reference",
      "gradescope-zip", "prairielearn", "mutants", "hints"};
  const std::string command = argc >= 2 ? argv[1] : "";
  if (command == "-h" || command == "--help" || command == "help") {
    std::cout << kUsage;
    return kExitOk;
  }
  if (!commands.count(command)) {
    if (!command.empty()) std::cerr << "jelly-grade: unknown command " << command << "\n";
    std::cerr << kUsage;
    return kExitUsage;
  }
  // One thread per grading case (cases already run in parallel), and the same bits every run.
#ifdef _WIN32
  _putenv_s("OMP_NUM_THREADS", "1");
  SetConsoleOutputCP(CP_UTF8);  // the report is UTF-8 ("—", "✗"): a console shows it as such
#else
  setenv("OMP_NUM_THREADS", "1", 1);
#endif
  Command cmd("jelly-grade " + command, kUsage, kUsage);
  Options o;
  declare(command, cmd, o);
  if (const auto code = cmd.parse_args(argc, argv, 2)) return *code;
  try {
    return run(command, o, cmd);
  } catch (const std::exception& e) {
    std::cerr << "jelly-grade: " << e.what() << "\n";
    return kExitUsage;
  }
}
