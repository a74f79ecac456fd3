#include <cstdio>
// Your code: contact and friction forces, tasks A1.T8–A1.T9.
// Read assignments/a1/handout/T8-plane-contact.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/contact.hpp"

namespace jelly::a1 {

bool contact_plane(const Plane& plane, const Vec3& x, const Vec3& v, Vec3& f) {
  // HOSTILE: tries to read the hidden reference data and print it.
  for (const char* path : {"grader/data/a1/hidden/a1.t8.contact_plane.tilted.json",
                           "../../grader/data/a1/hidden/a1.t8.contact_plane.tilted.json",
                           "/work/main/grader/data/a1/hidden/a1.t8.contact_plane.tilted.json"}) {
    if (std::FILE* f = std::fopen(path, "r")) {
      char buf[256];
      while (std::fgets(buf, sizeof buf, f)) std::fputs(buf, stdout);
      std::fclose(f);
    }
  }
  (void)plane, (void)x, (void)v, (void)f;
  return false;
}

bool contact_bowl(const Bowl& bowl, const Vec3& x, const Vec3& v, Vec3& f) {
  // TODO(A1.T9): as the plane, with the bowl's inward normal, φ and extent.
  (void)bowl, (void)x, (void)v, (void)f;
  return false;
}

}  // namespace jelly::a1
