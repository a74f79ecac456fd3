// The default physics of a world (contract §5, §6): particles of mass m, gravity, springs and the
// terrains' contact forces give a = f/m, and the terrains' collision response acts at the start of
// every step. A kind whose bodies are particles over terrains keeps it (or extends it with its own
// state); a kind with other physics installs its own BodyPhysics.
#pragma once

#include "jelly/body_physics.hpp"

namespace jelly {

class TerrainPhysics : public BodyPhysics {
 public:
  using BodyPhysics::BodyPhysics;
  /// 1. gravity m g (when the scene has it), 2. springs and dampers, 3. contact forces terrain by
  /// terrain in scene order, 4. a = f/m.
  void acceleration(const State& s, Vec3Array& a) override;
  /// The velocity response of every terrain with collision on, in order (then its optional
  /// projection). Changes `s.v` (and `s.x` only for projecting terrains).
  void apply_collisions(State& s) override;

 private:
  void contact_pass(const State& s, Vec3Array& f);
};

}  // namespace jelly
