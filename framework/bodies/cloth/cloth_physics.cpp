// The physics of a cloth world (assignment A2, cloth contract §1–§5): cloths with pins, spheres,
// the accelerations a = g + w·Σf and the impulse response at the start of every step.
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_tasks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "jelly/spring_check.hpp"
#include "jelly/terrain_physics.hpp"
#include "jelly/world.hpp"

namespace jelly {

namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

void check_sphere(const SphereSpec& spec, int index) {
  const std::string where = "sphere " + std::to_string(index) + ": ";
  if (!finite(spec.center)) throw std::invalid_argument(where + "center: expected finite numbers");
  if (!(spec.radius > 0.0) || !std::isfinite(spec.radius))
    throw std::invalid_argument(where + "radius = " + std::to_string(spec.radius) +
                                ": expected a finite radius > 0 m");
  if (spec.kinematic) {
    for (std::size_t k = 0; k < spec.schedule.size(); ++k) {
      const ScheduleEntry& e = spec.schedule[k];
      if (!std::isfinite(e.time) || !finite(e.velocity))
        throw std::invalid_argument(where + "schedule entry " + std::to_string(k) +
                                    ": expected a finite time and velocity");
      if (k > 0 && !(e.time > spec.schedule[k - 1].time))
        throw std::invalid_argument(where + "schedule entry " + std::to_string(k) + ": time " +
                                    std::to_string(e.time) +
                                    " s: expected times that increase strictly (decision 5)");
    }
  } else {
    if (spec.mass && (!(*spec.mass > 0.0) || !std::isfinite(*spec.mass)))
      throw std::invalid_argument(where + "mass = " + std::to_string(*spec.mass) +
                                  ": expected a finite mass > 0 kg");
    if (!finite(spec.velocity))
      throw std::invalid_argument(where + "velocity: expected finite numbers");
  }
}

double kinetic(double mass, const Vec3& v) { return 0.5 * mass * v.squaredNorm(); }

}  // namespace

int ClothPhysics::add_cloth(const ClothSpec& spec) {
  World& w = world();
  if (!spheres_.empty())
    throw std::logic_error(
        "add_cloth: every cloth comes before the spheres (their particles are "
        "the state's first columns)");
  if (w.state().size() != cloth_particles_ || !w.terrains().empty())
    throw std::logic_error(
        "add_cloth: a cloth world holds cloths and spheres only (no cube, free "
        "particle or terrain)");
  if (!(spec.mass > 0.0) || !std::isfinite(spec.mass))
    throw std::invalid_argument("cloth: mass = " + std::to_string(spec.mass) +
                                ": expected a finite mass > 0 kg per particle");
  if (!(spec.air_drag >= 0.0) || !std::isfinite(spec.air_drag))
    throw std::invalid_argument("cloth: air_drag = " + std::to_string(spec.air_drag) +
                                ": expected a finite k_air ≥ 0 N·s/m");
  if (!cloths_.empty() && spec.air_drag != air_drag_)
    throw std::invalid_argument("cloth: air_drag: every cloth of one world has the same k_air");
  const auto first = static_cast<int>(w.state().size());
  ClothGrid grid(spec, first);
  const std::vector<GridCoord> pins = resolve_pins(spec);
  Vec3Array velocities(3, grid.particle_count());
  velocities.colwise() = spec.velocity;
  for (const GridCoord& p : pins) velocities.col(p[0] * grid.n() + p[1]).setZero();
  w.add_particles(grid.initial_positions(), velocities, spec.mass);
  for (const GridCoord& p : pins) inverse_masses(w)[grid.index(p[0], p[1])] = 0.0;
  cloth_particles_ = w.state().size();
  air_drag_ = spec.air_drag;
  cloths_.push_back(std::move(grid));
  return static_cast<int>(cloths_.size()) - 1;
}

