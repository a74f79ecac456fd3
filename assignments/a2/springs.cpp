// Your code: the cloth's spring builder, tasks A2.T1–A2.T3.
// Read assignments/a2/handout/T1-structural.md first. Check yourself with: tools/selfcheck
#include "jelly/a2/springs.hpp"

namespace jelly::a2 {

void add_structural_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  // TODO(A2.T1): structural springs to the forward neighbours (1,0) and (0,1).
  // assignments/a2/handout/T1-structural.md. Append to `out` (never clear it); index with
  // cloth.index(i, k), test neighbours with cloth.contains(...); rest length = distance at
  // construction. 1200 springs for n = 25.
  (void)cloth;
  (void)out;
}

void add_shear_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  // TODO(A2.T2): shear springs along the two forward diagonals (1,1) and (1,−1).
  // assignments/a2/handout/T2-shear.md. 1152 springs for n = 25.
  (void)cloth;
  (void)out;
}

void add_bending_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  // TODO(A2.T3): bending springs to the neighbours two steps ahead: (2,0) and (0,2).
  // assignments/a2/handout/T3-bending.md. Rest length 2s; 1150 springs for n = 25.
  (void)cloth;
  (void)out;
}

}  // namespace jelly::a2
