#include "jelly/spring_pass.hpp"

namespace jelly {

void accumulate_spring_forces(const SpringGroup& group, const State& s, Vec3Array& f,
                              SpringForceFunction spring_force, DamperForceFunction damper_force) {
  for (const Spring& sp : group.springs) {
    const Vec3 xa = s.x.col(sp.a), xb = s.x.col(sp.b);
    const Vec3 fa =
        spring_force(xa, xb, group.ks, sp.rest_length, group.degenerate_length) +
        damper_force(xa, xb, s.v.col(sp.a), s.v.col(sp.b), group.kd, group.degenerate_length);
    f.col(sp.a) += fa;
    f.col(sp.b) -= fa;
  }
}

}  // namespace jelly
