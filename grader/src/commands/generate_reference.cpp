#include "commands/commands.hpp"

#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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

// Whether `path` holds `data` already, but for its "commit" field.
bool same_but_commit(const fs::path& path, const Json& data) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  try {
    Json old = Json::parse(in);
    Json now = data;
    old.erase("commit");
    now.erase("commit");
    return old == now;
  } catch (const std::exception&) {
    return false;  // unreadable: write it again
  }
}

/// The runner's generators (`--list`: "name<TAB>description" a line).
std::map<std::string, std::string> runner_generators(const fs::path& runner) {
  const std::string listing = run_text({runner.string(), "--list"});
  std::map<std::string, std::string> descriptions;
  std::istringstream in(listing);
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) descriptions[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return descriptions;
}

/// What the reference made of one case: its prepared input and its stored outputs.
struct ReferenceRun {
  Json input = Json::object();
  Json outputs = Json::object();
};

/// Runs the reference on case `c` (prepare, then run). On failure says why, naming the case's
/// file and line, and returns false.
bool run_reference(const GradeConfig& config, const CaseSpec& c, const fs::path& work,
                   ReferenceRun& ref) {
  const ChildResult prep = run_case(config.reference_runner, c, nullptr, work, 120.0, 0, true);
  try {
    const Json prepared = Json::parse(prep.result);
    if (prepared.contains("error")) throw std::runtime_error(prepared["error"].get<std::string>());
    ref.input = prepared.at("input");
  } catch (const std::exception& e) {
    // The case's file and line: a missing or mistyped parameter is named by the runner, which
    // knows the key but not where the case was written.
    std::cerr << "jelly-grade: " << case_location(config, c) << ": case " << c.id
              << ": preparing it failed: " << e.what() << " " << prep.err << "\n";
    return false;
  }
  const ChildResult run = run_case(config.reference_runner, c, &ref.input, work, 120.0, 0);
  Json result;
  try {
    result = Json::parse(run.result);
  } catch (const std::exception&) {
    std::cerr << "jelly-grade: " << case_location(config, c) << ": the reference failed on " << c.id
              << " (exit " << run.exit_code << ", signal " << run.signal << "): " << run.err
              << "\n";
    return false;
  }
  if (result.contains("error") && result["error"].is_string()) {
    // A missing or mistyped parameter: the runner names the key, the case file says where.
    std::cerr << "jelly-grade: " << case_location(config, c) << ": case " << c.id
              << ": the reference failed: " << result["error"].get<std::string>() << "\n";
    return false;
  }
  if (!result.contains("outputs")) {
    std::cerr << "jelly-grade: " << case_location(config, c) << ": the reference failed on " << c.id
              << ": " << result.dump() << "\n";
    return false;
  }
  // Recorded frames (rule "frames") are for the report only: never stored as reference data;
  // nor are the details that explain a student's value (Outputs::detail).
  for (const auto& [name, value] : result["outputs"].items())
    if (c.rule_for(name).kind != Rule::Kind::Frames) {
      ref.outputs[name] = value;
      ref.outputs[name].erase("detail_low");
      ref.outputs[name].erase("detail_high");
    }
  if (ref.outputs.dump().find("null") != std::string::npos) {
    std::cerr << "jelly-grade: the reference produced NaN or infinity in " << c.id
              << "; fix the case before generating reference data\n";
    return false;
  }
  return true;
}

/// A case's reference data file: the outputs and what they were made from.
Json reference_data(const GradeConfig& config, const CaseSpec& c, const ReferenceRun& ref,
                    const std::string& digest, const std::string& commit) {
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
  if (!ref.input.empty()) data["input"] = ref.input;
  data["outputs"] = ref.outputs;
  return data;
}

/// Writes `data` to `p` whole or not at all: a stopped run leaves the old file, never half of
/// the new one. False (said) when it cannot.
bool write_whole(const fs::path& p, const Json& data) {
  fs::create_directories(p.parent_path());
  const fs::path tmp = p.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << data.dump(1) << "\n";
    if (!out.flush()) {
      std::cerr << "jelly-grade: cannot write " << tmp.string() << "\n";
      return false;
    }
  }
  fs::rename(tmp, p);
  return true;
}

/// Removes the data of cases that no longer exist (not in `written`); returns their names.
std::vector<std::string> remove_stale_data(const GradeConfig& config,
                                           const std::set<fs::path>& written) {
  std::vector<std::string> removed;
  for (const char* vis : {"public", "hidden"}) {
    const fs::path dir = config.data_dir(vis);
    if (!fs::exists(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json" && !written.count(e.path())) {
        removed.push_back(e.path().filename().string());
        fs::remove(e.path());
      }
  }
  return removed;
}

}  // namespace

int generate_reference(const GradeConfig& config, const CaseBook& book) {
  if (config.reference_runner.empty() || !fs::exists(config.reference_runner)) {
    std::cerr
        << "jelly-grade: generate-reference needs the reference runner (solutions/ must exist and "
           "jelly-grade-reference-runner must be built)\n";
    return 2;
  }
  const std::map<std::string, std::string> descriptions =
      runner_generators(config.reference_runner);
  const std::string digest = harness_digest(config);
  const std::string commit = git_commit(config.source_dir);
  const fs::path work = config.binary_dir / "grader" / "generate";
  fs::create_directories(work);
  std::set<fs::path> written;
  std::vector<std::string> rewritten, created;
  std::size_t unchanged = 0;
  for (const CaseSpec& c : book.cases) {
    if (!descriptions.count(c.generator)) {
      std::cerr << "jelly-grade: " << case_location(config, c) << ": case " << c.id
                << ": the runner has no generator \"" << c.generator
                << "\" (see jelly-grade-reference-runner --list)\n";
      return 2;
    }
    ReferenceRun ref;
    if (!run_reference(config, c, work, ref)) return 2;
    const Json data = reference_data(config, c, ref, digest, commit);
    const fs::path p = reference_path(config, c);
    written.insert(p);
    // A file whose data is the same but for the commit it was made at stays as it is, so that the
    // diff of a regeneration shows only the cases that changed.
    if (same_but_commit(p, data)) {
      ++unchanged;
      continue;
    }
    const bool is_new = !fs::exists(p);
    if (!write_whole(p, data)) return 2;
    (is_new ? created : rewritten).push_back(p.filename().string());
  }
  const std::vector<std::string> removed = remove_stale_data(config, written);
  for (const std::string& name : created) std::cout << "  wrote (new) " << name << "\n";
  for (const std::string& name : rewritten) std::cout << "  rewrote " << name << "\n";
  for (const std::string& name : removed)
    std::cout << "  removed " << name << " (no such case any more)\n";
  std::cout << "jelly-grade: reference data for " << written.size()
            << " cases: " << rewritten.size() << " rewritten, " << unchanged << " unchanged, "
            << removed.size() << " removed, " << created.size() << " new (commit " << commit
            << ")\n";
  return 0;
}

}  // namespace jelly::grade
