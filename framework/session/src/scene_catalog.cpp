#include "jelly/session/scene_catalog.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

#include "jelly/linked_assignments.hpp"
#include "jelly/session/assignments.hpp"

namespace jelly::session {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kBuiltin = "builtin:";

/// The built-in scenes: each linked assignment's default scene with its compiled-in text, by id.
struct Builtin {
  std::string name;
  const LinkedAssignment* assignment;
};

std::vector<Builtin> builtins() {
  std::vector<Builtin> out;
  for (const LinkedAssignment& a : linked_assignments()) {
    const std::string& name = manifest_of(a).default_scene;
    if (name.empty() || a.default_scene_text.empty()) continue;
    if (std::none_of(out.begin(), out.end(), [&](const Builtin& b) { return b.name == name; }))
      out.push_back({name, &a});
  }
  return out;
}

std::string_view without_prefix(std::string_view name) {
  return name.substr(0, kBuiltin.size()) == kBuiltin ? name.substr(kBuiltin.size()) : name;
}

}  // namespace

fs::path default_scenes_dir() {
  if (const char* env = std::getenv("JELLY_SCENES"); env && *env) return env;
#ifdef JELLY_SCENES_DIR
  if (fs::is_directory(JELLY_SCENES_DIR)) return JELLY_SCENES_DIR;
#endif
  return "scenes";
}

std::string default_scene_name() {
  for (const LinkedAssignment& a : linked_assignments())
    if (const std::string& name = manifest_of(a).default_scene; !name.empty()) return name;
  return "";
}

std::optional<SceneResult> builtin_scene(std::string_view name) {
  const std::string_view plain = without_prefix(name);
  for (const Builtin& b : builtins()) {
    if (b.name != plain) continue;
    SceneResult r = parse_scene(b.assignment->default_scene_text, std::string(kBuiltin) + b.name);
    if (r) r.scene->description = "(built in) " + r.scene->description;
    return r;
  }
  return std::nullopt;
}

std::vector<SceneEntry> list_scenes(const fs::path& dir) {
  std::vector<SceneEntry> out;
  std::error_code ec;
  if (fs::is_directory(dir, ec)) {
    for (auto it = fs::recursive_directory_iterator(dir, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (!it->is_regular_file() || it->path().extension() != ".toml") continue;
      std::string name = fs::relative(it->path(), dir).replace_extension().generic_string();
      out.push_back({name, it->path()});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
  std::vector<SceneEntry> missing;
  for (const Builtin& b : builtins())
    if (std::none_of(out.begin(), out.end(), [&](const SceneEntry& e) { return e.name == b.name; }))
      missing.push_back(SceneEntry{std::string(kBuiltin) + b.name, {}});
  out.insert(out.begin(), missing.begin(), missing.end());
  return out;
}

std::string example_scene(const fs::path& dir) {
  std::vector<SceneEntry> files = list_scenes(dir);
  files.erase(std::remove_if(files.begin(), files.end(),
                             [](const SceneEntry& e) { return e.path.empty(); }),
              files.end());
  for (const LinkedAssignment& a : linked_assignments()) {
    const std::string& name = manifest_of(a).default_scene;
    if (std::any_of(files.begin(), files.end(),
                    [&](const SceneEntry& e) { return e.name == name; }))
      return name;
  }
  if (!files.empty()) return files.front().name;
  return default_scene_name();
}

std::string scenes_line(const fs::path& dir) {
  std::vector<std::string> items;  // top-level names, and "folder/ (N scenes)" per sub-folder
  std::string folder;
  int in_folder = 0;
  const auto flush = [&] {
    if (in_folder > 0)
      items.push_back(folder + "/ (" + std::to_string(in_folder) +
                      (in_folder == 1 ? " scene)" : " scenes)"));
    in_folder = 0;
  };
  for (const SceneEntry& e : list_scenes(dir)) {
    if (e.path.empty()) continue;  // a built-in copy: not a file of `dir`
    const std::size_t slash = e.name.find('/');
    if (slash == std::string::npos) {
      flush();
      items.push_back(e.name);
      continue;
    }
    if (e.name.substr(0, slash) != folder) flush();
    folder = e.name.substr(0, slash);
    ++in_folder;
  }
  flush();
  if (items.empty()) return "no scenes in " + dir.string();
  // Wrapped for a terminal: lines of at most about 100 columns, the next ones indented.
  std::string out = "scenes in " + dir.string() + ":";
  std::size_t column = out.size();
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string item = items[k] + (k + 1 < items.size() ? "," : "");
    if (column + 1 + item.size() > 100 && column > 2) {
      out += "\n ";
      column = 1;
    }
    out += " " + item;
    column += 1 + item.size();
  }
  return out;
}

SceneResult load_entry(const SceneEntry& e) {
  if (e.path.empty()) {
    if (std::optional<SceneResult> r = builtin_scene(e.name)) return *r;
    SceneResult r;
    r.error = SceneError{e.name, "", 0, 0, "no built-in scene of this name"};
    return r;
  }
  return load_scene(e.path);
}

SceneResult resolve_scene(std::string_view what, const fs::path& dir) {
  const std::string s(what);
  const bool builtin = s.compare(0, kBuiltin.size(), kBuiltin) == 0;
  if (builtin)
    if (std::optional<SceneResult> r = builtin_scene(s)) return *r;
  std::error_code ec;
  if (fs::is_regular_file(s, ec)) return load_scene(s);
  const fs::path in_dir = dir / (s + ".toml");
  if (fs::is_regular_file(in_dir, ec)) return load_scene(in_dir);
  const bool has_suffix = s.size() > 5 && s.compare(s.size() - 5, 5, ".toml") == 0;
  const fs::path as_named = dir / s;
  if (has_suffix && fs::is_regular_file(as_named, ec)) return load_scene(as_named);
  if (!builtin)  // a default scene's name with no file in `dir`: the built-in copy
    if (std::optional<SceneResult> r = builtin_scene(s)) return *r;
  if (fs::exists(s, ec)) return load_scene(s);  // e.g. a folder: load_scene says what is wrong
  std::string known;
  for (const SceneEntry& e : list_scenes(dir)) known += (known.empty() ? "" : ", ") + e.name;
  SceneResult r;
  r.error = SceneError{s, "", 0, 0,
                       "no such scene: not a file, and not a name in " + dir.string() + " (tried " +
                           (has_suffix ? as_named.string() : in_dir.string()) +
                           "); known scenes: " + known + " (or a path to a .toml scene file)"};
  return r;
}

}  // namespace jelly::session
