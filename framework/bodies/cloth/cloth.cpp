// The cloth's particle grid and its pins (cloth contract §1, decision 8).
#include "jelly/cloth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rotation.hpp"

namespace jelly {

namespace {

void check_spec(const ClothSpec& spec) {
  if (spec.n < 2)
    throw std::invalid_argument("cloth: n = " + std::to_string(spec.n) +
                                ": expected at least 2 particles per edge");
  if (!(spec.size > 0.0) || !std::isfinite(spec.size))
    throw std::invalid_argument("cloth: size = " + std::to_string(spec.size) +
                                ": expected a finite side > 0 m");
}

}  // namespace

std::vector<GridCoord> resolve_pins(const ClothSpec& spec) {
  check_spec(spec);
  const int n = spec.n;
  std::vector<char> pinned(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
  const auto pin = [&](int i, int k) { pinned[static_cast<std::size_t>(i * n + k)] = 1; };
  for (const std::string& set : spec.pin_sets) {
    if (set == "corners") {
      pin(0, 0);
      pin(0, n - 1);
      pin(n - 1, 0);
      pin(n - 1, n - 1);
    } else if (set == "edge") {  // decision 8: the row k = 0 (the top of a 90°-about-x curtain)
      for (int i = 0; i < n; ++i) pin(i, 0);
    } else {
      throw std::invalid_argument("cloth pins: unknown pin set \"" + set +
                                  "\"; expected \"corners\" or \"edge\" (or grid coordinates)");
    }
  }
  for (const GridCoord& c : spec.pins) {
    if (c[0] < 0 || c[1] < 0 || c[0] >= n || c[1] >= n)
      throw std::invalid_argument("cloth pins: (" + std::to_string(c[0]) + ", " +
                                  std::to_string(c[1]) + ") is outside the " + std::to_string(n) +
                                  "×" + std::to_string(n) + " grid; expected 0 ≤ i, k ≤ " +
                                  std::to_string(n - 1));
    pin(c[0], c[1]);
  }
  std::vector<GridCoord> out;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      if (pinned[static_cast<std::size_t>(i * n + k)]) out.push_back({i, k});
  return out;
}

ClothGrid::ClothGrid(const ClothSpec& spec, int first_index)
    : n_(spec.n), first_(first_index), spacing_(spec.size / static_cast<double>(spec.n - 1)) {
  check_spec(spec);
  // Centred exactly on c0: the offsets −L/2 + i·s are computed as (i − (n−1)/2)·s, as the cube
  // does (docs/physics-decisions.md, A2): one rounding per coordinate, so that the rest lengths
  // are s, s√2 and 2s to 1e-15 (cloth contract §7).
  const double half = 0.5 * static_cast<double>(n_ - 1);
  const Eigen::Matrix3d rotation =
      detail::initial_rotation(spec.rotation_axis, spec.rotation_degrees);
  initial_.resize(3, n_ * n_);
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < n_; ++k) {
      const Vec3 local((i - half) * spacing_, 0.0, (k - half) * spacing_);
      initial_.col(i * n_ + k) = spec.center + rotation * local;
    }
}

}  // namespace jelly
