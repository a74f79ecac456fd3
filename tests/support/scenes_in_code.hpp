// Scenes built in code for tests that must not depend on the scene files or the loader.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "jelly/a1/task_table.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"
#include "jelly/test_systems.hpp"

namespace jelly::testing {

/// The course's 2023 scene (contract §9, course-anchor): n = 10 cube at (−4.8, 11, 0), ks 2000 /
/// kd 60 on every spring type, gravity, the floor with its hole then the bowl, h = 0.001.
inline SceneSpec course_2023(IntegratorKind integrator = IntegratorKind::ExplicitEuler,
                             double dt = 0.001) {
  SceneSpec s = course_2023_scene();
  s.integrator = integrator;
  s.dt = dt;
  return s;
}

/// The course cube in free fall: gravity, all springs, no terrain.
inline SceneSpec free_fall(IntegratorKind integrator = IntegratorKind::ExplicitEuler) {
  SceneSpec s = course_2023(integrator);
  s.terrains.clear();
  return s;
}

/// The two-particle spring whose exact solution TwoParticleSpring knows (contract §9): unit masses,
/// rest length 1 stretched by 0.1, no damping, no gravity, no terrain; step h.
inline SceneSpec two_particle_spring(IntegratorKind kind, double h) {
  SceneSpec s;
  s.integrator = kind;
  s.dt = h;
  s.body_kind = kParticlesKind;
  const State init = TwoParticleSpring::initial_state(0.1);
  particles_scene(s).positions = init.x;
  particles_scene(s).velocities = init.v;
  particles_scene(s).mass = 1.0;
  particles_scene(s).springs.push_back({0, 1, 1.0});
  s.structural = {true, TwoParticleSpring::kStiffness, 0.0};
  return s;  // no gravity, no terrain
}

/// The largest particle position error of the two-particle spring after 1 s at step h (the
/// detector off: explicit Euler and midpoint grow on an undamped spring).
inline double error_at_one_second(IntegratorKind kind, double h) {
  Simulator::Options o{kind, h};
  o.detect_instability = false;
  Simulator sim(build_world(two_particle_spring(kind, h), a1::task_table()), o);
  sim.run_until(1.0);
  const double x1 = TwoParticleSpring::exact_x1(1.0);
  const State& s = sim.state();
  return std::max((s.x.col(1) - Vec3(x1, 0, 0)).norm(), (s.x.col(0) - Vec3(-x1, 0, 0)).norm());
}

/// Test-name generator for suites parameterised by integrator ("rk4", "midpoint", ...).
inline std::string integrator_param_name(const ::testing::TestParamInfo<IntegratorKind>& p) {
  return std::string(to_string(p.param));
}

}  // namespace jelly::testing
