// The skeleton's rotations (kinematics contract §3, §5, §11.9, §11.10): E against an independent
// construction, quaternions against E, the Euler round trip on random angles and in the gimbal
// band, and slerp's short path, nlerp band, antipodal and nearly equal quaternions.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "jelly/skeleton/rotation.hpp"

namespace jelly::skeleton {
namespace {

Mat3 independent_e(const Vec3& degrees) {
  const Vec3 r = degrees * (3.14159265358979323846 / 180.0);
  return (Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

double max_abs(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

Vec3 random_angles(std::mt19937_64& random) {
  std::uniform_real_distribution<double> any(-180.0, 180.0), tilt(-89.9, 89.9);
  return Vec3(any(random), tilt(random), any(random));
}

Quaternion random_quaternion(std::mt19937_64& random) {
  std::normal_distribution<double> n;
  return Quaternion(n(random), n(random), n(random), n(random)).normalized();
}

TEST(SkeletonRotation, AxisRotationsAreRightHanded) {
  EXPECT_LT((rotation_x(90.0) * Vec3::UnitY() - Vec3::UnitZ()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((rotation_y(90.0) * Vec3::UnitZ() - Vec3::UnitX()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((rotation_z(90.0) * Vec3::UnitX() - Vec3::UnitY()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(euler_matrix(Vec3::Zero()), Mat3::Identity());
}

TEST(SkeletonRotation, EulerMatrixIsRzRyRx) {
  std::mt19937_64 random(1);
  for (int i = 0; i < 200; ++i) {
    const Vec3 a = random_angles(random);
    ASSERT_LT(max_abs(euler_matrix(a) - independent_e(a)), 1e-14) << a.transpose();
  }
  // Not R_x·R_y·R_z (the course's students' reversed order, contract §9).
  const Vec3 a(30.0, 40.0, 50.0);
  EXPECT_GT(max_abs(euler_matrix(a) - rotation_x(30.0) * rotation_y(40.0) * rotation_z(50.0)), 0.1);
}

TEST(SkeletonRotation, QuaternionIsTheRotationOfE) {
  std::mt19937_64 random(2);
  for (int i = 0; i < 200; ++i) {
    const Vec3 a = random_angles(random);
    const Quaternion q = euler_to_quaternion(a);
    ASSERT_NEAR(q.norm(), 1.0, 1e-15);
    ASSERT_LT(max_abs(quaternion_matrix(q) - euler_matrix(a)), 1e-14) << a.transpose();
    ASSERT_LT(max_abs(q.toRotationMatrix() - euler_matrix(a)), 1e-14) << a.transpose();
  }
}

TEST(SkeletonRotation, EulerRoundTripOnRandomAngles) {
  std::mt19937_64 random(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a = random_angles(random);
    const Vec3 back = quaternion_to_euler(euler_to_quaternion(a));
    ASSERT_LT((back - a).cwiseAbs().maxCoeff(), 1e-9)
        << a.transpose() << " -> " << back.transpose();
  }
}

TEST(SkeletonRotation, EulerAnglesOfRandomQuaternionsAreInRangeAndExact) {
  std::mt19937_64 random(4);
  for (int i = 0; i < 1000; ++i) {
    const Quaternion q = random_quaternion(random);
    const Vec3 e = quaternion_to_euler(q);
    ASSERT_TRUE(e.x() > -180.0 && e.x() <= 180.0) << e.transpose();
    ASSERT_TRUE(e.y() >= -90.0 && e.y() <= 90.0) << e.transpose();
    ASSERT_TRUE(e.z() > -180.0 && e.z() <= 180.0) << e.transpose();
    ASSERT_TRUE(same_rotation(euler_to_quaternion(e), q, 1e-9)) << e.transpose();
  }
}

TEST(SkeletonRotation, QuaternionToEulerNormalisesAndIgnoresSign) {
  const Vec3 a(10.0, -20.0, 30.0);
  const Quaternion q = euler_to_quaternion(a);
  const Quaternion scaled(-3.0 * q.w(), -3.0 * q.x(), -3.0 * q.y(), -3.0 * q.z());
  EXPECT_LT((quaternion_to_euler(scaled) - a).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SkeletonRotation, HalfTurnIsPlus180) {
  EXPECT_EQ(quaternion_to_euler(euler_to_quaternion(Vec3(180.0, 0.0, 0.0))).x(), 180.0);
  EXPECT_EQ(quaternion_to_euler(euler_to_quaternion(Vec3(-180.0, 0.0, 0.0))).x(), 180.0);
  EXPECT_EQ(quaternion_to_euler(euler_to_quaternion(Vec3(0.0, 0.0, -180.0))).z(), 180.0);
  EXPECT_EQ(quaternion_to_euler(Quaternion(0.0, 0.0, 0.0, -1.0)).z(), 180.0);
}

// The band |R₂₀| ≥ 1 − 1e-12 starts 8.1e-5° from ry = ±90°: inside, ry is ±90 exactly, rx = 0 and
// the rotation agrees to 2e-6 (contract §11.9); just outside, the ordinary formulas hold.
TEST(SkeletonRotation, GimbalBand) {
  for (double sign : {1.0, -1.0}) {
    for (double off : {0.0, 1e-6, 5e-5}) {
      const Vec3 a(25.0, sign * (90.0 - off), -40.0);
      const Quaternion q = euler_to_quaternion(a);
      const Vec3 e = quaternion_to_euler(q);
      EXPECT_EQ(e.y(), sign * 90.0) << off;
      EXPECT_EQ(e.x(), 0.0) << off;
      EXPECT_TRUE(same_rotation(euler_to_quaternion(e), q, 2e-6)) << off << ": " << e.transpose();
      if (off == 0.0) {
        EXPECT_TRUE(same_rotation(euler_to_quaternion(e), q, 1e-12)) << e.transpose();
      }
    }
    const Vec3 outside(25.0, sign * (90.0 - 2e-4), -40.0);
    const Quaternion q = euler_to_quaternion(outside);
    const Vec3 e = quaternion_to_euler(q);
    EXPECT_NE(std::fabs(e.y()), 90.0);
    EXPECT_TRUE(same_rotation(euler_to_quaternion(e), q, 2e-6)) << e.transpose();
  }
}

TEST(SkeletonRotation, SlerpEndsAndMidpoint) {
  const Quaternion a = euler_to_quaternion(Vec3(0, 0, 0)), b = euler_to_quaternion(Vec3(0, 0, 90));
  EXPECT_TRUE(same_rotation(slerp(a, b, 0.0), a, 1e-15));
  EXPECT_TRUE(same_rotation(slerp(a, b, 1.0), b, 1e-15));
  EXPECT_TRUE(same_rotation(slerp(a, b, 0.5), euler_to_quaternion(Vec3(0, 0, 45)), 1e-15));
  EXPECT_TRUE(same_rotation(slerp(a, b, 0.25), euler_to_quaternion(Vec3(0, 0, 22.5)), 1e-15));
}

TEST(SkeletonRotation, SlerpIsTheStandardFormulaOnTheShortPath) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Quaternion a = random_quaternion(random), b = random_quaternion(random);
    const double t = unit(random);
    const Quaternion s = slerp(a, b, t);
    ASSERT_LT((s.coeffs() - a.slerp(t, b).coeffs()).cwiseAbs().maxCoeff(),
              1e-14);  // Eigen's: the same formula
    const Quaternion minus_b(-b.w(), -b.x(), -b.y(), -b.z());
    ASSERT_EQ(slerp(a, minus_b, t).coeffs(),
              s.coeffs());  // −b is the same rotation: the same result
    ASSERT_GE(s.dot(a),
              std::min(1.0, a.dot(b) * (a.dot(b) < 0 ? -1 : 1)) - 1e-12);  // between, short path
  }
}

TEST(SkeletonRotation, SlerpOfAntipodalQuaternions) {
  const Quaternion q = euler_to_quaternion(Vec3(10, 20, 30));
  const Quaternion minus_q(-q.w(), -q.x(), -q.y(), -q.z());
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    const Quaternion s = slerp(q, minus_q, t);
    EXPECT_LT((s.coeffs() - q.coeffs()).cwiseAbs().maxCoeff(), 1e-15) << t;
  }
}

TEST(SkeletonRotation, SlerpOfNearlyEqualQuaternionsIsFiniteAndUnit) {
  const Quaternion a = euler_to_quaternion(Vec3(10, 20, 30));
  for (double tiny : {1e-7, 1e-9, 1e-13, 0.0}) {
    const Quaternion b = euler_to_quaternion(Vec3(10, 20, 30 + tiny));
    for (double t : {0.0, 0.5, 1.0}) {
      const Quaternion s = slerp(a, b, t);
      ASSERT_TRUE(s.coeffs().allFinite()) << tiny << ", " << t;
      EXPECT_NEAR(s.norm(), 1.0, 1e-15) << tiny << ", " << t;
      EXPECT_TRUE(same_rotation(s, euler_to_quaternion(Vec3(10, 20, 30 + t * tiny)), 1e-12))
          << tiny << ", " << t;
    }
  }
}

TEST(SkeletonRotation, SameRotationUpToSign) {
  const Quaternion q = euler_to_quaternion(Vec3(10, 20, 30));
  const Quaternion minus_q(-q.w(), -q.x(), -q.y(), -q.z());
  EXPECT_TRUE(same_rotation(q, minus_q, 0.0));
  EXPECT_FALSE(same_rotation(q, euler_to_quaternion(Vec3(10, 20, 30.001)), 1e-9));
  // Two Euler triples of one rotation.
  EXPECT_TRUE(same_rotation(euler_to_quaternion(Vec3(180, 180, 180)),
                            euler_to_quaternion(Vec3(0, 0, 0)), 1e-15));
}

}  // namespace
}  // namespace jelly::skeleton
