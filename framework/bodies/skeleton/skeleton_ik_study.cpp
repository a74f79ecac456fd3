// The study of inverse kinematics' accuracy against its cost (kinematics contract §10,
// docs/ik-studies.md): §6.4's iteration with the tasks' parts or the study's own variants.
#include "skeleton_ik_study.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "jelly/body_kind.hpp"
#include "jelly/portable_math.hpp"
#include "jelly/recorder.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::bodies {

namespace {

using skeleton::BoneFrames;
using skeleton::Matrix3X;
using skeleton::Posture;
using skeleton::Skeleton;
using skeleton::VectorX;

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

bool rotates_about(const skeleton::Bone& bone, int k) {
  return bone.parent < 0 || bone.has_rotation(k);
}

void require(bool filled, const char* name) {
  if (!filled)
    throw std::runtime_error(std::string("the IK study needs the task ") + name +
                             ", and this program's tasks do not fill it");
}

/// x from J and e by the variant's solver.
void solve_update(const IkStudyVariant& v, const SkeletonTasks& tasks, const Matrix3X& J,
                  const Vec3& e, VectorX& x) {
  if (v.solver == IkStudySolver::MinimumNorm) {
    tasks.least_squares(J, e, x);
    return;
  }
  if (v.solver == IkStudySolver::Damped) {
    const skeleton::Mat3 damped =
        J * J.transpose() + v.lambda * v.lambda * skeleton::Mat3::Identity();
    x = J.transpose() * damped.ldlt().solve(e);
    return;
  }
  const Vec3 jjte = J * (J.transpose() * e);
  const double norm2 = jjte.squaredNorm();
  const double alpha = norm2 > 0.0 ? e.dot(jjte) / norm2 : 0.0;
  x = alpha * (J.transpose() * e);
}

/// θ_i[k] += (step·x[3b + k])·180/π for the chain's channels (§6.4).
void add_update(const Skeleton& sk, const std::vector<int>& chain, double step, const VectorX& x,
                Posture& p) {
  for (std::size_t b = 0; b < chain.size(); ++b)
    for (int k = 0; k < 3; ++k)
      if (rotates_about(sk.bones[chain[b]], k))
        p.angles[chain[b]][k] +=
            (step * x(3 * static_cast<Eigen::Index>(b) + k)) * kDegreesPerRadian;
}

bool all_finite(const Posture& p) {
  for (const Vec3& a : p.angles)
    if (!a.allFinite()) return false;
  return true;
}

bool same_bits(const Posture& a, const Posture& b) {
  return a.angles == b.angles && a.root_translation == b.root_translation;
}

double max_change_degrees(const Posture& a, const Posture& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.angles.size(); ++i)
    m = std::max(m, (a.angles[i] - b.angles[i]).cwiseAbs().maxCoeff());
  return m;
}

