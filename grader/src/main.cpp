// jelly-grade: the headless autograder (docs/grader.md).
//
//   jelly-grade grade SUBMISSION_DIR [--visibility public|all] [--out DIR]
//               [--format terminal,gradescope,prairielearn,junit,markdown,html] [--timeout S]
//               [--jobs N] [--verbose] [--no-frames] [--runner FILE] [--strict]
//   (grade, batch, prairielearn, mutants) [--isolation auto|bwrap|user|none]
//               [--compile-memory MIB] [--compile-cpu S]
//   jelly-grade batch SUBMISSIONS_DIR --out DIR [--jobs N] [--visibility public|all]
//   jelly-grade generate-reference
//   jelly-grade gradescope-zip OUT.zip
//   jelly-grade prairielearn [--student DIR] [--results DIR]
//   jelly-grade mutants [--table FILE] [--jobs N]
// Common: [--config grade-config.json] [--rubric rubric.toml]
//
// --runner FILE grades a runner CMake built from the student's tasks (target
// jelly-grade-student-runner) instead of compiling SUBMISSION_DIR: the self-check on Windows and
// macOS (target `selfcheck`), without a sandbox. --strict: exit status 1 unless the score is full.
//
// Exit status: 0 when grading ran, whatever the score (1 with --strict when it is not full); 1 when a self-test (mutants) fails or a batch
// had a grader error; 2 on grader errors (bad arguments, missing or stale reference data).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "report.hpp"

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#endif

