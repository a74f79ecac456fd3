// Rotations of the kinematics contract §3 and slerp (§5, §11.9, §11.10), with the core's
// portable sines, cosines and arcs only.
#include "jelly/skeleton/rotation.hpp"

#include <algorithm>
#include <cmath>

#include "jelly/portable_math.hpp"

namespace jelly::skeleton {

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// The half-angle quaternion of a rotation by `degrees` about axis k (0 = x, 1 = y, 2 = z).
Quaternion axis_quaternion(double degrees, int k) {
  const double half = degrees * kRadiansPerDegree * 0.5;
  double s = 0.0, c = 0.0;
  portable::sin_cos(half, s, c);
  Quaternion q(c, 0.0, 0.0, 0.0);
  q.vec()[k] = s;
  return q;
}

// An angle in degrees from atan2, with −180° taken as 180° (the range (−180°, 180°]).
double half_open_degrees(double radians) {
  const double degrees = radians * kDegreesPerRadian;
  return degrees <= -180.0 ? 180.0 : degrees;
}

}  // namespace

Mat3 rotation_x(double degrees) {
  const double a = degrees * kRadiansPerDegree;
  double s = 0.0, c = 0.0;
  portable::sin_cos(a, s, c);
  Mat3 r;
  r << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  return r;
}

Mat3 rotation_y(double degrees) {
  const double a = degrees * kRadiansPerDegree;
  double s = 0.0, c = 0.0;
  portable::sin_cos(a, s, c);
  Mat3 r;
  r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  return r;
}

Mat3 rotation_z(double degrees) {
  const double a = degrees * kRadiansPerDegree;
  double s = 0.0, c = 0.0;
  portable::sin_cos(a, s, c);
  Mat3 r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

Mat3 euler_matrix(const Vec3& degrees) {
  const Mat3 zy = rotation_z(degrees.z()) * rotation_y(degrees.y());
  return zy * rotation_x(degrees.x());
}

Quaternion multiply(const Quaternion& a, const Quaternion& b) {
  return Quaternion(a.w() * b.w() - a.x() * b.x() - a.y() * b.y() - a.z() * b.z(),
                    a.w() * b.x() + a.x() * b.w() + a.y() * b.z() - a.z() * b.y(),
                    a.w() * b.y() - a.x() * b.z() + a.y() * b.w() + a.z() * b.x(),
                    a.w() * b.z() + a.x() * b.y() - a.y() * b.x() + a.z() * b.w());
}

Quaternion euler_to_quaternion(const Vec3& degrees) {
  const Quaternion zy = multiply(axis_quaternion(degrees.z(), 2), axis_quaternion(degrees.y(), 1));
  return multiply(zy, axis_quaternion(degrees.x(), 0));
}

Mat3 quaternion_matrix(const Quaternion& q) {
  const double n = std::sqrt(q.w() * q.w() + q.x() * q.x() + q.y() * q.y() + q.z() * q.z());
  const double w = q.w() / n, x = q.x() / n, y = q.y() / n, z = q.z() / n;
  Mat3 r;
  r << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),  //
      2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),   //
      2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y);
  return r;
}

// E = R_z·R_y·R_x has R₂₀ = −sin ry, R₂₁ = cos ry sin rx, R₂₂ = cos ry cos rx,
// R₁₀ = sin rz cos ry, R₀₀ = cos rz cos ry; at ry = ±90° only rz − rx (or rz + rx) is defined.
Vec3 quaternion_to_euler(const Quaternion& q) {
  const Mat3 r = quaternion_matrix(q);
  if (std::fabs(r(2, 0)) >= 1.0 - kGimbalBand) {
    const double ry = r(2, 0) < 0.0 ? 90.0 : -90.0;
    return Vec3(0.0, ry, half_open_degrees(portable::atan2(-r(0, 1), r(1, 1))));
  }
  const double ry = portable::asin(-r(2, 0)) * kDegreesPerRadian;
  const double rx = half_open_degrees(portable::atan2(r(2, 1), r(2, 2)));
  const double rz = half_open_degrees(portable::atan2(r(1, 0), r(0, 0)));
  return Vec3(rx, ry, rz);
}

Quaternion slerp(const Quaternion& a, const Quaternion& b, double t) {
  double d = a.w() * b.w() + a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
  const double sign = d < 0.0 ? -1.0 : 1.0;
  d *= sign;
  double wa = 1.0 - t, wb = t;
  if (d <= 1.0 - kSlerpLinearBand) {
    const double omega = portable::acos(d);
    const double s = portable::sin(omega);
    wa = portable::sin((1.0 - t) * omega) / s;
    wb = portable::sin(t * omega) / s;
  }
  wb *= sign;
  Quaternion q(wa * a.w() + wb * b.w(), wa * a.x() + wb * b.x(), wa * a.y() + wb * b.y(),
               wa * a.z() + wb * b.z());
  if (d > 1.0 - kSlerpLinearBand) {
    const double n = std::sqrt(q.w() * q.w() + q.x() * q.x() + q.y() * q.y() + q.z() * q.z());
    q = Quaternion(q.w() / n, q.x() / n, q.y() / n, q.z() / n);
  }
  return q;
}

bool same_rotation(const Quaternion& a, const Quaternion& b, double tol) {
  const double minus = (a.coeffs() - b.coeffs()).cwiseAbs().maxCoeff();
  const double plus = (a.coeffs() + b.coeffs()).cwiseAbs().maxCoeff();
  return std::min(minus, plus) <= tol;
}

}  // namespace jelly::skeleton