void ClothPhysics::build_cloth_springs(int cloth, SpringType type, double ks, double kd) {
  World& w = world();
  const TaskTable& tasks = w.tasks();
  const ClothGrid& grid = cloths_.at(static_cast<std::size_t>(cloth));
  using Builder = void (*)(const ClothGrid&, std::vector<Spring>&);
  Builder fn = nullptr;
  const char* builder = "";
  switch (type) {
    case SpringType::Structural:
      fn = cloth_tasks(tasks).add_grid_structural_springs;
      builder = "add_grid_structural_springs";
      break;
    case SpringType::Shear:
      fn = cloth_tasks(tasks).add_grid_shear_springs;
      builder = "add_grid_shear_springs";
      break;
    case SpringType::Bending:
      fn = cloth_tasks(tasks).add_grid_bending_springs;
      builder = "add_grid_bending_springs";
      break;
    case SpringType::ShearBody:
      throw std::invalid_argument("a cloth has no body diagonals (cloth contract §2)");
  }
  if (!fn)
    throw std::runtime_error(std::string("the task table (") + std::string(tasks.origin) +
                             ") has no " + builder + ": it cannot build a cloth's springs");
  SpringGroup group;
  group.type = type;
  group.ks = ks;
  group.kd = kd;
  group.degenerate_length = degenerate_length_for(grid.spacing());
  fn(grid, group.springs);
  // The framework never trusts a builder's output blindly: a bad index would crash the force pass.
  const int lo = grid.first_index();
  const int hi = lo + grid.particle_count();
  check_built_springs(group, lo, hi, builder);
  w.add_spring_group(std::move(group));
}

int ClothPhysics::add_sphere(const SphereSpec& spec) {
  World& w = world();
  if (cloths_.empty() && spheres_.empty() && w.state().size() > 0)
    throw std::logic_error("add_sphere: spheres belong to a cloth world (no cube or particle)");
  if (!w.terrains().empty()) throw std::logic_error("add_sphere: a cloth world has no terrain");
  check_sphere(spec, static_cast<int>(spheres_.size()));
  SphereSlot slot;
  slot.spec = spec;
  slot.center = spec.center;
  if (!spec.kinematic) {
    const double mass = spec.mass ? *spec.mass : default_sphere_mass(spec.radius);
    Vec3Array x(3, 1), v(3, 1);
    x.col(0) = spec.center;
    v.col(0) = spec.velocity;
    slot.particle = w.add_particles(x, v, mass);
  }
  // A world of spheres alone is a cloth world too (a = g + w·Σf, the §4 response).
  spheres_.push_back(std::move(slot));
  return static_cast<int>(spheres_.size()) - 1;
}

void ClothPhysics::set_cloth_collisions(const ClothCollisionSettings& c) {
  const auto check = [](bool ok, const char* key, double value, const char* expected) {
    if (!ok)
      throw std::invalid_argument(std::string("collision: ") + key + " = " + std::to_string(value) +
                                  ": expected " + expected);
  };
  check(c.cloth_restitution >= 0.0 && c.cloth_restitution <= 1.0, "cloth_restitution",
        c.cloth_restitution, "a number in [0, 1]");
  check(c.sphere_restitution >= 0.0 && c.sphere_restitution <= 1.0, "sphere_restitution",
        c.sphere_restitution, "a number in [0, 1]");
  check(c.tolerance >= 0.0 && std::isfinite(c.tolerance), "tolerance", c.tolerance,
        "a finite ε ≥ 0 m");
  check(c.friction >= 0.0 && std::isfinite(c.friction), "friction", c.friction, "a finite μ ≥ 0");
  check(c.push_out >= 0.0 && c.push_out <= 1.0, "push_out", c.push_out, "β in [0, 1]");
  collisions_ = c;
}

void ClothPhysics::begin_step(long step, double h) {
  for (SphereSlot& s : spheres_)
    if (s.spec.kinematic && !s.driven) s.velocity = scheduled_velocity(s.spec.schedule, step, h);
}

void ClothPhysics::end_step(double h) {
  for (SphereSlot& s : spheres_)
    if (s.spec.kinematic) s.center += h * s.velocity;
}

void ClothPhysics::drive_sphere(int sphere, const Vec3& velocity) {
  if (sphere < 0 || sphere >= sphere_count() ||
      !spheres_[static_cast<std::size_t>(sphere)].spec.kinematic)
    throw std::out_of_range("drive_sphere: sphere " + std::to_string(sphere) +
                            " is not a kinematic sphere of this world");
  SphereSlot& s = spheres_[static_cast<std::size_t>(sphere)];
  s.velocity = velocity;
  s.driven = true;
}

