// Finding scenes: every *.toml under the scenes folder, by name or path, plus a built-in copy of
// each linked assignment's default scene (its manifest's default_scene, compiled in: used when the
// scenes folder lacks that file, or by name as builtin:<scene>). No GL: the CLI uses it.
#pragma once

#include <filesystem>
#include <optional>
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
/// The scene a program starts with when none is named (the viewer, the smoke test): the
/// default_scene of the first linked assignment (by id) whose manifest names one; "" when none
/// does.
std::string default_scene_name();
/// Every *.toml under `dir` (recursively), sorted by name, after the built-in copy of each linked
/// assignment's default scene that `dir` lacks ("builtin:<scene>").
std::vector<SceneEntry> list_scenes(const std::filesystem::path& dir);
/// The one way every command (`jelly run/check/params/study/render`, jelly-lab) finds a scene:
/// a path to a scene file; else a name under `dir`, with or without ".toml" ("hard/stiff-springs");
/// else "builtin:<scene>", or a default scene's plain name when `dir` lacks its file: the built-in
/// copy. When nothing fits, the error names the argument, every place tried and the known names.
SceneResult resolve_scene(std::string_view name_or_path, const std::filesystem::path& dir);
/// For help texts, which must name only scenes that this build can run: the example scene, the
/// default_scene of the first linked assignment (by id) that `dir` holds, else the first scene in
/// `dir`, else the first linked default scene (built in); "" when there is none of these.
std::string example_scene(const std::filesystem::path& dir);
/// For help texts: one line naming the scenes in `dir` (its files only, never a scene of an
/// assignment this build does not link), each sub-folder as "hard/ (15 scenes)":
/// "scenes in DIR: a, b, hard/ (15 scenes)", or "no scenes in DIR".
std::string scenes_line(const std::filesystem::path& dir);
/// Loads one catalogue entry.
SceneResult load_entry(const SceneEntry& entry);
/// The built-in copy of `name` ("course-2023" or "builtin:course-2023"): the linked assignment's
/// default scene file as it was at build time, its description marked "(built in)". nullopt when
/// no linked assignment has a default scene of that name.
std::optional<SceneResult> builtin_scene(std::string_view name);

}  // namespace jelly::session
