// Reference solution of A1.T4–A1.T5 (spring and damper forces). Not shipped to students.
// The World of the reference uses the fast spring engine (spring_engine.cpp) instead of the
// provided loop below; both apply these two functions.
#include "jelly/tasks/forces.hpp"

namespace jelly::tasks {

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

// Provided, not a task: applies your two functions to every spring of a group. Keep it as it is.
void accumulate_spring_forces(const SpringGroup& group, const State& s, Vec3Array& f) {
  for (const Spring& sp : group.springs) {
    const Vec3 xa = s.x.col(sp.a), xb = s.x.col(sp.b);
    const Vec3 fa =
        spring_force(xa, xb, group.ks, sp.rest_length, group.degenerate_length) +
        damper_force(xa, xb, s.v.col(sp.a), s.v.col(sp.b), group.kd, group.degenerate_length);
    f.col(sp.a) += fa;
    f.col(sp.b) -= fa;
  }
}

}  // namespace jelly::tasks
