// Reference solution of A2.T12 (bonus: Coulomb friction). Not shipped to students.
#include "jelly/a2/friction.hpp"

#include <algorithm>

namespace jelly::a2 {

void friction_impulse(const Impulse& normal, double mu, double w_a, double w_b, Vec3& v_a,
                      Vec3& v_b) {
  const double w = w_a + w_b;
  if (!normal.applied || !(w > 0.0)) return;
  const Vec3 v_rel = v_a - v_b;
  const Vec3 tangential = v_rel - normal.normal.dot(v_rel) * normal.normal;
  const double speed = tangential.norm();
  if (speed < 1e-12) return;
  const Vec3 t = tangential / speed;
  const double j_t = std::min(mu * normal.j, speed / w);  // Coulomb's cone, never reversing
  v_a -= (w_a * j_t) * t;
  v_b += (w_b * j_t) * t;
}

}  // namespace jelly::a2
