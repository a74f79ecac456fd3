// Student tasks A1.T6–A1.T7: collision response (physics contract §4).
// Handout: assignments/a1/handout/T6-plane-collision.md, T7-bowl-collision.md.
#pragma once

#include "jelly/terrain.hpp"
#include "jelly/types.hpp"

namespace jelly::a1 {

/// A1.T6 — Velocity response of one particle against a plane (with its hole, if it has one).
/// With φ = N·(x − p): the particle collides when φ < ε, N·v < 0 and it is outside the hole (its
/// distance to the hole centre, measured in the plane, is at least r_h). Then, with
/// v_N = (N·v) N and v_T = v − v_N:  v ← −k_r v_N + v_T.  Positions never change.
/// Returns true when the particle collided (v was changed).
bool collide_plane(const Plane& plane, const Vec3& x, Vec3& v);

/// A1.T7 — Velocity response of one particle against a bowl (the inside of a sphere below its rim).
/// N = (c − x)/|c − x| (inward), φ = R − |x − c|. Collides when φ < ε, N·v < 0, x_y ≤ y_rim + ε and
/// the horizontal distance from x to the bowl's vertical axis is at most bowl.rim_radius().
/// Response as for the plane. Returns true when the particle collided.
bool collide_bowl(const Bowl& bowl, const Vec3& x, Vec3& v);

}  // namespace jelly::a1
