#include "inputs/config.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace jelly::grade {

const AssignmentConfig& GradeConfig::assignment() const {
  if (!selected) throw std::logic_error("jelly-grade: no assignment selected (select_assignment)");
  return *selected;
}

fs::path GradeConfig::data_dir(const std::string& visibility) const {
  if (visibility == "hidden") return grader_dir() / "data" / assignment().id / "hidden";
  return assignment_grader_dir() / "data" / visibility;
}

fs::path GradeConfig::cache_dir() const {
  if (const char* env = std::getenv("JELLY_GRADE_CACHE")) return env;
  return binary_dir / "grader" / "object-cache";
}

namespace {

// The config file: `path`, else $JELLY_GRADE_CONFIG, else the one this build wrote.
std::string config_file(const std::string& path) {
  std::string p = path;
  if (p.empty()) {
    if (const char* env = std::getenv("JELLY_GRADE_CONFIG")) p = env;
  }
#ifdef JELLY_GRADE_DEFAULT_CONFIG
  if (p.empty()) p = JELLY_GRADE_DEFAULT_CONFIG;
#endif
  return p;
}

nlohmann::json read_json(const std::string& p) {
  std::ifstream in(p);
  if (!in)
    throw std::runtime_error("cannot read the grader config " + p +
                             " (build the jelly-grade target first; CMake writes it)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(p + ": not valid JSON: " + e.what());
  }
  return j;
}

// The strings of a JSON array of paths or flags, without the empty ones and /usr/include.
std::vector<std::string> string_list(const nlohmann::json& array) {
  std::vector<std::string> out;
  for (const auto& s : array) {
    const std::string v = s.get<std::string>();
    // /usr/include is searched anyway; naming it with -I breaks libstdc++'s #include_next.
    if (!v.empty() && v != "/usr/include") out.push_back(v);
  }
  return out;
}

// One entry of "assignments" or "draft_assignments" (`table`, for the errors), with its manifest.
AssignmentConfig read_assignment(const std::string& p, const std::string& table,
                                 const std::string& id, const nlohmann::json& o) {
  const std::string where = table + "." + id + ".";
  auto field = [&](const char* key) {
    if (!o.contains(key) || !o[key].is_string())
      throw std::runtime_error(p + ": " + where + key + ": expected a string");
    return o[key].get<std::string>();
  };
  auto list = [&](const char* key) {
    if (!o.contains(key) || !o[key].is_array())
      throw std::runtime_error(p + ": " + where + key + ": expected an array");
    return string_list(o[key]);
  };
  AssignmentConfig a;
  a.id = id;
  a.dir = field("dir");
  a.solutions_dir = field("solutions_dir");
  a.reference_dir = o.value("reference_dir", a.solutions_dir.string());
  a.include_dirs = list("include_dirs");
  a.link_objects = list("link_objects");
  a.link_libraries = list("link_libraries");
  a.reference_runner = o.value("reference_runner", "");
  a.student_runner = o.value("student_runner", "");
  try {
    a.manifest = read_manifest(a.dir / "assignment.toml");
  } catch (const ManifestError& e) {
    throw std::runtime_error(e.what());
  }
  return a;
}

}  // namespace

GradeConfig load_config(const std::string& path) {
  const std::string p = config_file(path);
  nlohmann::json j = read_json(p);
  auto strings = [&](const char* key) {
    if (!j.contains(key) || !j[key].is_array())
      throw std::runtime_error(p + ": missing array '" + key + "'");
    return string_list(j[key]);
  };
  GradeConfig c;
  c.compiler = j.at("compiler").get<std::string>();
  c.compiler_id = j.value("compiler_id", "");
  c.compile_flags = strings("compile_flags");
  c.defines = strings("defines");
  c.link_flags = strings("link_flags");
  c.source_dir = j.at("source_dir").get<std::string>();
  c.binary_dir = j.at("binary_dir").get<std::string>();
  c.jelly_cli = j.value("jelly_cli", "");
  if (j.contains("drafts")) c.drafts = strings("drafts");
  if (const char* env = std::getenv("JELLY_GRADE_JELLY")) c.jelly_cli = env;
  c.config_path = p;
  if (!j.contains("assignments") || !j["assignments"].is_object() || j["assignments"].empty())
    throw std::runtime_error(p +
                             ": assignments: expected an object with one entry per assignment "
                             "(rebuild: this config predates assignments as plug-ins)");
  for (const auto& [id, o] : j["assignments"].items())
    c.assignments.push_back(read_assignment(p, "assignments", id, o));
  if (j.contains("draft_assignments") && j["draft_assignments"].is_object())
    for (const auto& [id, o] : j["draft_assignments"].items())
      c.draft_assignments.push_back(read_assignment(p, "draft_assignments", id, o));
  for (AssignmentConfig& a : c.draft_assignments) a.draft = true;
  const auto by_id = [](const AssignmentConfig& x, const AssignmentConfig& y) {
    return x.id < y.id;
  };
  std::sort(c.assignments.begin(), c.assignments.end(), by_id);
  std::sort(c.draft_assignments.begin(), c.draft_assignments.end(), by_id);
  return c;
}

