// A4's reference (solutions/a4/) against the kinematics contract §6: the chain and the Jacobian of
// §8 on the course's files at scale 0.2, the Jacobian against central differences where the
// Euler angles' derivatives are the frame's axes, the least-squares solve against Eigen's complete
// orthogonal decomposition, and the hw3-ik solve's numbers (§8, §11.17), an unreachable target
// and what a solve may change (§6.4, §6.5, §11.14).
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "a4_ik_ops.hpp"
#include "course_mocap.hpp"
#include "jelly/a4/chain.hpp"
#include "jelly/a4/ik.hpp"
#include "jelly/a4/jacobian.hpp"
#include "jelly/a4/kinematics.hpp"
#include "jelly/a4/least_squares.hpp"

namespace jelly {
namespace {

using skeleton::BoneFrames;
using skeleton::IkOps;
using skeleton::IkResult;
using skeleton::IkSettings;
using skeleton::Matrix3X;
using skeleton::Posture;
using skeleton::Skeleton;
using skeleton::VectorX;

constexpr double kPi = 3.14159265358979323846;

// The course's hw3-ik scene (contract §7): IK.amc frame 0, lowerback → rfingers, this target.
struct CourseIk {
  Skeleton skeleton = testing::course_skeleton();
  Posture posture = testing::course_motion(skeleton, "IK.amc").frames.at(0);
  std::vector<int> chain = a4::ik_chain(skeleton, bone("lowerback"), bone("rfingers"));
  Vec3 target = Vec3(-0.0692501, 3.85358, -1.63441);

