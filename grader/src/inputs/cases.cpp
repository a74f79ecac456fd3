#include "inputs/cases.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "inputs/files.hpp"
#include "jelly/fnv1a.hpp"

namespace jelly::grade {

namespace {

// The offset basis of every digest and case hash the grader has written: one digit short of
// FNV-1a's standard basis (kFnv1aOffsetBasis), as the first version of the grader typed it. Kept,
// because the reference data records hashes made with it.
constexpr std::uint64_t kDigestBasis = 1469598103934665603ULL;

std::string where(const std::string& file, const toml::node& node, const std::string& key) {
  const auto& src = node.source();
  return file + ":" + std::to_string(src.begin.line) + ": " + key;
}

Rule parse_rule(const std::string& text, const std::string& context,
                const std::map<std::string, Tolerance>& tols) {
  std::istringstream in(text);
  std::string word;
  in >> word;
  Rule r;
  if (word == "info") {
    r.kind = Rule::Kind::Info;
  } else if (word == "frames") {
    r.kind = Rule::Kind::Frames;
  } else if (word == "range") {
    r.kind = Rule::Kind::Range;
    if (!(in >> r.lo >> r.hi))
      throw std::runtime_error(context + ": expected \"range LO HI\", got \"" + text + "\"");
  } else if (word == "tol") {
    in >> r.tolerance;
    if (!tols.count(r.tolerance))
      throw std::runtime_error(context + ": unknown tolerance \"" + r.tolerance +
                               "\" (define it in cases/tolerances.toml)");
  } else {
    throw std::runtime_error(
        context + ": expected \"tol NAME\", \"range LO HI\", \"info\" or \"frames\", got \"" +
        text + "\"");
  }
  return r;
}

// A TOML value as JSON (tables keep toml++'s key order, which is sorted and so deterministic).
Json to_json(const toml::node& n) {
  if (const toml::table* t = n.as_table()) {
    Json o = Json::object();
    for (const auto& [k, v] : *t) o[std::string(k.str())] = to_json(v);
    return o;
  }
  if (const toml::array* a = n.as_array()) {
    Json arr = Json::array();
    for (const toml::node& v : *a) arr.push_back(to_json(v));
    return arr;
  }
  if (auto v = n.value_exact<std::int64_t>()) return Json(*v);
  if (auto v = n.value_exact<double>()) return Json(*v);
  if (auto v = n.value_exact<bool>()) return Json(*v);
  if (auto v = n.value_exact<std::string>()) return Json(*v);
  throw std::runtime_error("unsupported TOML value (dates are not case parameters)");
}

// Shell-style pattern of an output name: '*' is any run of characters, '?' one character, anything
// else itself (POSIX fnmatch without flags, minus bracket classes, which no case file uses).
bool glob_match(const char* pattern, const char* text) {
  const char* star = nullptr;
  const char* resume = nullptr;
  while (*text) {
    if (*pattern == '*') {
      star = pattern++;
      resume = text;
    } else if (*pattern == '?' || *pattern == *text) {
      ++pattern, ++text;
    } else if (star) {
      pattern = star + 1;
      text = ++resume;
    } else {
      return false;
    }
  }
  while (*pattern == '*') ++pattern;
  return *pattern == '\0';
}

}  // namespace

const Rule CaseSpec::rule_for(const std::string& output) const {
  for (const auto& [pattern, rule] : rules)
    if (glob_match(pattern.c_str(), output.c_str())) return rule;
  Rule r;
  r.tolerance = tolerance;
  return r;
}

double Rubric::raw_total() const {
  double t = 0.0;
  for (const TaskSpec& s : tasks)
    if (!s.bonus) t += s.points;
  return t;
}

const TaskSpec* Rubric::find(const std::string& id) const {
  for (const TaskSpec& t : tasks)
    if (t.id == id) return &t;
  return nullptr;
}

// A rubric given with --rubric: the manifest's [grading] table (or its keys at the top) and its
// [[task]] entries with their points; the other keys of a manifest may be there or not. Without
// hand_graded_points it keeps `hand_graded_points` (the assignment's own).
AssignmentManifest read_rubric(const std::string& path, double hand_graded_points) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(path + ":" + std::to_string(e.source().begin.line) + ": " +
                             std::string(e.description()));
  }
  const toml::table* grading = root["grading"].as_table();
  const toml::table& g = grading ? *grading : root;
  AssignmentManifest m;
  m.autograded_total = g["autograded_total"].value_or(80.0);
  m.hand_graded_points = g["hand_graded_points"].value_or(hand_graded_points);
  if (m.hand_graded_points < 0.0)
    throw std::runtime_error(path + ": hand_graded_points: expected a number of points ≥ 0");
  m.hidden_visibility = g["hidden_visibility"].value_or(std::string("after_due_date"));
  const toml::array* tasks = root["task"].as_array();
  if (!tasks) throw std::runtime_error(path + ": expected [[task]] entries");
  for (const toml::node& n : *tasks) {
    const toml::table* t = n.as_table();
    if (!t) throw std::runtime_error(where(path, n, "task") + ": expected a table");
    ManifestTask s;
    s.id = (*t)["id"].value_or(std::string());
    s.title = (*t)["title"].value_or(std::string());
    s.category = (*t)["category"].value_or(std::string());
    s.file = (*t)["file"].value_or(std::string());
    if (const toml::array* fns = (*t)["functions"].as_array())
      for (const toml::node& f : *fns) s.functions.push_back(f.value_or(std::string()));
    const auto pts = (*t)["points"].value<double>();
    if (s.id.empty() || !pts || *pts < 0.0)
      throw std::runtime_error(where(path, n, "task") +
                               ": every [[task]] needs an id and points ≥ 0");
    s.points = *pts;
    if (const toml::node* b = t->get("bonus")) {
      if (!b->as_boolean())
        throw std::runtime_error(where(path, *b, "bonus") + ": expected true or false");
      s.bonus = b->as_boolean()->get();
    }
    m.tasks.push_back(s);
  }
  return m;
}

