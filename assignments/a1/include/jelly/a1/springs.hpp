// Student tasks A1.T1–A1.T3: the spring builder (physics contract §2).
// Handout: assignments/a1/handout/T1-structural.md, T2-shear.md, T3-bending.md.
#pragma once

#include <vector>

#include "jelly/cube.hpp"
#include "jelly/spring.hpp"

namespace jelly::a1 {

/// A1.T1 — Appends the structural springs of `cube` to `out`: every particle (i, j, k) is joined
/// to its forward neighbours at grid offsets (1,0,0), (0,1,0), (0,0,1) where they exist.
/// Rest length = distance between the two particles' positions at construction (s).
/// For n = 10 this appends 3·n²·(n−1) = 2700 springs; no spring twice.
void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out);

/// A1.T2 — Appends the shear springs of `cube` to `out`: forward face diagonals (0,1,1) (0,1,−1)
/// (1,0,1) (1,0,−1) (1,1,0) (1,−1,0) [rest s√2] and body diagonals (1,1,1) (1,1,−1) (1,−1,1)
/// (1,−1,−1) [rest s√3]. For n = 10: 4860 + 2916 = 7776 springs; no spring twice.
void add_shear_springs(const CubeLattice& cube, std::vector<Spring>& out);

/// A1.T3 — Appends the bending springs of `cube` to `out`: offsets (2,0,0), (0,2,0), (0,0,2)
/// [rest 2s]. For n = 10: 3·n²·(n−2) = 2400 springs.
void add_bending_springs(const CubeLattice& cube, std::vector<Spring>& out);

}  // namespace jelly::a1
