// The world: particles, the effects a scene asks for, and their evaluation (contract §6, §7).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jelly/cloth.hpp"
#include "jelly/cube.hpp"
#include "jelly/jacobian.hpp"
#include "jelly/spheres.hpp"
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
  // Cloth scenes (cloth contract §4, §5); all stay 0 in a scene without the effect.
  std::int64_t drag_applications = 0;      ///< evaluations that added air drag
  std::int64_t sphere_pair_tests = 0;      ///< sphere–sphere pairs examined
  std::int64_t particle_sphere_tests = 0;  ///< cloth particle–sphere pairs examined
  std::int64_t impulses = 0;               ///< normal impulses applied (both kinds of pair)
  std::int64_t friction_impulses = 0;      ///< calls of the friction task
  std::int64_t push_outs = 0;              ///< particles moved by push-out
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

  // ----- cloth scenes (assignment A2, cloth contract) -----
  /// Adds the particles of a cloth: pinned ones (resolve_pins) get inverse mass 0 and stay at
  /// rest, the others spec.velocity. Returns its index in cloths(). A world with a cloth
  /// evaluates a = g + w·Σf per particle (decision 3), and its drag is spec.air_drag.
  int add_cloth(const ClothSpec& spec);
  /// Builds the springs of `type` (Structural, Shear or Bending) of cloth `cloth` with the
  /// student's grid builder (through the task table) and adds them as a group.
  void build_cloth_springs(int cloth, SpringType type, double ks, double kd);
  /// Adds a sphere, after every cloth. A dynamic sphere is one more particle of the integrated
  /// state (mass from the spec, else 1000·r³; no drag); a kinematic one is not. Returns its index.
  int add_sphere(const SphereSpec& spec);
  /// The coefficients of cloth–sphere and sphere–sphere pairs (defaults: decision 10).
  void set_cloth_collisions(const ClothCollisionSettings& settings);
  /// Before step n (cloth contract §5): every kinematic sphere takes its velocity u(t_n),
  /// t_n = n·h, from its schedule (or from drive_sphere()). No-op without kinematic spheres.
  void begin_step(long step, double h);
  /// After the integrator (step 3): every kinematic sphere moves by h·u(t_n).
  void end_step(double h);
  /// From now on kinematic sphere `sphere` moves at `velocity`, its schedule ignored (the
  /// viewer's arrow keys). Throws std::out_of_range when it is not a kinematic sphere.
  void drive_sphere(int sphere, const Vec3& velocity);
  /// Puts kinematic sphere `sphere` at `center`, as recorded elsewhere (`jelly render --replay`
  /// draws a graded run's frames with it). Throws std::out_of_range when it is not a kinematic
  /// sphere.
  void place_sphere(int sphere, const Vec3& center);

  /// Pins (inverse mass 0, velocity 0 from now on) or frees (inverse mass 1/m) cloth particle
  /// `particle`: the viewer's keys 1–4 toggle the corners. Throws std::out_of_range for a
  /// particle that is not a cloth's.
  void set_pinned(int particle, bool pinned);
  bool is_pinned(int particle) const { return inv_mass_[particle] == 0.0; }

  const std::vector<ClothGrid>& cloths() const { return cloths_; }
  /// Number of spheres, dynamic and kinematic, in scene order.
  int sphere_count() const { return static_cast<int>(spheres_.size()); }
  /// Sphere `i` now: centre, velocity, radius and inverse mass (0 when kinematic).
  SphereBody sphere(int i) const;
  bool sphere_is_kinematic(int i) const;
  /// The state column of dynamic sphere `i`; −1 for a kinematic one.
  int sphere_particle(int i) const;
  /// Number of cloth particles (the state's first columns; dynamic spheres follow them).
  Eigen::Index cloth_particle_count() const { return cloth_particles_; }
  /// Work done on the system by kinematic spheres so far: the kinetic-energy change of their
  /// impulses (decision 11) [J].
  double kinematic_work() const { return kinematic_work_; }
  const ClothCollisionSettings& cloth_collisions() const { return collisions_; }

  // ----- the System interface -----
  void acceleration(const State& s, Vec3Array& a) override;
  Eigen::Index particle_count() const override { return state_.size(); }
  const Eigen::VectorXd& masses() const override { return mass_; }
  std::vector<std::pair<int, int>> jacobian_pattern() const override;
  void force_jacobians(const State& s, ForceJacobians& jac) override;
  /// Pinned cloth particles (inverse mass 0) are fixed; an A1 world has none.
  bool is_fixed(Eigen::Index i) const override { return inverse_mass_form_ && inv_mass_[i] == 0.0; }
  /// True for a world with a cloth: accelerations are a = g + w·Σf (cloth decision 3), the
  /// collision response is that of the cloth contract §4 and energy follows decision 11.
  bool has_cloth() const { return inverse_mass_form_; }

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
  // Cloth worlds (world_cloth.cpp).
  void cloth_acceleration(const State& s, Vec3Array& a);
  void apply_cloth_collisions(State& s);
  SphereBody sphere_body(const State& s, std::size_t i) const;
  void store_sphere_velocity(State& s, std::size_t i, const Vec3& velocity);
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
  // Cloth scenes.
  struct SphereSlot {
    SphereSpec spec;
    int particle = -1;             // state column of a dynamic sphere
    Vec3 center{0.0, 0.0, 0.0};    // a kinematic sphere's centre
    Vec3 velocity{0.0, 0.0, 0.0};  // a kinematic sphere's u(t_n)
    bool driven = false;           // drive_sphere() replaced the schedule
  };
  std::vector<ClothGrid> cloths_;
  std::vector<SphereSlot> spheres_;
  ClothCollisionSettings collisions_;
  Eigen::Index cloth_particles_ = 0;
  double air_drag_ = 0.0;
  double kinematic_work_ = 0.0;
  bool inverse_mass_form_ = false;  // a = g + w·Σf (cloth worlds); A1 worlds divide by m
};

}  // namespace jelly
