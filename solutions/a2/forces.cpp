// Reference solution of A2.T4–A2.T5 (spring and damper forces). Not shipped to students.
// The World of the reference uses the fast spring engine (spring_engine.cpp, when it has one)
// instead of the framework's loop (jelly/spring_pass.hpp); both apply these two functions.
#include "jelly/a2/forces.hpp"

namespace jelly::a2 {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);  // one division instead of three
  return (-ks * (length - rest_length)) * u;
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);
  return (-kd * (va - vb).dot(u)) * u;
}

}  // namespace jelly::a2
