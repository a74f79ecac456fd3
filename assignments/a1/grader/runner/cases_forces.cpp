// A1.T4–T5 cases: spring_force and damper_force on hand-made springs (the mass_spring module's
// slot-level cases, grader/runner/mass_spring_cases.cpp), and a small cube whose springs come from
// the REFERENCE (stored in the case input), moved by the framework's symplectic Euler. The spring
// scene has kd = 0 and the damper scene ks = 0, so each scene exercises one task.
#include <cstdint>
#include <cstdio>
#include <string>

#include "cases.hpp"
#include "jelly/integrator.hpp"
#include "jelly/world.hpp"
#include "mass_spring_cases.hpp"

namespace jelly::grade {

namespace {

// A prepared cube (params.cube, reference springs) with ks = params.ks and kd = params.kd,
// stretched about its centre by params.stretch, jittered by params.jitter·U and given velocities
// params.speed·U (U uniform in [−1, 1) from params.seed), then stepped params.steps times by
// params.h with the framework's symplectic Euler; positions every params.sample_every steps.
void run_cube_scene(const TaskTable& tasks, const Params& params, const Json& input, Outputs& out) {
  World world(tasks);
  add_prepared_cube(world, params, input, params.number("ks"), params.number("kd"));
  State& s = world.state();
  Sequence r(static_cast<std::uint64_t>(params.integer("seed")));
  const double stretch = params.number("stretch"), jitter = params.number("jitter"),
               speed = params.number("speed");
  const double h = params.number("h");
  const long steps = params.integer("steps"), every = params.integer("sample_every");
  const Vec3 c = s.x.rowwise().mean();
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    s.x.col(i) = c + stretch * (s.x.col(i) - c) + jitter * r.next3();
    s.v.col(i) = speed * r.next3();
  }
  Workspace w;
  w.resize(s.size());
  char what[120];
  for (long step = 1; step <= steps; ++step) {
    symplectic_euler_step(world, s, h, w);
    if (step % every == 0) {
      std::snprintf(what, sizeof what, "positions of the %ld particles after %ld steps of %g s",
                    static_cast<long>(s.size()), step, h);
      out.array("x_step" + std::to_string(step), s.x,
                std::string(what) + " (framework symplectic Euler, your forces) [m]");
    }
  }
}

}  // namespace

// spring_force / damper_force: the mass_spring module's (mass_spring_cases.hpp); force_scene: see
// run_cube_scene.
void register_force_cases(Registry& r) {
  register_spring_force_cases(r);
  r.add({"force_scene",
         "a deformed, moving cube with the reference springs, your forces, framework integrator",
         &prepare_cube_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_cube_scene(t, p, in, o);
         }});
}

}  // namespace jelly::grade
