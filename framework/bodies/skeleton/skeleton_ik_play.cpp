// `jelly run` and `jelly check` of an inverse-kinematics scene (body.mode = "ik", kinematics
// contract §6, §7, §11.16): the posture of one AMC frame, each chain solved in order through the
// SkeletonTasks slots (jelly/skeleton_ik.hpp), once or, with a schedule, once per output frame,
// warm-started; `--summary` writes the final postures with a comment line per solve
// (docs/skeleton-scenes.md).
#include <stdexcept>

#include "jelly/skeleton_ik.hpp"
#include "param_table.hpp"
#include "skeleton_play.hpp"

namespace jelly::bodies {

namespace {

using params_detail::format_double;
using skeleton::BoneFrames;
using skeleton::IkResult;
using skeleton::Posture;

bool has_schedule(const SceneSpec& scene) {
  for (const IkChainSpec& c : ik_chain_specs(scene))
    if (!c.schedule.empty()) return true;
  return false;
}

}  // namespace

Vec3 ik_target_at(const IkChainSpec& chain, double t) {
  if (chain.target) return *chain.target;
  const std::vector<ScheduleEntry>& s = chain.schedule;
  if (t <= s.front().time) return s.front().velocity;
  for (std::size_t k = 0; k + 1 < s.size(); ++k)
    if (t < s[k + 1].time) {
      const double w = (t - s[k].time) / (s[k + 1].time - s[k].time);
      return (1.0 - w) * s[k].velocity + w * s[k + 1].velocity;
    }
  return s.back().velocity;
}

skeleton::IkSettings ik_settings_of(const SkeletonSceneSpec& k) {
  skeleton::IkSettings s;
  s.step = k.step;
  s.epsilon = k.epsilon;
  s.max_iterations = static_cast<int>(k.max_iterations);
  s.limits = k.limits;
  s.restore = k.restore;
  return s;
}

namespace {

std::string vec_text(const Vec3& v) {
  return "(" + format_double(v.x()) + ", " + format_double(v.y()) + ", " + format_double(v.z()) +
         ")";
}

std::string chain_name(const IkChainSpec& c) { return c.start + " -> " + c.end; }

std::string solve_comment(const SceneSpec& scene, const IkSceneSolve& s) {
  return text_printf("# frame %d chain %zu %s: target %s, updates %d, stable %s, error %s", s.frame,
                     s.chain, chain_name(ik_chain_specs(scene)[s.chain]).c_str(),
                     vec_text(s.target).c_str(), s.result.updates,
                     s.result.stable ? "true" : "false", format_double(s.result.error).c_str());
}

std::string summary_header(const SceneSpec& scene, const IkSceneRun& run) {
  std::string header;
  for (const IkSceneSolve& s : run.solves) header += solve_comment(scene, s) + "\n";
  return header + kSkeletonSummaryColumns;
}

/// The report's line of chain `c`: its one solve, or its solves over the schedule's frames.
std::string chain_line(const SceneSpec& scene, const IkSceneRun& run, std::size_t c) {
  int solves = 0, stable = 0;
  long updates = 0;
  const IkSceneSolve* last = nullptr;
  for (const IkSceneSolve& s : run.solves) {
    if (s.chain != c) continue;
    ++solves;
    stable += s.result.stable ? 1 : 0;
    updates += s.result.updates;
    last = &s;
  }
  const std::string name = chain_name(ik_chain_specs(scene)[c]);
  const std::string outcome = text_printf("%d updates, %s, error %s", last->result.updates,
                                          last->result.stable ? "stable" : "not stable",
                                          format_double(last->result.error).c_str());
  if (solves == 1) return text_printf("  chain %zu %s: %s\n", c, name.c_str(), outcome.c_str());
  return text_printf("  chain %zu %s: %d solves, %ld updates, %d stable; the last: %s\n", c,
                     name.c_str(), solves, updates, stable, outcome.c_str());
}

}  // namespace

std::string ik_solve_where(int frame, std::size_t c, const IkChainSpec& chain) {
  return text_printf("output frame %d, chain %zu (%s)", frame, c, chain_name(chain).c_str());
}

IkSceneRun run_ik_scene(const SceneSpec& scene, const SkeletonInputs& in,
                        const SkeletonTasks& tasks, bool record_errors) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  const std::vector<IkChainSpec>& chains = ik_chain_specs(scene);
  IkSceneRun run;
  Posture posture = in.motion.frames[static_cast<std::size_t>(k.frame)];
  const long long frames = ik_solved_frames(scene);
  for (int i = 0; i < frames; ++i) {
    for (std::size_t c = 0; c < chains.size(); ++c) {
      IkSolveRequest request;
      request.start_bone = *in.skeleton.find(chains[c].start);
      request.end_bone = *in.skeleton.find(chains[c].end);
      request.target = ik_target_at(chains[c], static_cast<double>(i) / k.fps);
      request.settings = ik_settings_of(k);
      request.where = ik_solve_where(i, c, chains[c]);
      IkSceneSolve solve{i, c, request.target, {}, {}};
      if (record_errors) request.errors = &solve.errors;
      solve.result = solve_ik(in.skeleton, tasks, request, posture);
      run.solves.push_back(std::move(solve));
    }
    run.postures.push_back(posture);
  }
  return run;
}

