// Your code: collision response, tasks A1.T6–A1.T7.
// Read assignments/a1/handout/T6-plane-collision.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/collision.hpp"

namespace jelly::a1 {

bool collide_plane(const Plane& plane, const Vec3& x, Vec3& v) {
  // TODO(A1.T6): respond when φ < ε, N·v < 0 and outside the hole: v ← −k_r v_N + v_T.
  // assignments/a1/handout/T6-plane-collision.md. Use plane.normal (never assume y is up); change
  // v, not x.
  (void)plane, (void)x, (void)v;
  return false;
}

bool collide_bowl(const Bowl& bowl, const Vec3& x, Vec3& v) {
  // TODO(A1.T7): as the plane, with the bowl's inward normal, φ = R − |x − c| and its extent.
  // assignments/a1/handout/T7-bowl-collision.md. Extent: x_y ≤ y_rim + ε AND horizontal distance to
  // the bowl's axis ≤ bowl.rim_radius().
  (void)bowl, (void)x, (void)v;
  return false;
}

}  // namespace jelly::a1
