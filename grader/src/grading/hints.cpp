#include "grading/hints.hpp"

#include <cmath>
#include <stdexcept>

#include "grading/tolerance.hpp"
#include "inputs/files.hpp"

namespace jelly::grade {

namespace {

// A number of an output, NaN for anything else (JSON stores NaN and infinity as null).
void flatten(const Json& j, std::vector<double>& out) {
  if (j.is_array())
    for (const Json& e : j) out.push_back(e.is_number() ? e.get<double>() : std::nan(""));
  else
    out.push_back(j.is_number() ? j.get<double>() : std::nan(""));
}

bool same_value(const Json& mine, const Json& theirs, double atol, double rtol) {
  if (theirs.is_string()) return mine == theirs;
  std::vector<double> a, b;
  flatten(mine, a);
  flatten(theirs, b);
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!std::isfinite(b[k]) || !std::isfinite(a[k])) {
      if (std::isfinite(b[k]) != std::isfinite(a[k])) return false;
      continue;
    }
    if (!within_tolerance(a[k], b[k], atol, rtol)) return false;
  }
  return true;
}

[[noreturn]] void bad(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": " + what +
                           " (regenerate it with `jelly-grade hints --assignment ID`)");
}

}  // namespace

std::filesystem::path hints_path(const GradeConfig& config) {
  return config.assignment_grader_dir() / "hints.json";
}

HintBook load_hints(const std::filesystem::path& path) {
  HintBook book;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return book;
  Json j;
  try {
    j = Json::parse(read_file(path));
  } catch (const std::exception& e) {
    bad(path, std::string("not JSON: ") + e.what());
  }
  if (!j.is_object() || j.value("format", 0) != kHintsFormat)
    bad(path, "format: expected " + std::to_string(kHintsFormat));
  if (!j.contains("mutants") || !j["mutants"].is_array()) bad(path, "mutants: expected an array");
  for (const Json& m : j["mutants"]) {
    HintSignature s;
    if (!m.is_object() || !m.contains("name") || !m["name"].is_string() ||
        !m.contains("description") || !m["description"].is_string() || !m.contains("cases") ||
        !m["cases"].is_array())
      bad(path, "mutants[]: expected name, description (strings) and cases (an array)");
    s.mutant = m["name"].get<std::string>();
    s.task = m.value("task", std::string());
    s.description = m["description"].get<std::string>();
    for (const Json& c : m["cases"]) {
      if (!c.is_object() || !c.contains("case") || !c["case"].is_string() ||
          !c.contains("outputs") || !c["outputs"].is_object())
        bad(path, "mutants[" + s.mutant + "].cases[]: expected case (a string) and outputs");
      s.cases[c["case"].get<std::string>()] = {c.value("case_hash", std::string()), c["outputs"]};
    }
    book.signatures.push_back(std::move(s));
  }
  return book;
}

bool same_outputs(const CaseSpec& spec, const Json& mine, const Json& theirs,
                  const std::map<std::string, Tolerance>& tolerances) {
  if (!mine.is_object() || !theirs.is_object() || theirs.empty()) return false;
  for (const auto& [name, out] : theirs.items()) {
    if (!mine.contains(name) || !mine[name].is_object() || !mine[name].contains("value") ||
        !out.is_object() || !out.contains("value"))
      return false;
    const Rule rule = spec.rule_for(name);
    double atol = 1e-9, rtol = 1e-9;  // a range output: the mutant's own value, to rounding
    if (rule.kind == Rule::Kind::Tolerance) {
      const auto t = tolerances.find(rule.tolerance);
      if (t == tolerances.end()) return false;
      atol = t->second.atol, rtol = t->second.rtol;
    }
    if (!same_value(mine[name]["value"], out["value"], atol, rtol)) return false;
  }
  return true;
}

Json graded_outputs(const CaseResult& c) {
  Json out = Json::object();
  if (!c.outputs.is_object() || !c.reference.is_object()) return out;
  for (const auto& [name, ref] : c.reference.items()) {
    const Rule rule = c.spec->rule_for(name);
    if (rule.kind == Rule::Kind::Info || rule.kind == Rule::Kind::Frames) continue;
    if (!c.outputs.contains(name) || !c.outputs[name].is_object() ||
        !c.outputs[name].contains("value"))
      return Json::object();  // an output missing: no signature
    out[name] = {{"value", c.outputs[name]["value"]}};
  }
  return out;
}

void apply_hints(const HintBook& hints, const CaseBook& book, const std::string& digest,
                 GradeReport& rep) {
  if (hints.empty()) return;
  for (CaseResult& c : rep.cases) {
    if (c.status != "failed" || c.not_run || !c.outputs.is_object() || c.spec->hidden) continue;
    const std::string hash = case_hash(*c.spec, digest);
    for (const HintSignature& s : hints.signatures) {
      const auto it = s.cases.find(c.spec->id);
      if (it == s.cases.end() || it->second.first != hash) continue;
      if (same_outputs(*c.spec, c.outputs, it->second.second, book.tolerances))
        c.hints.push_back(s.description);
    }
  }
}

}  // namespace jelly::grade
