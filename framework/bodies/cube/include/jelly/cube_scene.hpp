// A cube scene's data (body.type = "cube"): the CubeSpec its [body] keys fill, kept in the scene's
// body_data (jelly/kind_parts.hpp).
#pragma once

#include "jelly/cube.hpp"
#include "jelly/scene_spec.hpp"

namespace jelly {

/// The kind the cube module registers.
inline constexpr BodyKind kCubeKind{"cube"};

/// The scene's cube, made with CubeSpec's defaults on first use.
inline CubeSpec& cube_spec(SceneSpec& scene) { return scene.body_data.get<CubeSpec>(); }
/// The scene's cube, or CubeSpec's defaults when the scene has none.
inline const CubeSpec& cube_spec(const SceneSpec& scene) {
  return scene.body_data.get_or_default<CubeSpec>();
}

}  // namespace jelly
