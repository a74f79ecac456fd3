// The sweep of `jelly study effects`: applies each value of one declared parameter (or each
// integrator), runs the scene, and measures the impact, bounce, rest and energy of the run, its
// body kind's measures, and its cost. Definitions: docs/parameters.md ("What is measured").
#include "study_effects.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "jelly/body_kind.hpp"
#include "jelly/params.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/simulator.hpp"
#include "jelly/task_table.hpp"
#include "study_files.hpp"

namespace jelly::cli::study {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  return parts;
}

/// Whether `key` matches `pattern`, where a '*' part matches any one part.
bool matches(const std::string& pattern, const std::string& key) {
  const auto p = dotted(pattern), k = dotted(key);
  if (p.size() != k.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] != "*" && p[i] != k[i]) return false;
  return true;
}

/// The declared keys `pattern` stands for (itself when declared and without '*').
std::vector<std::string> expand(const SceneSpec& scene, const std::string& pattern,
                                std::optional<ParamType> type = std::nullopt) {
  std::vector<std::string> keys;
  for (const ParamInfo& p : scene_parameters(scene))
    if (matches(pattern, p.key) && (!type || p.type == *type)) keys.push_back(p.key);
  return keys;
}

/// Sets `key` (one declared key, or a vector key + ".x"/".y"/".z") to `value`; the error text or
/// "".
std::string set_one(SceneSpec& scene, const std::string& key, const std::string& value,
                    int component) {
  if (component < 0) {
    if (const auto e = set_parameter(scene, key, value)) return e->text();
    return "";
  }
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v))
    return "--set: " + key + "." + "xyz"[component] + ": expected a number, got '" + value + "'";
  std::vector<double> xyz;
  std::stringstream ss(*get_parameter(scene, key));
  for (std::string c; std::getline(ss, c, ',');) xyz.push_back(std::strtod(c.c_str(), nullptr));
  if (xyz.size() != 3) return "--set: " + key + ": not a vector";
  xyz[static_cast<std::size_t>(component)] = v;
  const std::string text = num(xyz[0]) + "," + num(xyz[1]) + "," + num(xyz[2]);
  if (const auto e = set_parameter(scene, key, text)) return e->text();
  return "";
}

