// Rotations of the kinematics contract §3 and the slerp of §5: Euler angles in degrees,
// E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx), unit quaternions. Sines, cosines and arcs come from
// jelly/portable_math.hpp and quaternion products are written out, so every platform computes
// the same bits.
#pragma once

#include <Eigen/Geometry>

#include "jelly/skeleton/skeleton.hpp"

namespace jelly::skeleton {

using Quaternion = Eigen::Quaterniond;

/// Right-handed rotations about x, y and z by `degrees`.
Mat3 rotation_x(double degrees);
Mat3 rotation_y(double degrees);
Mat3 rotation_z(double degrees);

/// E(rx, ry, rz) = R_z(rz)·R_y(ry)·R_x(rx), angles (rx, ry, rz) in degrees.
Mat3 euler_matrix(const Vec3& degrees);

/// The unit quaternion of E(θ): q = q_z·q_y·q_x, each q_a = (cos(a/2), sin(a/2)·axis).
Quaternion euler_to_quaternion(const Vec3& degrees);

/// The rotation matrix of q (normalised first).
Mat3 quaternion_matrix(const Quaternion& q);

/// Angles (rx, ry, rz) [degrees] with E = R(q): ry ∈ [−90°, 90°], rx, rz ∈ (−180°, 180°]. q is
/// normalised first. In the gimbal band |R₂₀| ≥ 1 − 1e-12: ry = ±90° exactly, rx = 0,
/// rz = atan2(−R₀₁, R₁₁) (contract §11.9).
Vec3 quaternion_to_euler(const Quaternion& q);

/// The Hamilton product a·b, written out (the same bits on every platform).
Quaternion multiply(const Quaternion& a, const Quaternion& b);

/// Slerp from a (t = 0) to b (t = 1) on the short path (b ← −b when a·b < 0):
/// sin((1−t)Ω)/sin Ω · a + sin(tΩ)/sin Ω · b with Ω = acos(a·b), not renormalised; where
/// |a·b| > 1 − 1e-12 the normalised linear interpolation (contract §5, §11.10).
Quaternion slerp(const Quaternion& a, const Quaternion& b, double t);

/// Whether a and b are the same rotation: every coefficient of a − b, or of a + b, within `tol`.
bool same_rotation(const Quaternion& a, const Quaternion& b, double tol);

/// The gimbal band of quaternion_to_euler and slerp's nlerp band (contract §5, §11.9).
inline constexpr double kGimbalBand = 1e-12;
inline constexpr double kSlerpLinearBand = 1e-12;

}  // namespace jelly::skeleton
