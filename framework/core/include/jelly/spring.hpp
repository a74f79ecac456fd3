// Springs: which particles they join, and the per-type coefficients they share.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace jelly {

/// The kinds of spring of a lattice (physics contract §2). Face and body shear diagonals share
/// the shear coefficients unless a scene sets `springs.shear_body` apart.
enum class SpringType : std::uint8_t { Structural, Shear, ShearBody, Bending };

/// Stable lower-case name of a spring type ("structural", "shear", "shear_body", "bending").
std::string_view to_string(SpringType type);

/// A spring shorter than this share of its body's length scale (a lattice's grid spacing, the
/// shortest rest length of explicit springs) has no direction and gets zero force (contract §2).
inline constexpr double kDegenerateShare = 1e-12;
/// The degenerate length of the springs of a body with length scale `spacing` [m].
constexpr double degenerate_length_for(double spacing) { return kDegenerateShare * spacing; }

/// One spring between particles a and b (indices into the state arrays).
struct Spring {
  int a = 0;                 ///< first particle (the one that "owns" the spring)
  int b = 0;                 ///< second particle
  double rest_length = 0.0;  ///< [m], the distance between a and b when the spring was built
};

/// All springs of one type in one body, with the coefficients they share.
struct SpringGroup {
  SpringType type = SpringType::Structural;
  double ks = 0.0;  ///< stiffness [N/m]
  double kd = 0.0;  ///< damping along the spring [N·s/m]
  double degenerate_length =
      0.0;  ///< [m] below this current length a spring has no direction: zero force
  std::vector<Spring> springs;
};

}  // namespace jelly
