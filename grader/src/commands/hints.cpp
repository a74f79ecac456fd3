// `jelly-grade hints`: the signatures of the mutation table's mistakes on the public cases
// (hints.hpp), and the proof that they recognise what they should and nothing else.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <mutex>

#include "commands/commands.hpp"
#include "grading/hints.hpp"
#include "grading/parallel.hpp"
#include "inputs/files.hpp"
#include "reports/points.hpp"

namespace jelly::grade {

namespace {

using Graded = GradedSubmission;

// What hints.json is made from: the case code (harness digest), the public cases, the reference's
// and the stubs' task files and every mutant's file. A change to any of them makes the file stale.
std::string sources_digest(const GradeConfig& config, const CaseBook& book) {
  const std::string harness = harness_digest(config);
  std::string all = "harness " + harness + "\n";
  for (const CaseSpec& c : book.cases)
    if (!c.hidden) all += "case " + c.id + " " + case_hash(c, harness) + "\n";
  for (const std::string& f : config.task_files())
    all += "file " + f + "\n" + read_file(config.reference_dir() / f) + "\n" +
           read_file(config.assignments_dir() / f) + "\n";
  std::vector<fs::path> mutants;
  for (const auto& e : fs::directory_iterator(config.mutants_dir()))
    if (e.path().extension() == ".toml") mutants.push_back(e.path());
  std::sort(mutants.begin(), mutants.end());
  for (const fs::path& m : mutants)
    all += "mutant " + m.filename().string() + "\n" + read_file(m) + "\n";
  return fnv_hex(all);
}

// Whether a case compares an output with a tolerance wider than 1e-6 (the course scene's outcome
// and first-contact time, set for chaotic motion): two different mistakes can land within it, so
// such a case is no signature of one.
bool loose(const CaseSpec& spec, const Json& reference, const CaseBook& book) {
  if (!reference.is_object()) return true;
  for (const auto& [name, ref] : reference.items()) {
    const Rule rule = spec.rule_for(name);
    if (rule.kind != Rule::Kind::Tolerance) continue;
    const auto t = book.tolerances.find(rule.tolerance);
    if (t == book.tolerances.end() || t->second.atol > 1e-6 || t->second.rtol > 1e-4) return true;
  }
  return false;
}

const CaseResult* find_case(const GradeReport& r, const std::string& id) {
  for (const CaseResult& c : r.cases)
    if (c.spec->id == id) return &c;
  return nullptr;
}

// The hints.json text of the graded reference, stubs (entries 0 and 1) and mutants.
std::string make_hints_json(const GradeConfig& config, const CaseBook& book,
                            const std::vector<Graded>& list) {
  const std::string harness = harness_digest(config);
  Json j;
  j["format"] = kHintsFormat;
  j["about"] =
      "Signatures of the mutation table's mistakes: each mutant's outputs on the public cases it "
      "fails. A failed public test whose outputs are within tolerance of a mutant's gets its "
      "description as a hint. Made by `jelly-grade hints --assignment " +
      config.assignment().id + config.assignment().draft_option() +
      "` (docs/grader.md, Hints); do not edit.";
  j["assignment"] = config.assignment().id;
  j["harness_digest"] = harness;
  j["sources_digest"] = sources_digest(config, book);
  Json mutants = Json::array(), without = Json::array();
  const GradeReport& stubs = list[1].report;
  for (std::size_t i = 2; i < list.size(); ++i) {
    const Graded& m = list[i];
    Json cases = Json::array();
    std::string why = "no public test fails, or only tests with a loose tolerance";
    for (const CaseResult& c : m.report.cases) {
      if (c.spec->hidden || c.status != "failed") continue;
      if (loose(*c.spec, c.reference, book)) continue;
      const Json outputs = graded_outputs(c);
      if (outputs.empty()) {
        why = "its failing public tests have no outputs (a crash or a missing output)";
        continue;
      }
      // Outputs the stubs give too are no signature of this mistake.
      const CaseResult* s = find_case(stubs, c.spec->id);
      if (s && same_outputs(*c.spec, graded_outputs(*s), outputs, book.tolerances)) {
        why = "its failing public tests give the stubs' outputs";
        continue;
      }
      cases.push_back(
          {{"case", c.spec->id}, {"case_hash", case_hash(*c.spec, harness)}, {"outputs", outputs}});
    }
    if (cases.empty()) {
      without.push_back({{"name", m.name}, {"why", why}});
      continue;
    }
    mutants.push_back(
        {{"name", m.name}, {"task", m.task}, {"description", m.description}, {"cases", cases}});
  }
  j["mutants"] = mutants;
  j["without_signature"] = without;
  return j.dump(1, ' ', false, Json::error_handler_t::replace) + "\n";
}

// The report's hints, all of them, for messages.
std::vector<std::string> all_hints(const GradeReport& r) {
  std::vector<std::string> out;
  for (const CaseResult& c : r.cases)
    for (const std::string& h : c.hints) out.push_back(c.spec->id + ": " + h);
  return out;
}

/// --digest and the first step of --check: whether `file` is there and made from today's sources.
/// 1 when it is missing or stale (said), 0 when --digest is all (said), -1 to go on.
int check_digest(const GradeConfig& config, const CaseBook& book, const HintsArgs& args,
                 const fs::path& file, const std::string& regenerate) {
  if (!fs::is_regular_file(file)) {
    std::cerr << "jelly-grade: " << file.string() << " is missing; " << regenerate << "\n";
    return 1;
  }
  const Json stored = Json::parse(read_file(file));
  if (stored.value("sources_digest", std::string()) != sources_digest(config, book)) {
    std::cerr << "jelly-grade: " << file.string()
              << " is stale: the mutants, the reference, the stubs, the public cases or the "
                 "case code changed since it was made; "
              << regenerate << "\n";
    return 1;
  }
  if (args.digest) {
    std::cout << "jelly-grade: " << file.string() << " is up to date\n";
    return 0;
  }
  return -1;
}

/// The reference, the stubs, the mutants (their folders made under root/mutants) and, after
/// them, the controls (--controls, under root/controls); `n_mutants` counts all but the controls.
std::vector<Graded> hint_list(const GradeConfig& config, const HintsArgs& args,
                              const fs::path& root, std::size_t& n_mutants) {
  std::vector<Graded> list;
  list.push_back({"reference", "", "", config.reference_dir(), {}, {}});
  list.push_back({"stubs", "", "", config.assignments_dir(), {}, {}});
  for (const MutantSpec& m : make_mutant_folders(config, config.mutants_dir(), root / "mutants"))
    list.push_back({m.name, m.task, m.description, m.dir, {}, {}});
  n_mutants = list.size();
  if (!args.controls.empty())
    for (const MutantSpec& m : make_mutant_folders(config, args.controls, root / "controls"))
      list.push_back({"control " + m.name, m.task, m.description, m.dir, {}, {}});
  return list;
}

/// Grades every entry on the public cases, without hints.
void grade_public(const GradeConfig& config, const CaseBook& book, std::vector<Graded>& list,
                  const fs::path& root, int jobs, const GradeOptions& options) {
  GradeOptions per = options;
  per.jobs = 1;
  per.include_hidden = false;  // only public-case data goes into the file
  per.hints = false;           // graded without hints; --check applies the file's below
  std::mutex mutex;
  parallel_for(list.size(), jobs, [&](std::size_t i) {
    try {
      list[i].report =
          grade_submission(config, book, list[i].dir, root / "work" / std::to_string(i), per);
    } catch (const std::exception& e) {
      list[i].error = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex);
    std::cerr << "  graded " << list[i].name << ": " << pts(list[i].report.score) << "\n";
  });
}

/// Whether every entry was graded and the reference passes every public test (said when not).
/// 0 when so, else the exit status.
int check_grading(const std::vector<Graded>& list) {
  for (const Graded& g : list)
    if (!g.error.empty()) {
      std::cerr << "jelly-grade: grading " << g.name << ": " << g.error << "\n";
      return 2;
    }
  if (list[0].report.score < list[0].report.max_score - 1e-9) {
    std::cerr << "jelly-grade: the reference does not pass every public test: no hints are made "
                 "from it\n";
    for (const std::string& n : list[0].report.notes) std::cerr << "  note: " << n << "\n";
    for (const CaseResult& c : list[0].report.cases)
      if (c.status == "failed")
        std::cerr << "  " << c.spec->id << ": "
                  << (c.failures.empty() ? std::string("failed") : c.failures.front()) << "\n";
    return 1;
  }
  return 0;
}

/// Writes hints.json; the exit status.
int write_hints(const fs::path& file, const std::string& text, std::size_t n_mutants) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out.flush()) {
    std::cerr << "jelly-grade: cannot write " << file.string() << "\n";
    return 2;
  }
  out.close();
  const HintBook made = load_hints(file);
  std::cout << "jelly-grade: wrote " << file.string() << " (" << made.signatures.size() << " of "
            << n_mutants - 2 << " mutants have a public signature)\n";
  return 0;
}

