// Student tasks A2.T6–A2.T7: impulses between point bodies (cloth contract §4).
// Handout: assignments/a2/handout/T6-cloth-sphere.md, T7-sphere-sphere.md.
//
// Both bodies of a pair have an inverse mass w (0 for a pinned particle or a kinematic sphere).
// With N the unit normal from B towards A, v_rel = v_A − v_B and φ the gap:
//   collides := φ < ε  ∧  N·v_rel < 0  ∧  w_A + w_B > 0
//   j = −(1 + e) (N·v_rel) / (w_A + w_B);   v_A ← v_A + w_A j N,   v_B ← v_B − w_B j N
// Each function changes velocities only when the pair collides, never positions, and returns
// what it applied (Impulse{applied, normal, j}); otherwise Impulse{} (applied = false).
#pragma once

#include "jelly/spheres.hpp"

namespace jelly::a2 {

/// A2.T6 — A cloth particle (A, radius 0) against a sphere (B): N = (x − c)/|x − c|,
/// φ = |x − c| − r, e = settings.restitution. No normal (nothing happens) when
/// |x − c| < 1e-12·r.
Impulse collide_particle_sphere(PointBody& particle, SphereBody& sphere,
                                const ImpulseSettings& settings);

/// A2.T7 — Sphere a (A) against sphere b (B): N = (c_a − c_b)/|c_a − c_b|,
/// φ = |c_a − c_b| − r_a − r_b. No normal when |c_a − c_b| < 1e-12·(r_a + r_b).
Impulse collide_spheres(SphereBody& a, SphereBody& b, const ImpulseSettings& settings);

}  // namespace jelly::a2
