// Finding scenes: every *.toml under the scenes folder, by name or path, plus a built-in copy of
// the course scene (used only while scenes/course-2023.toml is not there). No GL: the CLI uses it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/scene.hpp"

namespace jelly::session {

struct SceneEntry {
  std::string name;  ///< path relative to the scenes folder without .toml, e.g. "hard/stiff"
  std::filesystem::path path;  ///< empty for the built-in scene
};

/// The scenes folder: $JELLY_SCENES, else the source tree's scenes/ (compiled in), else ./scenes.
std::filesystem::path default_scenes_dir();
/// Every *.toml under `dir` (recursively), sorted by name; the built-in course scene is added
/// when `dir` has no course-2023.toml.
std::vector<SceneEntry> list_scenes(const std::filesystem::path& dir);
/// The one way every command (`jelly run/check/params/study/render`, jelly-lab) finds a scene:
/// a path to a scene file; else a name under `dir`, with or without ".toml" ("course-2023",
/// "hard/stiff-springs"); else "builtin:course-2023" (or "course-2023" when `dir` lacks it).
/// When nothing fits, the error names the argument, every place tried and the known names.
SceneResult resolve_scene(std::string_view name_or_path, const std::filesystem::path& dir);
/// Loads one catalogue entry.
SceneResult load_entry(const SceneEntry& entry);
/// The 2023 course scene built in code from the terrain presets (course-anchor.md defaults).
SceneSpec builtin_course_2023();

}  // namespace jelly::session