namespace {

using namespace jelly::grade;

int usage(const char* message = nullptr) {
  if (message) std::cerr << "jelly-grade: " << message << "\n";
  std::cerr << "usage:\n"
               "  jelly-grade grade SUBMISSION_DIR [--visibility public|all] [--out DIR]\n"
               "                    [--format terminal,gradescope,prairielearn,junit,markdown,html]\n"
               "                    [--timeout S] [--jobs N] [--verbose] [--no-frames]\n"
               "                    [--runner FILE (a prebuilt runner: the self-check, no sandbox)] [--strict]\n"
               "  jelly-grade batch SUBMISSIONS_DIR --out DIR [--jobs N] [--visibility public|all]\n"
               "  jelly-grade generate-reference\n"
               "  jelly-grade gradescope-zip OUT.zip\n"
               "  jelly-grade prairielearn [--student DIR] [--results DIR]\n"
               "  jelly-grade mutants [--table FILE] [--jobs N]\n"
               "  common options: --config FILE (grade-config.json), --rubric FILE\n"
               "  sandbox (grade, batch, prairielearn, mutants): --isolation auto|bwrap|user|none (default auto),\n"
               "    --compile-memory MIB (default 2048), --compile-cpu S (default 120)\n";
  return 2;
}

std::set<std::string> split(const std::string& s) {
  std::set<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.insert(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  // One thread per grading case (cases already run in parallel), and the same bits every run.
#ifdef _WIN32
  _putenv_s("OMP_NUM_THREADS", "1");
  SetConsoleOutputCP(CP_UTF8);  // the report is UTF-8 ("—", "✗"): a console shows it as such
#else
  setenv("OMP_NUM_THREADS", "1", 1);
#endif
  const std::string command = argv[1];
  std::vector<std::string> positional;
  std::string config_path, rubric_path, out, visibility = "all", formats = "terminal,gradescope", table, student,
                                             results;
  double timeout = 10.0, compile_memory_mib = 2048, compile_cpu = 120;
  std::string isolation = "auto", runner;
  bool strict = false;  // --strict: exit 1 unless full marks (the selfcheck target's pass/fail)
  int jobs = 0;
  bool verbose = false;
  bool no_frames = false;  // --no-frames: no rendered frames in report.md / report.html
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--config") config_path = value();
      else if (a == "--rubric") rubric_path = value();
      else if (a == "--out") out = value();
      else if (a == "--visibility") visibility = value();
      else if (a == "--format") formats = value();
      else if (a == "--timeout") timeout = std::stod(value());
      else if (a == "--jobs") jobs = std::stoi(value());
      else if (a == "--table") table = value();
      else if (a == "--student") student = value();
      else if (a == "--results") results = value();
      else if (a == "--isolation") isolation = value();
      else if (a == "--compile-memory") compile_memory_mib = std::stod(value());
      else if (a == "--compile-cpu") compile_cpu = std::stod(value());
      else if (a == "--verbose") verbose = true;
      else if (a == "--no-frames") no_frames = true;
      else if (a == "--runner") runner = value();
      else if (a == "--strict") strict = true;
      else if (!a.empty() && a[0] == '-') return usage(("unknown option " + a).c_str());
      else positional.push_back(a);
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (visibility != "public" && visibility != "all") return usage("--visibility must be public or all");
  if (!(timeout > 0)) return usage("--timeout must be > 0 seconds");
  if (!(compile_memory_mib >= 64)) return usage("--compile-memory must be at least 64 (MiB)");
  if (!(compile_cpu > 0)) return usage("--compile-cpu must be > 0 seconds");
  try {
    const GradeConfig config = load_config(config_path);
    const CaseBook book = load_case_book(config, rubric_path);
    GradeOptions options;
    options.include_hidden = visibility == "all";
    options.timeout_s = timeout;
    options.jobs = jobs;
    options.build_limits.memory_bytes = static_cast<std::size_t>(compile_memory_mib * (1 << 20));
    options.build_limits.cpu_s = compile_cpu;
    // Student code is compiled and run only by these commands: the sandbox is chosen once for them.
    if (!runner.empty() && command != "grade") return usage("--runner is an option of grade only");
    if (!runner.empty() && isolation != "auto" && isolation != "none")
      return usage("--runner runs your own code without a sandbox: --isolation must be auto or none");
    options.runner = runner;
    if (!runner.empty()) options.isolation = own_machine_isolation();
    else if (command == "grade" || command == "batch" || command == "prairielearn" || command == "mutants")
      options.isolation = choose_isolation(config, isolation);
    if (command == "grade") {
      if (positional.size() != 1) return usage("grade needs one SUBMISSION_DIR");
      const std::set<std::string> f = split(formats);
      for (const std::string& x : f)
        if (!std::set<std::string>{"terminal", "gradescope", "prairielearn", "junit", "markdown", "html"}.count(x))
          return usage(("unknown format " + x).c_str());
      const fs::path out_dir = out.empty() ? fs::path("grade-results") : fs::path(out);
      const fs::path work = out_dir / ".work";
      fs::remove_all(work);
      const GradeReport r = grade_submission(config, book, positional[0], work, options);
      std::set<std::string> files = f;
      files.erase("terminal");
      if (!files.empty()) write_reports(r, book, out_dir, files, no_frames ? nullptr : &config);
      // JELLY_GRADE_KEEP_WORK=1 keeps the built runner (out/.work/build/runner) for experiments
      // such as the tolerance measurements of docs/tolerances.md.
      if (!std::getenv("JELLY_GRADE_KEEP_WORK")) fs::remove_all(work);
      if (f.count("terminal")) std::cout << terminal_summary(r, verbose);
      return strict && !(r.compiled && r.max_score > 0 && r.score >= r.max_score - 1e-9) ? 1 : 0;
    }
    if (command == "batch") {
      if (positional.size() != 1 || out.empty()) return usage("batch needs SUBMISSIONS_DIR and --out DIR");
      return batch(config, book, positional[0], out, jobs, options, !no_frames);
    }
    if (command == "generate-reference") return generate_reference(config, book);
    if (command == "gradescope-zip") {
      if (positional.size() != 1) return usage("gradescope-zip needs OUT.zip");
      return gradescope_zip(config, positional[0]);
    }
    if (command == "prairielearn") {
      const fs::path s = student.empty() ? fs::path("/grade/student") : fs::path(student);
      const fs::path res = results.empty() ? fs::path("/grade/results") : fs::path(results);
      fs::create_directories(res);
      const fs::path work = res / ".work";
      const GradeReport r = grade_submission(config, book, s, work, options);
      fs::remove_all(work);
      std::ofstream(res / "results.json") << prairielearn_results(r).dump(2) << "\n";
      std::cout << terminal_summary(r, false);
      return 0;
    }
    if (command == "mutants") return mutants(config, book, table, out, jobs, options);
    return usage(("unknown command " + command).c_str());
  } catch (const std::exception& e) {
    std::cerr << "jelly-grade: " << e.what() << "\n";
    return 2;
  }
}
