// Reference solution of A1.T1–A1.T3 (the spring builder). Not shipped to students.
#include <array>
#include <initializer_list>

#include "jelly/a1/springs.hpp"

namespace jelly::a1 {

namespace {

using Offset = std::array<int, 3>;

// For every particle, a spring to each forward neighbour at the given grid offsets that exists.
void add_forward_springs(const CubeLattice& cube, std::initializer_list<Offset> offsets,
                         std::vector<Spring>& out) {
  const int n = cube.n();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const Offset& o : offsets) {
          const int i2 = i + o[0], j2 = j + o[1], k2 = k + o[2];
          if (!cube.contains(i2, j2, k2)) continue;
          const double rest = (cube.position(i2, j2, k2) - cube.position(i, j, k)).norm();
          out.push_back(Spring{cube.index(i, j, k), cube.index(i2, j2, k2), rest});
        }
}

}  // namespace

void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  add_forward_springs(cube, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, out);
}

void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // The offsets as a table (the grader's mutants edit this text).
  // clang-format off
  add_forward_springs(cube,
                      {{0, 1, 1}, {0, 1, -1}, {1, 0, 1}, {1, 0, -1}, {1, 1, 0}, {1, -1, 0},
                       {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}},
                      out);
  // clang-format on
}

void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  add_forward_springs(cube, {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}, out);
}

}  // namespace jelly::a1
