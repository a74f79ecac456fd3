#include "jelly/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace jelly {

namespace {

// The detector's settings for a world: A1's as given; on a cloth world the floor of the margin is
// 1e-3·Σm·|g|·L (cloth decision 11: Σm over the cloth and the dynamic spheres, L the cloth's side).
StabilityMonitor::Config monitor_config(const World& world, StabilityMonitor::Config config) {
  if (!world.has_cloth()) return config;
  double side = 0.0;
  for (const ClothGrid& c : world.cloths())
    side = std::max(side, c.spacing() * static_cast<double>(c.n() - 1));
  const double g = world.gravity() ? world.gravity()->norm() : 0.0;
  const double floor = 1e-3 * world.masses().sum() * g * side;
  if (floor > 0.0) config.absolute_floor = floor;
  return config;
}

}  // namespace

Simulator::Simulator(std::unique_ptr<World> world, Options options)
    : world_(std::move(world)),
      options_(options),
      monitor_(world_ ? monitor_config(*world_, options.monitor) : options.monitor) {
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
  world_->begin_step(steps_, options_.dt);  // kinematic spheres take u(t_n) (cloth §5)
  world_->apply_collisions(s);              // §6 step 1
  integrate();                              // §6 step 2
  world_->end_step(options_.dt);            // kinematic spheres move (cloth §5 step 3)
  ++steps_;
  if (options_.detect_instability && monitor_.wants_sample(steps_)) {
    const bool finite = s.x.allFinite() && s.v.allFinite();
    double e = finite ? energy().total() : std::nan("");
    // A cloth world compares E − W with E(0), W the kinematic spheres' work (decision 11).
    if (world_->has_cloth()) e -= world_->kinematic_work();
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
