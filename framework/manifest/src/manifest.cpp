#include "jelly/manifest.hpp"

#include "jelly/toml_text.hpp"

#include <algorithm>
#include <fstream>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>

#include <toml++/toml.h>

namespace jelly {

namespace {

std::string where(const std::string& source, const toml::node* n) {
  if (n && n->source().begin.line > 0) return source + ":" + std::to_string(n->source().begin.line);
  return source;
}

[[noreturn]] void fail(const std::string& source, const toml::node* n, const std::string& key,
                       const std::string& expected) {
  throw ManifestError(where(source, n) + ": " + key + ": expected " + expected);
}

// A plain name: letters, digits, '_' and '-' (folder names, namespaces, ids).
bool is_name(std::string_view s, bool allow_dash) {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || (allow_dash && c == '-');
    if (!ok) return false;
  }
  return !(s[0] >= '0' && s[0] <= '9');
}

// A file name relative to a folder, with no way out of it.
bool is_relative_path(std::string_view s) {
  if (s.empty() || s[0] == '/' || s[0] == '\\' || s.find(':') != std::string_view::npos)
    return false;
  std::string part;
  std::istringstream in{std::string(s)};
  while (std::getline(in, part, '/'))
    if (part.empty() || part == "." || part == "..") return false;
  return s.find('\\') == std::string_view::npos;
}

class Reader {
 public:
  Reader(const toml::table& t, std::string source, std::string prefix)
      : t_(t), source_(std::move(source)), prefix_(std::move(prefix)) {}

  std::string key(const std::string& k) const { return prefix_ + k; }

  std::string string(const std::string& k, bool required, const std::string& expected) {
    seen_.insert(k);
    const toml::node* n = t_.get(k);
    if (!n) {
      if (required) fail(source_, nullptr, key(k), expected + " (the key is missing)");
      return {};
    }
    const auto* s = n->as_string();
    if (!s || s->get().empty()) fail(source_, n, key(k), expected);
    return s->get();
  }

  std::vector<std::string> strings(const std::string& k, bool required,
                                   const std::string& expected) {
    seen_.insert(k);
    const toml::node* n = t_.get(k);
    std::vector<std::string> out;
    if (!n) {
      if (required) fail(source_, nullptr, key(k), expected + " (the key is missing)");
      return out;
    }
    const auto* a = n->as_array();
    if (!a) fail(source_, n, key(k), expected);
    for (const toml::node& e : *a) {
      const auto* s = e.as_string();
      if (!s || s->get().empty()) fail(source_, &e, key(k), expected);
      out.push_back(s->get());
    }
    return out;
  }

  double number(const std::string& k, bool required, double fallback, const std::string& expected) {
    seen_.insert(k);
    const toml::node* n = t_.get(k);
    if (!n) {
      if (required) fail(source_, nullptr, key(k), expected + " (the key is missing)");
      return fallback;
    }
    double v = 0.0;
    if (const auto* i = n->as_integer())
      v = static_cast<double>(i->get());
    else if (const auto* f = n->as_floating_point())
      v = f->get();
    else
      fail(source_, n, key(k), expected);
    if (!(v >= 0.0) || v > 1e9) fail(source_, n, key(k), expected);
    return v;
  }

  bool boolean(const std::string& k, const std::string& expected) {
    seen_.insert(k);
    const toml::node* n = t_.get(k);
    if (!n) return false;
    const auto* b = n->as_boolean();
    if (!b) fail(source_, n, key(k), expected);
    return b->get();
  }

  const toml::node* node(const std::string& k) {
    seen_.insert(k);
    return t_.get(k);
  }

  // Checked first: a key not in `known` is a typo, reported at its line before a required key it
  // may have been meant as is reported missing.
  void only_keys(std::initializer_list<const char*> known) const {
    for (const auto& [k, v] : t_) {
      bool ok = false;
      for (const char* name : known) ok = ok || k.str() == name;
      if (!ok)
        fail(source_, &v, key(std::string(k.str())), "no such key (see docs/new-assignment.md)");
    }
  }

  // Every key the reader did not ask for is a mistake (a typo would otherwise be ignored).
  void no_unknown_keys() const {
    for (const auto& [k, v] : t_)
      if (!seen_.count(std::string(k.str())))
        fail(source_, &v, key(std::string(k.str())), "no such key (see docs/new-assignment.md)");
  }

