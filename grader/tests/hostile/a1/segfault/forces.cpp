// Your code: spring and damper forces, tasks A1.T4–A1.T5.
// Read assignments/a1/handout/T4-spring-force.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/forces.hpp"

namespace jelly::a1 {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  // HOSTILE: writes through a null pointer.
  volatile int* p = nullptr;
  *p = 42;
  (void)xa, (void)xb, (void)ks, (void)rest_length, (void)degenerate_length;
  return Vec3::Zero();
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  // TODO(A1.T5): f = −kd ((v_a − v_b)·u) u; zero when |x_a − x_b| is degenerate.
  (void)xa, (void)xb, (void)va, (void)vb, (void)kd, (void)degenerate_length;
  return Vec3::Zero();
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

}  // namespace jelly::a1