  int bone(const std::string& name) const {
    const std::optional<int> i = skeleton.find(name);
    EXPECT_TRUE(i.has_value()) << name;
    return i.value_or(0);
  }
  BoneFrames fk(const Posture& p) const {
    BoneFrames f;
    a4::forward_kinematics(skeleton, p, f);
    return f;
  }
  Matrix3X jacobian(const Posture& p, const std::vector<int>& c) const {
    Matrix3X J;
    a4::ik_jacobian(skeleton, fk(p), c, J);
    return J;
  }
  IkResult solve(const IkSettings& settings, Posture& p) const {
    const IkOps ops = testing::reference_ik_ops(skeleton, chain, target, settings);
    return a4::ik_solve(settings, ops, p);
  }
};

int rotation_channels(const Skeleton& s, const std::vector<int>& chain) {
  int n = 0;
  for (int i : chain)
    for (int k = 0; k < 3; ++k) n += (s.bones[i].parent < 0 || s.bones[i].has_rotation(k)) ? 1 : 0;
  return n;
}

bool same_bits(const Posture& a, const Posture& b) {
  if (a.angles.size() != b.angles.size()) return false;
  for (std::size_t i = 0; i < a.angles.size(); ++i)
    if (a.angles[i] != b.angles[i]) return false;
  return a.root_translation == b.root_translation;
}

bool finite(const Posture& p) {
  for (const Vec3& a : p.angles)
    if (!a.allFinite()) return false;
  return p.root_translation.allFinite();
}

// ----- T1: the chain (§6.1) -----

TEST(A4Reference, TheCoursesChainHasNineBonesAndNineteenChannels) {
  const CourseIk c;
  ASSERT_EQ(c.chain.size(), 9u);
  EXPECT_EQ(c.chain.front(), c.bone("rfingers"));
  EXPECT_EQ(c.chain.back(), c.bone("lowerback"));
  for (std::size_t b = 1; b < c.chain.size(); ++b)
    EXPECT_EQ(c.skeleton.bones[c.chain[b - 1]].parent, c.chain[b]) << "entry " << b;
  EXPECT_EQ(rotation_channels(c.skeleton, c.chain), 19);
}

TEST(A4Reference, AChainWhoseStartIsNoAncestorRunsToTheRoot) {
  const CourseIk c;
  const int end = c.bone("rfingers");
  EXPECT_EQ(a4::ik_chain(c.skeleton, end, end), std::vector<int>{end});
  const std::vector<int> to_root = a4::ik_chain(c.skeleton, c.bone("lfingers"), end);
  ASSERT_EQ(to_root.size(), 10u);
  EXPECT_EQ(to_root.back(), 0);
  EXPECT_EQ(a4::ik_chain(c.skeleton, 0, end), to_root);
  // A start below the end bone is no ancestor either.
  EXPECT_EQ(a4::ik_chain(c.skeleton, end, c.bone("rhumerus")).back(), 0);
}

// ----- T2: the Jacobian (§6.2) -----

TEST(A4Reference, TheCoursesJacobianIs3By27WithEightZeroColumns) {
  const CourseIk c;
  const Matrix3X J = c.jacobian(c.posture, c.chain);
  ASSERT_EQ(J.rows(), 3);
  ASSERT_EQ(J.cols(), 27);
  int zero = 0;
  for (Eigen::Index j = 0; j < J.cols(); ++j) {
    const std::size_t b = static_cast<std::size_t>(j / 3);
    const bool has = c.skeleton.bones[c.chain[b]].has_rotation(static_cast<int>(j % 3));
    if (J.col(j).isZero(0.0)) ++zero;
    EXPECT_EQ(J.col(j).isZero(0.0), !has) << "column " << j;
  }
  EXPECT_EQ(zero, 8);
}

// The central difference of the end effector over angle k of bone i [per radian].
Vec3 effector_slope(const CourseIk& c, const Posture& p, int end, int i, int k) {
  const double h = 1e-4;  // degrees
  Posture plus = p, minus = p;
  plus.angles[i][k] += h;
  minus.angles[i][k] -= h;
  return (c.fk(plus).end[end] - c.fk(minus).end[end]) / (2.0 * h * kPi / 180.0);
}

// Checks the columns of `chain` against central differences, for angles k in `axes`.
void expect_columns_are_slopes(const CourseIk& c, const Posture& p, const std::vector<int>& chain,
                               const std::vector<int>& axes) {
  const Matrix3X J = c.jacobian(p, chain);
  for (std::size_t b = 0; b < chain.size(); ++b) {
    const int i = chain[b];
    for (int k : axes) {
      if (!(c.skeleton.bones[i].parent < 0 || c.skeleton.bones[i].has_rotation(k))) continue;
      const Vec3 column = J.col(3 * static_cast<Eigen::Index>(b) + k);
      const Vec3 slope = effector_slope(c, p, chain.front(), i, k);
      EXPECT_LE((column - slope).norm(), 1e-7 * (1.0 + slope.norm()))
          << c.skeleton.bones[i].name << " axis " << k << ": J " << column.transpose()
          << ", differences " << slope.transpose();
    }
  }
}

TEST(A4Reference, WhereTheChainsAnglesAreZeroEveryColumnIsTheEffectorsSlope) {
  const CourseIk c;
  // With E(θ_i) = I, ∂E/∂θ_k is the axis k itself: the course's columns are the derivatives.
  for (const std::vector<int>& chain :
       {c.chain, a4::ik_chain(c.skeleton, c.bone("lfingers"), c.bone("rfingers"))}) {
    Posture p = c.posture;
    for (int i : chain) p.angles[i] = Vec3::Zero();
    expect_columns_are_slopes(c, p, chain, {0, 1, 2});
  }
}

TEST(A4Reference, AtAnyPostureTheRxColumnIsTheEffectorsSlope) {
  // E = R_z·R_y·R_x: rx turns about the bone's own x axis after the others, R_i.col(0).
  const CourseIk c;
  expect_columns_are_slopes(c, c.posture, c.chain, {0});
}

// ----- T3: least squares (§6.3, §11.15) -----

VectorX reference_solve(const Matrix3X& J, const Vec3& e) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  cod.setThreshold(static_cast<double>(std::max(J.rows(), J.cols())) * 0x1p-52);
  cod.compute(Eigen::MatrixXd(J));
  return cod.solve(Eigen::VectorXd(e));
}

// σ_max / σ_min over the singular values the contract keeps.
double condition(const Matrix3X& J) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(J)};
  const Eigen::VectorXd& s = svd.singularValues();
  const double cutoff = static_cast<double>(std::max(J.rows(), J.cols())) * 0x1p-52 * s(0);
  double smallest = s(0);
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > cutoff) smallest = s(i);
  return s(0) / smallest;
}

void expect_solves_like_cod(const Matrix3X& J, const Vec3& e, const std::string& what) {
  VectorX x;
  a4::least_squares(J, e, x);
  ASSERT_EQ(x.size(), J.cols()) << what;
  ASSERT_TRUE(x.allFinite()) << what;
  const VectorX want = reference_solve(J, e);
  const double kappa = condition(J);
  EXPECT_LE((x - want).norm(), 1e-13 * kappa * kappa * (1.0 + want.norm()))
      << what << ": condition " << kappa;
}

