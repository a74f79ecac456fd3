// `jelly run` of a skeleton scene: every output frame's posture (the motion's, the warp's or the
// blend's) through the SkeletonTasks slots, its forward kinematics, and one `--summary` row per
// frame and bone (docs/skeleton-scenes.md). What a task returns is checked before it is used, so
// a wrong answer is an error naming the task, never a crash.
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "jelly/recorder.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "param_table.hpp"
#include "skeleton_play.hpp"

namespace jelly::bodies {

namespace {

using params_detail::format_double;
using skeleton::BoneFrames;
using skeleton::Motion;
using skeleton::Posture;

/// Throws when `slot` is null: what the scene needs, which task slot, what it computes.
template <class Slot>
void require(Slot slot, const char* name, const char* what, const TaskTable& tasks,
             const SceneSpec& scene) {
  if (slot) return;
  const std::string origin = tasks.origin.empty() ? "none linked" : std::string(tasks.origin);
  throw std::runtime_error(
      "a skeleton " + std::string(skeleton_mode_name(skeleton_scene(scene).mode)) +
      " needs the task " + name + " (" + what + "), and this program's tasks (" + origin +
      ") do not fill it: SkeletonTasks::" + name + " is null");
}

void require_slots(const SceneSpec& scene, const TaskTable& tasks) {
  const SkeletonTasks& t = skeleton_tasks(tasks);
  require(t.forward_kinematics, "forward_kinematics", "forward kinematics, kinematics contract §4",
          tasks, scene);
  const SkeletonMode mode = skeleton_scene(scene).mode;
  if (mode == SkeletonMode::Warp) {
    require(t.time_map, "time_map", "the time map s(i), kinematics contract §5", tasks, scene);
    require(t.warped_posture, "warped_posture", "the warped posture, kinematics contract §5", tasks,
            scene);
  }
  if (mode == SkeletonMode::Blend)
    require(t.blend_motions, "blend_motions", "the motion blend, kinematics contract §5", tasks,
            scene);
}

void check_posture(const char* task, int frame, const Posture& p, std::size_t bones) {
  if (p.angles.size() != bones)
    task_error(task, frame,
               "returned a posture of " + std::to_string(p.angles.size()) +
                   " angle triples; the skeleton has " + std::to_string(bones) + " bones");
}

/// The posture of each output frame, from the scene's mode and the tasks.
class Postures {
 public:
  Postures(const SceneSpec& scene, const SkeletonInputs& in, const SkeletonTasks& tasks)
      : in_(in), tasks_(tasks), mode_(skeleton_scene(scene).mode) {
    const SkeletonSceneSpec& k = skeleton_scene(scene);
    warp_.input_frames = static_cast<int>(in.motion.frames.size());
    warp_.output_frames = skeleton_output_frames(scene, in);
    warp_.keyframe_in = static_cast<int>(k.keyframe_in);
    warp_.keyframe_out = static_cast<int>(k.keyframe_out);
    if (mode_ == SkeletonMode::Blend) {
      const skeleton::Blend blend{static_cast<int>(k.a), static_cast<int>(k.b),
                                  static_cast<int>(k.window)};
      tasks.blend_motions(in.skeleton, in.motion, in.motion_b, blend, blended_);
    }
  }

  int count() const {
    if (mode_ == SkeletonMode::Warp) return warp_.output_frames;
    if (mode_ == SkeletonMode::Blend) return static_cast<int>(blended_.frames.size());
    return static_cast<int>(in_.motion.frames.size());
  }

  const Posture& at(int i) {
    const std::size_t bones = in_.skeleton.bones.size();
    if (mode_ == SkeletonMode::Playback) return in_.motion.frames[i];
    if (mode_ == SkeletonMode::Blend) {
      check_posture("blend_motions", i, blended_.frames[i], bones);
      return blended_.frames[i];
    }
    const double s = tasks_.time_map(i, warp_);
    const double last = warp_.input_frames - 1;
    if (!(s >= 0.0 && s <= last))
      task_error(
          "time_map", i,
          "returned s = " + format_double(s) + "; expected 0 ≤ s ≤ N − 1 = " + format_double(last));
    warped_ = Posture::zero(bones);
    tasks_.warped_posture(in_.skeleton, in_.motion, s, warped_);
    check_posture("warped_posture", i, warped_, bones);
    return warped_;
  }

