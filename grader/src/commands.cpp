#include "commands.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

#include <toml++/toml.h>

#include "csv.hpp"
#include "files.hpp"
#include "report.hpp"
#include "text_safety.hpp"

namespace jelly::grade {

namespace {

std::string run_text(const std::vector<std::string>& argv, const fs::path& cwd = {}) {
  const Limits lim = trusted_tool_limits(120.0, 16 << 20);
  const ChildResult c = run_child(argv, lim, cwd);
  if (c.exit_code != 0) return "";
  return c.out;
}

std::string git_commit(const fs::path& dir) {
  std::string s = run_text({"/usr/bin/git", "-C", dir.string(), "rev-parse", "HEAD"});
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s.empty() ? "unknown" : s;
}

std::string pts(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

}  // namespace

std::string sandbox_setup_lines(const std::string& source) {
  // One sandbox user per core: each concurrent compile or test runs as a user of its own, so that
  // killing what one run left behind never touches another (isolation.hpp).
  const std::string user = std::string(kSandboxUser) + "-$i";
  return std::string("for i in $(seq 0 $(( $(nproc) - 1 ))); do id -u ") + user +
         " >/dev/null 2>&1 || useradd --system --no-create-home --user-group --shell " +
         "/usr/sbin/nologin " + user + "; done\n" + "chown root:root " + source + "/grader/data " +
         source + "/grader/cases\n" + "chmod 0700 " + source + "/grader/data " + source +
         "/grader/cases\n" + "if [ -d " + source +
         "/build/grader/object-cache ]; then chmod 0700 " + source +
         "/build/grader/object-cache; fi\n";
}

int generate_reference(const GradeConfig& config, const CaseBook& book) {
  if (config.reference_runner.empty() || !fs::exists(config.reference_runner)) {
    std::cerr
        << "jelly-grade: generate-reference needs the reference runner (solutions/ must exist and "
           "jelly-grade-reference-runner must be built)\n";
    return 2;
  }
  const std::string listing = run_text({config.reference_runner.string(), "--list"});
  std::map<std::string, std::string> descriptions;
  std::istringstream in(listing);
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) descriptions[line.substr(0, tab)] = line.substr(tab + 1);
  }
  const std::string digest = harness_digest(config);
  const std::string commit = git_commit(config.source_dir);
  const fs::path work = config.binary_dir / "grader" / "generate";
  fs::create_directories(work);
  std::set<fs::path> written;
  for (const CaseSpec& c : book.cases) {
    if (!descriptions.count(c.generator)) {
      std::cerr << "jelly-grade: " << c.source << ": case " << c.id
                << ": the runner has no generator \"" << c.generator
                << "\" (see jelly-grade-reference-runner --list)\n";
      return 2;
    }
    const ChildResult prep = run_case(config.reference_runner, c, nullptr, work, 120.0, 0, true);
    Json input = Json::object();
    try {
      const Json prepared = Json::parse(prep.result);
      if (prepared.contains("error"))
        throw std::runtime_error(prepared["error"].get<std::string>());
      input = prepared.at("input");
    } catch (const std::exception& e) {
      std::cerr << "jelly-grade: preparing " << c.id << " failed: " << e.what() << " " << prep.err
                << "\n";
      return 2;
    }
    const ChildResult run = run_case(config.reference_runner, c, &input, work, 120.0, 0);
    Json result;
    try {
      result = Json::parse(run.result);
    } catch (const std::exception&) {
      std::cerr << "jelly-grade: the reference failed on " << c.id << " (exit " << run.exit_code
                << ", signal " << run.signal << "): " << run.err << "\n";
      return 2;
    }
    if (!result.contains("outputs")) {
      std::cerr << "jelly-grade: the reference failed on " << c.id << ": " << result.dump() << "\n";
      return 2;
    }
    // Recorded frames (rule "frames") are for the report only: never stored as reference data;
    // nor are the details that explain a student's value (Outputs::detail).
    Json outputs = Json::object();
    for (const auto& [name, value] : result["outputs"].items())
      if (c.rule_for(name).kind != Rule::Kind::Frames) {
        outputs[name] = value;
        outputs[name].erase("detail_low");
        outputs[name].erase("detail_high");
      }
    if (outputs.dump().find("null") != std::string::npos) {
      std::cerr << "jelly-grade: the reference produced NaN or infinity in " << c.id
                << "; fix the case before generating reference data\n";
      return 2;
    }
    Json data;
    data["format_version"] = kReferenceFormat;
    data["case_id"] = c.id;
    data["case_hash"] = case_hash(c, digest);
    data["case_generator"] = c.generator;
    data["params"] = c.params;
    data["harness_digest"] = digest;
    data["generator"] = "jelly-grade generate-reference (jelly-grade-reference-runner, solutions/)";
    data["commit"] = commit;
    data["compiler"] = config.compiler_id;
    std::string flags;
    for (const std::string& f : config.compile_flags) flags += (flags.empty() ? "" : " ") + f;
    data["flags"] = flags;
    if (!input.empty()) data["input"] = input;
    data["outputs"] = outputs;
    const fs::path p = reference_path(config, c);
    fs::create_directories(p.parent_path());
    std::ofstream(p) << data.dump(1) << "\n";
    written.insert(p);
  }
  // Remove data of cases that no longer exist.
  for (const char* vis : {"public", "hidden"}) {
    const fs::path dir = config.data_dir(vis);
    if (!fs::exists(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json" && !written.count(e.path())) fs::remove(e.path());
  }
  std::cout << "jelly-grade: wrote reference data for " << written.size() << " cases (commit "
            << commit << ")\n";
  return 0;
}

int batch(const GradeConfig& config, const CaseBook& book, const std::string& dir,
          const std::string& out, int jobs, const GradeOptions& options, bool frames) {
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
  const int workers =
      jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<GradeReport> reports(subs.size());
  std::vector<std::string> errors(subs.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex mutex;
  GradeOptions per = options;
  per.jobs = 1;  // parallel across students, serial within one
  auto worker = [&]() {
    for (;;) {
      const std::size_t i = next++;
      if (i >= subs.size()) return;
      const std::string name = subs[i].filename().string();
      try {
        reports[i] = grade_submission(config, book, subs[i], students / name / "work", per);
        write_reports(reports[i], book, students / name, {"gradescope", "markdown"},
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
      std::cerr << "\r[" << done << "/" << subs.size() << "] " << safe_text(name) << ": "
                << (errors[i].empty() ? pts(reports[i].score) + " / " + pts(reports[i].max_score)
                                      : "grader error")
                << "            " << std::flush;
    }
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < workers; ++i) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  std::cerr << "\n";
  std::vector<std::string> header = {"student", "score", "max_score", "compiled"};
  for (const TaskSpec& t : book.rubric.tasks) header.push_back(csv_field(t.id));
  header.push_back("error");
  std::string csv = csv_row(header);
  int status = 0;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    std::vector<std::string> row = {csv_field(safe_text(subs[i].filename().string()))};
    if (!errors[i].empty()) {
      for (std::size_t k = 0; k < 3 + book.rubric.tasks.size(); ++k) row.push_back("");
      row.push_back(csv_field(safe_text(errors[i])));
      status = 1;
    } else {
      row.push_back(pts(reports[i].score));
      row.push_back(pts(reports[i].max_score));
      row.push_back(reports[i].compiled ? "1" : "0");
      for (const TaskResult& t : reports[i].tasks) row.push_back(pts(t.score));
      row.push_back("");
    }
    csv += csv_row(row);
  }
  write_file_atomically(fs::path(out) / "scores.csv", csv);
  std::cout << "jelly-grade: graded " << subs.size() << " submissions into " << out
            << " (scores.csv; each student's reports in students/)\n";
  return status;
}

namespace {

/// Copies the header folder INCLUDE_DIR/SUBDIR (which must hold FILE) into the zip's
/// source/third_party/NAME/include/SUBDIR with the first licence that exists; says what is
/// missing and returns false when the headers are not there.
bool bundle_headers(const fs::path& stage, const std::string& name, const fs::path& include_dir,
                    const std::string& subdir, const std::string& file,
                    const std::vector<fs::path>& licences, const std::string& package) {
  const fs::path headers = include_dir / subdir;
  const fs::path bundle = stage / "source" / "third_party" / name;
  if (!fs::exists(headers / file)) {
    std::cerr << "jelly-grade: gradescope-zip: " << name << " headers not found at "
              << headers.string() << " (expected " << file << " there; install " << package
              << ")\n";
    return false;
  }
  fs::create_directories(bundle / "include");
  fs::copy(headers, bundle / "include" / subdir, fs::copy_options::recursive);
  for (const fs::path& licence : licences)
    if (fs::exists(licence)) {
      fs::copy_file(licence, bundle / "LICENSE", fs::copy_options::overwrite_existing);
      break;
    }
  return true;
}

/// setup.sh's compiler check, between its BEGIN/END lines (tests/grader/setup_compiler_check.sh
/// runs the block alone with stand-in compilers). The framework needs GCC 11 or newer
/// (floating-point std::to_chars) and CMake 3.16 or newer. Gradescope's Ubuntu 22.04 base image has
/// GCC 11.4 and CMake 3.22; on an older image the block installs g++-11 where the archive has it,
/// else it stops naming what to choose. The compiler it settles on is exported as CXX for CMake.
std::string compiler_check_lines() {
  return R"SH(# BEGIN compiler check: GCC 11+ (floating-point std::to_chars), CMake 3.16+
cxx="${CXX:-g++}"
gcc_major() {
  { "$1" -dumpfullversion -dumpversion 2>/dev/null | head -1 | cut -d. -f1; } || true
}
if ! { "$cxx" --version 2>/dev/null || true; } | head -1 | grep -qi clang; then
  major="$(gcc_major "$cxx")"
  if [ -z "$major" ] || [ "$major" -lt 11 ]; then
    echo "setup.sh: $cxx is GCC ${major:-(not found)}; Jelly Lab needs GCC 11 or newer" \
         "(floating-point std::to_chars). Installing g++-11."
    if apt-get install -y --no-install-recommends g++-11 &&
       [ "$(gcc_major g++-11)" -ge 11 ] 2>/dev/null; then
      cxx=g++-11
    else
      echo "setup.sh: FAILED: no GCC 11 or newer on this image. Choose Gradescope's Ubuntu" \
           "22.04 base image (GCC 11.4, CMake 3.22), the one Jelly Lab is tested with." >&2
      exit 1
    fi
  fi
fi
cmake_version="$({ cmake --version 2>/dev/null || true; } | head -1 | awk '{ print $3 }')"
if [ -z "$cmake_version" ] ||
   [ "$(printf '%s\n3.16\n' "$cmake_version" | sort -V | head -1)" != 3.16 ]; then
  echo "setup.sh: FAILED: CMake ${cmake_version:-(not found)}; Jelly Lab needs CMake 3.16 or" \
       "newer. Choose Gradescope's Ubuntu 22.04 base image (CMake 3.22)." >&2
  exit 1
fi
export CXX="$cxx"
echo "setup.sh: compiler $CXX ($("$CXX" --version | head -1)), CMake $cmake_version"
# END compiler check
)SH";
}

}  // namespace

int gradescope_zip(const GradeConfig& config, const std::string& zip_path) {
  const fs::path stage = config.binary_dir / "grader" / "gradescope-zip";
  fs::remove_all(stage);
  // The staging folder holds the hidden data and cases: it goes as soon as the zip is written (or
  // failed), whatever happens.
  struct RemoveStage {
    fs::path dir;
    ~RemoveStage() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } remove_stage{stage};
  fs::create_directories(stage / "source");
  // The framework as a student release has it, plus the grader's hidden data; never solutions/.
  // Everything, setup.sh and run_autograder included, sits at the zip's top level: Gradescope
  // extracts the zip into /autograder/source, where both scripts expect the framework's
  // CMakeLists.txt (and copies run_autograder to /autograder/run_autograder).
  for (const char* item : {"CMakeLists.txt", "cmake", "framework", "assignments", "grader"}) {
    const fs::path from = config.source_dir / item;
    if (!fs::exists(from)) continue;
    fs::copy(from, stage / "source" / item, fs::copy_options::recursive);
  }
  // Not needed to grade, and the mutants quote the reference solution.
  fs::remove_all(stage / "source" / "grader" / "tests");
  fs::remove_all(stage / "source" / "grader" / "mutants");
  // toml++'s and CLI11's headers, for an image without libtomlplusplus-dev or libcli11-dev
  // (Gradescope's Ubuntu): the build then uses them header-only (cmake/JellyDeps.cmake). Taken from
  // this machine, with their licences.
  if (!bundle_headers(stage, "tomlplusplus", JELLY_TOMLPLUSPLUS_INCLUDE_DIR, "toml++", "toml.h",
                      {"/usr/share/doc/libtomlplusplus-dev/copyright",
                       JELLY_TOMLPLUSPLUS_INCLUDE_DIR "/../LICENSE"},
                      "libtomlplusplus-dev") ||
      !bundle_headers(
          stage, "cli11", JELLY_CLI11_INCLUDE_DIR, "CLI", "CLI.hpp",
          {"/usr/share/doc/libcli11-dev/copyright", JELLY_CLI11_INCLUDE_DIR "/../LICENSE"},
          "libcli11-dev"))
    return 2;
  std::ofstream(stage / "source" / "setup.sh")
      << "#!/usr/bin/env bash\n"
         "# Gradescope image setup (runs once): dependencies, then the framework and jelly-grade.\n"
         "set -euo pipefail\n"
         "apt-get update\n"
         "apt-get install -y --no-install-recommends cmake g++ make libeigen3-dev "
         "nlohmann-json3-dev "
         "libseccomp-dev bubblewrap\n"
         "# toml++ and CLI11: the packages where the distribution has them, else the headers "
         "bundled in source/.\n"
         "apt-get install -y --no-install-recommends libtomlplusplus-dev || "
         "echo 'setup.sh: no libtomlplusplus-dev; using source/third_party/tomlplusplus'\n"
         "apt-get install -y --no-install-recommends libcli11-dev || "
         "echo 'setup.sh: no libcli11-dev; using source/third_party/cli11'\n"
      << compiler_check_lines()
      << "cd /autograder/source\n"
         "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DJELLY_TASKS=assignments "
         "-DJELLY_BUILD_TESTS=OFF "
         "-DJELLY_BUILD_BENCHMARKS=OFF -DJELLY_BUILD_VIEWER=OFF\n"
         "cmake --build build -j\"$(nproc)\" --target jelly-grade\n"
         "# Warm the object cache with the stubs so that unchanged files are never recompiled.\n"
         "build/grader/jelly-grade grade assignments --visibility public --out /tmp/warm --format "
         "gradescope || true\n"
         "# Student code is compiled and run in a bubblewrap sandbox where the image allows user "
         "namespaces,\n"
         "# else as this unprivileged user, with the grader's secrets readable by root only "
         "(docs/grader.md).\n"
      << sandbox_setup_lines("/autograder/source");
  std::ofstream(stage / "source" / "run_autograder")
      << "#!/usr/bin/env bash\n"
         "# Gradescope entry point: grades /autograder/submission, writes "
         "/autograder/results/results.json.\n"
         "cd /autograder/source\n"
         "mkdir -p /autograder/results\n"
         "# Again at every run: an image made by an older setup.sh, or files restored with other "
         "modes.\n"
      << sandbox_setup_lines("/autograder/source")
      << "build/grader/jelly-grade grade /autograder/submission --visibility all --out "
         "/autograder/results "
         "--format gradescope,terminal --isolation \"${JELLY_GRADE_ISOLATION:-auto}\"\n";
  fs::permissions(stage / "source" / "setup.sh",
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(stage / "source" / "run_autograder",
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
  const fs::path zip = fs::absolute(zip_path);
  fs::remove(zip);
  const Limits lim = trusted_tool_limits(300.0);
  const ChildResult c =
      run_child({"/usr/bin/zip", "-q", "-r", zip.string(), "."}, lim, stage / "source");
  if (c.exit_code != 0) {
    std::cerr << "jelly-grade: zip failed: " << c.err << "\n";
    return 2;
  }
  std::cout << "jelly-grade: wrote " << zip.string()
            << " (setup.sh, run_autograder and the framework without solutions/, all at the top: "
               "Gradescope extracts it into /autograder/source)\n";
  return 0;
}

int mutants(const GradeConfig& config, const CaseBook& book, const std::string& table_path,
            const std::string& work, int jobs, const GradeOptions& options) {
  struct Mutant {
    std::string name, task, file, description;
    bool public_catches = false;  // the handout says the self-check catches it: a public test must
    std::vector<std::tuple<std::string, std::string, int>>
        replacements;  // find, with, nth occurrence
    fs::path dir;
    GradeReport report;
    std::string error;
  };
  std::vector<Mutant> list;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(config.mutants_dir()))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  const fs::path root = work.empty() ? config.binary_dir / "grader" / "mutants" : fs::path(work);
  fs::remove_all(root);
  // Entry 0: the reference; entry 1: the stubs; then the mutants.
  list.push_back(
      {"reference", "", "", "solutions/ unchanged", false, {}, config.solutions_dir(), {}, {}});
  list.push_back(
      {"stubs", "", "", "assignments/ unchanged", false, {}, config.assignments_dir(), {}, {}});
  for (const fs::path& f : files) {
    toml::table t = toml::parse_file(f.string());
    Mutant m;
    m.name = f.stem().string();
    m.task = t["task"].value_or(std::string());
    m.file = t["file"].value_or(std::string());
    m.description = t["description"].value_or(std::string());
    m.public_catches = t["public_catches"].value_or(false);
    if (const toml::array* reps = t["replace"].as_array())
      for (const toml::node& n : *reps) {
        const toml::table& r = *n.as_table();
        m.replacements.emplace_back(r["find"].value_or(std::string()),
                                    r["with"].value_or(std::string()),
                                    static_cast<int>(r["nth"].value_or(1)));
      }
    if (m.task.empty() || m.file.empty() || m.replacements.empty()) {
      std::cerr << "jelly-grade: " << f
                << ": a mutant needs task, file and at least one [[replace]]\n";
      return 2;
    }
    m.dir = root / m.name / "submission";
    fs::create_directories(m.dir);
    for (const std::string& name : config.task_files())
      fs::copy_file(config.solutions_dir() / name, m.dir / name,
                    fs::copy_options::overwrite_existing);
    std::string text = read_file(m.dir / m.file);
    for (const auto& [find, with, nth] : m.replacements) {
      auto at = text.find(find);
      for (int k = 1; k < nth && at != std::string::npos; ++k)
        at = text.find(find, at + find.size());
      if (find.empty() || at == std::string::npos) {
        std::cerr << "jelly-grade: " << f << ": \"" << find << "\" is not in solutions/" << m.file
                  << " (the mutant no longer applies)\n";
        return 2;
      }
      text.replace(at, find.size(), with);
    }
    std::ofstream(m.dir / m.file, std::ios::binary) << text;
    list.push_back(std::move(m));
  }
  const int workers =
      jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  GradeOptions per = options;
  per.jobs = 1;
  per.include_hidden = true;
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  auto worker = [&]() {
    for (;;) {
      const std::size_t i = next++;
      if (i >= list.size()) return;
      try {
        list[i].report =
            grade_submission(config, book, list[i].dir, root / list[i].name / "work", per);
      } catch (const std::exception& e) {
        list[i].error = e.what();
      } catch (...) {
        list[i].error = "unknown error";
      }
      std::lock_guard<std::mutex> lock(mutex);
      std::cerr << "  graded " << list[i].name << ": " << pts(list[i].report.score) << "\n";
    }
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < workers; ++i) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();

  auto task_score = [](const GradeReport& r, const std::string& id) {
    for (const TaskResult& t : r.tasks)
      if (t.spec->id == id) return t.score;
    return 0.0;
  };
  const GradeReport& ref = list[0].report;
  bool all_ok = true;
  std::ostringstream table;
  table << "| Mutant | Task | What it does | Own task | Lost elsewhere | Caught by | Public tests "
           "| Verdict |\n"
           "|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Mutant& m = list[i];
    const GradeReport& r = m.report;
    std::string verdict, own = "—", elsewhere, caught, by_public = "—";
    bool ok = m.error.empty();
    if (!ok) verdict = "grader error: " + m.error;
    if (ok && i == 0) {
      ok = r.compiled && std::abs(r.score - r.max_score) < 1e-9;
      own = pts(r.score) + " / " + pts(r.max_score);
      verdict = ok ? "full marks ✓" : "NOT full marks ✗";
      if (!ok)
        for (const CaseResult& c : r.cases)
          if (c.status == "failed") caught += c.spec->id + " ";
    } else if (ok && i == 1) {
      ok = r.compiled && r.score == 0.0;
      own = pts(r.score) + " / " + pts(r.max_score);
      verdict = ok ? "zero ✓" : "NOT zero ✗";
      for (const CaseResult& c : r.cases)
        if (c.status == "passed" && c.max_score > 0) caught += c.spec->id + " (passed!) ";
    } else if (ok) {
      const double mine = task_score(r, m.task), full = task_score(ref, m.task);
      own = pts(mine) + " / " + pts(full);
      const bool lost = r.compiled && mine < full - 1e-9;
      bool leak = !r.compiled;
      for (const TaskResult& t : r.tasks) {
        if (t.spec->id == m.task) continue;
        const double d = task_score(ref, t.spec->id) - t.score;
        if (d > 1e-9) {
          leak = true;
          elsewhere += t.spec->id + " −" + pts(d) + " ";
        }
      }
      bool public_caught = false;
      for (const CaseResult& c : r.cases)
        if (c.status == "failed" && c.spec->task == m.task) {
          caught += c.spec->id + " ";
          public_caught = public_caught || !c.spec->hidden;
        }
      by_public = std::string(public_caught ? "caught" : "missed") +
                  (m.public_catches ? " (required)" : "");
      ok = lost && !leak && (public_caught || !m.public_catches);
      verdict = !lost  ? "NOT caught ✗"
                : leak ? "loses points elsewhere ✗"
                : !ok  ? "NOT caught by a public test ✗"
                       : "caught in its task only ✓";
    }
    if (elsewhere.empty()) elsewhere = "none";
    all_ok = all_ok && ok;
    table << "| " << m.name << " | " << (m.task.empty() ? "all" : m.task) << " | " << m.description
          << " | " << own << " | " << elsewhere << " | " << (caught.empty() ? "—" : caught) << " | "
          << by_public << " | " << verdict << " |\n";
  }
  std::cout << table.str();
  if (!table_path.empty()) {
    std::ofstream f(table_path);
    f << "# Grader self-test: the mutation table\n\n"
         "Generated by `jelly-grade mutants --table docs/mutation-table.md` (CTest "
         "`grader.mutants` runs the same\n"
         "checks). Each mutant is a realistic mistake applied to a copy of `solutions/` (specs in\n"
         "`grader/mutants/*.toml`) and graded with all tests, public and hidden. A mutant must "
         "lose points in\n"
         "its own task and keep every point elsewhere; the reference must score full marks and the "
         "stubs zero.\n"
         "\"Caught by\" lists the failing tests of the mutant's own task; \"Public tests\" says "
         "whether the public\n"
         "tests alone (the student's self-check) catch it, and \"(required)\" marks the mistakes "
         "the handout says the\n"
         "self-check catches (`public_catches = true` in the mutant's file): for those, \"missed\" "
         "fails the self-test.\n\n"
      << table.str();
  }
  std::cout << (all_ok ? "jelly-grade: mutation self-test passed\n"
                       : "jelly-grade: mutation self-test FAILED\n");
  return all_ok ? 0 : 1;
}

}  // namespace jelly::grade