// J with rows 1 and 2 exact multiples of row 0 (rank 1) or row 2 of row 0 (rank 2).
Matrix3X random_jacobian(std::mt19937& rng, Eigen::Index cols, int rank) {
  std::normal_distribution<double> normal;
  Matrix3X J(3, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (int r = 0; r < 3; ++r) J(r, j) = normal(rng);
  if (rank <= 2) J.row(2) = 2.0 * J.row(0);
  if (rank <= 1) J.row(1) = 0.5 * J.row(0);
  return J;
}

TEST(A4Reference, LeastSquaresIsTheMinimumNormSolutionOnRandomJacobians) {
  std::mt19937 rng(20261129);
  std::normal_distribution<double> normal;
  for (Eigen::Index cols : {3, 6, 12, 27}) {
    for (int rank = 1; rank <= 3; ++rank) {
      for (int trial = 0; trial < 20; ++trial) {
        const Matrix3X J = random_jacobian(rng, cols, rank);
        const Vec3 e(normal(rng), normal(rng), normal(rng));
        expect_solves_like_cod(J, e,
                               "3x" + std::to_string(cols) + " rank " + std::to_string(rank) +
                                   " trial " + std::to_string(trial));
      }
    }
  }
}

TEST(A4Reference, LeastSquaresSolvesTheCoursesJacobianAndIsFiniteAtEveryScale) {
  const CourseIk c;
  const Matrix3X J = c.jacobian(c.posture, c.chain);
  const Vec3 e = c.target - c.fk(c.posture).end[c.chain.front()];
  expect_solves_like_cod(J, e, "hw3-ik's first J");
  VectorX x;
  a4::least_squares(J, e, x);
  for (double scale : {1e-150, 1e-100, 1e100, 1e150}) {
    VectorX scaled;
    a4::least_squares(scale * J, e, scaled);  // the answer scales by 1/scale
    ASSERT_TRUE(scaled.allFinite()) << scale;
    EXPECT_LE((scale * scaled - x).norm(), 1e-12 * x.norm()) << scale;
    a4::least_squares(scale * J, scale * e, scaled);  // the same answer
    ASSERT_TRUE(scaled.allFinite()) << scale;
    EXPECT_LE((scaled - x).norm(), 1e-12 * x.norm()) << scale;
  }
}

TEST(A4Reference, LeastSquaresOfAZeroJacobianIsZero) {
  for (Eigen::Index cols : {0, 3, 27}) {
    VectorX x = VectorX::Constant(5, 7.0);
    a4::least_squares(Matrix3X::Zero(3, cols), Vec3(1.0, -2.0, 3.0), x);
    ASSERT_EQ(x.size(), cols);
    EXPECT_TRUE(x.isZero(0.0)) << x.transpose();
  }
}

// ----- T4, T5: the solve (§6.4, §6.5, §8, §11.14, §11.17) -----

TEST(A4Reference, Hw3IkStartsAt1_75161AndConvergesAfter73Updates) {
  const CourseIk c;
  EXPECT_NEAR((c.target - c.fk(c.posture).end[c.chain.front()]).norm(), 1.75161, 5e-6);
  Posture p = c.posture;
  const IkResult r = c.solve(IkSettings{}, p);
  EXPECT_EQ(r.updates, 73);
  EXPECT_TRUE(r.stable);
  EXPECT_LT(r.error, 1e-3);
  EXPECT_NEAR((c.target - c.fk(p).end[c.chain.front()]).norm(), r.error, 0.0);
}

TEST(A4Reference, Hw3IkWithLimitsConvergesAfter105Updates) {
  const CourseIk c;
  IkSettings limits;
  limits.limits = true;
  Posture p = c.posture;
  const IkResult r = c.solve(limits, p);
  EXPECT_EQ(r.updates, 105);
  EXPECT_TRUE(r.stable);
  for (int i : c.chain) {
    const skeleton::Bone& b = c.skeleton.bones[i];
    for (std::size_t ch = 0; ch < b.limits.size(); ++ch) {
      const int k = static_cast<int>(b.channels[ch]) - static_cast<int>(skeleton::Channel::rx);
      EXPECT_GE(p.angles[i][k], b.limits[ch].lo) << b.name << " " << k;
      EXPECT_LE(p.angles[i][k], b.limits[ch].hi) << b.name << " " << k;
    }
  }
}

// §11.17: one update fewer lands just outside ε: the margins the counts rest on.
TEST(A4Reference, OneUpdateFewerStopsJustOutsideEpsilonAndIsRestored) {
  const CourseIk c;
  for (const bool limits : {false, true}) {
    IkSettings s;
    s.limits = limits;
    s.max_iterations = limits ? 104 : 72;
    Posture p = c.posture;
    const IkResult r = c.solve(s, p);
    EXPECT_EQ(r.updates, s.max_iterations);
    EXPECT_FALSE(r.stable);
    EXPECT_NEAR(r.error, limits ? 1.0510e-3 : 1.00472e-3, limits ? 5e-8 : 5e-9);
    EXPECT_TRUE(same_bits(p, c.posture)) << "restored, bit for bit";
  }
  // §11.14: the last allowed update landing within ε is stable, with max_iterations updates.
  IkSettings exact;
  exact.max_iterations = 73;
  Posture p = c.posture;
  const IkResult r = c.solve(exact, p);
  EXPECT_EQ(r.updates, 73);
  EXPECT_TRUE(r.stable);
}

TEST(A4Reference, ASolveChangesOnlyTheChainsChannels) {
  const CourseIk c;
  for (const bool limits : {false, true}) {
    IkSettings s;
    s.limits = limits;
    Posture p = c.posture;
    ASSERT_TRUE(c.solve(s, p).stable);
    EXPECT_EQ(p.root_translation, c.posture.root_translation);
    for (std::size_t i = 0; i < p.angles.size(); ++i) {
      const bool in_chain =
          std::find(c.chain.begin(), c.chain.end(), static_cast<int>(i)) != c.chain.end();
      for (int k = 0; k < 3; ++k) {
        if (in_chain && c.skeleton.bones[i].has_rotation(k)) continue;
        EXPECT_EQ(p.angles[i][k], c.posture.angles[i][k]) << c.skeleton.bones[i].name << " " << k;
      }
    }
  }
}

TEST(A4Reference, TheInitialPostureIsNotClamped) {
  // IK.amc breaks thorax's rx limit (−10.43° against −10°): no update, no clamp.
  const CourseIk c;
  const int thorax = c.bone("thorax");
  ASSERT_LT(c.posture.angles[thorax].x(), -10.0);
  IkSettings s;
  s.limits = true;
  s.max_iterations = 0;
  s.restore = false;
  Posture p = c.posture;
  const IkResult r = c.solve(s, p);
  EXPECT_EQ(r.updates, 0);
  EXPECT_NEAR(r.error, 1.75161, 5e-6);
  EXPECT_TRUE(same_bits(p, c.posture));
}

TEST(A4Reference, AnUnreachableTargetIsUnstableRestoredAndFinite) {
  CourseIk c;
  c.target = c.fk(c.posture).end[0] + Vec3(0.0, 40.0, 0.0);  // far above the head
  for (const bool limits : {false, true}) {
    IkSettings s;
    s.limits = limits;
    Posture p = c.posture;
    const IkResult r = c.solve(s, p);
    EXPECT_FALSE(r.stable);
    EXPECT_EQ(r.updates, s.max_iterations);
    EXPECT_TRUE(std::isfinite(r.error));
    EXPECT_GT(r.error, 1.0);
    EXPECT_TRUE(same_bits(p, c.posture)) << "restored, bit for bit";
    s.restore = false;
    const IkResult kept = c.solve(s, p);
    EXPECT_FALSE(kept.stable);
    EXPECT_TRUE(finite(p)) << "no NaN, no Inf";
    EXPECT_EQ(kept.error, r.error) << "the same iteration";
  }
}

TEST(A4Reference, ClampToLimitsClampsTheChainsLimitedChannelsInDofOrder) {
  const CourseIk c;
  const int clavicle = c.bone("rclavicle");  // dof ry rz, limits (−10 20) (−20 0)
  Posture p = c.posture;
  p.angles[clavicle] = Vec3(50.0, 50.0, 50.0);
  p.angles[0] = Vec3(500.0, -500.0, 500.0);
  const int lclavicle = c.bone("lclavicle");  // not in the chain
  p.angles[lclavicle] = Vec3(50.0, 50.0, 50.0);
  a4::clamp_to_limits(c.skeleton, a4::ik_chain(c.skeleton, 0, c.bone("rfingers")), p);
  EXPECT_EQ(p.angles[clavicle], Vec3(50.0, 20.0, 0.0)) << "rx is no channel: untouched";
  EXPECT_EQ(p.angles[0], Vec3(500.0, -500.0, 500.0)) << "the root is never clamped";
  EXPECT_EQ(p.angles[lclavicle], Vec3(50.0, 50.0, 50.0)) << "not in the chain";
}

// The solve alone, through made-up collaborators (graded alone: §6.5, §11.14).
TEST(A4Reference, ASolveIsStableOnlyBelowEpsilonAndRestoresTheInputPosture) {
  IkSettings s;
  Posture input = Posture::zero(2);
  input.angles[1] = Vec3(1.0, 2.0, 3.0);
  for (const double error : {0.5e-3, 1e-3, 2.0}) {
    IkOps ops;
    ops.iterate = [error](Posture& p) {
      p.angles[1] = Vec3(9.0, 9.0, 9.0);
      IkResult r;
      r.updates = 7;
      r.error = error;
      return r;
    };
    Posture p = input;
    const IkResult r = a4::ik_solve(s, ops, p);
    EXPECT_EQ(r.updates, 7);
    EXPECT_EQ(r.error, error) << "measured before any restore";
    EXPECT_EQ(r.stable, error < 1e-3);
    EXPECT_EQ(p.angles[1], r.stable ? Vec3(9.0, 9.0, 9.0) : Vec3(1.0, 2.0, 3.0));
  }
}

}  // namespace
}  // namespace jelly
