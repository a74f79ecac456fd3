// A skeleton scene's data (body.type = "skeleton", kinematics contract §7): the files it names,
// its scale and rate, and what it asks for (playback, a time warp, a blend or inverse kinematics
// with its chains, [[chain]]), kept in the scene's body_data (jelly/kind_parts.hpp).
// docs/skeleton-scenes.md lists the keys.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/scene_spec.hpp"
#include "jelly/schedule.hpp"
#include "jelly/skeleton/ik.hpp"

namespace jelly {

/// The kind the skeleton module registers.
inline constexpr BodyKind kSkeletonKind{"skeleton"};

/// What a skeleton scene plays (body.mode).
enum class SkeletonMode { Playback, Warp, Blend, Ik };

/// One chain of an inverse-kinematics scene ([[chain]], kinematics contract §6, §11.16): its start
/// and end bones by name, and its target, fixed or along a schedule.
struct IkChainSpec {
  std::string start;           ///< the start bone (its name in the ASF)
  std::string end;             ///< the end bone, whose end reaches for the target
  std::optional<Vec3> target;  ///< a fixed target [scene units]; none with a schedule
  /// A moving target: from entry k's time on, linearly towards entry k + 1's (ScheduleEntry's
  /// `velocity` holds the target); before the first time the first target, after the last the
  /// last. Times strictly increasing.
  std::vector<ScheduleEntry> schedule;
};

/// What a skeleton scene's [body] says. Paths are as written, relative to the scene file.
struct SkeletonSceneSpec {
  std::string asf;     ///< the skeleton (ASF)
  std::string amc;     ///< the motion (AMC); motion A of a blend
  double scale = 0.2;  ///< lengths and root translations are multiplied by it (the course's 0.2)
  double fps = 120.0;  ///< frames per second of the motion and of the output (CMU's rate)
  SkeletonMode mode = SkeletonMode::Playback;
  // A warp (contract §5): M output frames (0: as many as the input), with one keyframe when
  // keyframe_in and keyframe_out are given (−1: none, a uniform retiming).
  long long frames = 0;
  long long keyframe_in = -1;
  long long keyframe_out = -1;
  // A blend (contract §5, the bonus): motion B, the first blended frames a of A and b of B, the
  // window W.
  std::string amc_b;
  long long a = 0;
  long long b = 0;
  long long window = 20;  ///< the course's window
  // Inverse kinematics (contract §6): the AMC frame (from 0) the posture starts from, and the
  // solve's settings, the course's by default (IkSettings' defaults). The chains: ik_chain_specs.
  long long frame = 0;
  double step = skeleton::IkSettings{}.step;
  double epsilon = skeleton::IkSettings{}.epsilon;
  long long max_iterations = skeleton::IkSettings{}.max_iterations;
  bool limits = skeleton::IkSettings{}.limits;
  bool restore = skeleton::IkSettings{}.restore;
};

/// The scene's chains ([[chain]]) in scene order; none until one is added.
inline std::vector<IkChainSpec>& ik_chain_specs(SceneSpec& scene) {
  return scene.body_data.get<std::vector<IkChainSpec>>();
}
inline const std::vector<IkChainSpec>& ik_chain_specs(const SceneSpec& scene) {
  return scene.body_data.get_or_default<std::vector<IkChainSpec>>();
}

/// body.mode's text: "playback", "warp", "blend" or "ik".
inline std::string_view skeleton_mode_name(SkeletonMode mode) {
  switch (mode) {
    case SkeletonMode::Warp: return "warp";
    case SkeletonMode::Blend: return "blend";
    case SkeletonMode::Ik: return "ik";
    case SkeletonMode::Playback: break;
  }
  return "playback";
}
/// The mode body.mode's text names, or nullopt.
inline std::optional<SkeletonMode> skeleton_mode_from_name(std::string_view name) {
  for (SkeletonMode m :
       {SkeletonMode::Playback, SkeletonMode::Warp, SkeletonMode::Blend, SkeletonMode::Ik})
    if (skeleton_mode_name(m) == name) return m;
  return std::nullopt;
}

/// The scene's skeleton data, made with its defaults on first use.
inline SkeletonSceneSpec& skeleton_scene(SceneSpec& scene) {
  return scene.body_data.get<SkeletonSceneSpec>();
}
/// The scene's skeleton data, or the defaults when the scene has none.
inline const SkeletonSceneSpec& skeleton_scene(const SceneSpec& scene) {
  return scene.body_data.get_or_default<SkeletonSceneSpec>();
}

}  // namespace jelly
