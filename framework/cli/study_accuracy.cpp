// The sweep of `jelly study accuracy`: runs, reference, errors, timings, observed orders.
#include "study_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include "jelly/auto_step.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/simulator.hpp"
#include "jelly/task_table.hpp"
#include "study_files.hpp"

namespace jelly::cli::study {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The whole number k with k·h = interval, or throws naming both.
long steps_per(double interval, double h, const char* what) {
  const double k = interval / h;
  const long r = std::lround(k);
  if (r < 1 || std::abs(k - static_cast<double>(r)) > 1e-6 * k) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s %g s is not a whole multiple of the step %g s", what,
                  interval, h);
    throw std::invalid_argument(buf);
  }
  return r;
}

/// What one run produces besides its row: the samples (reference runs only).
struct RunOutput {
  RunRow row;
  std::vector<Vec3Array> samples;  // positions at t = j · sample_dt, j = 0..J
  long first_collision_step = -1;
};

Simulator::Options watched_options(IntegratorKind kind, double h) {
  Simulator::Options options(kind, h);
  options.detect_instability = false;  // watched below, so that the run is not stopped
  return options;
}

/// One run of run_once: the simulator, the §8 detector watching it, and what the run measures.
class AccuracyRun {
 public:
  AccuracyRun(const SceneSpec& scene, IntegratorKind kind, double h, const SweepOptions& o,
              const std::vector<Vec3Array>* reference, bool keep)
      : reference_(reference),
        keep_(keep),
        total_(steps_per(o.duration, h, "the duration")),
        per_sample_(steps_per(o.sample_dt, h, "the sample interval")),
        sim_(build_world(scene, session::tasks_for(scene)), watched_options(kind, h)),
        monitor_(sim_.detector_config()) {  // the detector's own settings for the world
    out_.row.integrator = kind;
    out_.row.h = h;
    monitor_.start(sim_.detector_energy());
    evaluations0_ = sim_.evaluations();
    if (keep_) out_.samples.push_back(sim_.state().x);
  }

  RunOutput run() {
    const int block = std::max(1, monitor_.config().sample_every);
    while (step_ < total_) {
      run_block(std::min(total_, (step_ / block + 1) * block));
      if (!watch()) break;
      if (step_ % per_sample_ == 0) sample();
    }
    finish();
    return std::move(out_);
  }

 private:
  /// Terrain responses, or the impulses of a body kind's own physics, so far.
  long collisions() {
    const auto& c = sim_.world().counters();
    return std::accumulate(c.collisions.begin(), c.collisions.end(), 0L) +
           static_cast<long>(c.impulses);
  }

  /// Times a block of steps up to `stop` between watch points (or up to a sample inside it); the
  /// watching and the error are not timed.
  void run_block(long stop) {
    const auto t0 = std::chrono::steady_clock::now();
    while (step_ < stop) {
      sim_.step();
      ++step_;
      if (out_.first_collision_step < 0 && collisions() > 0) out_.first_collision_step = step_;
      if (step_ % per_sample_ == 0 && step_ < stop) break;  // a sample inside the block
    }
    wall_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  /// At a watch point, a sample or the end: false when the state is not finite (the run stops).
  bool watch() {
    RunRow& row = out_.row;
    const State& s = sim_.state();
    if (!(monitor_.wants_sample(step_) || step_ % per_sample_ == 0 || step_ == total_)) return true;
    const bool finite = s.x.allFinite() && s.v.allFinite();
    if (!finite) {
      row.finite = false;
      if (row.stable) {
        row.stable = false;
        row.reason = "a position or velocity is not finite";
        row.detected_at = sim_.time();
      }
      return false;
    }
    if (row.stable && monitor_.wants_sample(step_)) {
      if (auto reason = monitor_.check(sim_.detector_energy(), true)) {
        row.stable = false;
        row.reason = *reason;
        row.detected_at = sim_.time();
      }
    }
    return true;
  }

  /// At a sample time: keeps the positions, and measures the error against the reference's.
  void sample() {
    const State& s = sim_.state();
    const long j = step_ / per_sample_;
    if (keep_) out_.samples.push_back(s.x);
    if (!reference_) return;
    const Vec3Array& xr = (*reference_)[static_cast<std::size_t>(j)];
    const Eigen::Index n = s.x.cols();
    double sq = 0.0, worst = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double d2 = (s.x.col(i) - xr.col(i)).squaredNorm();
      sq += d2;
      worst = std::max(worst, d2);
    }
    sum_sq_ += sq / static_cast<double>(n);
    ++count_;
    if (step_ == total_) out_.row.error_final = std::sqrt(worst);
  }