/// --check of one entry with the file's hints applied: what is wrong ("" when nothing).
/// `recognised` counts the mutants with a signature that got their own hint.
std::string hint_problem(const HintBook& book_of_file, const Graded& g, std::size_t i,
                         std::size_t n_mutants, const std::vector<std::string>& got,
                         std::size_t& recognised) {
  const bool has_signature =
      std::any_of(book_of_file.signatures.begin(), book_of_file.signatures.end(),
                  [&](const HintSignature& s) { return s.mutant == g.name; });
  std::string problem;
  if (i < 2 || i >= n_mutants) {
    // The reference, the stubs and the honest mistakes: no hint at all.
    if (!got.empty()) problem = "got a hint it must not get: " + got.front();
    if (i >= n_mutants && g.report.score >= g.report.max_score - 1e-9)
      problem = "fails no public test, so it proves nothing (make it a real mistake)";
  } else if (has_signature) {
    bool own = false;
    for (const CaseResult& c : g.report.cases)
      own = own || std::find(c.hints.begin(), c.hints.end(), g.description) != c.hints.end();
    if (!own)
      problem = "has a signature but was not recognised";
    else
      ++recognised;
  }
  return problem;
}

/// --check: the file is what the sources make today, and it recognises what it should.
int check_hints(const GradeConfig& config, const CaseBook& book, const fs::path& file,
                const std::string& text, const std::string& regenerate, std::vector<Graded>& list,
                std::size_t n_mutants) {
  bool ok = true;
  if (read_file(file) != text) {
    std::cerr << "FAIL: " << file.string() << " differs from what the mutants give today; "
              << regenerate << "\n";
    ok = false;
  }
  const HintBook book_of_file = load_hints(file);
  const std::string harness = harness_digest(config);
  std::size_t recognised = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    Graded& g = list[i];
    apply_hints(book_of_file, book, harness, g.report);
    const std::vector<std::string> got = all_hints(g.report);
    const std::string problem = hint_problem(book_of_file, g, i, n_mutants, got, recognised);
    std::cout << "  " << (problem.empty() ? "ok  " : "FAIL") << " " << g.name << ": "
              << (problem.empty() ? (got.empty() ? std::string("no hint")
                                                 : std::to_string(got.size()) + " hinted test(s)")
                                  : problem)
              << "\n";
    ok = ok && problem.empty();
  }
  std::cout << "jelly-grade: " << recognised << " of " << book_of_file.signatures.size()
            << " mutants with a signature recognised; " << (list.size() - n_mutants)
            << " honest mistakes, the reference and the stubs without a hint\n"
            << (ok ? "jelly-grade: hints check passed\n" : "jelly-grade: hints check FAILED\n");
  return ok ? 0 : 1;
}

}  // namespace

