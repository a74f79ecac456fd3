#include <cstdlib>
// Your code: collision response, tasks A1.T6–A1.T7.
// Read assignments/a1/handout/T6-plane-collision.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/collision.hpp"

namespace jelly::a1 {

bool collide_plane(const Plane& plane, const Vec3& x, Vec3& v) {
  // HOSTILE: ends the program from inside a task function.
  std::exit(0);
  (void)plane, (void)x, (void)v;
  return false;
}

bool collide_bowl(const Bowl& bowl, const Vec3& x, Vec3& v) {
  // TODO(A1.T7): as the plane, with the bowl's inward normal, φ = R − |x − c| and its extent.
  (void)bowl, (void)x, (void)v;
  return false;
}

}  // namespace jelly::a1
