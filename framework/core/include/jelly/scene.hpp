// Scenes: what a scene file describes, how it is loaded and validated, and how it becomes a World.
//
// The scene itself is jelly/scene_spec.hpp. Every parameter is declared once (params.hpp: name,
// unit, default, range, description); the loader, `jelly run --set`, the viewer's panels and the
// grader all go through that declaration.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/params.hpp"  // get_parameter, set_parameter, set_assignment
#include "jelly/scene_spec.hpp"
#include "jelly/world.hpp"

namespace jelly {

/// Either a scene or the first error found.
struct SceneResult {
  std::optional<SceneSpec> scene;
  std::optional<SceneError> error;
  explicit operator bool() const { return scene.has_value(); }
};

/// Reads, parses and validates a scene file. Never throws, never exits, writes nothing.
SceneResult load_scene(const std::filesystem::path& path);
/// Parses and validates scene text; `source_name` names it in errors (used by tests and the
/// fuzzer).
SceneResult parse_scene(std::string_view text, std::string_view source_name);

/// Writes a scene back as TOML that load_scene reads to the same SceneSpec.
std::string to_toml(const SceneSpec& scene);

/// Builds the World a scene describes, with the given task implementations. Only the effects the
/// scene names are built: absent spring types are not built, absent terrains not added, no gravity
/// means no gravity term (contract §7).
std::unique_ptr<World> build_world(const SceneSpec& scene, const TaskTable& tasks);

/// Named terrain presets: "course-2023-floor", "course-2023-bowl", "course-2021-plane",
/// "course-2021-sphere", "course-2021-bowl", "course-2021-tilted". nullopt when unknown.
std::optional<Terrain> terrain_preset(std::string_view name);
/// All preset names.
std::vector<std::string_view> terrain_preset_names();

/// The course's 2023 scene as scenes/course-2023.toml describes it (an n = 10 body at
/// (−4.8, 11, 0), ks 2000 / kd 60 on every spring type, gravity, the floor with its hole then the
/// bowl, h = 0.001, 10 s, symplectic Euler), built in code: for tests and benchmarks that must not
/// depend on scene files, and for the viewer when the file is missing.
SceneSpec course_2023_scene();

}  // namespace jelly
