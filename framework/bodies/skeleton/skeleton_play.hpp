// Internal to the skeleton kind: what `jelly check` and `jelly run` do with a skeleton scene
// (docs/skeleton-scenes.md). The files a scene names are read and its arguments checked against
// them (kinematics contract §5); a run then plays every output frame through the SkeletonTasks
// slots.
#pragma once

#include <string>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_scene.hpp"

namespace jelly::bodies {

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

}  // namespace jelly::bodies
