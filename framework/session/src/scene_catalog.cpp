#include "jelly/session/scene_catalog.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace jelly::session {

namespace fs = std::filesystem;

fs::path default_scenes_dir() {
  if (const char* env = std::getenv("JELLY_SCENES"); env && *env) return env;
#ifdef JELLY_SCENES_DIR
  if (fs::is_directory(JELLY_SCENES_DIR)) return JELLY_SCENES_DIR;
#endif
  return "scenes";
}

SceneSpec builtin_course_2023() {
  SceneSpec s = course_2023_scene();
  s.description = "The 2023 course scene (built in): " + s.description;
  return s;
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
  const bool has_course = std::any_of(out.begin(), out.end(),
                                      [](const SceneEntry& e) { return e.name == "course-2023"; });
  if (!has_course) out.insert(out.begin(), SceneEntry{"builtin:course-2023", {}});
  return out;
}

SceneResult load_entry(const SceneEntry& e) {
  if (e.path.empty()) {
    SceneResult r;
    r.scene = builtin_course_2023();
    return r;
  }
  return load_scene(e.path);
}

SceneResult resolve_scene(std::string_view what, const fs::path& dir) {
  const std::string s(what);
  if (s == "builtin:course-2023") return load_entry({s, {}});
  std::error_code ec;
  if (fs::is_regular_file(s, ec)) return load_scene(s);
  const fs::path in_dir = dir / (s + ".toml");
  if (fs::is_regular_file(in_dir, ec)) return load_scene(in_dir);
  const bool has_suffix = s.size() > 5 && s.compare(s.size() - 5, 5, ".toml") == 0;
  const fs::path as_named = dir / s;
  if (has_suffix && fs::is_regular_file(as_named, ec)) return load_scene(as_named);
  if (s == "course-2023") return load_entry({s, {}});  // no file yet: the built-in copy
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
