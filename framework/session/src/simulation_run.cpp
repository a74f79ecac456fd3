#include "jelly/session/simulation_run.hpp"

#include <chrono>
#include <stdexcept>
#include <utility>

namespace jelly::session {

SimulationRun::SimulationRun(RunSetup setup, TaskTable tasks)
    : setup_(std::move(setup)), tasks_(tasks) {
  reset();
}

void SimulationRun::reset(RunSetup setup) {
  setup_ = std::move(setup);
  reset();
}

void SimulationRun::reset() {
  sim_.reset();
  attachment_.reset();
  history_.clear();
  ms_per_step_ = 0.0;
  error_.clear();
  try {
    Simulator::Options o;
    o.integrator = setup_.integrator;
    o.dt = setup_.dt;
    auto world = build_world(setup_.scene, tasks_);
    // A world with no particles (a kind whose steps play recorded frames) has nothing to
    // integrate: the framework's integrator steps it, whatever the task table holds.
    if (world->particle_count() == 0) o.integrator = IntegratorKind::SymplecticEuler;
    auto_step_.reset();
    if (setup_.scene.auto_dt) {
      // The same choice as `jelly run --auto-dt`: a 60 Hz frame, the setup's step as the cap.
      auto_step_ = choose_step(*world, world->state(), setup_.integrator, 1.0 / 60.0, setup_.dt);
      o.dt = auto_step_->chosen_h;
    }
    sim_ = std::make_unique<Simulator>(std::move(world), o);
    record(0.0);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

double SimulationRun::com_height() const {
  if (!sim_) return 0.0;
  const World& w = sim_->world();
  const Eigen::VectorXd& m = w.masses();
  const double total = m.sum();
  return total > 0.0 ? w.state().x.row(1).dot(m) / total : 0.0;
}

void SimulationRun::record(double ms) {
  RunSample s;
  s.time = sim_->time();
  const Energy e = sim_->energy();
  s.energy = e.total();
  s.kinetic = e.kinetic;
  s.com_height = com_height();
  s.ms_per_step = ms;
  history_.push_back(s);
  while (history_.size() > kHistory) history_.pop_front();
}

long SimulationRun::advance_to(double t_target, double budget_ms) {
  if (!sim_ || sim_->instability()) return 0;
  using clock = std::chrono::steady_clock;
  const auto ms_since = [](clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  };
  const auto start = clock::now();
  const double h = step();  // the automatic step when the scene asks for one
  long steps = 0, timed = 0;
  double step_ms = 0.0;  // wall time inside Simulator::step only (not sampling, not drawing)
  budget_hit_ = false;
  while (sim_->time() + 0.5 * h <= t_target) {
    const auto t0 = clock::now();
    const StepResult result = sim_->step();
    const double d = ms_since(t0);
    ++steps;
    if (result == StepResult::Unstable)
      break;  // that step also ran the stability estimate: not timed
    step_ms += d;
    ++timed;
    if (steps % kSampleEvery == 0 && sim_->time() + 0.5 * h <= t_target)
      record(ms_per_step_ > 0.0 ? ms_per_step_ : step_ms / timed);
    if (ms_since(start) >= budget_ms) {
      budget_hit_ = sim_->time() + 0.5 * h <= t_target;
      break;
    }
  }
  if (timed > 0) {
    const double per = step_ms / static_cast<double>(timed);
    ms_per_step_ = ms_per_step_ == 0.0 ? per : 0.9 * ms_per_step_ + 0.1 * per;
  }
  if (steps > 0) record(ms_per_step_);
  return steps;
}

void SimulationRun::step_once() {
  if (!sim_ || sim_->instability()) return;
  const auto start = std::chrono::steady_clock::now();
  sim_->step();
  record(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace jelly::session
