// The framework's own geometric queries on terrains: signed distance, normal, extent, lowest point.
// Used for drawing, the optional projection effect, diagnostics (penetration) and the energy
// reference. The student tasks do not call these; they compute their own tests.
#pragma once

#include <optional>

#include "jelly/terrain.hpp"

namespace jelly {

/// Signed distance φ(x) to the terrain's surface, positive on the free side [m].
double signed_distance(const Terrain& t, const Vec3& x);
/// Unit normal N at x pointing to the free side.
Vec3 surface_normal(const Terrain& t, const Vec3& x);
/// Whether x is inside the terrain's extent (outside the plane's hole; inside the bowl's cap
/// region: x_y ≤ y_rim + ε and within the rim radius of the axis; everywhere for a sphere).
bool in_extent(const Terrain& t, const Vec3& x);
/// Lowest height (along y) a particle resting on this terrain can reach; nullopt when unbounded
/// (tilted planes, planes with a hole, spheres).
std::optional<double> lowest_point(const Terrain& t);
/// Lower bound of φ over an axis-aligned box [lo, hi]: when it is ≥ ε no particle in the box can
/// collide or be in contact, so the pass may be skipped (an exact, conservative broad phase).
double min_signed_distance(const Terrain& t, const Vec3& lo, const Vec3& hi);
/// Whether every point of the box is outside the terrain's extent for sure (e.g. above the bowl's
/// rim by more than ε).
bool box_outside_extent(const Terrain& t, const Vec3& lo, const Vec3& hi);

}  // namespace jelly
