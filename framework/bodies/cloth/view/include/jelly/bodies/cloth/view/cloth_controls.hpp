// The viewer's live controls of a cloth scene (assignment A2), as the 2024 course had them: keys
// 1–4 pin and unpin the cloth's four corners, the arrow keys drive the first kinematic sphere.
// No GL and no window: the view's controls (cloth_view.cpp) map keys onto these, the tests call
// them directly.
#pragma once

#include <optional>

#include "jelly/cloth.hpp"
#include "jelly/world.hpp"

namespace jelly::cloth_view {

/// Speed of the arrow keys' drive [m/s]: the cloth-2024 scene's scheduled speed. (The course set
/// ±5 m/s, but its framework ran at about a quarter of real time: about 1.25 m/s on screen.)
inline constexpr double kDriveSpeed = 2.0;

/// Particle index of corner `corner` (0–3, keys 1–4) of `grid`: (0,0), (0,n−1), (n−1,0), (n−1,n−1).
int corner_particle(const ClothGrid& grid, int corner);

/// Keys 1–4: pins a free corner (0–3) of the world's first cloth, or frees a pinned one
/// (World::set_pinned). Returns whether it is pinned now; nullopt when the world has no cloth or
/// `corner` is not 0–3.
std::optional<bool> toggle_corner_pin(World& world, int corner);

/// Index of the first kinematic sphere of `world`, −1 when it has none.
int first_kinematic_sphere(const World& world);

/// The arrow keys, relative to the view.
enum class Arrow { Left, Right, Up, Down };

/// The drive velocity after pressing `arrow` while the sphere is driven at `current`: as in the
/// course, a key sets one horizontal component to ±speed and keeps the other. Up moves away from
/// the viewer and Left to the screen's left, each along the world axis (±x or ±z) nearest to
/// that direction for a camera at `yaw_degrees` (render::OrbitCamera: 0 looks along −z, positive
/// swings the camera towards +x). The y component stays.
Vec3 arrow_drive(const Vec3& current, Arrow arrow, double yaw_degrees, double speed = kDriveSpeed);

/// Drives the first kinematic sphere of `world` at `velocity` from now on (World::drive_sphere;
/// its schedule is ignored until the world is rebuilt). False when there is none.
bool drive_first_kinematic_sphere(World& world, const Vec3& velocity);

}  // namespace jelly::cloth_view
