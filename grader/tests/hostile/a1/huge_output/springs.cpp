#include <cstdio>
// Your code: the spring builder, tasks A1.T1–A1.T3.
// Read assignments/a1/handout/T1-structural.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/springs.hpp"

namespace jelly::a1 {

void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // HOSTILE: prints without end (gigabytes).
  for (;;) std::printf("debug: building structural springs of a cube with n = %d\n", cube.n());
  (void)cube;
  (void)out;
}

void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T2): shear springs along the 6 forward face diagonals and the 4 body diagonals.
  (void)cube;
  (void)out;
}

void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T3): bending springs to the neighbours two steps ahead: (2,0,0), (0,2,0), (0,0,2).
  (void)cube;
  (void)out;
}

}  // namespace jelly::a1