 private:
  const toml::table& t_;
  std::string source_;
  std::string prefix_;
  std::set<std::string> seen_;
};

void check_files(const std::string& source, const toml::node* n, const std::string& key,
                 const std::vector<std::string>& files) {
  std::set<std::string> seen;
  for (const std::string& f : files) {
    if (!is_relative_path(f) || f.find('/') != std::string::npos)
      fail(source, n, key, "plain file names in the assignment's folder, not \"" + f + "\"");
    if (!seen.insert(f).second) fail(source, n, key, "each file once, not \"" + f + "\" twice");
  }
}

// `bodies`: each entry a body kind's name, or name:variant (names of letters, digits, '_' and
// '-'), each scene claimed once: "kind" with "kind:variant" would claim that variant twice.
std::vector<BodyClaim> read_bodies(const std::string& source, const toml::node* n,
                                   const std::vector<std::string>& texts) {
  const std::string what =
      "a body kind's name (a scene's [body] type: every scene of the kind) or kind:variant (only "
      "its scenes of that variant, docs/new-assignment.md), names of letters, digits, '_' and '-'";
  std::vector<BodyClaim> out;
  const auto* arr = n ? n->as_array() : nullptr;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const toml::node* at = arr && i < arr->size() ? arr->get(i) : n;
    const std::string& t = texts[i];
    const std::size_t colon = t.find(':');
    BodyClaim c{t.substr(0, colon), colon == std::string::npos ? "" : t.substr(colon + 1)};
    if (!is_name(c.kind, true) || (colon != std::string::npos && !is_name(c.variant, true)))
      fail(source, at, "bodies", what + ", not \"" + t + "\"");
    for (const BodyClaim& before : out)
      if (before.kind == c.kind &&
          (before.variant.empty() || c.variant.empty() || before.variant == c.variant))
        fail(source, at, "bodies",
             "each scene claimed once, and \"" + before.text() + "\" already claims the scenes \"" +
                 t + "\" does");
    out.push_back(std::move(c));
  }
  return out;
}

/// The manifest's TOML, or the error that says where it is not TOML.
toml::table parse_toml(std::string_view text, const std::string& source) {
  if (const auto at = toml_non_ascii_outside_strings(text))
    throw ManifestError(source + ":" + std::to_string(at->line) + ":" + std::to_string(at->column) +
                        ": " + std::string(kTomlNonAsciiMessage));
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ManifestError(source + ":" + std::to_string(e.source().begin.line) +
                        ": not valid TOML: " + std::string(e.description()));
  }
}

/// The reading of one manifest's table, a step per group of keys. The steps run in the order the
/// keys are checked, so the error thrown is the first one met in that order.
class ManifestReader {
 public:
  ManifestReader(const toml::table& root, const std::string& source)
      : source_(source), r_(root, source, "") {}

  AssignmentManifest read() {
    r_.only_keys({"id", "namespace", "title", "files", "reference_files", "task_modules", "bodies",
                  "default_scene", "handout", "contracts", "studies", "grading", "task", "draft"});
    m_.draft =
        r_.boolean("draft", "true or false (true: an assignment in preparation, never graded)");
    read_identity();
    read_files();
    read_scenes();
    read_handout();
    read_studies();
    read_grading();
    read_tasks();
    check_regular_points();
    r_.no_unknown_keys();
    return std::move(m_);
  }

 private:
  /// id, namespace and title.
  void read_identity() {
    m_.id = r_.string("id", true, "the assignment's id, a lower-case name such as \"hw1\"");
    if (!is_name(m_.id, true))
      fail(source_, r_.node("id"), "id",
           "letters, digits, '-' and '_' only, not \"" + m_.id + "\"");
    m_.ns = r_.string("namespace", true, "the C++ namespace of the tasks (jelly::<namespace>)");
    if (!is_name(m_.ns, false))
      fail(source_, r_.node("namespace"), "namespace", "a C++ identifier, not \"" + m_.ns + "\"");
    m_.title = r_.string("title", true, "a one-line title");
  }

  /// files, reference_files and task_modules.
  void read_files() {
    m_.files = r_.strings("files", true, "a non-empty list of the files a student edits");
    if (m_.files.empty()) fail(source_, r_.node("files"), "files", "at least one file");
    check_files(source_, r_.node("files"), "files", m_.files);
    m_.reference_files = r_.strings("reference_files", false, "a list of file names");
    check_files(source_, r_.node("reference_files"), "reference_files", m_.reference_files);
    m_.task_modules =
        r_.strings("task_modules", false, "a list of task module names (solutions/tasks/)");
  }

  /// bodies (the scenes it claims) and default_scene.
  void read_scenes() {
    m_.bodies = read_bodies(
        source_, r_.node("bodies"),
        r_.strings(
            "bodies", false,
            "a list of the body.type names of framework/bodies/ its tasks simulate (a name or "
            "name:variant)"));
    m_.default_scene = r_.string("default_scene", false, "a scene name");
  }

