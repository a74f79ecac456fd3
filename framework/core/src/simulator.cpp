#include "jelly/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace jelly {

Simulator::Simulator(std::unique_ptr<World> world, Options options)
    : world_(std::move(world)),
      options_(options),
      // The detector's settings are the world's physics' (a kind may set the margin's floor).
      monitor_(world_ ? world_->physics().detector_config(options.monitor) : options.monitor) {
  if (!world_) throw std::invalid_argument("Simulator needs a world");
  if (!(options_.dt > 0.0) || !std::isfinite(options_.dt))
    throw std::invalid_argument("Simulator: the step size must be a finite number > 0");
  const TaskTable& tasks = world_->tasks();
  switch (options_.integrator) {
    case IntegratorKind::ExplicitEuler: step_fn_ = tasks.explicit_euler_step; break;
    case IntegratorKind::ImplicitEuler: step_fn_ = tasks.implicit_euler_step; break;
    case IntegratorKind::Midpoint: step_fn_ = tasks.midpoint_step; break;
    case IntegratorKind::RK4: step_fn_ = tasks.rk4_step; break;
    case IntegratorKind::SymplecticEuler: step_fn_ = &symplectic_euler_step; break;
    case IntegratorKind::BackwardEuler: backward_ = std::make_unique<BackwardEulerSolver>(); break;
  }
  if (!step_fn_ && !backward_)
    throw std::invalid_argument("Simulator: the task table has no function for integrator " +
                                std::string(to_string(options_.integrator)));
  workspace_.resize(world_->particle_count());
  initial_state_ = world_->state();
  if (options_.detect_instability) monitor_.start(energy().total());
}

const StabilityEstimate& Simulator::estimate() {
  if (!estimate_) estimate_ = estimate_stability(*world_, initial_state_);
  return *estimate_;
}

void Simulator::integrate() {
  State& s = world_->state();
  if (backward_) {
    backward_->step(*world_, s, options_.dt);
  } else {
    workspace_.resize(s.size());
    step_fn_(*world_, s, options_.dt, workspace_);
  }
}

StepResult Simulator::step() {
  if (instability_) return StepResult::Unstable;
  State& s = world_->state();
  world_->begin_step(steps_, options_.dt);  // what the physics moves itself takes its velocity
  world_->apply_collisions(s);              // §6 step 1
  integrate();                              // §6 step 2
  world_->end_step(options_.dt);            // what the physics moves itself moves
  ++steps_;
  if (options_.detect_instability && monitor_.wants_sample(steps_)) {
    const bool finite = s.x.allFinite() && s.v.allFinite();
    double e = finite ? energy().total() : std::nan("");
    // E − W is compared with E(0), W the work done from outside (the physics'; 0 by default).
    e -= world_->physics().external_work();
    if (auto reason = monitor_.check(e, finite)) {
      InstabilityReport r;
      r.integrator = options_.integrator;
      r.step_size = options_.dt;
      r.step = steps_;
      r.time = time();
      r.reason = *reason;
      r.energy_start = monitor_.start_energy();
      r.energy_now = e;
      // The estimate is taken on the initial configuration (contract §8).
      r.critical_step = estimate().critical_step(options_.integrator);
      r.recommended_step = estimate().recommended_step(options_.integrator);
      instability_ = r;
      return StepResult::Unstable;
    }
  }
  return StepResult::Ok;
}

StepResult Simulator::run_until(double t_end, const std::function<void(const Simulator&)>& after) {
  const long target = std::lround(t_end / options_.dt);
  StepResult result = instability_ ? StepResult::Unstable : StepResult::Ok;
  while (steps_ < target && result == StepResult::Ok) {
    result = step();
    if (after) after(*this);
  }
  return result;
}

}  // namespace jelly
