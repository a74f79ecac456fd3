// The world: particles, the effects a scene asks for, and their evaluation (contract §6, §7).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jelly/body_physics.hpp"
#include "jelly/jacobian.hpp"
#include "jelly/spring.hpp"
#include "jelly/task_table.hpp"
#include "jelly/terrain.hpp"

namespace jelly {

/// How often each effect ran. Tests use these to prove that only what a scene calls for is
/// simulated (contract §7); the viewer shows them. 64-bit on every platform (`long` is 32 bits
/// on Windows, and springs_evaluated passes 2³¹ within minutes of a running viewer).
struct EffectCounters {
  std::int64_t acceleration_evaluations = 0;               ///< calls of World::acceleration
  std::int64_t gravity_applications = 0;                   ///< evaluations that added gravity
  std::array<std::int64_t, 4> spring_group_evaluations{};  ///< per SpringType, group passes
  std::int64_t springs_evaluated = 0;                      ///< springs summed over all passes
  std::int64_t collision_passes = 0;            ///< calls of apply_collisions that had any terrain
  std::vector<std::int64_t> collision_queries;  ///< per terrain: particles tested for collision
  std::vector<std::int64_t> contact_queries;    ///< per terrain: particles tested for contact
  std::vector<std::int64_t> collisions;         ///< per terrain: responses applied
  std::vector<std::int64_t> contacts;           ///< per terrain: contact forces applied
  std::vector<std::int64_t>
      broadphase_skips;  ///< per terrain: passes skipped whole by the bounding box
  /// Impulses applied by a kind's own physics (the studies count them with the terrains'
  /// responses); 0 in a scene without them. A kind counts the rest of its own effects itself.
  std::int64_t impulses = 0;
};

/// Energy of a state (contract §8) [J].
struct Energy {
  double kinetic = 0.0;
  double gravitational = 0.0;  ///< measured from World::reference_height()
  double spring = 0.0;         ///< ½ ks (l − rest)² summed over springs
  double total() const { return kinetic + gravitational + spring; }
};

/// Particles, springs, terrains and gravity: only what the scene asked for exists (contract §7).
/// The World owns the current state and is the System the integrators advance. What differs
/// between body kinds (the acceleration, the collision response, the state only a kind has) is
/// its BodyPhysics (jelly/body_physics.hpp): the default (jelly/terrain_physics.hpp), or the one
/// its kind installed (framework/bodies/<kind>/).
class World : public JacobianSystem {
 public:
  explicit World(TaskTable tasks);
  ~World() override;
  /// Moves the parts and the physics (which then works on the new World); the World moved from
  /// is left empty with the default physics.
  World(World&& other);
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  World& operator=(World&&) = delete;

  // ----- building (before the first step) -----
  /// Adds free particles with the given positions, velocities and mass; returns the first index.
  int add_particles(const Vec3Array& positions, const Vec3Array& velocities, double mass);
  /// Adds a group of springs as given (explicit scenes, grader inputs).
  void add_spring_group(SpringGroup group);
  /// Turns gravity on with acceleration g [m/s²], or off (nullopt).
  void set_gravity(std::optional<Vec3> g);
  /// Appends a terrain; terrains act in the order they were added.
  void add_terrain(Terrain terrain);
  /// Lets the spring pass use up to `threads` threads (default 1). Results do not depend on it.
  void set_force_threads(int threads);
  int force_threads() const { return threads_; }

  // ----- the System interface -----
  void acceleration(const State& s, Vec3Array& a) override;
  Eigen::Index particle_count() const override { return state_.size(); }
  const Eigen::VectorXd& masses() const override { return mass_; }
  std::vector<std::pair<int, int>> jacobian_pattern() const override;
  void force_jacobians(const State& s, ForceJacobians& jac) override;
  /// Whether particle i is held fixed: the physics says (none by default).
  bool is_fixed(Eigen::Index i) const override;

  // ----- a step (the Simulator's order: begin_step, apply_collisions, integrator, end_step) ---
  /// Before step n of size h: what the physics moves itself takes its velocity (no-op by default).
  void begin_step(long step, double h);
  /// Step 1 of contract §6: the physics' collision response (by default every terrain with
  /// collision on, in order, then its optional projection). Changes `s.v` (and maybe `s.x`).
  void apply_collisions(State& s);
  /// After the integrator: what the physics moves itself moves (no-op by default).
  void end_step(double h);

  // ----- its body kind's physics -----
  BodyPhysics& physics() { return *physics_; }
  const BodyPhysics& physics() const { return *physics_; }
  /// Replaces the physics (a kind's, made for this world) before the first step.
  void set_physics(std::unique_ptr<BodyPhysics> physics);

  // ----- state and queries -----
  State& state() { return state_; }
  const State& state() const { return state_; }
  const Eigen::VectorXd& inverse_masses() const { return inv_mass_; }
  const std::vector<SpringGroup>& spring_groups() const { return groups_; }
  const std::vector<Terrain>& terrains() const { return terrains_; }
  const std::optional<Vec3>& gravity() const { return gravity_; }
  const TaskTable& tasks() const { return tasks_; }
  std::size_t spring_count() const;

  /// Height (along −g, or y without gravity) from which gravitational energy is measured: the
  /// lowest point of the scene's bounded terrains, else the lowest initial particle (contract §8;
  /// see docs/physics-decisions.md). Fixed when the first particles are added and terrains set.
  double reference_height() const;
  /// Kinetic, gravitational and spring energy of state s (the physics' external_work() is not in
  /// it).
  Energy energy(const State& s) const;

  const EffectCounters& counters() const { return counters_; }
  void reset_counters();

 private:
  friend class BodyPhysics;  // the parts its kinds' physics work on
  void add_spring_forces(const State& s, Vec3Array& f);
  void pattern_cache() const;

  TaskTable tasks_;
  std::unique_ptr<SpringGroupPass> spring_pass_;  // the task library's engine, if it has one
  State state_;
  Eigen::VectorXd mass_;
  Eigen::VectorXd inv_mass_;
  std::vector<SpringGroup> groups_;
  std::vector<Terrain> terrains_;
  std::optional<Vec3> gravity_;
  EffectCounters counters_;
  Vec3Array force_;  // scratch, 3×N
  double lowest_initial_height_ = 0.0;
  int threads_ = 1;
  // Jacobian pattern: pair index of every spring, per group (built on first use).
  mutable std::vector<std::pair<int, int>> pairs_;
  mutable std::vector<std::vector<int>> pair_of_spring_;
  std::unique_ptr<BodyPhysics> physics_;  // last: made for this world, after its parts
};

}  // namespace jelly
