// Your code: spring and damper forces, tasks A2.T4–A2.T5.
// Read assignments/a2/handout/T4-spring-force.md first. Check yourself with: tools/selfcheck
#include "jelly/a2/forces.hpp"

namespace jelly::a2 {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  // TODO(A2.T4): f = −ks (|d| − rest) u with d = x_a − x_b, u = d/|d|; zero when |d| is degenerate.
  // assignments/a2/handout/T4-spring-force.md. This is the force on a; never return NaN.
  (void)xa, (void)xb, (void)ks, (void)rest_length, (void)degenerate_length;
  return Vec3::Zero();
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  // TODO(A2.T5): f = −kd ((v_a − v_b)·u) u; zero when |x_a − x_b| is degenerate.
  // assignments/a2/handout/T5-damper-force.md. Only the relative velocity ALONG the spring is
  // damped.
  (void)xa, (void)xb, (void)va, (void)vb, (void)kd, (void)degenerate_length;
  return Vec3::Zero();
}

}  // namespace jelly::a2