/// The names of the measures `m` turns on, as a manifest lists them.
std::vector<std::string> measure_names(const Measures& m) {
  std::vector<std::string> names;
  for (const std::string& name : known_measures())
    if ((name == "impact" && m.impact) || (name == "bounce" && m.bounce) ||
        (name == "rest" && m.rest) || (name == "energy" && m.energy) || m.has(name))
      names.push_back(name);
  return names;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// The particles a study measures (a kind may leave out bodies that follow it in the state), their
/// masses, and the world's up (against gravity; +y without it).
struct MeasuredBody {
  const Eigen::VectorXd& mass;
  Eigen::Index count;
  double total_mass;
  Vec3 up;
};

MeasuredBody measured_body(const World& world, const BodyKindModule& body_kind) {
  const Vec3 up = world.gravity() && world.gravity()->norm() > 0.0
                      ? Vec3(-world.gravity()->normalized())
                      : Vec3(0.0, 1.0, 0.0);
  const Eigen::VectorXd& mass = world.masses();
  const Eigen::Index body = body_kind.measured_particles(world);
  const double total_mass = mass.head(body).sum();
  return {mass, body, total_mass, up};
}

/// What a state shows of the measured body: its centre of mass, the centre's velocity and height
/// along up, and the fastest particle's speed.
struct Look {
  Vec3 com_v;
  double height, max_speed;
  Vec3 com;
};

Look look_at(const MeasuredBody& b, const State& s) {
  Look l{Vec3::Zero(), 0.0, 0.0, Vec3::Zero()};
  for (Eigen::Index i = 0; i < b.count; ++i) {
    l.com += b.mass[i] * s.x.col(i);
    l.com_v += b.mass[i] * s.v.col(i);
    l.max_speed = std::max(l.max_speed, s.v.col(i).norm());
  }
  l.com /= b.total_mass;
  l.height = b.up.dot(l.com);
  l.com_v /= b.total_mass;
  return l;
}

/// The collision responses, contact forces and impulses of the run so far.
std::int64_t touches(const World& world) {
  const auto& c = world.counters();
  return std::accumulate(c.collisions.begin(), c.collisions.end(), std::int64_t{0}) +
         std::accumulate(c.contacts.begin(), c.contacts.end(), std::int64_t{0}) + c.impulses;
}

/// The impact, the turn and the bounce of the centre of mass, followed step by step.
struct BounceWatch {
  bool contact = false, turned = false;
  double turn_height = kNaN;

  /// After a step that began at `t_before` and went from `before` to `now`.
  void observe(const Simulator& sim, double t_before, const Look& before, const Look& now,
               const Vec3& up, EffectsRow& row) {
    if (!contact && touches(sim.world()) > 0) {
      contact = true;
      row.contact_time = t_before;
      row.impact_speed = before.com_v.norm();
    }
    if (contact && !turned && up.dot(now.com_v) >= 0.0) {
      turned = true;
      row.turn_time = sim.time();
      turn_height = now.height;
      row.peak_speed = 0.0;
      row.com_apex = now.height;
    }
    if (turned) {
      row.peak_speed = std::max(row.peak_speed, now.com_v.norm());
      row.com_apex = std::max(row.com_apex, now.height);
    }
  }
};

/// The samples of the run over time, one every `every` seconds of simulated time.
struct Sampler {
  EffectsSeries& series;
  double every;
  double next = 0.0;

  void take(const Simulator& sim, const Look& l, double volume_ratio) {
    series.t.push_back(sim.time());
    series.com_height.push_back(l.height);
    series.com_speed.push_back(l.com_v.norm());
    series.volume_ratio.push_back(volume_ratio);
    series.max_speed.push_back(l.max_speed);
    series.energy.push_back(sim.energy().total());
    next += every;
  }
};

/// Whether the state is no longer finite; the run is then unstable from now on.
bool blew_up(const Simulator& sim, EffectsRow& row) {
  const State& s = sim.state();
  if (!s.x.allFinite() || !s.v.allFinite()) {
    row.finite = false;
    if (row.stable) {
      row.stable = false;
      row.reason = "a position or velocity is not finite";
      row.detected_at = sim.time();
    }
    return true;
  }
  return false;
}

/// Whether the stability detector, which samples every few steps, fires after `step`.
bool detector_fired(StabilityMonitor& monitor, const Simulator& sim, long step, EffectsRow& row) {
  if (monitor.wants_sample(step))
    if (auto reason = monitor.check(sim.detector_energy(), true)) {
      row.stable = false;
      row.reason = *reason;
      row.detected_at = sim.time();
      return true;
    }
  return false;
}

/// What is known at the end of the run: the bounce, the rest, the kind's measures, the energy and
/// the cost.
void finish_row(const Simulator& sim, const BounceWatch& bounce, double rest_since,
                const BodyStudyValues& v, const EffectsOptions& o, double wall, EffectsRow& row) {
  if (bounce.turned) row.bounce = row.com_apex - bounce.turn_height;
  row.sim_time = sim.time();
  row.rest_time = !std::isnan(rest_since) && row.sim_time - rest_since >= o.rest_hold - 1e-9
                      ? rest_since
                      : kNaN;
  row.kind_values = v.values;
  row.energy_end = sim.energy().total();
  row.wall = wall;
  row.evaluations = sim.evaluations();
  if (const BackwardEulerSolver* be = sim.backward_euler())
    row.cg_iterations = be->total_iterations();
}

/// One run: steps the scene to the duration and measures as it goes (the measuring is not timed).
EffectsRow measure(const SceneSpec& scene, IntegratorKind kind, const EffectsOptions& o,
                   EffectsSeries& series) {
  EffectsRow row;
  row.integrator = kind;
  row.h = scene.dt;
  Simulator::Options options(kind, scene.dt);
  options.detect_instability = false;  // watched below (the same detector, every 10 steps)
  Simulator sim(build_world(scene, session::tasks_for(scene)), options);
  const World& world = sim.world();
  StabilityMonitor monitor(sim.detector_config());  // the detector's own settings for the world
  row.energy_start = sim.energy().total();
  monitor.start(sim.detector_energy());
  row.particles = static_cast<long>(world.particle_count());
  row.springs = static_cast<long>(world.spring_count());
  const BodyKindModule& body_kind = body_kind_of(scene);
  row.kind = &body_kind;
  const MeasuredBody body = measured_body(world, body_kind);
  Look before = look_at(body, sim.state());
  // What the body's kind measures on it (a kind's measures); NaN for what it does not.
  const std::unique_ptr<BodyStudy> kind_study = body_kind.study(
      world, sim.state(), StudyLook{before.com, before.height, body.up}, measure_names(o.measures));
  const BodyStudyValues no_values;
  const BodyStudyValues& kind_values = kind_study ? kind_study->values() : no_values;

  const long total = std::max(1L, static_cast<long>(std::ceil(o.duration / scene.dt - 1e-9)));
  row.contact_time = row.impact_speed = row.turn_time = kNaN;
  row.peak_speed = row.com_apex = row.bounce = kNaN;
  BounceWatch bounce;
  double rest_since = 0.0;
  Sampler sampler{series, o.series_dt};
  sampler.take(sim, before, kind_values.over_time);
  double wall = 0.0;
  for (long step = 1; step <= total; ++step) {
    const double t_before = sim.time();
    const auto t0 = std::chrono::steady_clock::now();
    sim.step();
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (blew_up(sim, row)) break;
    const Look now = look_at(body, sim.state());
    bounce.observe(sim, t_before, before, now, body.up, row);
    if (kind_study) kind_study->observe(sim.state(), StudyLook{now.com, now.height, body.up});
    if (now.max_speed >= o.rest_speed)
      rest_since = kNaN;
    else if (std::isnan(rest_since))
      rest_since = sim.time();
    const bool fired = detector_fired(monitor, sim, step, row);
    const bool last = fired || step == total;
    if (sim.time() >= sampler.next - 1e-9 * scene.dt || last)
      sampler.take(sim, now, kind_values.over_time);
    if (last) break;  // the detector fired: what follows would measure a broken run
    before = now;
  }
  finish_row(sim, bounce, rest_since, kind_values, o, wall, row);
  return row;
}

/// The wall time of the same steps again, without measuring (for the median over repeats).
double time_again(const SceneSpec& scene, IntegratorKind kind, long steps) {
  Simulator::Options options(kind, scene.dt);
  options.detect_instability = false;
  Simulator sim(build_world(scene, session::tasks_for(scene)), options);
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) sim.step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The progress line's part of the kinds' measures placed at `place` that `m` turns on.
std::string kinds_seen(const Measures& m, const EffectsRow& row, MeasurePlace place) {
  std::string seen;
  for (const KindMeasure& k : kind_measures()) {
    const BodyMeasureColumn& c = k.measure->progress;
    if (k.measure->place == place && m.has(k.measure->name))
      seen += " " + std::string(c.header) + " " + fmt(c.format, row.shown(k, c)) + " " +
              std::string(c.unit) + ",";
  }
  return seen;
}

}  // namespace

