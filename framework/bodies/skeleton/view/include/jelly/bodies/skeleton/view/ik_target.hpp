// Moving an ik scene's target in the viewer without GL (A4): the point under the mouse in the plane
// through the target that faces the camera (the drag), the target nearest the mouse on screen (the
// pick), and the camera's axes the keys move it along. The viewer's controls
// (skeleton_ik_controls.cpp) and the tests call them alike.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "jelly/render/camera.hpp"
#include "jelly/types.hpp"

namespace jelly::skeleton_view {

/// The point under pixel `mouse` of a `width` × `height` viewport (x right, y down from its
/// top-left, as OrbitCamera::project) in the plane through `through` whose normal is the camera's
/// view direction: the mouse's ray, unprojected through the camera's view and projection, met with
/// that plane. nullopt when the ray misses it (parallel to it, or the plane behind the eye).
std::optional<Vec3> point_under_mouse(const render::OrbitCamera& camera, int width, int height,
                                      const Eigen::Vector2d& mouse, const Vec3& through);

/// The index of the point of `targets` drawn nearest `mouse` (pixels, as above), if within
/// `radius` pixels of it; −1 otherwise.
int target_near(const render::OrbitCamera& camera, int width, int height,
                const Eigen::Vector2d& mouse, const std::vector<Vec3>& targets, double radius);

/// The camera's axes in the world, unit length: 0 right, 1 up (both on the screen), 2 away from
/// the eye (the view direction).
Vec3 camera_axis(const render::OrbitCamera& camera, int axis);

}  // namespace jelly::skeleton_view
