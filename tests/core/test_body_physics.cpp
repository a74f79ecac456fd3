// The World and the Simulator ask the world's BodyPhysics (jelly/body_physics.hpp) for what
// differs between body kinds, and name no kind: a physics made here (a point that falls at
// 1 m/s², with work done on it from outside) is all a step uses.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <typeinfo>

#include "jelly/body_physics.hpp"
#include "jelly/simulator.hpp"
#include "jelly/terrain_physics.hpp"
#include "jelly/world.hpp"

namespace jelly {
namespace {

struct Calls {
  int acceleration = 0, collisions = 0, begin = 0, end = 0;
  long last_step = -1;
};

class FallingPoint final : public BodyPhysics {
 public:
  FallingPoint(World& world, Calls& calls) : BodyPhysics(world), calls_(calls) {}
  void acceleration(const State& s, Vec3Array& a) override {
    ++calls_.acceleration;
    a.resize(3, s.size());
    a.colwise() = Vec3(0.0, -1.0, 0.0);
  }
  void apply_collisions(State& s) override {
    (void)s;
    ++calls_.collisions;
  }
  void begin_step(long step, double h) override {
    (void)h;
    ++calls_.begin;
    calls_.last_step = step;
  }
  void end_step(double h) override {
    (void)h;
    ++calls_.end;
  }
  bool is_fixed(Eigen::Index i) const override { return i == 1; }
  double external_work() const override { return 2.0; }
  StabilityMonitor::Config detector_config(StabilityMonitor::Config config) const override {
    config.absolute_floor = 5.0;
    return config;
  }
  const char* refuses_terrain() const override { return "a falling point has no terrain"; }

 private:
  Calls& calls_;
};

std::unique_ptr<World> two_points() {
  auto world = std::make_unique<World>(TaskTable{});
  world->add_particles(Vec3Array::Zero(3, 2), Vec3Array::Zero(3, 2), 1.0);
  return world;
}

TEST(BodyPhysics, AStepIsWhatTheWorldsPhysicsSays) {
  Calls calls;
  auto world = two_points();
  world->set_physics(std::make_unique<FallingPoint>(*world, calls));
  Simulator::Options options(IntegratorKind::SymplecticEuler, 0.5);
  options.detect_instability = false;
  Simulator sim(std::move(world), options);
  ASSERT_EQ(sim.step(), StepResult::Ok);
  ASSERT_EQ(sim.step(), StepResult::Ok);
  EXPECT_EQ(calls.begin, 2);
  EXPECT_EQ(calls.collisions, 2);
  EXPECT_EQ(calls.end, 2);
  EXPECT_EQ(calls.last_step, 1);
  EXPECT_EQ(calls.acceleration, 2);      // symplectic Euler: one evaluation a step
  EXPECT_EQ(sim.state().v(1, 0), -1.0);  // two steps of 0.5 s at 1 m/s²
  EXPECT_FALSE(sim.world().is_fixed(0));
  EXPECT_TRUE(sim.world().is_fixed(1));
  // The detector: its margin's floor and E − W are the physics'.
  EXPECT_EQ(sim.detector_config().absolute_floor, 5.0);
  EXPECT_EQ(sim.detector_energy(), sim.energy().total() - 2.0);
  EXPECT_THROW(sim.world().add_terrain(Terrain{}), std::logic_error);
}

TEST(BodyPhysics, TheDefaultIsParticlesOverTerrains) {
  auto world = two_points();
  EXPECT_EQ(typeid(world->physics()), typeid(TerrainPhysics));
  EXPECT_FALSE(world->is_fixed(0));
  EXPECT_EQ(world->physics().external_work(), 0.0);
  world->add_terrain(Terrain{});  // allowed
  EXPECT_EQ(world->terrains().size(), 1u);
}

TEST(BodyPhysics, AMovedWorldTakesItsPhysicsAlong) {
  Calls calls;
  World a(TaskTable{});
  a.add_particles(Vec3Array::Zero(3, 1), Vec3Array::Zero(3, 1), 1.0);
  a.set_physics(std::make_unique<FallingPoint>(a, calls));
  World b(std::move(a));
  EXPECT_TRUE(b.physics().made_for(b));
  EXPECT_EQ(b.particle_count(), 1);
  Vec3Array acc;
  b.acceleration(b.state(), acc);
  EXPECT_EQ(calls.acceleration, 1);
  // The world moved from is empty, with the default physics of its own.
  EXPECT_TRUE(a.physics().made_for(a));
  EXPECT_EQ(typeid(a.physics()), typeid(TerrainPhysics));
  // A physics made for another world is refused.
  EXPECT_THROW(b.set_physics(std::make_unique<TerrainPhysics>(a)), std::logic_error);
}

}  // namespace
}  // namespace jelly
