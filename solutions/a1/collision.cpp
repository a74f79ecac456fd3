// Reference solution of A1.T6–A1.T7 (collision response). Not shipped to students.
#include <cmath>

#include "jelly/a1/collision.hpp"

namespace jelly::a1 {

namespace {

// v ← −k_r v_N + v_T with v_N = (N·v) N, v_T = v − v_N.
Vec3 reflect(const Vec3& v, const Vec3& n, double restitution) {
  const Vec3 vn = n.dot(v) * n;
  const Vec3 vt = v - vn;
  return -restitution * vn + vt;
}

}  // namespace

bool collide_plane(const Plane& plane, const Vec3& x, Vec3& v) {
  const Vec3& n = plane.normal;
  const double phi = n.dot(x - plane.point);
  if (!(phi < plane.surface.epsilon) || !(n.dot(v) < 0.0)) return false;
  if (plane.has_hole) {
    const Vec3 d = x - plane.hole_center;
    const Vec3 in_plane = d - n.dot(d) * n;
    if (in_plane.norm() < plane.hole_radius) return false;  // over the hole: falls through
  }
  v = reflect(v, n, plane.surface.restitution);
  return true;
}

bool collide_bowl(const Bowl& bowl, const Vec3& x, Vec3& v) {
  const Vec3 to_center = bowl.center - x;
  const double distance = to_center.norm();
  if (distance == 0.0) return false;  // at the centre the normal is undefined (and φ = R ≥ ε)
  const double phi = bowl.radius - distance;
  const Vec3 n = to_center / distance;
  if (!(phi < bowl.surface.epsilon) || !(n.dot(v) < 0.0)) return false;
  if (!(x.y() <= bowl.rim_height + bowl.surface.epsilon)) return false;
  const double dx = x.x() - bowl.center.x(), dz = x.z() - bowl.center.z();
  if (std::sqrt(dx * dx + dz * dz) > bowl.rim_radius()) return false;
  v = reflect(v, n, bowl.surface.restitution);
  return true;
}

}  // namespace jelly::a1
