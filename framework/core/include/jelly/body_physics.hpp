// What a step does that differs between kinds of body (docs/architecture.md "Bodies"): a World
// holds one BodyPhysics, and the World and the Simulator ask it instead of testing which kind the
// world holds. A body kind that brings physics of its own (framework/bodies/<kind>/) installs it
// when it builds its world; every other world has the default, TerrainPhysics
// (jelly/terrain_physics.hpp): particles of mass m over terrains.
#pragma once

#include <vector>

#include "jelly/stability.hpp"
#include "jelly/types.hpp"

namespace jelly {

class World;
struct EffectCounters;
struct SpringGroup;

/// The physics of a world's body kind, with the state only that kind has. Made for one World and
/// owned by it (a World that moves takes its physics along and tells it).
class BodyPhysics {
 public:
  explicit BodyPhysics(World& world) : world_(&world) {}
  virtual ~BodyPhysics() = default;
  BodyPhysics(const BodyPhysics&) = delete;
  BodyPhysics& operator=(const BodyPhysics&) = delete;

  /// a(s) of every particle (the World's System::acceleration).
  virtual void acceleration(const State& s, Vec3Array& a) = 0;
  /// Step 1 of a step (contract §6): the collision response; changes `s.v` (and `s.x` where the
  /// kind's contract moves particles).
  virtual void apply_collisions(State& s) = 0;
  /// Before step `step` of size h, and after its integrator: whatever the kind moves itself.
  virtual void begin_step(long step, double h) {
    (void)step;
    (void)h;
  }
  virtual void end_step(double h) { (void)h; }
  /// Whether particle i is held fixed (JacobianSystem::is_fixed). None by default.
  virtual bool is_fixed(Eigen::Index i) const {
    (void)i;
    return false;
  }
  /// Work done on the system from outside it so far [J]; the stability detector compares the
  /// energy less this with the energy at the start. 0 by default.
  virtual double external_work() const { return 0.0; }
  /// The detector's settings for this world, from the ones a run asks for. Those by default.
  virtual StabilityMonitor::Config detector_config(StabilityMonitor::Config config) const {
    return config;
  }
  /// Zeroes the kind's own effect counters, when the World zeroes its EffectCounters.
  virtual void reset_counters() {}
  /// Why the world may not get a terrain; nullptr when it may.
  virtual const char* refuses_terrain() const { return nullptr; }
  /// Whether this physics was made for `world`.
  bool made_for(const World& world) const { return world_ == &world; }

 protected:
  /// The World's parts a kind's physics works on (World befriends BodyPhysics only).
  World& world() const { return *world_; }
  static Vec3Array& force_scratch(World& world);
  static EffectCounters& counters(World& world);
  static Eigen::VectorXd& inverse_masses(World& world);
  static std::vector<SpringGroup>& spring_groups(World& world);
  /// Tells the task library's spring engine that springs of a group were taken out.
  static void springs_changed(World& world);
  /// Adds the forces of every spring group to f and counts them: in one call when the task
  /// library offers a spring engine, else group by group.
  static void add_spring_forces(World& world, const State& s, Vec3Array& f);

 private:
  friend class World;  // a World that moves sets world_ to itself
  World* world_;
};

}  // namespace jelly
