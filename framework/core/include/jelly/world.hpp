// The world: particles, the effects a scene asks for, and their evaluation (contract §6, §7).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jelly/cube.hpp"
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
};

/// Energy of a state (contract §8) [J].
struct Energy {
  double kinetic = 0.0;
  double gravitational = 0.0;  ///< measured from World::reference_height()
  double spring = 0.0;         ///< ½ ks (l − rest)² summed over springs
  double total() const { return kinetic + gravitational + spring; }
};

/// Particles, springs, terrains and gravity: only what the scene asked for exists (contract §7).
/// The World owns the current state and is the System the integrators advance.
class World : public JacobianSystem {
 public:
  explicit World(TaskTable tasks);

  // ----- building (before the first step) -----
  /// Adds the particles of a cube; returns its index in cubes(). Springs are added separately.
  int add_cube(const CubeSpec& spec);
  /// Adds free particles with the given positions, velocities and mass; returns the first index.
  int add_particles(const Vec3Array& positions, const Vec3Array& velocities, double mass);
  /// Builds the springs of `type` in cube `cube` with the student's builder (through the task
  /// table) and adds them as a group. ShearBody takes the body diagonals out of the shear builder's
  /// output (call it after Shear when the scene sets body diagonals apart).
  void build_cube_springs(int cube, SpringType type, double ks, double kd);
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

  /// Step 1 of contract §6: the velocity response of every terrain with collision on, in order
  /// (then its optional projection). Changes `s.v` (and `s.x` only for projecting terrains).
  void apply_collisions(State& s);

  // ----- state and queries -----
  State& state() { return state_; }
  const State& state() const { return state_; }
  const Eigen::VectorXd& inverse_masses() const { return inv_mass_; }
  const std::vector<SpringGroup>& spring_groups() const { return groups_; }
  const std::vector<Terrain>& terrains() const { return terrains_; }
  const std::optional<Vec3>& gravity() const { return gravity_; }
  const std::vector<CubeLattice>& cubes() const { return cubes_; }
  const TaskTable& tasks() const { return tasks_; }
  std::size_t spring_count() const;

  /// Height (along −g, or y without gravity) from which gravitational energy is measured: the
  /// lowest point of the scene's bounded terrains, else the lowest initial particle (contract §8;
  /// see docs/physics-decisions.md). Fixed when the first particles are added and terrains set.
  double reference_height() const;
  /// Kinetic, gravitational and spring energy of state s.
  Energy energy(const State& s) const;

  const EffectCounters& counters() const { return counters_; }
  void reset_counters();

 private:
  void contact_pass(const State& s, Vec3Array& f);
  void pattern_cache() const;

  TaskTable tasks_;
  std::unique_ptr<SpringGroupPass> spring_pass_;  // the task library's engine, if it has one
  State state_;
  Eigen::VectorXd mass_;
  Eigen::VectorXd inv_mass_;
  std::vector<CubeLattice> cubes_;
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
};

}  // namespace jelly
