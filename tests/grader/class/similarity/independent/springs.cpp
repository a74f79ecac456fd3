// An independent correct A1.T1–A1.T3 (the similarity test's second honest student, written from
// the handout without looking at solutions/a1/springs.cpp): it must not be flagged as a copy.
#include "jelly/a1/springs.hpp"

namespace jelly::a1 {

static void connect(const CubeLattice& cube, int di, int dj, int dk, std::vector<Spring>& out) {
  const int n = cube.n();
  for (int p = 0; p < n * n * n; ++p) {
    const int i = p / (n * n);
    const int j = (p / n) % n;
    const int k = p % n;
    if (cube.contains(i + di, j + dj, k + dk)) {
      Spring s;
      s.a = cube.index(i, j, k);
      s.b = cube.index(i + di, j + dj, k + dk);
      s.rest_length = (cube.position(i, j, k) - cube.position(i + di, j + dj, k + dk)).norm();
      out.push_back(s);
    }
  }
}

void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  connect(cube, 1, 0, 0, out);
  connect(cube, 0, 1, 0, out);
  connect(cube, 0, 0, 1, out);
}

void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  // face diagonals: two non-zero components, the first of them positive
  for (int s = -1; s <= 1; s += 2) {
    connect(cube, 0, 1, s, out);
    connect(cube, 1, 0, s, out);
    connect(cube, 1, s, 0, out);
  }
  // body diagonals: (1, ±1, ±1)
  for (int sj = -1; sj <= 1; sj += 2)
    for (int sk = -1; sk <= 1; sk += 2) connect(cube, 1, sj, sk, out);
}

void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out) {
  connect(cube, 2, 0, 0, out);
  connect(cube, 0, 2, 0, out);
  connect(cube, 0, 0, 2, out);
}

}  // namespace jelly::a1