void ClothPhysics::place_sphere(int sphere, const Vec3& center) {
  if (sphere < 0 || sphere >= sphere_count() ||
      !spheres_[static_cast<std::size_t>(sphere)].spec.kinematic)
    throw std::out_of_range("place_sphere: sphere " + std::to_string(sphere) +
                            " is not a kinematic sphere of this world");
  spheres_[static_cast<std::size_t>(sphere)].center = center;
}

void ClothPhysics::set_pinned(int particle, bool pinned) {
  if (particle < 0 || particle >= cloth_particles_)
    throw std::out_of_range("set_pinned: particle " + std::to_string(particle) +
                            " is not a cloth particle (0.." + std::to_string(cloth_particles_ - 1) +
                            ")");
  World& w = world();
  if (pinned) {
    inverse_masses(w)[particle] = 0.0;
    w.state().v.col(particle).setZero();
  } else {
    inverse_masses(w)[particle] = 1.0 / w.masses()[particle];
  }
}

bool ClothPhysics::is_pinned(int particle) const {
  const Eigen::VectorXd& w = world().inverse_masses();
  return particle >= 0 && particle < w.size() && w[particle] == 0.0;
}

SphereBody ClothPhysics::sphere(int i) const {
  return sphere_body(world().state(), static_cast<std::size_t>(i));
}

bool ClothPhysics::sphere_is_kinematic(int i) const {
  return spheres_.at(static_cast<std::size_t>(i)).spec.kinematic;
}

int ClothPhysics::sphere_particle(int i) const {
  return spheres_.at(static_cast<std::size_t>(i)).particle;
}

SphereBody ClothPhysics::sphere_body(const State& s, std::size_t i) const {
  const SphereSlot& slot = spheres_.at(i);
  SphereBody b;
  b.radius = slot.spec.radius;
  if (slot.particle >= 0) {
    b.center = s.x.col(slot.particle);
    b.velocity = s.v.col(slot.particle);
    b.inverse_mass = world().inverse_masses()[slot.particle];
  } else {
    b.center = slot.center;
    b.velocity = slot.velocity;
    b.inverse_mass = 0.0;
  }
  return b;
}

void ClothPhysics::store_sphere_velocity(State& s, std::size_t i, const Vec3& velocity) {
  const SphereSlot& slot = spheres_[i];
  if (slot.particle >= 0) s.v.col(slot.particle) = velocity;  // a kinematic sphere keeps u(t_n)
}

void ClothPhysics::acceleration(const State& s, Vec3Array& a) {
  World& w = world();
  EffectCounters& effects = counters(w);
  Vec3Array& force = force_scratch(w);
  ++effects.acceleration_evaluations;
  const Eigen::Index n = s.size();
  force.resize(3, n);
  force.setZero();
  // Σf: springs and dampers of every group the scene built (the same pass as A1's) ...
  if (!w.spring_groups().empty()) add_spring_forces(w, s, force);
  // ... plus air drag −k_air·v on the cloth's particles only (spheres feel none), when named;
  // then a = g + w·Σf for w > 0 and exactly 0 for w = 0 (decision 3). One pass over the particles.
  const double* f = force.data();
  const double* v = s.v.data();
  const double k = air_drag_;
  const Eigen::Index dragged = k > 0.0 ? cloth_particles_ : 0;
  if (dragged > 0) ++cloth_counters_.drag_applications;
  Vec3 g = Vec3::Zero();
  if (w.gravity()) {
    ++effects.gravity_applications;
    g = *w.gravity();
  }
  a.resize(3, n);
  double* out = a.data();
  const double* inv_mass = w.inverse_masses().data();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double wi = inv_mass[i];
    if (!(wi > 0.0)) {
      out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = 0.0;
      continue;
    }
    for (int d = 0; d < 3; ++d) {
      double fi = f[3 * i + d];
      if (i < dragged) fi -= k * v[3 * i + d];
      out[3 * i + d] = g[d] + wi * fi;
    }
  }
}

