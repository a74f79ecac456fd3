// An independent correct A1.T4–A1.T5 (the similarity test's second honest student, written from
// the handout without looking at the reference's forces.cpp): it must not be flagged as a copy.
#include "jelly/a1/forces.hpp"

namespace jelly::a1 {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  Vec3 result = Vec3::Zero();
  const double dist = (xa - xb).norm();
  if (dist < degenerate_length || dist == 0.0) return result;  // no direction: no force
  const double stretch = dist - rest_length;
  result = (xa - xb) / dist;
  result *= -ks * stretch;
  return result;
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  const Vec3 axis = xa - xb;
  const double len = axis.norm();
  if (len < degenerate_length || len == 0.0) {
    return Vec3::Zero();
  }
  const Vec3 dir = axis / len;
  const double closing = dir.dot(va) - dir.dot(vb);
  return -kd * closing * dir;
}

}  // namespace jelly::a1
