#include "commands/commands.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <tuple>

#include <toml++/toml.h>

#include "grading/parallel.hpp"
#include "inputs/files.hpp"
#include "reports/points.hpp"

namespace jelly::grade {

namespace {

// A path as the table shows it: relative to the checkout when inside it ("solutions/<id>").
std::string in_tree(const GradeConfig& config, const fs::path& p) {
  const fs::path rel =
      p.lexically_normal().lexically_relative(config.source_dir.lexically_normal());
  if (rel.empty() || *rel.begin() == "..") return p.string();
  std::string s = rel.generic_string();
  while (!s.empty() && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

std::vector<MutantSpec> make_mutant_folders(const GradeConfig& config, const fs::path& specs_dir,
                                            const fs::path& root) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(specs_dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<MutantSpec> out;
  for (const fs::path& f : files) {
    toml::table t = toml::parse_file(f.string());
    MutantSpec m;
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
    if (m.task.empty() || m.file.empty() || m.replacements.empty())
      throw std::runtime_error(f.string() +
                               ": a mutant needs task, file and at least one [[replace]]");
    m.dir = root / m.name / "submission";
    fs::create_directories(m.dir);
    for (const std::string& name : config.task_files())
      fs::copy_file(config.reference_dir() / name, m.dir / name,
                    fs::copy_options::overwrite_existing);
    std::string text = read_file(m.dir / m.file);
    for (const auto& [find, with, nth] : m.replacements) {
      auto at = text.find(find);
      for (int k = 1; k < nth && at != std::string::npos; ++k)
        at = text.find(find, at + find.size());
      if (find.empty() || at == std::string::npos)
        throw std::runtime_error(f.string() + ": \"" + find + "\" is not in solutions/" + m.file +
                                 " (the mutant no longer applies)");
      text.replace(at, find.size(), with);
    }
    std::ofstream(m.dir / m.file, std::ios::binary) << text;
    out.push_back(std::move(m));
  }
  return out;
}

namespace {

/// One row of the table: a submission (the reference, the stubs or a mutant) and its grading.
struct Mutant {
  std::string name, task, file, description;
  bool public_catches = false;  // the handout says the self-check catches it: a public test must
  std::vector<std::tuple<std::string, std::string, int>>
      replacements;  // find, with, nth occurrence
  fs::path dir;
  GradeReport report;
  std::string error;
};

/// Entry 0: the reference; entry 1: the stubs; then the mutants (their folders made under root).
std::vector<Mutant> mutant_list(const GradeConfig& config, const fs::path& root) {
  std::vector<Mutant> list;
  list.push_back({"reference",
                  "",
                  "",
                  in_tree(config, config.solutions_dir()) + "/ unchanged",
                  false,
                  {},
                  config.reference_dir(),
                  {},
                  {}});
  list.push_back({"stubs",
                  "",
                  "",
                  in_tree(config, config.assignments_dir()) + "/ unchanged",
                  false,
                  {},
                  config.assignments_dir(),
                  {},
                  {}});
  for (MutantSpec& spec : make_mutant_folders(config, config.mutants_dir(), root)) {
    Mutant m;
    m.name = spec.name, m.task = spec.task, m.file = spec.file;
    m.description = spec.description, m.public_catches = spec.public_catches;
    m.replacements = spec.replacements, m.dir = spec.dir;
    list.push_back(std::move(m));
  }
  return list;
}

/// Grades every entry with all tests, public and hidden.
void grade_all(const GradeConfig& config, const CaseBook& book, std::vector<Mutant>& list,
               const fs::path& root, int jobs, const GradeOptions& options) {
  GradeOptions per = options;
  per.jobs = 1;
  per.include_hidden = true;
  per.hints = false;  // the table is about points, not about the hints (jelly-grade hints)
  std::mutex mutex;
  parallel_for(list.size(), jobs, [&](std::size_t i) {
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
  });
}

double task_score(const GradeReport& r, const std::string& id) {
  for (const TaskResult& t : r.tasks)
    if (t.spec->id == id) return t.score;
  return 0.0;
}

/// A row's verdict and the columns that explain it.
struct Verdict {
  bool ok = true;
  std::string verdict, own = "—", elsewhere, caught, by_public = "—";
};

/// The reference must score full marks.
Verdict judge_reference(const GradeReport& r) {
  Verdict v;
  v.ok = r.compiled && std::abs(r.score - r.max_score) < 1e-9 &&
         std::abs(r.bonus_score - r.bonus_max) < 1e-9;
  v.own = pts(r.score) + " / " + pts(r.max_score) +
          (r.has_bonus() ? " + bonus " + pts(r.bonus_score) + " / " + pts(r.bonus_max) : "");
  v.verdict = v.ok ? "full marks ✓" : "NOT full marks ✗";
  if (!v.ok)
    for (const CaseResult& c : r.cases)
      if (c.status == "failed") v.caught += c.spec->id + " ";
  return v;
}

/// The stubs must score zero.
Verdict judge_stubs(const GradeReport& r) {
  Verdict v;
  v.ok = r.compiled && r.score == 0.0 && r.bonus_score == 0.0;
  v.own = pts(r.score) + " / " + pts(r.max_score) +
          (r.has_bonus() ? " + bonus " + pts(r.bonus_score) : "");
  v.verdict = v.ok ? "zero ✓" : "NOT zero ✗";
  for (const CaseResult& c : r.cases)
    if (c.status == "passed" && c.max_score > 0) v.caught += c.spec->id + " (passed!) ";
  return v;
}

/// A mutant must lose points in its own task, keep every point elsewhere, and be caught by a
/// public test when its file says the self-check catches it.
Verdict judge_mutant(const Mutant& m, const GradeReport& ref) {
  const GradeReport& r = m.report;
  Verdict v;
  const double mine = task_score(r, m.task), full = task_score(ref, m.task);
  v.own = pts(mine) + " / " + pts(full);
  const bool lost = r.compiled && mine < full - 1e-9;
  bool leak = !r.compiled;
  for (const TaskResult& t : r.tasks) {
    if (t.spec->id == m.task) continue;
    const double d = task_score(ref, t.spec->id) - t.score;
    if (d > 1e-9) {
      leak = true;
      v.elsewhere += t.spec->id + " −" + pts(d) + " ";
    }
  }
  bool public_caught = false;
  for (const CaseResult& c : r.cases)
    if (c.status == "failed" && c.spec->task == m.task) {
      v.caught += c.spec->id + " ";
      public_caught = public_caught || !c.spec->hidden;
    }
  v.by_public =
      std::string(public_caught ? "caught" : "missed") + (m.public_catches ? " (required)" : "");
  v.ok = lost && !leak && (public_caught || !m.public_catches);
  v.verdict = !lost   ? "NOT caught ✗"
              : leak  ? "loses points elsewhere ✗"
              : !v.ok ? "NOT caught by a public test ✗"
                      : "caught in its task only ✓";
  return v;
}

/// The Markdown table of every entry; `all_ok` tells whether every row's verdict is good.
std::string mutation_table(const std::vector<Mutant>& list, bool& all_ok) {
  const GradeReport& ref = list[0].report;
  all_ok = true;
  std::ostringstream table;
  table << "| Mutant | Task | What it does | Own task | Lost elsewhere | Caught by | Public tests "
           "| Verdict |\n"
           "|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Mutant& m = list[i];
    Verdict v;
    if (!m.error.empty()) {
      v.ok = false;
      v.verdict = "grader error: " + m.error;
    } else if (i == 0) {
      v = judge_reference(m.report);
    } else if (i == 1) {
      v = judge_stubs(m.report);
    } else {
      v = judge_mutant(m, ref);
    }
    if (v.elsewhere.empty()) v.elsewhere = "none";
    all_ok = all_ok && v.ok;
    table << "| " << m.name << " | " << (m.task.empty() ? "all" : m.task) << " | " << m.description
          << " | " << v.own << " | " << v.elsewhere << " | " << (v.caught.empty() ? "—" : v.caught)
          << " | " << v.by_public << " | " << v.verdict << " |\n";
  }
  return table.str();
}

/// docs/mutation-table*.md: the table under a header that says how it was made.
void write_table_file(const GradeConfig& config, const std::string& table_path,
                      const std::string& table) {
  std::ofstream f(table_path);
  f << "# Grader self-test: the mutation table\n\n"
       "Generated by `jelly-grade mutants --assignment "
    << config.assignment().id << config.assignment().draft_option() << " --table "
    << in_tree(config, fs::absolute(table_path))
    << "` (CTest `grader.mutants` runs the same\n"
       "checks). Each mutant is a realistic mistake applied to a copy of `"
    << in_tree(config, config.solutions_dir()) << "/` (specs in\n`"
    << in_tree(config, config.mutants_dir())
    << "/*.toml`) and graded with all tests, public and hidden. A mutant must "
       "lose points in\n"
       "its own task and keep every point elsewhere; the reference must score full marks and the "
       "stubs zero.\n"
       "\"Caught by\" lists the failing tests of the mutant's own task; \"Public tests\" says "
       "whether the public\n"
       "tests alone (the student's self-check) catch it, and \"(required)\" marks the mistakes "
       "the handout says the\n"
       "self-check catches (`public_catches = true` in the mutant's file): for those, \"missed\" "
       "fails the self-test.\n\n"
    << table;
}

}  // namespace

int mutants(const GradeConfig& config, const CaseBook& book, const std::string& table_path,
            const std::string& work, int jobs, const GradeOptions& options,
            const HintsArgs* hints_check) {
  // One folder per assignment: the A1 and A2 runs (two CTest tests) may run at once.
  const fs::path root = work.empty()
                            ? config.binary_dir / "grader" / "mutants" / config.assignment().id
                            : fs::path(work);
  fs::remove_all(root);
  std::vector<Mutant> list = mutant_list(config, root);
  grade_all(config, book, list, root, jobs, options);
  bool all_ok = true;
  const std::string table = mutation_table(list, all_ok);
  std::cout << table;
  if (!table_path.empty()) write_table_file(config, table_path, table);
  std::cout << (all_ok ? "jelly-grade: mutation self-test passed\n"
                       : "jelly-grade: mutation self-test FAILED\n");
  int status = all_ok ? 0 : 1;
  if (hints_check) {
    std::vector<GradedSubmission> graded;
    for (Mutant& m : list)
      graded.push_back({m.name, m.task, m.description, m.dir, std::move(m.report), m.error});
    HintsArgs args = *hints_check;
    if (args.work.empty()) args.work = (root / "hints").string();
    status = std::max(status,
                      check_hints_of_graded(config, book, args, std::move(graded), jobs, options));
  }
  return status;
}

}  // namespace jelly::grade
