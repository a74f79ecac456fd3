// Scenes built in code for tests that must not depend on the scene files or the loader.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "jelly/scene.hpp"

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

/// Test-name generator for suites parameterised by integrator ("rk4", "midpoint", ...).
inline std::string integrator_param_name(const ::testing::TestParamInfo<IntegratorKind>& p) {
  return std::string(to_string(p.param));
}

}  // namespace jelly::testing
