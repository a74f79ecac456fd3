// Student task A2.T12 (bonus): Coulomb friction right after a normal impulse (cloth contract §4).
// Handout: assignments/a2/handout/T12-friction.md.
#pragma once

#include "jelly/spheres.hpp"

namespace jelly::a2 {

/// A2.T12 — After the normal impulse `normal` (N, j) of a pair with inverse masses w_a, w_b and
/// velocities v_a, v_b (already changed by it): with v_rel,T = v_rel − (N·v_rel) N and
/// t = v_rel,T / |v_rel,T| (nothing when |v_rel,T| < 1e-12), applies j_T = min(μ j, |v_rel,T| /
/// (w_a + w_b)): v_a ← v_a − w_a j_T t, v_b ← v_b + w_b j_T t.
void friction_impulse(const Impulse& normal, double mu, double w_a, double w_b, Vec3& v_a,
                      Vec3& v_b);

}  // namespace jelly::a2
