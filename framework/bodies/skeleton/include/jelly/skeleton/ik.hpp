// Inverse kinematics on the skeleton (assignment A4, the kinematics contract §6): the settings of a
// solve, what it returns, and its collaborators. The iteration (A4.T4) and the solve with limits
// and restore (A4.T5) get their collaborators as an argument, `IkOps`, so that each is graded
// alone: the framework fills it from the student's own slots in `jelly run` and the viewer, the
// grader from recorded reference answers (docs/architecture.md, the skeleton module). Angles are
// degrees, lengths the skeleton's units times the scene's scale, y is up.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>

#include "jelly/skeleton/skeleton.hpp"

namespace jelly::skeleton {

/// The Jacobian of a chain of m bones: 3 × 3m (contract §6.2).
using Matrix3X = Eigen::Matrix<double, 3, Eigen::Dynamic>;
/// The update of a chain of m bones, 3m entries [radians of the columns' rotations] (§6.3).
using VectorX = Eigen::VectorXd;

/// The settings of a solve (contract §6: the course's defaults).
struct IkSettings {
  double step = 0.1;          ///< scales x before it is added (unitless)
  double epsilon = 1e-3;      ///< stop when |x* − p| < ε [scene units]
  int max_iterations = 1000;  ///< updates allowed, ≥ 0
  bool limits = false;        ///< clamp each updated channel to its ASF limits (the bonus)
  bool restore = true;        ///< an unstable solve puts the input posture back (the bonus)
};

/// What a solve returns (§6.5, §11.14): the updates made, |x* − p| after the last forward
/// kinematics (before any restore), and whether that is < ε.
struct IkResult {
  int updates = 0;
  double error = std::numeric_limits<double>::infinity();  ///< ∞: not measured (a stub)
  bool stable = false;
};

/// The collaborators of the iteration (A4.T4) and of the solve (A4.T5), filled by the framework
/// (your own tasks in `jelly run` and the viewer; recorded answers in the grader). Call them,
/// never your own functions. Each is about one chain and one target, fixed when it was made.
struct IkOps {
  /// p = e_end, the end of the chain's end bone after forward kinematics of the posture (T0).
  std::function<Vec3(const Posture&)> end_effector;
  /// J of §6.2 at the posture (T0, T2): resized to 3 × 3m.
  std::function<void(const Posture&, Matrix3X& J)> jacobian;
  /// x of §6.3, the minimum-norm least-squares solution of J x = e (T3): resized to J.cols().
  std::function<void(const Matrix3X& J, const Vec3& e, VectorX& x)> solve;
  /// Clamps the chain's channels to their limits (T5's clamp_to_limits).
  std::function<void(Posture&)> clamp;
  /// The iteration of §6.4 with this chain, target and settings (T4's ik_iterate).
  std::function<IkResult(Posture&)> iterate;
};

}  // namespace jelly::skeleton
