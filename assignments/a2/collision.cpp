// Your code: impulses between point bodies, tasks A2.T6–A2.T7.
// Read assignments/a2/handout/T6-cloth-sphere.md first. Check yourself with: tools/selfcheck
#include "jelly/a2/collision.hpp"

namespace jelly::a2 {

Impulse collide_particle_sphere(PointBody& particle, SphereBody& sphere,
                                const ImpulseSettings& settings) {
  // TODO(A2.T6): N = (x − c)/|x − c|, φ = |x − c| − r; when φ < ε, N·v_rel < 0 and w_A + w_B > 0,
  // apply j = −(1 + e)(N·v_rel)/(w_A + w_B) to both velocities and return {true, N, j}.
  // assignments/a2/handout/T6-cloth-sphere.md. Use inverse masses: a pinned particle (w = 0)
  // must never move.
  (void)particle, (void)sphere, (void)settings;
  return Impulse{};
}

Impulse collide_spheres(SphereBody& a, SphereBody& b, const ImpulseSettings& settings) {
  // TODO(A2.T7): the same impulse between two spheres, N = (c_a − c_b)/|c_a − c_b|,
  // φ = |c_a − c_b| − r_a − r_b.
  // assignments/a2/handout/T7-sphere-sphere.md. Two equal spheres meeting at ±1 m/s with e = 0.8
  // leave at ∓0.8 m/s.
  (void)a, (void)b, (void)settings;
  return Impulse{};
}

}  // namespace jelly::a2
