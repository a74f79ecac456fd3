// A skeleton scene's data (body.type = "skeleton", kinematics contract §7): the files it names,
// its scale and rate, and what it asks for (playback, a time warp or a blend), kept in the scene's
// body_data (jelly/kind_parts.hpp). docs/skeleton-scenes.md lists the keys.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "jelly/scene_spec.hpp"

namespace jelly {

/// The kind the skeleton module registers.
inline constexpr BodyKind kSkeletonKind{"skeleton"};

/// What a skeleton scene plays (body.mode).
enum class SkeletonMode { Playback, Warp, Blend };

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
};

/// body.mode's text: "playback", "warp" or "blend".
inline std::string_view skeleton_mode_name(SkeletonMode mode) {
  return mode == SkeletonMode::Warp ? "warp" : mode == SkeletonMode::Blend ? "blend" : "playback";
}
/// The mode body.mode's text names, or nullopt.
inline std::optional<SkeletonMode> skeleton_mode_from_name(std::string_view name) {
  for (SkeletonMode m : {SkeletonMode::Playback, SkeletonMode::Warp, SkeletonMode::Blend})
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
