// The informational course scene: ALL of the student's code together (their springs, forces,
// collision, contact and explicit Euler) on the 2023 course scene. Contact makes it chaotic, so the
// orchestrator checks outcomes (finite, where the jelly comes to rest, penetration, first-contact
// time) and the report plots the centre-of-mass height against the reference. It also records the
// particle positions at a few times (params.frame_times): outputs the orchestrator never grades
// nor stores as reference data, from which the report renders the student's run beside the
// reference's (docs/grader.md, "Frames").
#include <cmath>

#include "cases.hpp"
#include "jelly/recorder.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"
#include "jelly/terrain_geometry.hpp"

namespace jelly::grade {

namespace {

// The course's scene (jelly::course_2023_scene: dt 1 ms, floor with hole, bowl, ks 2000 / kd 60),
// stepped with the student's explicit Euler instead of the file's symplectic Euler.
SceneSpec course_scene() {
  SceneSpec s = course_2023_scene();
  s.integrator = IntegratorKind::ExplicitEuler;
  return s;
}

void run_course(const TaskTable& tasks, const Params& params, Outputs& out) {
  const SceneSpec spec = course_scene();
  Simulator::Options o;
  o.integrator = spec.integrator;
  o.dt = spec.dt;
  o.detect_instability = true;
  Simulator sim(build_world(spec, tasks), o);
  std::vector<double> t, cy, cx, cz;
  double first_contact = -1.0, max_penetration = 0.0;
  const double duration = params.number("duration");
  const long every = params.integer("sample_every");
  const double window = params.number("mean_window");
  const long steps = std::lround(duration / spec.dt);
  // Frames for the report: positions at the first step at or after each requested time [s].
  const std::vector<double> frame_at =
      params.has("frame_times") ? params.numbers("frame_times") : std::vector<double>{};
  std::vector<double> frame_times, frame_positions;
  std::size_t next_frame = 0;
  const auto record_frames = [&]() {
    for (; next_frame < frame_at.size() && sim.time() + 0.5 * spec.dt >= frame_at[next_frame];
         ++next_frame) {
      const Vec3Array& x = sim.state().x;
      frame_times.push_back(sim.time());
      frame_positions.insert(frame_positions.end(), x.data(), x.data() + x.size());
    }
  };
  record_frames();
  for (long k = 1; k <= steps; ++k) {
    if (sim.step() != StepResult::Ok) break;
    record_frames();
    const State& s = sim.state();
    if (first_contact < 0.0) {
      long hits = 0;
      for (long c : sim.world().counters().collisions) hits += c;
      for (long c : sim.world().counters().contacts) hits += c;
      if (hits > 0) first_contact = sim.time();
    }
    if (k % every == 0) {
      const Vec3 com = s.x.rowwise().mean();
      t.push_back(sim.time());
      cx.push_back(com.x());
      cy.push_back(com.y());
      cz.push_back(com.z());
      // Penetration: depth behind the floor outside the hole, or behind the bowl's wall.
      for (Eigen::Index i = 0; i < s.size(); ++i)
        for (const Terrain& tr : sim.world().terrains())
          if (in_extent(tr, s.x.col(i)))
            max_penetration = std::max(max_penetration, -signed_distance(tr, s.x.col(i)));
    }
  }
  const bool unstable = sim.instability().has_value();
  // Mean centre of mass over the last 5 s: the jelly still sloshes in the bowl at 10 s, and a
  // mean is far less sensitive to the chaos of contact than one instant.
  Vec3 mean = Vec3::Zero();
  int count = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] > duration - window + 1e-9) mean += Vec3(cx[i], cy[i], cz[i]), ++count;
  if (count > 0) mean /= count;
  const Bowl bowl = std::get<Bowl>(terrain_preset("course-2023-bowl")->shape);
  const double axis = std::hypot(mean.x() - bowl.center.x(), mean.z() - bowl.center.z());
  const bool in_bowl = axis < bowl.rim_radius() && mean.y() < bowl.rim_height + 2.0;
  const Vec3 com = sim.state().x.rowwise().mean();
  out.value("finished", unstable ? 0.0 : 1.0,
            "the run reached 10 s without the stability detector firing (1 yes)");
  out.values("com_time", t, "times of the centre-of-mass samples [s]");
  out.values("com_y", cy, "centre-of-mass height every 50 ms [m]");
  out.values("com_x", cx, "centre-of-mass x every 50 ms [m]");
  out.values("com_z", cz, "centre-of-mass z every 50 ms [m]");
  out.vec("mean_com_last_5s", mean,
          "mean centre of mass over the last 5 s (where the jelly settles) [m]");
  out.value("in_bowl", in_bowl ? 1.0 : 0.0, "the jelly ends up in the bowl (1 yes)");
  out.vec("final_com", com, "centre of mass at t = 10 s [m]");
  out.value("first_contact_time", first_contact, "time of the first collision or contact [s]");
  out.value("max_penetration", max_penetration,
            "deepest any particle went behind the floor or the bowl's wall [m]");
  out.value("final_kinetic_energy", sim.energy().kinetic, "kinetic energy at t = 10 s [J]");
  if (!frame_at.empty()) {
    out.values("frame_times", frame_times,
               "times of the recorded frames [s] (for the report, not graded)");
    out.values("frame_positions", frame_positions,
               "every particle's x, y, z at each recorded frame, frame after frame [m] (for the "
               "report, not graded)");
  }
}

}  // namespace

// course_scene: params.duration [s], centre of mass sampled every params.sample_every steps, its
// mean over the last params.mean_window seconds; positions recorded at params.frame_times [s]
// (optional).
void register_scene_cases(Registry& r) {
  r.add({"course_scene", "the 2023 course scene with all of the student's code (explicit Euler)",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_course(t, p, o);
         }});
}

}  // namespace jelly::grade