/// What one apply_collisions pass's steps share.
struct ClothPhysics::CollisionPass {
  const ClothTasks& tasks;  // looked up once, not per pair
  const Eigen::VectorXd& mass;
  const Eigen::VectorXd& inv_mass;
  EffectCounters& effects;
  ClothCounters& own;  // the cloth's own effects
  const ClothCollisionSettings& c;
  bool friction;  // a friction impulse follows every applied impulse
};

void ClothPhysics::apply_collisions(State& s) {
  if (spheres_.empty()) return;  // an effect the scene does not name costs nothing
  World& w = world();
  const ClothTasks& tasks = cloth_tasks(w.tasks());
  const ClothCollisionSettings& c = collisions_;
  const bool friction = c.friction > 0.0 && tasks.friction_impulse != nullptr;
  const CollisionPass pass{tasks, w.masses(), w.inverse_masses(), counters(w), cloth_counters_,
                           c,     friction};
  // 1. Every sphere–sphere pair i < j in scene order (decisions 1, 2).
  if (tasks.collide_spheres && spheres_.size() > 1) collide_sphere_pairs(s, pass);
  // 2. For each sphere in scene order, every cloth particle in index order (then push-out).
  if (!tasks.collide_particle_sphere && !(c.push_out > 0.0)) return;
  for (std::size_t k = 0; k < spheres_.size(); ++k) collide_cloth_with_sphere(s, k, pass);
}

void ClothPhysics::collide_sphere_pairs(State& s, const CollisionPass& pass) {
  const ClothTasks& tasks = pass.tasks;
  const Eigen::VectorXd& mass = pass.mass;
  EffectCounters& effects = pass.effects;
  const ClothCollisionSettings& c = pass.c;
  const std::size_t count = spheres_.size();
  const ImpulseSettings settings{c.sphere_restitution, c.tolerance};
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i + 1; j < count; ++j) {
      const bool ki = spheres_[i].particle < 0, kj = spheres_[j].particle < 0;
      if (ki && kj) continue;  // two kinematic spheres pass through each other
      ++pass.own.sphere_pair_tests;
      SphereBody a = sphere_body(s, i), b = sphere_body(s, j);
      // Work of a kinematic sphere: the kinetic-energy change of the dynamic one (decision 11).
      const int dynamic = ki ? spheres_[j].particle : (kj ? spheres_[i].particle : -1);
      const double before = dynamic >= 0 ? kinetic(mass[dynamic], s.v.col(dynamic)) : 0.0;
      const Impulse imp = tasks.collide_spheres(a, b, settings);
      if (imp.applied) {
        ++effects.impulses;
        if (pass.friction) {
          ++pass.own.friction_impulses;
          tasks.friction_impulse(imp, c.friction, a.inverse_mass, b.inverse_mass, a.velocity,
                                 b.velocity);
        }
      }
      store_sphere_velocity(s, i, a.velocity);
      store_sphere_velocity(s, j, b.velocity);
      if (dynamic >= 0) kinematic_work_ += kinetic(mass[dynamic], s.v.col(dynamic)) - before;
    }
}

void ClothPhysics::collide_cloth_with_sphere(State& s, std::size_t k, const CollisionPass& pass) {
  const ClothCollisionSettings& c = pass.c;
  const bool push_out = c.push_out > 0.0;
  const ImpulseSettings settings{c.cloth_restitution, c.tolerance};
  SphereBody sphere = sphere_body(s, k);
  // Broad phase: a pair can collide (φ < ε) or be pushed out (φ < 0) only when |x − c| < r + ε.
  // Pairs farther by more than a relative 1e-9 (far beyond any rounding of φ) are not offered to
  // the task: for a correct task that changes no bit, and it spares most of the calls.
  const double reach = sphere.radius + std::max(c.tolerance, 0.0);
  const double reach2 = reach * reach * (1.0 + 1e-9);
  const Vec3 centre = sphere.center;
  for (Eigen::Index i = 0; i < cloth_particles_; ++i) {
    const double d0 = s.x(0, i) - centre[0], d1 = s.x(1, i) - centre[1], d2 = s.x(2, i) - centre[2];
    if (!(d0 * d0 + d1 * d1 + d2 * d2 < reach2)) continue;
    if (pass.tasks.collide_particle_sphere)
      collide_particle_sphere(s, i, k, sphere, settings, pass);
    // Push-out (decision 7): every examined pair with w > 0 and φ < 0; pins and spheres never
    // move. φ and N are the framework's.
    if (push_out && pass.inv_mass[i] > 0.0) push_out_particle(s, i, sphere, pass);
  }
}

