// A particles scene's data (body.type = "particles": the two-particle spring, particle clouds): its
// particles and explicit springs as [body] gives them, kept in the scene's body_data
// (jelly/kind_parts.hpp).
#pragma once

#include <vector>

#include "jelly/scene_spec.hpp"

namespace jelly {

/// The kind the particles module registers.
inline constexpr BodyKind kParticlesKind{"particles"};

/// A body given particle by particle.
struct ParticleBodySpec {
  Vec3Array positions;          ///< 3×N [m]
  Vec3Array velocities;         ///< 3×N [m/s] (zero when the scene gives none)
  double mass = 1.0;            ///< every particle [kg]
  std::vector<Spring> springs;  ///< explicit springs (rest length given or from positions)
  SpringType spring_type = SpringType::Structural;  ///< whose coefficients they use
};

/// The scene's particles, made empty on first use.
inline ParticleBodySpec& particles_scene(SceneSpec& scene) {
  return scene.body_data.get<ParticleBodySpec>();
}
/// The scene's particles, or none when the scene has none.
inline const ParticleBodySpec& particles_scene(const SceneSpec& scene) {
  return scene.body_data.get_or_default<ParticleBodySpec>();
}

}  // namespace jelly