IkSceneRun ik_solved_run(const SceneSpec& scene, const SkeletonInputs& in,
                         const SkeletonTasks& tasks) {
  const std::string slot = missing_ik_slot(tasks);
  if (!slot.empty())
    throw std::runtime_error("skeleton inverse kinematics needs the task " + slot +
                             " (kinematics contract §6): SkeletonTasks::" + slot + " is null");
  return run_ik_scene(scene, in, tasks, true);
}

long long ik_solved_frames(const SceneSpec& scene) {
  if (!has_schedule(scene)) return 1;
  const double last = scene.duration * skeleton_scene(scene).fps;
  long long n = 0;
  while (static_cast<double>(n) <= last) ++n;
  return n;
}

std::string ik_check_lines(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  std::string out = text_printf(
      "  inverse kinematics from frame %lld: step %g, epsilon %g, max_iterations %lld, limits %s, "
      "restore %s; %lld solved frames\n",
      k.frame, k.step, k.epsilon, k.max_iterations, k.limits ? "on" : "off",
      k.restore ? "on" : "off", ik_solved_frames(scene));
  const std::vector<IkChainSpec>& chains = ik_chain_specs(scene);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    const std::string target =
        chains[c].target ? "target " + vec_text(*chains[c].target)
                         : text_printf("a schedule of %zu targets", chains[c].schedule.size());
    out += text_printf("  chain %zu %s (bones %d -> %d): %s\n", c, chain_name(chains[c]).c_str(),
                       *in.skeleton.find(chains[c].start), *in.skeleton.find(chains[c].end),
                       target.c_str());
  }
  return out;
}

std::string play_ik_scene(const SceneSpec& scene, const TaskTable& tasks,
                          const FramePlayOptions& options) {
  const SkeletonTasks& slots = skeleton_tasks(tasks);
  if (const std::string slot = missing_ik_slot(slots); !slot.empty()) {
    const std::string origin = tasks.origin.empty() ? "none linked" : std::string(tasks.origin);
    throw std::runtime_error("skeleton inverse kinematics needs the task " + slot +
                             " (kinematics contract §6), and this program's tasks (" + origin +
                             ") do not fill it: SkeletonTasks::" + slot + " is null");
  }
  const SkeletonInputs in = read_skeleton_inputs(scene);
  const IkSceneRun run = run_ik_scene(scene, in, slots, false);
  const std::unique_ptr<CsvWriter> summary =
      open_skeleton_summary(options.summary_path, summary_header(scene, run));
  const long every = std::max(1L, options.every);
  long rows = 0;
  BoneFrames frames;
  for (std::size_t i = 0; i < run.postures.size(); ++i) {
    const int frame = static_cast<int>(i);
    checked_forward_kinematics(slots, in, run.postures[i], frame, frames);
    if (summary && frame % every == 0)
      rows += write_skeleton_frame(*summary, frame, in, run.postures[i], frames, false);
  }
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  std::string report =
      text_printf("%s: solved %s over %s from frame %lld of %s (%zu bones) at %g fps\n",
                  scene.name.c_str(), counted(ik_chain_specs(scene).size(), "chain").c_str(),
                  counted(run.postures.size(), "frame").c_str(), k.frame, in.amc_file.c_str(),
                  in.skeleton.bones.size(), k.fps);
  for (std::size_t c = 0; c < ik_chain_specs(scene).size(); ++c)
    report += chain_line(scene, run, c);
  if (summary) {
    summary->flush();
    report += text_printf("  wrote %ld summary rows to %s\n", rows, options.summary_path.c_str());
  }
  return report;
}

}  // namespace jelly::bodies
