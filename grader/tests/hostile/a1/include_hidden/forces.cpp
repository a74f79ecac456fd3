// HOSTILE: includes the hidden reference data to see it in a compiler error.
#include "../../grader/data/a1/hidden/a1.t4.spring_force.random.json"
// Your code: spring and damper forces, tasks A1.T4–A1.T5.
// Read assignments/a1/handout/T4-spring-force.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/forces.hpp"

namespace jelly::a1 {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  // TODO(A1.T4): f = −ks (|d| − rest) u with d = x_a − x_b, u = d/|d|; zero when |d| is degenerate.
  (void)xa, (void)xb, (void)ks, (void)rest_length, (void)degenerate_length;
  return Vec3::Zero();
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  // TODO(A1.T5): f = −kd ((v_a − v_b)·u) u; zero when |x_a − x_b| is degenerate.
  (void)xa, (void)xb, (void)va, (void)vb, (void)kd, (void)degenerate_length;
  return Vec3::Zero();
}

}  // namespace jelly::a1