namespace {

// Rubric: the assignment's manifest ([grading] and the [[task]] points), or with --rubric
// another manifest-shaped file (a term's own points; docs/instructor-guide.md).
AssignmentManifest rubric_manifest(const GradeConfig& config, const std::string& rubric_path) {
  const std::string rpath = rubric_path.empty() ? config.rubric_path().string() : rubric_path;
  AssignmentManifest rubric;
  try {
    rubric = rubric_path.empty()
                 ? config.assignment().manifest
                 : read_rubric(rubric_path, config.assignment().manifest.hand_graded_points);
  } catch (const ManifestError& e) {
    throw std::runtime_error(e.what());
  }
  return rubric;
}

Rubric rubric_of(const AssignmentManifest& manifest) {
  Rubric rubric;
  rubric.autograded_total = manifest.autograded_total;
  rubric.hand_graded_points = manifest.hand_graded_points;
  rubric.hidden_visibility = manifest.hidden_visibility;
  for (const ManifestTask& t : manifest.tasks) {
    TaskSpec s;
    s.id = t.id;
    s.title = t.title;
    s.category = t.category;
    s.functions = t.functions_text();
    s.file = t.file;
    s.points = t.points;
    s.bonus = t.bonus;
    rubric.tasks.push_back(s);
  }
  return rubric;
}

// The cases folder's .toml files, sorted.
std::vector<fs::path> case_files(const GradeConfig& config) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(config.cases_dir()))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// One [tolerance.NAME] table of file f.
Tolerance parse_tolerance(const fs::path& f, const toml::key& key, const toml::node& node) {
  const toml::table* t = node.as_table();
  Tolerance tol;
  tol.name = std::string(key.str());
  const auto atol = t ? (*t)["atol"].value<double>() : std::nullopt;
  const auto rtol = t ? (*t)["rtol"].value<double>() : std::nullopt;
  tol.why = t ? (*t)["why"].value_or(std::string()) : std::string();
  if (!atol || !rtol || tol.why.empty())
    throw std::runtime_error(where(f.string(), node, "tolerance." + tol.name) +
                             ": needs atol, rtol and a one-line why");
  tol.atol = *atol;
  tol.rtol = *rtol;
  return tol;
}