/// One pass of the iteration: fills the run's errors, and `us` with the processor time of each.
Posture iterate_once(const Skeleton& sk, const IkStudyProblem& pr, const IkStudyVariant& v,
                     const skeleton::IkSettings& s, const SkeletonTasks& tasks, IkStudyRun& run,
                     std::vector<double>& us) {
  Posture p = pr.posture;
  BoneFrames f;
  Matrix3X J;
  VectorX x;
  run.error.clear();
  us.clear();
  const std::clock_t start = std::clock();
  for (int updates = 0;; ++updates) {
    tasks.forward_kinematics(sk, p, f);
    const Vec3 e = pr.target - f.end[pr.chain.front()];
    run.error.push_back(e.norm());
    us.push_back(1e6 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
    run.finite = run.finite && std::isfinite(run.error.back()) && all_finite(p);
    if (run.error.back() < s.epsilon || updates >= s.max_iterations) break;
    if (v.exact_jacobian) {
      exact_euler_jacobian(sk, f, p, pr.chain, J);
    } else {
      tasks.ik_jacobian(sk, f, pr.chain, J);
    }
    solve_update(v, tasks, J, e, x);
    add_update(sk, pr.chain, s.step, x, p);
    if (s.limits) tasks.clamp_to_limits(sk, pr.chain, p);
  }
  return p;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

std::string IkStudyVariant::name() const {
  std::string n = solver == IkStudySolver::MinimumNorm ? "minimum-norm"
                  : solver == IkStudySolver::Transpose ? "transpose"
                                                       : text_printf("dls-%g", lambda);
  return exact_jacobian ? n + "+exact" : n;
}

void exact_euler_jacobian(const Skeleton& sk, const BoneFrames& frames, const Posture& posture,
                          const std::vector<int>& chain, Matrix3X& J) {
  J = Matrix3X::Zero(3, 3 * static_cast<Eigen::Index>(chain.size()));
  if (chain.empty()) return;
  const Vec3 p = frames.end[chain[0]];
  for (std::size_t b = 0; b < chain.size(); ++b) {
    const int i = chain[b];
    const Vec3 arm = p - frames.start[i];
    double sx = 0.0, cx = 0.0, sy = 0.0, cy = 0.0;
    portable::sin_cos(posture.angles[i].x() * kRadiansPerDegree, sx, cx);
    portable::sin_cos(posture.angles[i].y() * kRadiansPerDegree, sy, cy);
    // R = A·R_z·R_y·R_x: ∂/∂rx turns about R·e_x, ∂/∂ry about A·R_z·e_y = R·R_xᵀ·e_y, ∂/∂rz about
    // A·e_z = R·R_xᵀ·R_yᵀ·e_z.
    const Vec3 local[3] = {Vec3(1.0, 0.0, 0.0), Vec3(0.0, cx, -sx), Vec3(-sy, sx * cy, cx * cy)};
    for (int k = 0; k < 3; ++k) {
      if (!rotates_about(sk.bones[i], k)) continue;
      J.col(3 * static_cast<Eigen::Index>(b) + k) = (frames.rotation[i] * local[k]).cross(arm);
    }
  }
}

IkStudyRun run_ik_variant(const Skeleton& sk, const IkStudyProblem& problem,
                          const IkStudyVariant& variant, const skeleton::IkSettings& settings,
                          const SkeletonTasks& tasks, int repeats) {
  require(tasks.forward_kinematics != nullptr, "forward_kinematics");
  require(tasks.ik_jacobian != nullptr, "ik_jacobian");
  require(tasks.least_squares != nullptr, "least_squares");
  require(!settings.limits || tasks.clamp_to_limits != nullptr, "clamp_to_limits");
  IkStudyRun run;
  run.variant = variant;
  run.settings = settings;
  std::vector<std::vector<double>> times;
  Posture last;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    times.emplace_back();
    last = iterate_once(sk, problem, variant, settings, tasks, run, times.back());
  }
  run.updates = static_cast<int>(run.error.size()) - 1;
  run.initial_error = run.error.front();
  run.final_error = run.error.back();
  run.stable = run.final_error < settings.epsilon;
  run.max_change_degrees = max_change_degrees(last, problem.posture);
  run.cpu_us.resize(run.error.size());
  std::vector<double> at(times.size());
  for (std::size_t k = 0; k < run.error.size(); ++k) {
    for (std::size_t r = 0; r < times.size(); ++r) at[r] = times[r][k];
    run.cpu_us[k] = median(at);
  }
  return run;
}

namespace {

/// IkOps from the task slots, for one chain and target (as `jelly run` fills them).
skeleton::IkOps task_ops(const Skeleton& sk, const IkStudyProblem& pr,
                         const skeleton::IkSettings& settings, const SkeletonTasks& tasks) {
  skeleton::IkOps ops;
  const Skeleton* s = &sk;
  const std::vector<int> chain = pr.chain;
  const SkeletonTasks t = tasks;
  ops.end_effector = [s, chain, t](const Posture& p) {
    BoneFrames f;
    t.forward_kinematics(*s, p, f);
    return Vec3(f.end[chain.front()]);
  };
  ops.jacobian = [s, chain, t](const Posture& p, Matrix3X& J) {
    BoneFrames f;
    t.forward_kinematics(*s, p, f);
    t.ik_jacobian(*s, f, chain, J);
  };
  ops.solve = t.least_squares;
  ops.clamp = [s, chain, t](Posture& p) { t.clamp_to_limits(*s, chain, p); };
  const Vec3 target = pr.target;
  ops.iterate = [s, chain, target, settings, t, inner = ops](Posture& p) {
    return t.ik_iterate(*s, chain, target, settings, inner, p);
  };
  return ops;
}

/// The course's variant solved again by the tasks' own ik_solve: whether it agrees with the
/// study's loop (updates and error, bit for bit) and, when unstable, restores the input posture.
void check_with_tasks(const Skeleton& sk, const IkStudyProblem& pr, const SkeletonTasks& tasks,
                      IkStudyRun& run) {
  if (tasks.ik_solve == nullptr || tasks.ik_iterate == nullptr || tasks.clamp_to_limits == nullptr)
    return;
  Posture p = pr.posture;
  const skeleton::IkResult r =
      tasks.ik_solve(run.settings, task_ops(sk, pr, run.settings, tasks), p);
  run.checked = true;
  run.tasks_agree =
      r.updates == run.updates && r.error == run.final_error && r.stable == run.stable;
  run.restored = !r.stable && run.settings.restore && same_bits(p, pr.posture);
  run.finite = run.finite && all_finite(p);
}

IkStudyRun named(IkStudyRun run, std::string group, std::string name) {
  run.group = std::move(group);
  run.name = std::move(name);
  return run;
}

skeleton::IkSettings settings_of(double step, double epsilon, bool limits) {
  skeleton::IkSettings s;
  s.step = step;
  s.epsilon = epsilon;
  s.limits = limits;
  return s;
}

/// The variants the solver comparison and the hard cases run: the course's, damped least squares
/// for each λ, the transpose and the exact Jacobian.
std::vector<IkStudyVariant> variants(const IkStudyInputs& in) {
  std::vector<IkStudyVariant> v{{IkStudySolver::MinimumNorm, 0.0, false}};
  for (double lambda : in.lambdas) v.push_back({IkStudySolver::Damped, lambda, false});
  v.push_back({IkStudySolver::Transpose, 0.0, false});
  v.push_back({IkStudySolver::MinimumNorm, 0.0, true});
  return v;
}

/// The problem with its target 40 units above the root (far above the head, out of every chain's
/// reach), as A4's reference test has it.
IkStudyProblem unreachable_problem(const IkStudyProblem& pr) {
  IkStudyProblem out = pr;
  out.target = pr.posture.root_translation + Vec3(0.0, 40.0, 0.0);
  return out;
}

/// The chain's first joint (its last bone's start) and its effector at the problem's posture.
std::pair<Vec3, Vec3> chain_span(const Skeleton& sk, const IkStudyProblem& pr,
                                 const SkeletonTasks& tasks) {
  BoneFrames f;
  tasks.forward_kinematics(sk, pr.posture, f);
  return {f.start[pr.chain.back()], f.end[pr.chain.front()]};
}

/// The straight arm with its target on the arm's line at 0.8 of its reach, moved up by 1 % of
/// the reach when `off_line`.
Vec3 straight_arm_target(const Skeleton& sk, const IkStudyProblem& pr, const SkeletonTasks& tasks,
                         bool off_line) {
  const auto [from, to] = chain_span(sk, pr, tasks);
  const Vec3 on_line = from + 0.8 * (to - from);
  return off_line ? on_line + Vec3(0.0, 0.01 * (to - from).norm(), 0.0) : on_line;
}

}  // namespace

std::vector<IkStudyRun> study_ik(const IkStudyInputs& in, const SkeletonTasks& tasks, int repeats) {
  std::vector<IkStudyRun> runs;
  const IkStudyVariant course;
  const auto add = [&](const IkStudyProblem& pr, const IkStudyVariant& v,
                       const skeleton::IkSettings& s, const std::string& group,
                       const std::string& name) {
    runs.push_back(named(run_ik_variant(in.skeleton, pr, v, s, tasks, repeats), group, name));
    if (v.solver == IkStudySolver::MinimumNorm && !v.exact_jacobian)
      check_with_tasks(in.skeleton, pr, tasks, runs.back());
  };
  for (double step : in.steps)
    add(in.problem, course, settings_of(step, 1e-3, false), "step", text_printf("step=%g", step));
  for (double eps : in.epsilons)
    add(in.problem, course, settings_of(0.1, eps, false), "epsilon",
        text_printf("epsilon=%g", eps));
  for (double step : {0.1, 1.0})
    for (const IkStudyVariant& v : variants(in))
      add(in.problem, v, settings_of(step, 1e-3, false), "solver",
          text_printf("%s/step=%g", v.name().c_str(), step));
  const IkStudyProblem unreachable = unreachable_problem(in.problem);
  IkStudyProblem off_line = in.straight_arm;
  off_line.target = straight_arm_target(in.skeleton, in.straight_arm, tasks, true);
  for (const IkStudyVariant& v : variants(in)) {
    add(unreachable, v, settings_of(0.1, 1e-3, false), "unreachable", "unreachable/" + v.name());
    add(in.straight_arm, v, settings_of(0.1, 1e-3, false), "straight", "straight/" + v.name());
    add(off_line, v, settings_of(0.1, 1e-3, false), "straight-off", "straight-off/" + v.name());
    add(in.problem, v, settings_of(0.1, 1e-3, true), "limits", "limits/" + v.name());
  }
  return runs;
}

IkStudyInputs read_ik_study_inputs(const std::string& asf, const std::string& amc, int frame,
                                   double scale, const std::string& start_bone,
                                   const std::string& end_bone, const Vec3& target,
                                   const SkeletonTasks& tasks) {
  require(tasks.ik_chain != nullptr, "ik_chain");
  require(tasks.forward_kinematics != nullptr, "forward_kinematics");
  const skeleton::SkeletonResult s = skeleton::read_asf(asf, scale);
  if (!s) throw std::runtime_error(s.error->text());
  IkStudyInputs in;
  in.skeleton = *s.skeleton;
  const skeleton::MotionResult m = skeleton::read_amc(amc, in.skeleton);
  if (!m) throw std::runtime_error(m.error->text());
  if (frame < 0 || frame >= static_cast<int>(m.motion->frames.size()))
    throw std::runtime_error(amc + " has no frame " + std::to_string(frame));
  const auto bone = [&](const std::string& name) {
    const std::optional<int> i = in.skeleton.find(name);
    if (!i) throw std::runtime_error(asf + " has no bone " + name);
    return *i;
  };
  in.problem.posture = m.motion->frames[frame];
  in.problem.chain = tasks.ik_chain(in.skeleton, bone(start_bone), bone(end_bone));
  in.problem.target = target;
  // The straight arm: every angle zero (the ASF's rest pose holds the right arm out straight),
  // the target on the arm's line at 0.8 of its reach: J Jᵀ is singular along that line.
  in.straight_arm.posture = Posture::zero(in.skeleton.bones.size());
  in.straight_arm.posture.root_translation = in.problem.posture.root_translation;
  in.straight_arm.chain = tasks.ik_chain(in.skeleton, bone("rhumerus"), bone("rfingers"));
  in.straight_arm.target = straight_arm_target(in.skeleton, in.straight_arm, tasks, false);
  if (in.problem.chain.empty() || in.straight_arm.chain.empty())
    throw std::runtime_error("the task ik_chain returned an empty chain");
  return in;
}

namespace {

std::unique_ptr<CsvWriter> open_output(const std::string& path, const char* header) {
  try {
    return std::make_unique<CsvWriter>(path, header);
  } catch (const std::runtime_error& e) {
    throw std::system_error(std::make_error_code(std::errc::io_error), e.what());
  }
}

constexpr const char* kRunsHeader =
    "group,name,variant,step,epsilon,limits,updates,initial_error,final_error,stable,finite,"
    "restored,tasks_agree,max_change_degrees,cpu_us,us_per_update";

void write_runs(const std::string& path, const std::vector<IkStudyRun>& runs) {
  const auto out = open_output(path, kRunsHeader);
  for (const IkStudyRun& r : runs) {
    const double us = r.cpu_us.back();
    out->write_cells({r.group, r.name, r.variant.name(), r.settings.step, r.settings.epsilon,
                      r.settings.limits ? 1.0 : 0.0, static_cast<double>(r.updates),
                      r.initial_error, r.final_error, r.stable ? 1.0 : 0.0, r.finite ? 1.0 : 0.0,
                      r.checked ? (r.restored ? 1.0 : 0.0) : -1.0,
                      r.checked ? (r.tasks_agree ? 1.0 : 0.0) : -1.0, r.max_change_degrees, us,
                      r.updates > 0 ? us / r.updates : 0.0});
  }
  out->flush();
}

void write_trace(const std::string& path, const std::vector<IkStudyRun>& runs) {
  const auto out = open_output(path, "name,update,error,cpu_us");
  for (const IkStudyRun& r : runs)
    for (std::size_t k = 0; k < r.error.size(); ++k)
      out->write_cells({r.name, static_cast<double>(k), r.error[k], r.cpu_us[k]});
  out->flush();
}

}  // namespace

std::string write_ik_study(const std::vector<IkStudyRun>& runs, const std::string& prefix) {
  const std::string runs_path = prefix + "-runs.csv", trace_path = prefix + "-trace.csv";
  write_runs(runs_path, runs);
  write_trace(trace_path, runs);
  std::string text =
      text_printf("%-34s %7s %12s %6s %10s\n", "run", "updates", "final error", "stable", "cpu us");
  for (const IkStudyRun& r : runs)
    text += text_printf("%-34s %7d %12.6g %6s %10.1f\n", r.name.c_str(), r.updates, r.final_error,
                        r.stable ? "yes" : (r.restored ? "rest." : "no"), r.cpu_us.back());
  return text + "wrote " + runs_path + " and " + trace_path + "\n";
}

}  // namespace jelly::bodies
