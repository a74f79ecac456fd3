// The physics of a cloth world (assignment A2, cloth contract §1–§5): cloths with pins, spheres,
// the accelerations a = g + w·Σf and the impulse response at the start of every step. The cloth
// kind (cloth_kind.cpp) installs it when it builds a world; code that builds or reads a cloth world
// reaches it through cloth_physics(world).
#pragma once

#include <cstdint>
#include <vector>

#include "jelly/body_physics.hpp"
#include "jelly/cloth.hpp"
#include "jelly/spheres.hpp"
#include "jelly/spring.hpp"

namespace jelly {

class World;

/// How often each of the cloth's own effects ran (the World's EffectCounters count the rest, the
/// impulses included): tests use them to prove that only what a scene calls for is simulated.
struct ClothCounters {
  std::int64_t drag_applications = 0;      ///< evaluations that added air drag
  std::int64_t sphere_pair_tests = 0;      ///< sphere–sphere pairs examined
  std::int64_t particle_sphere_tests = 0;  ///< particle–sphere pairs examined
  std::int64_t friction_impulses = 0;      ///< calls of the friction task
  std::int64_t push_outs = 0;              ///< particles moved by push-out
};

class ClothPhysics : public BodyPhysics {
 public:
  using BodyPhysics::BodyPhysics;

  // ----- building (before the first step) -----
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

  // ----- while it runs -----
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
  /// Whether particle `particle` of the world has inverse mass 0 (false outside the world).
  bool is_pinned(int particle) const;

  // ----- queries -----
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
  /// The cloth's own effects since the world's counters were last zeroed.
  const ClothCounters& cloth_counters() const { return cloth_counters_; }

  // ----- the BodyPhysics interface -----
  /// a = g + w·Σf, Σf the springs and the cloth's air drag; exactly 0 for w = 0 (decision 3).
  void acceleration(const State& s, Vec3Array& a) override;
  /// The impulse response of cloth contract §4: sphere–sphere pairs, then every cloth particle
  /// against each sphere (then push-out).
  void apply_collisions(State& s) override;
  /// Before step n (cloth contract §5): every kinematic sphere takes its velocity u(t_n),
  /// t_n = n·h, from its schedule (or from drive_sphere()). No-op without kinematic spheres.
  void begin_step(long step, double h) override;
  /// After the integrator (step 3): every kinematic sphere moves by h·u(t_n).
  void end_step(double h) override;
  /// Pinned cloth particles (inverse mass 0) are fixed.
  bool is_fixed(Eigen::Index i) const override;
  /// The kinematic spheres' work (decision 11): the detector compares E − W with E(0).
  double external_work() const override { return kinematic_work_; }
  /// The floor of the detector's margin is 1e-3·Σm·|g|·L (decision 11: Σm over the cloth and the
  /// dynamic spheres, L the cloth's side).
  StabilityMonitor::Config detector_config(StabilityMonitor::Config config) const override;
  /// A cloth world has no terrain (cloth contract §6).
  const char* refuses_terrain() const override;
  void reset_counters() override { cloth_counters_ = ClothCounters{}; }

 private:
  struct SphereSlot {
    SphereSpec spec;
    int particle = -1;             // state column of a dynamic sphere
    Vec3 center{0.0, 0.0, 0.0};    // a kinematic sphere's centre
    Vec3 velocity{0.0, 0.0, 0.0};  // a kinematic sphere's u(t_n)
    bool driven = false;           // drive_sphere() replaced the schedule
  };
  SphereBody sphere_body(const State& s, std::size_t i) const;
  void store_sphere_velocity(State& s, std::size_t i, const Vec3& velocity);
  // apply_collisions' steps: sphere pairs, then each sphere against the cloth's particles.
  struct CollisionPass;
  void collide_sphere_pairs(State& s, const CollisionPass& pass);
  void collide_cloth_with_sphere(State& s, std::size_t k, const CollisionPass& pass);
  void collide_particle_sphere(State& s, Eigen::Index i, std::size_t k, SphereBody& sphere,
                               const ImpulseSettings& settings, const CollisionPass& pass);
  void push_out_particle(State& s, Eigen::Index i, const SphereBody& sphere,
                         const CollisionPass& pass);

  std::vector<ClothGrid> cloths_;
  std::vector<SphereSlot> spheres_;
  ClothCollisionSettings collisions_;
  Eigen::Index cloth_particles_ = 0;
  double air_drag_ = 0.0;
  double kinematic_work_ = 0.0;
  ClothCounters cloth_counters_;
};

/// The cloth physics of `world`, installed in place of the default on a world that holds nothing
/// yet. Throws std::logic_error for a world that holds particles, terrains or another kind's
/// physics (a cloth world holds cloths and spheres only).
ClothPhysics& cloth_physics(World& world);
/// The cloth physics of `world` to read; a world without it reads as one with no cloth and no
/// sphere (an empty cloth physics).
const ClothPhysics& cloth_physics(const World& world);
/// The cloth physics of `world`, or nullptr when it is not a cloth world.
ClothPhysics* find_cloth_physics(World& world);
const ClothPhysics* find_cloth_physics(const World& world);

}  // namespace jelly
