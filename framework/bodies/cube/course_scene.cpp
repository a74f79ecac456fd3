// The course's 2023 cube scene built in code (jelly/scene.hpp, course_2023_scene): for tests and
// benchmarks that must not depend on scene files, and for the viewer when the file is missing.
#include "jelly/cube_scene.hpp"
#include "jelly/scene.hpp"

namespace jelly {

SceneSpec course_2023_scene() {
  SceneSpec s;
  s.name = "course-2023";
  s.description =
      "A jelly cube falls onto a floor with a hole and tips into the bowl below (course 2023).";
  s.integrator = IntegratorKind::SymplecticEuler;
  s.dt = 0.001;
  s.duration = 10.0;
  s.gravity = Vec3(0.0, -9.8, 0.0);
  s.body_kind = kCubeKind;
  cube_spec(s).center = Vec3(-4.8, 11.0, 0.0);
  s.structural = {true, 2000.0, 60.0};
  s.shear = {true, 2000.0, 60.0};
  s.bending = {true, 2000.0, 60.0};
  s.terrains = {*terrain_preset("course-2023-floor"), *terrain_preset("course-2023-bowl")};
  return s;
}

}  // namespace jelly
