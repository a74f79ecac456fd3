// Your code: contact and friction forces, tasks A1.T8–A1.T9.
// Read assignments/a1/handout/T8-plane-contact.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/contact.hpp"

namespace jelly::a1 {

bool contact_plane(const Plane& plane, const Vec3& x, const Vec3& v, Vec3& f) {
  // TODO(A1.T8): when φ < ε, N·v < ε, N·f < 0 and outside the hole: f ← f + f_c + f_f.
  // assignments/a1/handout/T8-plane-contact.md. f_c = −(N·f) N, f_f = −k_f (−N·f) v_T. ADD to f.
  (void)plane, (void)x, (void)v, (void)f;
  return false;
}

bool contact_bowl(const Bowl& bowl, const Vec3& x, const Vec3& v, Vec3& f) {
  // TODO(A1.T9): as the plane, with the bowl's inward normal, φ and extent.
  // assignments/a1/handout/T9-bowl-contact.md.
  (void)bowl, (void)x, (void)v, (void)f;
  return false;
}

}  // namespace jelly::a1
