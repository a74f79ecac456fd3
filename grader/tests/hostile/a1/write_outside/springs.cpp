#include <cstdio>
// Your code: the spring builder, tasks A1.T1–A1.T3.
// Read assignments/a1/handout/T1-structural.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/springs.hpp"

namespace jelly::a1 {

void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T1): structural springs to the forward neighbours (1,0,0), (0,1,0), (0,0,1).
  (void)cube;
  (void)out;
}

void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // HOSTILE: tries to write a file outside its folder.
  if (std::FILE* f = std::fopen("/tmp/jelly-grade-hostile-was-here", "w")) {
    std::fputs("written by a submission\n", f);
    std::fclose(f);
  }
  (void)cube;
  (void)out;
}

void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T3): bending springs to the neighbours two steps ahead: (2,0,0), (0,2,0), (0,0,2).
  (void)cube;
  (void)out;
}

}  // namespace jelly::a1
