// Spheres of the cloth scenes and the impulses between point bodies (cloth contract §3, §4).
// The student's collision tasks see PointBody, SphereBody and ImpulseSettings only.
#pragma once

#include <optional>
#include <vector>

#include "jelly/schedule.hpp"
#include "jelly/types.hpp"

namespace jelly {

/// A sphere as a scene describes it.
struct SphereSpec {
  Vec3 center{0.0, 0.0, 0.0};           ///< [m]
  double radius = 0.5;                  ///< [m]
  bool kinematic = false;               ///< moved by `schedule`, inverse mass 0
  std::optional<double> mass;           ///< dynamic only; default 1000·r³ [kg]
  Vec3 velocity{0.0, 0.0, 0.0};         ///< dynamic only: initial velocity [m/s]
  std::vector<ScheduleEntry> schedule;  ///< kinematic only; times strictly increasing
};

/// The course's sphere mass, 1000·r³ (no 4π/3) [kg].
inline double default_sphere_mass(double radius) { return 1000.0 * radius * radius * radius; }

/// The velocity a schedule gives at the start of step `step` of size h: the last entry with
/// time ≤ step·h + 1e-6·h; zero before the first entry (decision 5: t_n = n·h, a product).
Vec3 scheduled_velocity(const std::vector<ScheduleEntry>& schedule, long step, double h);

/// A cloth particle as a collision task sees it (radius 0).
struct PointBody {
  Vec3 position{0.0, 0.0, 0.0};  ///< x [m]
  Vec3 velocity{0.0, 0.0, 0.0};  ///< v [m/s]
  double inverse_mass = 0.0;     ///< w = 1/m [1/kg]; 0 for a pinned particle
};

/// A sphere as a collision task sees it.
struct SphereBody {
  Vec3 center{0.0, 0.0, 0.0};    ///< c [m]
  Vec3 velocity{0.0, 0.0, 0.0};  ///< u [m/s] (a kinematic sphere's scheduled velocity)
  double radius = 0.0;           ///< r [m]
  double inverse_mass = 0.0;     ///< 1/M [1/kg]; 0 for a kinematic sphere
};

/// The coefficients of one kind of pair (cloth–sphere or sphere–sphere).
struct ImpulseSettings {
  double restitution = 0.0;  ///< e
  double tolerance = 0.01;   ///< ε [m]: a pair collides when φ < ε (and approaches)
};

/// What a collision task did: whether it applied an impulse, the unit normal N (from B towards
/// A) and the size j of the normal impulse [N·s]. The framework hands it to the friction task.
struct Impulse {
  bool applied = false;
  Vec3 normal{0.0, 0.0, 0.0};
  double j = 0.0;
};

/// The collision settings of a cloth scene (cloth contract §4, decision 10 defaults).
struct ClothCollisionSettings {
  double cloth_restitution = 0.0;   ///< e_cloth
  double sphere_restitution = 0.8;  ///< e_sphere
  double tolerance = 0.01;          ///< ε [m], both kinds of pair
  double friction = 0.0;            ///< μ; 0: the friction task is never called
  double push_out = 0.0;            ///< β in [0, 1]; 0: no push-out
};

}  // namespace jelly