// The tolerances file f declares, into `tolerances`; a file that is not TOML is an error here.
void read_tolerances(const fs::path& f, std::map<std::string, Tolerance>& tolerances) {
  toml::table tbl;
  try {
    tbl = toml::parse_file(f.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(f.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                             std::string(e.description()));
  }
  if (const toml::table* tols = tbl["tolerance"].as_table()) {
    for (const auto& [key, node] : *tols) {
      const Tolerance tol = parse_tolerance(f, key, node);
      tolerances[tol.name] = tol;
    }
  }
}

// The fields of one [[case]] of file f, as written.
CaseSpec case_fields(const fs::path& f, const toml::node& n) {
  const toml::table& t = *n.as_table();
  CaseSpec c;
  c.source = f.filename().string();
  c.line = static_cast<int>(n.source().begin.line);
  c.id = t["id"].value_or(std::string());
  c.task = t["task"].value_or(std::string());
  c.title = t["title"].value_or(std::string());
  c.weight = t["weight"].value_or(1.0);
  c.timeout_s = t["timeout"].value_or(0.0);
  c.tolerance = t["tolerance"].value_or(std::string());
  c.generator = t["generator"].value_or(std::string());
  c.element = t["element"].value_or(c.element);
  return c;
}

Json case_params(const toml::node& params, const std::string& ctx) {
  if (!params.is_table())
    throw std::runtime_error(ctx + ": params must be a table (params = { ... } or [case.params])");
  try {
    return to_json(params);
  } catch (const std::exception& e) {
    throw std::runtime_error(ctx + ".params: " + e.what());
  }
}

// One [[case]] of file f, checked against the rubric, the tolerances and the cases before it.
CaseSpec parse_case(const fs::path& f, const toml::node& n, const CaseBook& book) {
  const toml::table& t = *n.as_table();
  CaseSpec c = case_fields(f, n);
  const std::string vis = t["visibility"].value_or(std::string("public"));
  const std::string ctx = where(f.string(), n, "case " + c.id);
  if (c.id.empty() || c.task.empty() || c.generator.empty())
    throw std::runtime_error(ctx + ": needs id, task and generator (a name from `runner --list`)");
  if (const toml::node* params = t.get("params")) c.params = case_params(*params, ctx);
  if (vis != "public" && vis != "hidden")
    throw std::runtime_error(ctx + ": visibility must be \"public\" or \"hidden\", got \"" + vis +
                             "\"");
  c.hidden = vis == "hidden";
  if (!book.rubric.find(c.task))
    throw std::runtime_error(ctx + ": task " + c.task + " is not in the rubric");
  if (!book.tolerances.count(c.tolerance))
    throw std::runtime_error(ctx + ": unknown tolerance \"" + c.tolerance + "\"");
  if (const toml::table* checks = t["checks"].as_table())
    for (const auto& [pattern, rule] : *checks)
      c.rules.emplace_back(
          std::string(pattern.str()),
          parse_rule(rule.value_or(std::string()), ctx + ".checks." + std::string(pattern.str()),
                     book.tolerances));
  for (const CaseSpec& other : book.cases)
    if (other.id == c.id) throw std::runtime_error(ctx + ": duplicate case id");
  return c;
}

// The cases file f declares, into the book.
void read_cases(const fs::path& f, CaseBook& book) {
  toml::table tbl = toml::parse_file(f.string());
  const toml::array* cases = tbl["case"].as_array();
  if (!cases) return;
  for (const toml::node& n : *cases) book.cases.push_back(parse_case(f, n, book));
}

}  // namespace

CaseBook load_case_book(const GradeConfig& config, const std::string& rubric_path) {
  CaseBook book;
  book.rubric = rubric_of(rubric_manifest(config, rubric_path));
  // Tolerances, then cases.
  const std::vector<fs::path> files = case_files(config);
  for (const fs::path& f : files) read_tolerances(f, book.tolerances);
  for (const fs::path& f : files) read_cases(f, book);
  return book;
}

std::string case_location(const GradeConfig& config, const CaseSpec& spec) {
  return (config.cases_dir() / spec.source).string() + ":" + std::to_string(spec.line);
}

std::filesystem::path reference_path(const GradeConfig& config, const CaseSpec& spec) {
  return config.data_dir(spec.hidden ? "hidden" : "public") / (spec.id + ".json");
}

std::optional<Json> load_reference(const GradeConfig& config, const CaseSpec& spec) {
  const fs::path p = reference_path(config, spec);
  std::ifstream in(p);
  if (!in) return std::nullopt;
  try {
    return Json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(p.string() + ": not valid JSON: " + e.what());
  }
}

std::string fnv_hex(const std::string& text) {
  const std::uint64_t h = fnv1a(text.data(), text.size(), kDigestBasis);
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

// The folders of the code that computes the selected assignment's cases: the general harness
// (grader/runner/), the slot-level cases of every body kind its manifest claims
// (framework/bodies/<kind>/grader/, when the kind has them) and the assignment's own generators.
std::vector<fs::path> generator_folders(const GradeConfig& config) {
  std::vector<fs::path> out = {config.grader_dir() / "runner"};
  std::set<std::string> kinds;
  for (const BodyClaim& claim : config.assignment().manifest.bodies) kinds.insert(claim.kind);
  for (const std::string& kind : kinds) {
    const fs::path dir = config.source_dir / "framework" / "bodies" / kind / "grader";
    if (fs::is_directory(dir)) out.push_back(dir);
  }
  out.push_back(config.runner_dir());
  return out;
}

}  // namespace

std::string harness_digest(const GradeConfig& config) {
  std::vector<fs::path> files;
  // The process around a case (its main() and its seccomp sandbox) does not change what a case
  // computes: changing how the runner is confined must not invalidate the reference data.
  static const char* const not_generator_code[] = {"main.cpp", "sandbox.cpp", "sandbox.hpp"};
  for (const fs::path& dir : generator_folders(config))
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() &&
          std::find(std::begin(not_generator_code), std::end(not_generator_code), name) ==
              std::end(not_generator_code))
        files.push_back(e.path());
    }
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& f : files) {
    // A Windows checkout may have CRLF line ends (git's core.autocrlf): the same code, the same
    // digest.
    std::string text = read_file(f);
    text.erase(std::remove(text.begin(), text.end(), '\r'), text.end());
    all += f.filename().string() + "\n" + text;
  }
  return fnv_hex(all);
}

std::string case_hash(const CaseSpec& spec, const std::string& digest) {
  return fnv_hex(spec.id + "\n" + spec.generator + "\n" + spec.params.dump() + "\n" + digest);
}

}  // namespace jelly::grade