 private:
  const SkeletonInputs& in_;
  const SkeletonTasks& tasks_;
  SkeletonMode mode_;
  skeleton::TimeWarp warp_;
  Motion blended_;
  Posture warped_;
};

std::string what_plays(const SceneSpec& scene, const SkeletonInputs& in, int frames) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  if (k.mode == SkeletonMode::Warp)
    return text_printf("a warp of %s, %zu -> %d frames", in.amc_file.c_str(),
                       in.motion.frames.size(), frames);
  if (k.mode == SkeletonMode::Blend)
    return text_printf("a blend of %s into %s", in.amc_file.c_str(), in.amc_b_file.c_str());
  return "the motion " + in.amc_file;
}

}  // namespace

void task_error(const char* task, int frame, const std::string& what) {
  throw std::runtime_error("task " + std::string(task) + ", output frame " + std::to_string(frame) +
                           ": " + what);
}

void checked_forward_kinematics(const SkeletonTasks& tasks, const SkeletonInputs& in,
                                const Posture& p, int frame, BoneFrames& out) {
  tasks.forward_kinematics(in.skeleton, p, out);
  const std::size_t bones = in.skeleton.bones.size();
  if (out.rotation.size() != bones || out.start.size() != bones || out.end.size() != bones)
    task_error("forward_kinematics", frame,
               "returned " + std::to_string(out.start.size()) + " starts, " +
                   std::to_string(out.end.size()) + " ends and " +
                   std::to_string(out.rotation.size()) + " rotations; the skeleton has " +
                   std::to_string(bones) + " bones");
}

long write_skeleton_frame(CsvWriter& out, int frame, const SkeletonInputs& in, const Posture& p,
                          const BoneFrames& f, bool quaternions) {
  std::vector<std::variant<double, std::string>> cells;
  for (std::size_t b = 0; b < in.skeleton.bones.size(); ++b) {
    cells.assign({static_cast<double>(frame), static_cast<double>(b), in.skeleton.bones[b].name});
    for (const Vec3* v : {&f.start[b], &f.end[b]})
      for (int d = 0; d < 3; ++d) cells.emplace_back((*v)[d]);
    if (quaternions) {
      const skeleton::Quaternion q = skeleton::euler_to_quaternion(p.angles[b]);
      for (double c : {q.w(), q.x(), q.y(), q.z()}) cells.emplace_back(c);
    }
    out.write_cells(cells);
  }
  return static_cast<long>(in.skeleton.bones.size());
}

std::unique_ptr<CsvWriter> open_skeleton_summary(const std::string& path,
                                                 const std::string& header) {
  if (path.empty()) return nullptr;
  try {
    return std::make_unique<CsvWriter>(path, header);
  } catch (const std::runtime_error& e) {  // an output, not the input: BodyKindModule::play
    throw std::system_error(std::make_error_code(std::errc::io_error), e.what());
  }
}

std::string play_skeleton_scene(const SceneSpec& scene, const TaskTable& tasks,
                                const FramePlayOptions& options) {
  if (skeleton_scene(scene).mode == SkeletonMode::Ik) return play_ik_scene(scene, tasks, options);
  require_slots(scene, tasks);
  const SkeletonInputs in = read_skeleton_inputs(scene);
  const SkeletonTasks& slots = skeleton_tasks(tasks);
  Postures postures(scene, in, slots);
  const bool quaternions = skeleton_scene(scene).mode != SkeletonMode::Playback;
  const std::unique_ptr<CsvWriter> summary =
      open_skeleton_summary(options.summary_path, std::string(kSkeletonSummaryColumns) +
                                                      (quaternions ? ",qw,qx,qy,qz" : ""));
  const long every = std::max(1L, options.every);
  // simulation.duration: the frames i with i / fps ≤ duration (all of them by default).
  const double fps = skeleton_scene(scene).fps;
  int played = 0;
  long rows = 0;
  BoneFrames frames;
  for (int i = 0; i < postures.count() && static_cast<double>(i) <= scene.duration * fps; ++i) {
    const Posture& p = postures.at(i);
    checked_forward_kinematics(slots, in, p, i, frames);
    if (summary && i % every == 0)
      rows += write_skeleton_frame(*summary, i, in, p, frames, quaternions);
    ++played;
  }
  std::string report =
      text_printf("%s: played %d of %d frames of %s (%zu bones) at %g fps\n", scene.name.c_str(),
                  played, postures.count(), what_plays(scene, in, postures.count()).c_str(),
                  in.skeleton.bones.size(), fps);
  if (summary) {
    summary->flush();
    report += text_printf("  wrote %ld summary rows to %s\n", rows, options.summary_path.c_str());
  }
  return report;
}

}  // namespace jelly::bodies
