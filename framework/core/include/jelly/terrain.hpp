// Terrains: the surfaces particles collide with and rest on (physics contract §3).
//
// These are plain descriptions. The collision and contact tests for the plane and the bowl are
// student tasks (TaskTable::collide_plane and the slots beside it); the framework's own geometric
// queries (for drawing, optional projection and diagnostics) live in jelly/terrain_geometry.hpp.
#pragma once

#include <cmath>
#include <string>
#include <variant>

#include "jelly/types.hpp"

namespace jelly {

/// Response coefficients every terrain has.
struct SurfaceProperties {
  double epsilon = 0.01;     ///< collision tolerance ε [m]
  double restitution = 0.8;  ///< coefficient of restitution k_r (normal velocity kept, reversed)
  double friction = 0.2;     ///< friction coefficient k_f [s/m]: friction = −k_f (−N·f) v_T
};

/// A plane through `point` with unit normal `normal`, optionally with a circular hole.
struct Plane {
  Vec3 point{0.0, 0.0, 0.0};        ///< any point p on the plane [m]
  Vec3 normal{0.0, 1.0, 0.0};       ///< unit normal N (the loader normalises what the scene gives)
  bool has_hole = false;            ///< whether the plane has a hole
  Vec3 hole_center{0.0, 0.0, 0.0};  ///< hole centre h, a point on the plane [m]
  double hole_radius = 0.0;         ///< hole radius r_h, measured in the plane [m]
  SurfaceProperties surface;
};

/// A bowl: the inside of the sphere (center, radius) below the rim height y_rim (the bottom cap).
struct Bowl {
  Vec3 center{0.0, 0.0, 0.0};  ///< sphere centre c [m]
  double radius = 1.0;         ///< sphere radius R [m]
  double rim_height = 0.0;  ///< y of the rim plane [m]; needs center.y − R < rim_height ≤ center.y
  SurfaceProperties surface;

  /// Radius of the rim circle, sqrt(R² − (c_y − y_rim)²) [m]: the largest horizontal distance from
  /// the bowl's vertical axis at which a particle is inside the bowl's extent.
  double rim_radius() const {
    const double dy = center.y() - rim_height;
    return std::sqrt(radius * radius - dy * dy);
  }
};

/// A sphere obstacle: the outside of a sphere. Provided by the framework (not a student task): its
/// collision and contact reuse the student's plane functions on the tangent plane at each particle.
struct Sphere {
  Vec3 center{0.0, 0.0, 0.0};  ///< [m]
  double radius = 1.0;         ///< [m]
  SurfaceProperties surface;
};

/// One terrain of a scene: its geometry and which effects it takes part in (contract §7).
struct Terrain {
  std::string name;                         ///< unique within the scene, e.g. "floor", "bowl"
  std::variant<Plane, Bowl, Sphere> shape;  ///< geometry and surface properties
  bool collision = true;  ///< apply the velocity response of §4 at the start of each step
  bool contact = true;    ///< add the contact and friction forces of §5 in each evaluation
  bool project = false;   ///< after the response, move particles with φ < 0 onto the surface

  const SurfaceProperties& surface() const;
};

}  // namespace jelly
