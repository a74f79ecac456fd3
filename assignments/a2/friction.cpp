// Your code: the bonus task A2.T12, Coulomb friction.
// Read assignments/a2/handout/T12-friction.md first. Check yourself with: tools/selfcheck
#include "jelly/a2/friction.hpp"

namespace jelly::a2 {

void friction_impulse(const Impulse& normal, double mu, double w_a, double w_b, Vec3& v_a,
                      Vec3& v_b) {
  // TODO(A2.T12, bonus): oppose the relative tangential velocity with j_T = min(μ j,
  // |v_rel,T| / (w_a + w_b)), never reversing the sliding.
  // assignments/a2/handout/T12-friction.md.
  (void)normal, (void)mu, (void)w_a, (void)w_b, (void)v_a, (void)v_b;
}

}  // namespace jelly::a2