  /// The row's totals: time, cost and the errors.
  void finish() {
    RunRow& row = out_.row;
    row.sim_time = sim_.time();
    row.wall = wall_;
    row.evaluations = sim_.evaluations() - evaluations0_;
    if (const BackwardEulerSolver* be = sim_.backward_euler())
      row.cg_iterations = be->total_iterations();
    if (!reference_) {
      row.error_rms = row.error_final = kNaN;
    } else if (!row.finite) {
      row.error_rms = row.error_final = kInf;
    } else {
      row.error_rms = count_ > 0 ? std::sqrt(sum_sq_ / static_cast<double>(count_)) : 0.0;
    }
  }

  const std::vector<Vec3Array>* reference_;
  bool keep_;
  long total_, per_sample_;
  Simulator sim_;
  StabilityMonitor monitor_;
  long evaluations0_ = 0;
  RunOutput out_;
  double sum_sq_ = 0.0;
  long count_ = 0;
  double wall_ = 0.0;  // [s] the timed steps
  long step_ = 0;
};

/// Runs one integrator at one step over [0, T]. With `reference`, measures the error at every
/// sample time; with `keep`, stores the samples. The §8 detector is watched (not obeyed): a run
/// it flags keeps going so that its error is still measured, and stops only when not finite.
RunOutput run_once(const SceneSpec& scene, IntegratorKind kind, double h, const SweepOptions& o,
                   const std::vector<Vec3Array>* reference, bool keep) {
  return AccuracyRun(scene, kind, h, o, reference, keep).run();
}

double order(double e_coarse, double e_fine, double h_coarse, double h_fine) {
  if (!(e_coarse > 0.0 && e_fine > 0.0) || !std::isfinite(e_coarse) || !std::isfinite(e_fine))
    return kNaN;
  return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
}

void check_options(const SweepOptions& o) {
  if (o.steps.empty()) throw std::invalid_argument("no step sizes to sweep");
  if (!(o.duration > 0.0) || !(o.sample_dt > 0.0) || o.reference_factor < 1 || o.repeats < 1)
    throw std::invalid_argument(
        "duration, sample interval, reference factor and repeats must be > 0");
}

/// The scene's size, and where the automatic step size would run each integrator, for
/// comparison with the sweep.
void describe_scene(const SceneSpec& scene, const SweepOptions& o, std::FILE* progress,
                    SweepResult& r) {
  const auto world = build_world(scene, session::tasks_for(scene));
  r.particles = static_cast<long>(world->particle_count());
  r.springs = world->spring_count();
  r.terrains = world->terrains().size();
  const StabilityEstimate e = estimate_stability(*world, world->state());
  for (IntegratorKind kind : o.integrators) {
    const AutoStep a = choose_step(e, kind, 1.0 / 60.0, scene.dt);
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.4g s (%d substeps per 1/60 s frame%s)", a.chosen_h,
                  a.substeps_per_frame, a.stable_step_exists ? "" : "; no step is stable");
    r.auto_steps.push_back(buf);
    if (progress)
      std::fprintf(progress, "auto step for %s: %s\n", std::string(to_string(kind)).c_str(), buf);
  }
}

