// Internal to the skeleton kind: what `jelly check` and `jelly run` do with a skeleton scene
// (docs/skeleton-scenes.md). The files a scene names are read and its arguments checked against
// them (kinematics contract §5); a run then plays every output frame through the SkeletonTasks
// slots.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/recorder.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_scene.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly::bodies {

/// "1 chain", "4 chains": a count with its noun, plural unless the count is 1 (messages, reports).
inline std::string counted(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// The files of a skeleton scene, read, with their names as messages give them.
struct SkeletonInputs {
  skeleton::Skeleton skeleton;
  skeleton::Motion motion;    ///< body.amc (motion A of a blend)
  skeleton::Motion motion_b;  ///< body.amc_b (a blend only)
  std::string asf_file, amc_file, amc_b_file;
  std::vector<std::string> notes;  ///< "file:line: what was skipped" (docs/skeleton-files.md)
};

/// Reads the scene's ASF and AMC files (paths relative to the scene file) and checks the scene's
/// arguments against the motions (0 < keyframe_in < N − 1, a + window ≤ |A|, ...). Throws
/// std::runtime_error with the first error: a file's "file:line: ..." or the scene's
/// "scene.toml: body.key: ...".
SkeletonInputs read_skeleton_inputs(const SceneSpec& scene);

/// The number of frames the scene's output has (the motion's, the warp's M or the blend's).
int skeleton_output_frames(const SceneSpec& scene, const SkeletonInputs& in);

/// `jelly check`'s report of a skeleton scene; throws std::runtime_error with the first error.
std::string check_skeleton_scene(const SceneSpec& scene);

/// `jelly run` of a skeleton scene through `tasks` (BodyKindModule::play).
std::string play_skeleton_scene(const SceneSpec& scene, const TaskTable& tasks,
                                const FramePlayOptions& options);

// ----- what a run's parts share (skeleton_play.cpp) -----

/// The `--summary` columns of every mode; a warp and a blend add qw,qx,qy,qz.
inline constexpr const char* kSkeletonSummaryColumns =
    "frame,bone,name,start_x,start_y,start_z,end_x,end_y,end_z";

/// Throws "task <task>, output frame <frame>: <what>".
[[noreturn]] void task_error(const char* task, int frame, const std::string& what);

/// Forward kinematics of `p` through the slot, its sizes checked (task_error otherwise).
void checked_forward_kinematics(const SkeletonTasks& tasks, const SkeletonInputs& in,
                                const skeleton::Posture& p, int frame, skeleton::BoneFrames& out);

/// One row per bone: frame, bone, name, start, end, and (with quaternions) the quaternion of the
/// bone's local angles, euler_to_quaternion's sign as computed. Returns the rows written.
long write_skeleton_frame(CsvWriter& out, int frame, const SkeletonInputs& in,
                          const skeleton::Posture& p, const skeleton::BoneFrames& f,
                          bool quaternions);

/// The --summary file with its header (lines, the last the columns), or nullptr when `path` is
/// empty. A file that cannot be opened is a std::system_error (an output, not the input).
std::unique_ptr<CsvWriter> open_skeleton_summary(const std::string& path,
                                                 const std::string& header);

// ----- inverse kinematics (skeleton_ik_play.cpp) -----

/// The frames an ik scene solves: 1, or with a chain's schedule every i with i / fps ≤
/// simulation.duration.
long long ik_solved_frames(const SceneSpec& scene);
/// `jelly check`'s lines about an ik scene's chains and settings.
std::string ik_check_lines(const SceneSpec& scene, const SkeletonInputs& in);
/// The target of `chain` at time t: its fixed target, or its schedule's, linear between entries.
Vec3 ik_target_at(const IkChainSpec& chain, double t);
/// The settings of every solve of the scene (body.step, epsilon, ...).
skeleton::IkSettings ik_settings_of(const SkeletonSceneSpec& k);
/// Where solve (frame, chain c) is, as its messages say: "output frame 0, chain 1 (a -> b)".
std::string ik_solve_where(int frame, std::size_t c, const IkChainSpec& chain);

/// One solve of an ik scene: where, its target, its outcome, and (when recorded) |x* − p| at each
/// end-effector evaluation it asked for.
struct IkSceneSolve {
  int frame = 0;
  std::size_t chain = 0;
  Vec3 target = Vec3::Zero();
  skeleton::IkResult result;
  std::vector<double> errors;
};
/// Every solve of an ik scene, in order, and the posture after each solved frame.
struct IkSceneRun {
  std::vector<IkSceneSolve> solves;
  std::vector<skeleton::Posture> postures;
};
/// The scene's solves (contract §6, §11.16): from the posture of AMC frame `frame`, each chain in
/// order at each solved frame, warm-started; throws std::runtime_error naming the task that
/// answered wrongly. The slots must all be filled (missing_ik_slot).
IkSceneRun run_ik_scene(const SceneSpec& scene, const SkeletonInputs& in,
                        const SkeletonTasks& tasks, bool record_errors);
/// run_ik_scene with the errors recorded, after checking every slot is filled (the viewer's
/// output motion); throws std::runtime_error naming the task that is missing or answered wrongly.
IkSceneRun ik_solved_run(const SceneSpec& scene, const SkeletonInputs& in,
                         const SkeletonTasks& tasks);
/// `jelly run` of an ik scene (body.mode = "ik").
std::string play_ik_scene(const SceneSpec& scene, const TaskTable& tasks,
                          const FramePlayOptions& options);

}  // namespace jelly::bodies
