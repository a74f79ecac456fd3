// Your code: the spring builder, tasks A1.T1–A1.T3.
// Read assignments/a1/handout/T1-structural.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/springs.hpp"

namespace jelly::a1 {

void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T1): structural springs to the forward neighbours (1,0,0), (0,1,0), (0,0,1).
  // assignments/a1/handout/T1-structural.md. Append to `out` (never clear it); index with
  // cube.index(i, j, k), test neighbours with cube.contains(...); rest length = distance at
  // construction.
  (void)cube;
  (void)out;
}

void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T2): shear springs along the 6 forward face diagonals and the 4 body diagonals.
  // assignments/a1/handout/T2-shear.md. 10 directions, some with a −1 component; 7776 springs for n
  // = 10.
  (void)cube;
  (void)out;
}

void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // TODO(A1.T3): bending springs to the neighbours two steps ahead: (2,0,0), (0,2,0), (0,0,2).
  // assignments/a1/handout/T3-bending.md. Rest length 2s; 2400 springs for n = 10.
  (void)cube;
  (void)out;
}

}  // namespace jelly::a1