  /// contracts (the handout's anchors) and handout.
  void read_handout() {
    m_.contracts = r_.strings("contracts", false,
                              "a list of contract names (the handout's anchors <name>-contract-N)");
    for (const std::string& c : m_.contracts)
      if (c.empty() || c.size() > 32 ||
          c.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
        fail(source_, r_.node("contracts"), "contracts",
             "names of lower-case letters, digits and '-' (a handout anchor), not \"" + c + "\"");
    m_.handout = r_.string("handout", false, "a file in the assignment's folder");
    if (!m_.handout.empty() && !is_relative_path(m_.handout))
      fail(source_, r_.node("handout"), "handout", "a path inside the assignment's folder");
  }

  /// The optional [studies] table.
  void read_studies() {
    const toml::node* n = r_.node("studies");
    if (!n) return;
    const auto* t = n->as_table();
    if (!t) fail(source_, n, "studies", "a table");
    Reader s(*t, source_, "studies.");
    s.only_keys({"measures"});
    m_.study_measures = s.strings("measures", false, "a list of measure names");
    s.no_unknown_keys();
  }

  /// The [grading] table, which every manifest has.
  void read_grading() {
    const toml::node* n = r_.node("grading");
    if (!n)
      fail(source_, nullptr, "grading",
           "a [grading] table with autograded_total (the key is missing)");
    const auto* t = n->as_table();
    if (!t) fail(source_, n, "grading", "a table");
    Reader g(*t, source_, "grading.");
    g.only_keys({"autograded_total", "hand_graded_points", "hidden_visibility"});
    m_.autograded_total = g.number("autograded_total", true, 0.0, "a number of points ≥ 0");
    m_.hand_graded_points =
        g.number("hand_graded_points", false, 0.0, "a number of points ≥ 0 graded by hand");
    const std::string vis = g.string("hidden_visibility", false,
                                     "\"hidden\", \"after_due_date\" or \"after_published\"");
    if (!vis.empty()) {
      if (vis != "hidden" && vis != "after_due_date" && vis != "after_published")
        fail(source_, g.node("hidden_visibility"), "grading.hidden_visibility",
             "\"hidden\", \"after_due_date\" or \"after_published\", not \"" + vis + "\"");
      m_.hidden_visibility = vis;
    }
    g.no_unknown_keys();
  }

  /// The [[task]] tables, at least one.
  void read_tasks() {
    tasks_ = r_.node("task");
    const auto* arr = tasks_ ? tasks_->as_array() : nullptr;
    if (!arr || arr->empty())
      fail(source_, tasks_, "task", "one [[task]] table per task (none found)");
    for (std::size_t i = 0; i < arr->size(); ++i) m_.tasks.push_back(read_task(*arr->get(i), i));
  }

  /// The i-th (from 0) [[task]] table.
  ManifestTask read_task(const toml::node& e, std::size_t i) {
    const auto* t = e.as_table();
    const std::string prefix = "task[" + std::to_string(i + 1) + "].";
    if (!t) fail(source_, &e, "task[" + std::to_string(i + 1) + "]", "a table");
    Reader tr(*t, source_, prefix);
    tr.only_keys({"id", "title", "short", "category", "file", "functions", "points", "handout",
                  "probe", "bonus"});
    ManifestTask task;
    read_task_names(tr, prefix, task);
    task.functions = tr.strings("functions", false, "a list of function names");
    task.points = tr.number("points", true, 0.0, "a number of points ≥ 0");
    task.handout = tr.string("handout", false, "a file in the assignment's folder");
    if (!task.handout.empty() && !is_relative_path(task.handout))
      fail(source_, tr.node("handout"), prefix + "handout",
           "a path inside the assignment's folder");
    task.probe = tr.string("probe", false, "the name of a TaskTable slot");
    read_task_bonus(tr, prefix, task);
    tr.no_unknown_keys();
    return task;
  }

  /// A task's id (unique), title, short name, category and file (one of `files`).
  void read_task_names(Reader& tr, const std::string& prefix, ManifestTask& task) {
    task.id = tr.string("id", true, "a task id such as \"HW.T1\"");
    if (!ids_.insert(task.id).second)
      fail(source_, tr.node("id"), prefix + "id",
           "a unique id (\"" + task.id + "\" is used twice)");
    task.title = tr.string("title", true, "a one-line title");
    task.short_name = tr.string("short", false, "a short name for the viewer's hint");
    if (task.short_name.empty()) task.short_name = task.title;
    task.category = tr.string("category", false, "a category name");
    task.file = tr.string("file", false, "one of `files`");
    if (!task.file.empty() &&
        std::find(m_.files.begin(), m_.files.end(), task.file) == m_.files.end())
      fail(source_, tr.node("file"), prefix + "file",
           "one of the assignment's `files`, not \"" + task.file + "\"");
  }

  /// A task's bonus flag; a bonus task has points and functions of its own.
  void read_task_bonus(Reader& tr, const std::string& prefix, ManifestTask& task) {
    task.bonus = tr.boolean("bonus",
                            "true or false (true: its points come on top of "
                            "grading.autograded_total)");
    if (task.bonus && !(task.points > 0.0))
      fail(source_, tr.node("points"), prefix + "points",
           "a number of points > 0 for a bonus task (bonus = true)");
    if (task.bonus && task.functions.empty())
      fail(source_, tr.node("bonus"), prefix + "bonus",
           "false for a task with no function of its own (a bonus task is graded on its "
           "functions)");
  }

  /// Autograded points need a task that is not a bonus to scale to.
  void check_regular_points() const {
    double regular = 0.0;
    for (const ManifestTask& t : m_.tasks)
      if (!t.bonus) regular += t.points;
    if (m_.autograded_total > 0.0 && !(regular > 0.0))
      fail(source_, tasks_, "task",
           "at least one task that is not a bonus with points > 0 (the bonus points come on top of "
           "grading.autograded_total, which the other tasks' points are scaled to)");
  }

  const std::string& source_;
  Reader r_;
  AssignmentManifest m_;
  const toml::node* tasks_ = nullptr;  // the [[task]] array, where its errors point
  std::set<std::string> ids_;          // the task ids read so far
};

}  // namespace

