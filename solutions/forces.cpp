// Reference solution of A1.T4–A1.T5 (spring and damper forces). Not shipped to students.
#include <cmath>
#include <cstddef>

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

void accumulate_spring_forces(const SpringGroup& group, const State& s, Vec3Array& f) {
  // The same arithmetic as spring_force(...) + damper_force(...), term by term (so the same bits),
  // with the direction computed once per spring and the state read through raw pointers:
  // column-major 3×N arrays hold particle i at [3i, 3i + 3).
  const double* x = s.x.data();
  const double* v = s.v.data();
  double* out = f.data();
  const double ks = group.ks, kd = group.kd, degenerate = group.degenerate_length;
  for (const Spring& sp : group.springs) {
    const double* xa = x + 3 * static_cast<std::ptrdiff_t>(sp.a);
    const double* xb = x + 3 * static_cast<std::ptrdiff_t>(sp.b);
    const double d0 = xa[0] - xb[0], d1 = xa[1] - xb[1], d2 = xa[2] - xb[2];
    const double length = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
    if (length < degenerate || length == 0.0) continue;
    const double inverse = 1.0 / length;
    const double u0 = d0 * inverse, u1 = d1 * inverse, u2 = d2 * inverse;
    const double* va = v + 3 * static_cast<std::ptrdiff_t>(sp.a);
    const double* vb = v + 3 * static_cast<std::ptrdiff_t>(sp.b);
    const double along = (va[0] - vb[0]) * u0 + (va[1] - vb[1]) * u1 + (va[2] - vb[2]) * u2;
    const double cs = -ks * (length - sp.rest_length);
    const double cd = -kd * along;
    const double f0 = cs * u0 + cd * u0, f1 = cs * u1 + cd * u1, f2 = cs * u2 + cd * u2;
    double* fa = out + 3 * static_cast<std::ptrdiff_t>(sp.a);
    double* fb = out + 3 * static_cast<std::ptrdiff_t>(sp.b);
    fa[0] += f0;
    fa[1] += f1;
    fa[2] += f2;
    fb[0] -= f0;
    fb[1] -= f1;
    fb[2] -= f2;
  }
}

}  // namespace jelly::tasks