void ClothPhysics::collide_particle_sphere(State& s, Eigen::Index i, std::size_t k,
                                           SphereBody& sphere, const ImpulseSettings& settings,
                                           const CollisionPass& pass) {
  const ClothTasks& tasks = pass.tasks;
  const Eigen::VectorXd& mass = pass.mass;
  EffectCounters& effects = pass.effects;
  const bool kinematic = spheres_[k].particle < 0;
  ++pass.own.particle_sphere_tests;
  PointBody p{s.x.col(i), s.v.col(i), pass.inv_mass[i]};
  const double before = kinematic ? kinetic(mass[i], p.velocity) : 0.0;
  const Impulse imp = tasks.collide_particle_sphere(p, sphere, settings);
  if (imp.applied) {
    ++effects.impulses;
    if (pass.friction) {
      ++pass.own.friction_impulses;
      tasks.friction_impulse(imp, pass.c.friction, p.inverse_mass, sphere.inverse_mass, p.velocity,
                             sphere.velocity);
    }
  }
  s.v.col(i) = p.velocity;
  if (kinematic) {
    kinematic_work_ += kinetic(mass[i], p.velocity) - before;
    sphere.velocity = spheres_[k].velocity;  // prescribed: no impulse changes it
  } else {
    s.v.col(spheres_[k].particle) = sphere.velocity;
  }
}

void ClothPhysics::push_out_particle(State& s, Eigen::Index i, const SphereBody& sphere,
                                     const CollisionPass& pass) {
  const Vec3 x = s.x.col(i);
  const Vec3 d = x - sphere.center;
  const double distance = d.norm();
  if (distance < 1e-12 * sphere.radius) return;  // at the centre: no normal
  const double phi = distance - sphere.radius;
  if (phi < 0.0) {
    s.x.col(i) = x - (pass.c.push_out * phi) * (d / distance);
    ++pass.own.push_outs;
  }
}

bool ClothPhysics::is_fixed(Eigen::Index i) const { return world().inverse_masses()[i] == 0.0; }

StabilityMonitor::Config ClothPhysics::detector_config(StabilityMonitor::Config config) const {
  const World& w = world();
  double side = 0.0;
  for (const ClothGrid& c : cloths_)
    side = std::max(side, c.spacing() * static_cast<double>(c.n() - 1));
  const double g = w.gravity() ? w.gravity()->norm() : 0.0;
  const double floor = 1e-3 * w.masses().sum() * g * side;
  if (floor > 0.0) config.absolute_floor = floor;
  return config;
}

const char* ClothPhysics::refuses_terrain() const {
  return "a cloth world has no terrain (cloth contract §6)";
}

ClothPhysics& cloth_physics(World& world) {
  if (auto* physics = dynamic_cast<ClothPhysics*>(&world.physics())) return *physics;
  const BodyPhysics& current = world.physics();
  if (world.particle_count() > 0 || !world.terrains().empty() ||
      typeid(current) != typeid(TerrainPhysics))
    throw std::logic_error(
        "a cloth world holds cloths and spheres only (no cube, free particle or terrain)");
  auto made = std::make_unique<ClothPhysics>(world);
  ClothPhysics& physics = *made;
  world.set_physics(std::move(made));
  return physics;
}

const ClothPhysics& cloth_physics(const World& world) {
  if (const ClothPhysics* physics = find_cloth_physics(world)) return *physics;
  static World empty{TaskTable{}};
  static const ClothPhysics none(empty);
  return none;
}

ClothPhysics* find_cloth_physics(World& world) {
  return dynamic_cast<ClothPhysics*>(&world.physics());
}

const ClothPhysics* find_cloth_physics(const World& world) {
  return dynamic_cast<const ClothPhysics*>(&world.physics());
}

}  // namespace jelly
