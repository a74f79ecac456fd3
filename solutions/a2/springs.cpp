// Reference solution of A2.T1–A2.T3 (the cloth's spring builder). Not shipped to students.
#include "jelly/a2/springs.hpp"

namespace jelly::a2 {

namespace {

// Appends, for every particle by index i·n + k ascending, the springs to the neighbours at the
// given offsets that exist, in the offsets' order (decision 9: the order changes rounding).
void add_offsets(const ClothGrid& cloth, const int (*offsets)[2], int count,
                 std::vector<Spring>& out) {
  const int n = cloth.n();
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      for (int o = 0; o < count; ++o) {
        const int i2 = i + offsets[o][0];
        const int k2 = k + offsets[o][1];
        if (!cloth.contains(i2, k2)) continue;
        out.push_back({cloth.index(i, k), cloth.index(i2, k2),
                       (cloth.position(i, k) - cloth.position(i2, k2)).norm()});
      }
}

}  // namespace

void add_structural_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  static const int offsets[][2] = {{1, 0}, {0, 1}};
  add_offsets(cloth, offsets, 2, out);
}

void add_shear_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  static const int offsets[][2] = {{1, 1}, {1, -1}};
  add_offsets(cloth, offsets, 2, out);
}

void add_bending_springs(const ClothGrid& cloth, std::vector<Spring>& out) {
  static const int offsets[][2] = {{2, 0}, {0, 2}};
  add_offsets(cloth, offsets, 2, out);
}

}  // namespace jelly::a2