bool AssignmentManifest::claims(std::string_view scene_kind, std::string_view scene_variant) const {
  for (const BodyClaim& c : bodies)
    if (c.claims(scene_kind, scene_variant)) return true;
  return false;
}

std::string ManifestTask::functions_text() const {
  if (functions.empty()) return "your code";
  std::string out;
  for (const std::string& f : functions) out += (out.empty() ? "" : ", ") + f;
  if (!file.empty()) out += " (" + file + ")";
  return out;
}

const ManifestTask* AssignmentManifest::find_task(std::string_view task_id) const {
  for (const ManifestTask& t : tasks)
    if (t.id == task_id) return &t;
  return nullptr;
}

std::string AssignmentManifest::task_prefix() const {
  if (tasks.empty()) return {};
  std::string p = tasks.front().id;
  for (const ManifestTask& t : tasks) {
    std::size_t i = 0;
    while (i < p.size() && i < t.id.size() && p[i] == t.id[i]) ++i;
    p.resize(i);
  }
  const std::size_t dot = p.rfind('.');
  return dot == std::string::npos ? std::string() : p.substr(0, dot + 1);
}

AssignmentManifest parse_manifest(std::string_view text, const std::string& source) {
  const toml::table root = parse_toml(text, source);
  return ManifestReader(root, source).read();
}

AssignmentManifest read_manifest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ManifestError(file.string() + ": cannot read the assignment's manifest");
  std::ostringstream text;
  text << in.rdbuf();
  AssignmentManifest m = parse_manifest(text.str(), file.string());
  m.dir = file.parent_path();
  if (m.dir.filename().string() != m.id)
    throw ManifestError(file.string() + ": id: expected the folder's name \"" +
                        m.dir.filename().string() + "\", not \"" + m.id + "\"");
  return m;
}

std::vector<AssignmentManifest> find_assignments(const std::filesystem::path& assignments_root) {
  namespace fs = std::filesystem;
  std::vector<AssignmentManifest> out;
  std::error_code ec;
  if (!fs::is_directory(assignments_root, ec))
    throw ManifestError(assignments_root.string() + ": not a folder of assignments");
  for (const fs::directory_entry& e : fs::directory_iterator(assignments_root, ec)) {
    const fs::path manifest = e.path() / "assignment.toml";
    if (e.is_directory(ec) && fs::is_regular_file(manifest, ec))
      out.push_back(read_manifest(manifest));
  }
  std::sort(out.begin(), out.end(),
            [](const AssignmentManifest& a, const AssignmentManifest& b) { return a.id < b.id; });
  std::map<std::string, std::string> namespaces;
  for (const AssignmentManifest& m : out)
    if (!namespaces.emplace(m.ns, m.id).second)
      throw ManifestError((m.dir / "assignment.toml").string() +
                          ": namespace: expected one of its " + "own, not \"" + m.ns +
                          "\" (assignment " + namespaces[m.ns] + " uses it)");
  return out;
}

const AssignmentManifest* assignment_for_files(const std::vector<AssignmentManifest>& all,
                                               const std::vector<std::string>& present) {
  auto has = [&](const std::string& f) {
    return std::find(present.begin(), present.end(), f) != present.end();
  };
  const AssignmentManifest* complete = nullptr;
  int complete_count = 0;
  const AssignmentManifest* partial = nullptr;
  int partial_count = 0;
  for (const AssignmentManifest& m : all) {
    const auto n = std::count_if(m.files.begin(), m.files.end(), has);
    if (n == static_cast<long>(m.files.size())) complete = &m, ++complete_count;
    if (n > 0) partial = &m, ++partial_count;
  }
  if (complete_count == 1) return complete;
  if (complete_count == 0 && partial_count == 1) return partial;
  return nullptr;
}

}  // namespace jelly
