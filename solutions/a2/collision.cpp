// Reference solution of A2.T6–A2.T7 (impulses between point bodies). Not shipped to students.
#include "jelly/a2/collision.hpp"

namespace jelly::a2 {

namespace {

// The impulse of cloth contract §4 along the unit normal N (from B towards A), given the gap φ.
Impulse apply_impulse(const Vec3& normal, double phi, Vec3& v_a, double w_a, Vec3& v_b, double w_b,
                      const ImpulseSettings& settings) {
  const double approach = normal.dot(v_a - v_b);
  const double w = w_a + w_b;
  if (!(phi < settings.tolerance) || !(approach < 0.0) || !(w > 0.0)) return Impulse{};
  const double j = -(1.0 + settings.restitution) * approach / w;
  v_a += (w_a * j) * normal;
  v_b -= (w_b * j) * normal;
  return Impulse{true, normal, j};
}

}  // namespace

Impulse collide_particle_sphere(PointBody& particle, SphereBody& sphere,
                                const ImpulseSettings& settings) {
  const Vec3 d = particle.position - sphere.center;
  const double distance = d.norm();
  if (distance < 1e-12 * sphere.radius) return Impulse{};  // at the centre: no normal
  const Vec3 normal = d / distance;
  return apply_impulse(normal, distance - sphere.radius, particle.velocity, particle.inverse_mass,
                       sphere.velocity, sphere.inverse_mass, settings);
}

Impulse collide_spheres(SphereBody& a, SphereBody& b, const ImpulseSettings& settings) {
  const Vec3 d = a.center - b.center;
  const double distance = d.norm();
  if (distance < 1e-12 * (a.radius + b.radius)) return Impulse{};
  const Vec3 normal = d / distance;
  return apply_impulse(normal, distance - a.radius - b.radius, a.velocity, a.inverse_mass,
                       b.velocity, b.inverse_mass, settings);
}

}  // namespace jelly::a2
