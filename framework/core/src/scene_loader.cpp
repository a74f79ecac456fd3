// PLACEHOLDER until the scene loader lands (helper task). Replaced wholesale.
#include "jelly/scene.hpp"

namespace jelly {

SceneResult parse_scene(std::string_view /*text*/, std::string_view source_name) {
  SceneResult r;
  r.error = SceneError{std::string(source_name), "", 0, 0, "scene loading is not built yet"};
  return r;
}

SceneResult load_scene(const std::filesystem::path& path) { return parse_scene("", path.string()); }

std::optional<SceneError> set_parameter(SceneSpec&, std::string_view key, std::string_view) {
  return SceneError{"--set", std::string(key), 0, 0, "not built yet"};
}

std::string to_toml(const SceneSpec&) { return {}; }

}  // namespace jelly