std::vector<KindMeasure> kind_measures() {
  std::vector<KindMeasure> all;
  for (const BodyKindModule* kind : body_kinds())
    for (const BodyMeasure& measure : kind->measures()) all.push_back({kind, &measure});
  return all;
}

std::vector<std::string> known_measures() {
  const auto placed = [](std::vector<std::string>& names, MeasurePlace place) {
    for (const KindMeasure& k : kind_measures())
      if (k.measure->place == place) names.emplace_back(k.measure->name);
  };
  std::vector<std::string> names = {"impact", "bounce"};
  placed(names, MeasurePlace::kLanding);
  names.insert(names.end(), {"rest", "energy"});
  placed(names, MeasurePlace::kMotion);
  return names;
}

bool Measures::has(std::string_view name) const {
  return std::find(kinds.begin(), kinds.end(), name) != kinds.end();
}

double EffectsRow::shown(const KindMeasure& m, const BodyMeasureColumn& c) const {
  const auto i = static_cast<std::size_t>(c.value);
  if (m.kind != kind || i >= kind_values.size()) return kNaN;
  return c.scale * kind_values[i];
}

Measures measures_from(const std::vector<std::string>& names, const std::string& manifest) {
  Measures m{false, false, false, false, {}};
  bool* flags[] = {&m.impact, &m.bounce, &m.rest, &m.energy};
  const char* own[] = {"impact", "bounce", "rest", "energy"};
  const std::vector<std::string> known = known_measures();
  for (const std::string& name : names) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument(manifest + ": studies.measures: unknown measure \"" + name +
                                  "\" (the framework measures: " + list + ")");
    }
    const auto it = std::find(std::begin(own), std::end(own), name);
    if (it != std::end(own))
      *flags[it - std::begin(own)] = true;
    else if (!m.has(name))
      m.kinds.push_back(name);
  }
  return m;
}

