// A cloth scene's data (body.type = "cloth", cloth contract §1, §4, §6): the ClothSpec its [body]
// keys fill, its spheres ([[sphere]]) and its [collision] settings, kept in the scene's body_data
// (jelly/kind_parts.hpp).
#pragma once

#include <vector>

#include "jelly/cloth.hpp"
#include "jelly/scene_spec.hpp"
#include "jelly/spheres.hpp"

namespace jelly {

/// The kind the cloth module registers.
inline constexpr BodyKind kClothKind{"cloth"};

/// The scene's cloth, made with ClothSpec's defaults on first use.
inline ClothSpec& cloth_spec(SceneSpec& scene) { return scene.body_data.get<ClothSpec>(); }
/// The scene's cloth, or ClothSpec's defaults when the scene has none.
inline const ClothSpec& cloth_spec(const SceneSpec& scene) {
  return scene.body_data.get_or_default<ClothSpec>();
}

/// The scene's spheres in scene order (they are part of the result); none until one is added.
inline std::vector<SphereSpec>& sphere_specs(SceneSpec& scene) {
  return scene.body_data.get<std::vector<SphereSpec>>();
}
inline const std::vector<SphereSpec>& sphere_specs(const SceneSpec& scene) {
  return scene.body_data.get_or_default<std::vector<SphereSpec>>();
}

/// The scene's [collision] settings: e_cloth, e_sphere, ε, μ, β.
inline ClothCollisionSettings& cloth_collisions(SceneSpec& scene) {
  return scene.body_data.get<ClothCollisionSettings>();
}
inline const ClothCollisionSettings& cloth_collisions(const SceneSpec& scene) {
  return scene.body_data.get_or_default<ClothCollisionSettings>();
}

}  // namespace jelly
