#include "jelly/render/session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace jelly::render {

SimulationRun::SimulationRun(RunSetup setup, TaskTable tasks) : setup_(std::move(setup)), tasks_(tasks) { reset(); }

void SimulationRun::reset(RunSetup setup) {
  setup_ = std::move(setup);
  reset();
}

void SimulationRun::reset() {
  sim_.reset();
  drawable_.reset();
  history_.clear();
  ms_per_step_ = 0.0;
  error_.clear();
  try {
    Simulator::Options o;
    o.integrator = setup_.integrator;
    o.dt = setup_.dt;
    auto world = build_world(setup_.scene, tasks_);
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
    if (result == StepResult::Unstable) break;  // that step also ran the stability estimate: not timed
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
  record(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

// ------------------------------------------------------------------------------------------------
double RealTimeClock::target(double sim_time, double wall_dt) {
  factor = std::clamp(factor, kMinFactor, kMaxFactor);
  wall_dt_ = std::clamp(wall_dt, 0.0, max_frame_s);
  // The accumulator: the target advances by factor × wall time from the previous target, not
  // from where the run stopped, so rounding to whole steps never accumulates.
  if (fresh_ || sim_time > target_ + 1.0 || sim_time < target_ - 1.0) target_ = sim_time;
  target_ += factor * wall_dt_;
  return target_;
}

void RealTimeClock::reached(double before, double after, bool budget_hit) {
  if (wall_dt_ <= 0.0) return;
  const double rate = (after - before) / wall_dt_;
  // Smooth over about a second of 60 Hz frames.
  achieved_ = fresh_ ? rate : 0.95 * achieved_ + 0.05 * rate;
  fresh_ = false;
  short_frames_ = 0.95 * short_frames_ + 0.05 * (budget_hit ? 1.0 : 0.0);
  behind_ = short_frames_ > 0.3;
  if (budget_hit) target_ = after;  // drop what could not be done: no spiral of death
}

void RealTimeClock::restart() {
  fresh_ = true;
  short_frames_ = 0.0;
  behind_ = false;
  achieved_ = factor;
}

std::vector<Viewport> comparison_layout(int count, int w, int h) {
  std::vector<Viewport> out;
  count = std::clamp(count, 1, 4);
  const int cols = count == 4 ? 2 : count, rows = count == 4 ? 2 : 1;
  for (int i = 0; i < count; ++i) {
    const int c = i % cols, r = i / cols;
    const int x0 = c * w / cols, x1 = (c + 1) * w / cols;
    const int y0 = r * h / rows, y1 = (r + 1) * h / rows;
    out.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return out;
}

namespace {
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string step_text(double h) {
  return h >= 1e-3 ? fmt("%.4g ms", h * 1e3) : fmt("%.4g us", h * 1e6);
}
}  // namespace

std::string caption(const RunSetup& s, double time, bool with_integrator) {
  const SceneSpec& sc = s.scene;
  std::string out = sc.name.empty() ? std::string("scene") : sc.name;
  if (with_integrator) out += "   " + std::string(display_name(s.integrator)) + "   h = " + step_text(s.dt);
  out += "   t = " + fmt("%.3f s", time);
  if (sc.body_kind == BodyKind::Cube) {
    out += "\ncube: n = " + std::to_string(sc.cube.n) + ", L = " + fmt("%.3g m", sc.cube.edge) +
           ", m = " + fmt("%.3g kg", sc.cube.mass) + "\n";
  } else {
    out += "\nparticles: " + std::to_string(sc.particles.positions.cols()) +
           ", m = " + fmt("%.3g kg", sc.particles.mass) + "\n";
  }
  const auto springs = [&](const char* name, const SpringSettings& ss) {
    if (ss.enabled) out += std::string(name) + " ks " + fmt("%g", ss.ks) + " kd " + fmt("%g", ss.kd) + "   ";
  };
  springs("structural", sc.structural);
  springs("shear", sc.shear);
  springs("shear_body", sc.shear_body);
  springs("bending", sc.bending);
  if (!sc.terrains.empty()) {
    out += "\n";
    for (const Terrain& t : sc.terrains) {
      const SurfaceProperties& p = t.surface();
      out += t.name + ": eps " + fmt("%g", p.epsilon) + " kr " + fmt("%g", p.restitution) +
             " kf " + fmt("%g", p.friction) + "   ";
    }
  }
  if (sc.gravity) out += "g = " + fmt("%g", sc.gravity->y()) + " m/s2";
  return out;
}

std::string run_label(const SimulationRun& run) {
  const int evals = evaluations_per_step(run.setup().integrator);
  std::string out = std::string(display_name(run.setup().integrator)) + "  (" + std::to_string(evals) +
                    (evals == 1 ? " eval/step)" : " evals/step)") + "\nh = " + step_text(run.step());
  if (run.ms_per_step() > 0.0) out += "  " + fmt("%.3f ms/step", run.ms_per_step());
  if (!run.setup().overrides.empty()) out += "\n" + run.setup().overrides;
  return out;
}

std::optional<std::string> apply_overrides(SceneSpec& scene, std::string_view text) {
  SceneSpec edited = scene;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find_first_of(";\n", start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    if (item.find_first_not_of(" \t\r") != std::string_view::npos)
      if (const auto error = set_assignment(edited, item)) return error->text();
    start = end + 1;
  }
  scene = std::move(edited);
  return std::nullopt;
}

}  // namespace jelly::render
