// Student tasks A2.T1–A2.T3: the cloth's spring builder (cloth contract §2).
// Handout: assignments/a2/handout/T1-structural.md, T2-shear.md, T3-bending.md.
#pragma once

#include <vector>

#include "jelly/cloth.hpp"
#include "jelly/spring.hpp"

namespace jelly::a2 {

/// A2.T1 — Appends the structural springs of `cloth` to `out`: every particle (i, k) is joined to
/// its forward neighbours at grid offsets (1,0) and (0,1) where they exist, in that order,
/// particles by index i·n + k ascending. Rest length = distance at construction (s).
/// For n = 25: 2·n·(n−1) = 1200 springs; no spring twice.
void add_structural_springs(const ClothGrid& cloth, std::vector<Spring>& out);

/// A2.T2 — Appends the shear springs: offsets (1,1) and (1,−1) [rest s√2].
/// For n = 25: 2·(n−1)² = 1152 springs.
void add_shear_springs(const ClothGrid& cloth, std::vector<Spring>& out);

/// A2.T3 — Appends the bending springs: offsets (2,0) and (0,2) [rest 2s].
/// For n = 25: 2·n·(n−2) = 1150 springs.
void add_bending_springs(const ClothGrid& cloth, std::vector<Spring>& out);

}  // namespace jelly::a2