/// Every step must divide the sample interval and the duration: checked all before running.
void check_steps(const SweepOptions& o, const std::vector<double>& steps) {
  steps_per(o.duration, o.sample_dt, "the duration (in samples)");
  for (double h : steps) {
    steps_per(o.sample_dt, h, "the sample interval");
    steps_per(o.duration, h, "the duration");
  }
}

/// The reference: RK4 at h_ref = h_min / factor, checked against RK4 at h_ref / 2.
RunOutput run_reference(const SceneSpec& scene, const SweepOptions& o, std::FILE* progress,
                        SweepResult& r) {
  r.reference.h = r.options.steps.back() / o.reference_factor;
  if (progress)
    std::fprintf(progress, "reference: rk4, h = %g s ...\n", r.reference.h), std::fflush(progress);
  RunOutput ref = run_once(scene, IntegratorKind::RK4, r.reference.h, o, nullptr, true);
  r.reference.wall = ref.row.wall;
  r.reference.stable = ref.row.stable && ref.row.finite;
  r.first_collision_step = ref.first_collision_step;
  r.first_collision_time =
      ref.first_collision_step < 0 ? -1.0 : ref.first_collision_step * r.reference.h;
  if (!ref.row.finite)
    throw std::runtime_error("the RK4 reference run blew up; choose smaller steps");
  if (o.check_reference) {
    if (progress)
      std::fprintf(progress, "reference check: rk4, h = %g s ...\n", r.reference.h / 2),
          std::fflush(progress);
    const RunOutput half =
        run_once(scene, IntegratorKind::RK4, r.reference.h / 2, o, &ref.samples, false);
    r.reference.checked = true;
    r.reference.check_rms = half.row.error_rms;
    r.reference.check_final = half.row.error_final;
  }
  return ref;
}

/// One integrator at every step size (coarse to fine), each row's orders against the one before.
void sweep_integrator(const SceneSpec& scene, const SweepOptions& o, IntegratorKind kind,
                      const std::vector<Vec3Array>& reference, std::FILE* progress,
                      SweepResult& r) {
  for (std::size_t i = 0; i < r.options.steps.size(); ++i) {
    const double h = r.options.steps[i];
    RunRow row = run_once(scene, kind, h, o, &reference, false).row;
    for (int rep = 1; rep < o.repeats; ++rep)
      row.wall = std::min(row.wall, run_once(scene, kind, h, o, nullptr, false).row.wall);
    row.order_rms = row.order_final = kNaN;
    // An order compares like with like: both runs stable, or both flagged (explicit Euler on
    // an undamped spring still converges over a finite horizon); never across a blow-up.
    if (i > 0 && r.rows.back().stable == row.stable) {
      const RunRow& prev = r.rows.back();
      row.order_rms = order(prev.error_rms, row.error_rms, prev.h, h);
      row.order_final = order(prev.error_final, row.error_final, prev.h, h);
    }
    if (progress) {
      std::fprintf(progress, "  %-16s h = %-10g %s  rms error %-10.3g wall %.3g s\n",
                   std::string(to_string(kind)).c_str(), h, row.stable ? "stable  " : "UNSTABLE",
                   row.error_rms, row.wall);
      std::fflush(progress);
    }
    r.rows.push_back(row);
  }
}

}  // namespace

SweepResult run_sweep(const SceneSpec& scene, const SweepOptions& o, std::FILE* progress) {
  check_options(o);
  SweepResult r;
  r.options = o;
  std::sort(r.options.steps.begin(), r.options.steps.end(), std::greater<>());
  r.scene_name = scene.name;
  r.load_before = loadavg();
  describe_scene(scene, o, progress, r);
  check_steps(o, r.options.steps);
  const RunOutput ref = run_reference(scene, o, progress, r);
  for (IntegratorKind kind : o.integrators)
    sweep_integrator(scene, o, kind, ref.samples, progress, r);
  r.load_after = loadavg();
  return r;
}

}  // namespace jelly::cli::study