namespace {

/// After the grading: the reference must pass, then hints.json is written, or (--check) compared
/// and proven on every entry. `list`: the reference, the stubs, the mutants (n_mutants entries in
/// all), then the controls.
int finish_hints(const GradeConfig& config, const CaseBook& book, const HintsArgs& args,
                 const fs::path& file, const std::string& regenerate, std::vector<Graded>& list,
                 std::size_t n_mutants) {
  if (const int status = check_grading(list); status != 0) return status;
  const std::string text =
      make_hints_json(config, book, std::vector<Graded>(list.begin(), list.begin() + n_mutants));
  if (!args.check) return write_hints(file, text, n_mutants);
  return check_hints(config, book, file, text, regenerate, list, n_mutants);
}

fs::path hints_file(const GradeConfig& config, const HintsArgs& args) {
  return args.out.empty() ? hints_path(config) : fs::path(args.out);
}

std::string regenerate_command(const GradeConfig& config, const fs::path& file) {
  return "run `jelly-grade hints --assignment " + config.assignment().id +
         config.assignment().draft_option() + "` and commit " + file.string();
}

fs::path work_root(const GradeConfig& config, const HintsArgs& args) {
  return args.work.empty() ? config.binary_dir / "grader" / "hints" / config.assignment().id
                           : fs::absolute(args.work);
}

}  // namespace

int hints(const GradeConfig& config, const CaseBook& book, const HintsArgs& args, int jobs,
          const GradeOptions& options) {
  const fs::path file = hints_file(config, args);
  const std::string regenerate = regenerate_command(config, file);
  if (args.digest || args.check) {
    const int status = check_digest(config, book, args, file, regenerate);
    if (status >= 0) return status;
  }
  const fs::path root = work_root(config, args);
  fs::remove_all(root);
  std::size_t n_mutants = 0;
  std::vector<Graded> list = hint_list(config, args, root, n_mutants);
  grade_public(config, book, list, root, jobs, options);
  return finish_hints(config, book, args, file, regenerate, list, n_mutants);
}

int check_hints_of_graded(const GradeConfig& config, const CaseBook& book, const HintsArgs& args,
                          std::vector<GradedSubmission> graded, int jobs,
                          const GradeOptions& options) {
  HintsArgs check = args;
  check.check = true;
  check.digest = false;
  const fs::path file = hints_file(config, check);
  const std::string regenerate = regenerate_command(config, file);
  if (const int status = check_digest(config, book, check, file, regenerate); status >= 0)
    return status;
  const std::size_t n_mutants = graded.size();
  if (!check.controls.empty()) {
    const fs::path root = work_root(config, check);
    fs::remove_all(root);
    std::vector<Graded> controls;
    for (const MutantSpec& m : make_mutant_folders(config, check.controls, root / "controls"))
      controls.push_back({"control " + m.name, m.task, m.description, m.dir, {}, {}});
    grade_public(config, book, controls, root, jobs, options);
    for (Graded& g : controls) graded.push_back(std::move(g));
  }
  return finish_hints(config, book, check, file, regenerate, graded, n_mutants);
}

}  // namespace jelly::grade