std::vector<SceneSpec> effects_scenes(const SceneSpec& scene, const EffectsOptions& o,
                                      std::vector<std::string>* keys_out) {
  if (o.key.empty()) {
    if (!o.values.empty()) throw std::invalid_argument("--values needs --param KEY");
    return {scene};
  }
  if (o.values.empty()) throw std::invalid_argument("--param " + o.key + " needs --values A,B,...");
  std::vector<std::string> keys = expand(scene, o.key);
  int component = -1;
  if (keys.empty()) {
    const auto parts = dotted(o.key);
    const std::string& last = parts.empty() ? o.key : parts.back();
    if (parts.size() > 1 && (last == "x" || last == "y" || last == "z")) {
      const std::string base = o.key.substr(0, o.key.size() - 2);
      keys = expand(scene, base, ParamType::Vector3);
      if (!keys.empty()) component = last[0] - 'x';
    }
  }
  if (keys.empty()) {
    // Let the declarations say what is wrong (with their "did you mean").
    SceneSpec copy = scene;
    std::string why =
        o.key.find('*') != std::string::npos
            ? "--param " + o.key + ": matches no parameter of this scene (see jelly params SCENE)"
            : set_one(copy, o.key, o.values.front(), -1);
    if (why.empty()) why = "--param " + o.key + ": not a parameter of this scene";
    throw std::invalid_argument(why);
  }
  std::vector<SceneSpec> scenes;
  for (const std::string& value : o.values) {
    SceneSpec s = scene;
    for (const std::string& key : keys)
      if (std::string why = set_one(s, key, value, component); !why.empty()) {
        const auto info = find_parameter(scene, key);
        if (info && info->type == ParamType::Vector3 && component < 0)
          why +=
              " (separate vector values with ';', e.g. --values '0,9,0;0,30,0', or sweep one "
              "component: --param " +
              key + ".y)";
        throw std::invalid_argument(why);
      }
    scenes.push_back(std::move(s));
  }
  if (keys_out) {
    keys_out->clear();
    for (const std::string& k : keys)
      keys_out->push_back(component < 0 ? k : k + "." + "xyz"[component]);
  }
  return scenes;
}

EffectsResult run_effects(const SceneSpec& scene, const EffectsOptions& o, std::FILE* progress) {
  // Every value is checked (effects_scenes) before anything runs: bad input runs and writes
  // nothing.
  if (!(o.duration > 0.0) || !(o.rest_speed > 0.0) || !(o.rest_hold >= 0.0) ||
      !(o.series_dt > 0.0) || o.repeats < 1)
    throw std::invalid_argument("duration, rest speed, sample interval and repeats must be > 0");
  EffectsResult r;
  r.options = o;
  r.scene_name = scene.name;
  r.scene_file = scene.source;
  const std::vector<SceneSpec> scenes = effects_scenes(scene, o, &r.keys);
  r.load_before = loadavg();
  const std::size_t runs = scenes.size() * std::max<std::size_t>(1, o.integrators.size());
  std::size_t done = 0;
  const std::size_t integrator_count = std::max<std::size_t>(1, o.integrators.size());
  for (std::size_t k = 0; k < integrator_count; ++k) {
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const IntegratorKind kind = o.integrators.empty() ? scenes[i].integrator : o.integrators[k];
      EffectsSeries series;
      EffectsRow row = measure(scenes[i], kind, o, series);
      row.value = o.key.empty() ? "" : o.values[i];
      if (o.repeats > 1) {
        std::vector<double> walls{row.wall};
        const long steps = std::lround(row.sim_time / row.h);
        for (int rep = 1; rep < o.repeats; ++rep)
          walls.push_back(time_again(scenes[i], kind, steps));
        row.wall = median(walls);
      }
      ++done;
      if (progress) {
        // The measures the scene's assignment reports, then the cost.
        std::string seen = row.stable ? "stable," : "UNSTABLE,";
        seen += kinds_seen(o.measures, row, MeasurePlace::kLanding);
        if (o.measures.bounce) seen += " bounce " + fmt("%.3g", row.bounce) + " m,";
        seen += kinds_seen(o.measures, row, MeasurePlace::kMotion);
        if (o.measures.rest)
          seen += " rest " +
                  (std::isnan(row.rest_time) ? "never" : fmt("%.3g", row.rest_time) + " s") + ",";
        std::fprintf(progress, "[%zu/%zu] %s%s%s %s h=%g: %s wall %.3g s\n", done, runs,
                     o.key.c_str(), o.key.empty() ? "" : "=", row.value.c_str(),
                     std::string(to_string(kind)).c_str(), row.h, seen.c_str(), row.wall);
        std::fflush(progress);
      }
      r.rows.push_back(std::move(row));
      r.series.push_back(std::move(series));
    }
  }
  r.load_after = loadavg();
  return r;
}

}  // namespace jelly::cli::study
