// Reference solution of A1.T8–A1.T9 (contact and friction forces). Not shipped to students.
#include <cmath>

#include "jelly/a1/contact.hpp"

namespace jelly::a1 {

namespace {

// f ← f + f_c + f_f with f_c = −(N·f) N and f_f = −k_f (−N·f) v_T, when N·f < 0.
bool push_back(const Vec3& n, const Vec3& v, double friction, Vec3& f) {
  const double nf = n.dot(f);
  if (!(nf < 0.0)) return false;
  const Vec3 vt = v - n.dot(v) * n;
  const Vec3 fc = -nf * n;
  const Vec3 ff = (-friction * -nf) * vt;
  f = f + fc + ff;
  return true;
}

}  // namespace

bool contact_plane(const Plane& plane, const Vec3& x, const Vec3& v, Vec3& f) {
  const Vec3& n = plane.normal;
  const double eps = plane.surface.epsilon;
  if (!(n.dot(x - plane.point) < eps) || !(n.dot(v) < eps)) return false;
  if (plane.has_hole) {
    const Vec3 d = x - plane.hole_center;
    if ((d - n.dot(d) * n).norm() < plane.hole_radius) return false;
  }
  return push_back(n, v, plane.surface.friction, f);
}

bool contact_bowl(const Bowl& bowl, const Vec3& x, const Vec3& v, Vec3& f) {
  const Vec3 to_center = bowl.center - x;
  const double distance = to_center.norm();
  if (distance == 0.0) return false;
  const Vec3 n = to_center / distance;
  const double eps = bowl.surface.epsilon;
  if (!(bowl.radius - distance < eps) || !(n.dot(v) < eps)) return false;
  if (!(x.y() <= bowl.rim_height + eps)) return false;
  const double dx = x.x() - bowl.center.x(), dz = x.z() - bowl.center.z();
  if (std::sqrt(dx * dx + dz * dz) > bowl.rim_radius()) return false;
  return push_back(n, v, bowl.surface.friction, f);
}

}  // namespace jelly::a1