namespace {

// The draft `id` that --draft asks for: one with a grader, else an error saying what it is.
const AssignmentConfig& chosen_draft(const GradeConfig& config, const std::string& id,
                                     const std::string& known) {
  for (const AssignmentConfig& a : config.draft_assignments)
    if (a.id == id) return a;
  if (std::find(config.drafts.begin(), config.drafts.end(), id) != config.drafts.end())
    throw std::runtime_error("--assignment " + id + " --draft: " + id +
                             " is a draft without a grader yet (no case generators in "
                             "assignments/" +
                             id + "/grader/runner/; docs/new-assignment.md, \"A draft\")");
  throw std::runtime_error("--assignment " + id + " --draft: " + id +
                           " is not a draft in this build (it has: " + known + ")");
}

}  // namespace

void select_assignment(GradeConfig& config, const std::string& id, const fs::path& submission,
                       bool draft) {
  std::string known;
  for (const AssignmentConfig& a : config.assignments) known += (known.empty() ? "" : ", ") + a.id;
  const AssignmentConfig* chosen = nullptr;
  if (draft) {
    if (id.empty()) throw std::runtime_error("--draft: say which draft with --assignment ID");
    chosen = &chosen_draft(config, id, known);
  } else if (!id.empty()) {
    for (const AssignmentConfig& a : config.assignments)
      if (a.id == id) chosen = &a;
    if (!chosen && std::find(config.drafts.begin(), config.drafts.end(), id) != config.drafts.end())
      throw std::runtime_error("--assignment " + id + ": " + id +
                               " is a draft in this build (its assignment.toml says draft = true): "
                               "it is built but not graded until that line is gone; its author "
                               "tries its grader with --draft (it has: " +
                               known + ")");
    if (!chosen)
      throw std::runtime_error("--assignment " + id +
                               ": no such assignment in this build (it has: " + known + ")");
  } else if (config.assignments.size() == 1) {
    chosen = &config.assignments.front();
  } else if (!submission.empty()) {
    // The names of the files anywhere in it: the build finds a task file in any subfolder
    // (build.cpp, find_named), so a nested submission names its assignment as a flat one does.
    std::vector<std::string> present;
    std::error_code ec;
    for (fs::recursive_directory_iterator
             it(submission, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec))
      if (!it->is_directory(ec)) {
        const std::string file = it->path().filename().string();
        present.push_back(file);
        // An LMS bulk-download name names the file it stands for (the build takes it too).
        if (const std::optional<LmsName> lms = lms_name(file)) present.push_back(lms->file);
      }
    std::vector<AssignmentManifest> manifests;
    for (const AssignmentConfig& a : config.assignments) manifests.push_back(a.manifest);
    if (const AssignmentManifest* m = assignment_for_files(manifests, present))
      for (const AssignmentConfig& a : config.assignments)
        if (a.id == m->id) chosen = &a;
    if (!chosen)
      throw std::runtime_error(submission.string() +
                               ": its files do not name exactly one assignment; say which with "
                               "--assignment ID (this build has: " +
                               known + ")");
  } else {
    throw std::runtime_error("this build has several assignments (" + known +
                             "): say which with --assignment ID");
  }
  config.selected = chosen;
  config.include_dirs = chosen->include_dirs;
  config.link_objects = chosen->link_objects;
  config.link_libraries = chosen->link_libraries;
  config.reference_runner = chosen->reference_runner;
}

std::optional<LmsName> lms_name(const std::string& file_name) {
  // At most 9 digits of resubmission number: a longer run (a hostile name) never reaches stol.
  static const std::regex lms(
      R"(^.+_(?:LATE_)?[0-9]+_(?:[0-9]+|assignsubmission_file)_(.+?)(?:-([0-9]{1,9}))?(\.[^.]+)$)");
  std::smatch m;
  if (!std::regex_match(file_name, m, lms)) return std::nullopt;
  return LmsName{m[1].str() + m[3].str(), m[2].matched ? std::stol(m[2].str()) : 0};
}

// The shallowest file called `name` under `root` (symbolic links included, so that they are
// refused with a message rather than silently ignored).
std::vector<fs::path> find_named(const fs::path& root, const std::string& name) {
  std::vector<fs::path> hits;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(
           root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    if (it->path().filename() == name && !it->is_directory(ec)) hits.push_back(it->path());
  }
  std::sort(hits.begin(), hits.end(), [](const fs::path& a, const fs::path& b) {
    const auto da = std::distance(a.begin(), a.end()), db = std::distance(b.begin(), b.end());
    return da != db ? da < db : a < b;
  });
  return hits;
}

// The file to grade as `name` under an LMS bulk-download name (config.hpp, lms_name): the latest
// resubmission of the shallowest ones, or an empty path.
fs::path find_lms_named(const fs::path& root, const std::string& name) {
  fs::path best;
  long best_depth = 0, best_number = -1;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(
           root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    if (it->is_directory(ec)) continue;
    const std::optional<LmsName> lms = lms_name(it->path().filename().string());
    if (!lms || lms->file != name) continue;
    const long depth = std::distance(it->path().begin(), it->path().end());
    if (best.empty() || depth < best_depth ||
        (depth == best_depth && (lms->resubmission > best_number ||
                                 (lms->resubmission == best_number && it->path() < best)))) {
      best = it->path();
      best_depth = depth;
      best_number = lms->resubmission;
    }
  }
  return best;
}

}  // namespace jelly::grade
