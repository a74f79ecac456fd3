// A skeleton scene's files, read and checked against its arguments (kinematics contract §5, §7),
// and `jelly check`'s report of them.
#include <filesystem>
#include <stdexcept>

#include "jelly/scene_spec.hpp"
#include "jelly/skeleton/skeleton_files.hpp"
#include "param_table.hpp"
#include "skeleton_play.hpp"

namespace jelly::bodies {

namespace {

using skeleton::FileError;
using skeleton::FileNote;

[[noreturn]] void scene_error(const SceneSpec& scene, const std::string& key,
                              const std::string& message) {
  throw std::runtime_error(SceneError{scene.source, key, 0, 0, message}.text());
}

/// `file` (UTF-8, as the scene writes it) relative to the scene file's folder.
std::filesystem::path scene_relative(const SceneSpec& scene, const std::string& file) {
  const std::filesystem::path p = std::filesystem::u8path(file);
  if (p.is_absolute() || scene.source.empty()) return p;
  return (std::filesystem::path(scene.source).parent_path() / p).lexically_normal();
}

/// A reader's error: its file and line, or (a file that cannot be read, line 0) the scene's key.
[[noreturn]] void file_error(const SceneSpec& scene, const std::string& key, const FileError& e) {
  if (e.line == 0) scene_error(scene, key, e.text());
  throw std::runtime_error(e.text());
}

void add_notes(std::vector<std::string>& out, const std::string& file,
               const std::vector<FileNote>& notes) {
  for (const FileNote& n : notes)
    out.push_back(file + ":" + std::to_string(n.line) + ": " + n.message);
}

skeleton::Motion read_motion(const SceneSpec& scene, const std::string& key,
                             const std::string& file, SkeletonInputs& in, std::string& shown) {
  const std::filesystem::path path = scene_relative(scene, file);
  shown = path.generic_string();
  skeleton::MotionResult r = skeleton::read_amc(path, in.skeleton);
  if (!r) file_error(scene, key, *r.error);
  add_notes(in.notes, shown, r.notes);
  r.motion->fps = skeleton_scene(scene).fps;
  return std::move(*r.motion);
}

std::string frames_of(const std::string& file, std::size_t n) {
  return std::filesystem::u8path(file).filename().u8string() + " has " + std::to_string(n) +
         " frames";
}

// Contract §5: N ≥ 2, M ≥ 2, 0 < K_in < N − 1, 0 < K_out < M − 1.
void check_warp(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  const long long n = static_cast<long long>(in.motion.frames.size());
  const long long m = skeleton_output_frames(scene, in);
  if (n < 2)
    scene_error(scene, "body.amc",
                "a warp needs a motion of at least 2 frames (kinematics contract §5), and " +
                    frames_of(k.amc, in.motion.frames.size()));
  if (!(k.keyframe_in < 0 || k.keyframe_in < n - 1))
    scene_error(scene, "body.keyframe_in",
                "must satisfy 0 < keyframe_in < N − 1 = " + std::to_string(n - 1) + " (" +
                    frames_of(k.amc, in.motion.frames.size()) +
                    ", counted from 0; kinematics contract §5), got " +
                    std::to_string(k.keyframe_in));
  if (!(k.keyframe_out < 0 || k.keyframe_out < m - 1))
    scene_error(scene, "body.keyframe_out",
                "must satisfy 0 < keyframe_out < M − 1 = " + std::to_string(m - 1) +
                    " (M = " + std::to_string(m) +
                    " output frames, counted from 0; kinematics contract §5), got " +
                    std::to_string(k.keyframe_out));
}

// Contract §5: a + W ≤ |A|, b + W ≤ |B|.
void check_blend(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  const auto fits = [&](const char* letter, long long first, const std::string& file,
                        std::size_t n) {
    if (first + k.window > static_cast<long long>(n))
      scene_error(scene, std::string("body.") + letter,
                  std::string("must satisfy ") + letter + " + window ≤ the motion's frames (" +
                      frames_of(file, n) + "; kinematics contract §5), got " +
                      std::to_string(first) + " + " + std::to_string(k.window) + " = " +
                      std::to_string(first + k.window));
  };
  fits("a", k.a, k.amc, in.motion.frames.size());
  fits("b", k.b, k.amc_b, in.motion_b.frames.size());
}

/// `name`, a bone the scene's `key` names, is one of the skeleton's: else an error with the
/// closest name and every name.
void check_bone(const SceneSpec& scene, const SkeletonInputs& in, const std::string& key,
                const std::string& name) {
  if (in.skeleton.find(name)) return;
  std::vector<std::string> names;
  std::string all;
  for (const skeleton::Bone& b : in.skeleton.bones) {
    names.push_back(b.name);
    all += (all.empty() ? "" : ", ") + b.name;
  }
  const std::string near = params_detail::closest(name, names);
  scene_error(scene, key,
              "no bone \"" + name + "\" in " + in.asf_file +
                  (near.empty() ? "" : " (did you mean \"" + near + "\"?)") +
                  " (bone names are case-sensitive); its bones: " + all);
}

// Contract §6, §7: body.frame is one of the motion's frames, and every chain's bones are in the
// skeleton.
void check_ik(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  if (k.frame >= static_cast<long long>(in.motion.frames.size()))
    scene_error(scene, "body.frame",
                "must be a frame of the motion, 0 ≤ frame < " +
                    std::to_string(in.motion.frames.size()) + " (" +
                    frames_of(k.amc, in.motion.frames.size()) + ", counted from 0), got " +
                    std::to_string(k.frame));
  const std::vector<IkChainSpec>& chains = ik_chain_specs(scene);
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const std::string key = "chain." + std::to_string(i) + ".";
    check_bone(scene, in, key + "start", chains[i].start);
    check_bone(scene, in, key + "end", chains[i].end);
  }
}

}  // namespace

SkeletonInputs read_skeleton_inputs(const SceneSpec& scene) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  SkeletonInputs in;
  const std::filesystem::path asf = scene_relative(scene, k.asf);
  in.asf_file = asf.generic_string();
  skeleton::SkeletonResult s = skeleton::read_asf(asf, k.scale);
  if (!s) file_error(scene, "body.asf", *s.error);
  add_notes(in.notes, in.asf_file, s.notes);
  in.skeleton = std::move(*s.skeleton);
  in.motion = read_motion(scene, "body.amc", k.amc, in, in.amc_file);
  if (k.mode == SkeletonMode::Blend) {
    in.motion_b = read_motion(scene, "body.amc_b", k.amc_b, in, in.amc_b_file);
    check_blend(scene, in);
  }
  if (k.mode == SkeletonMode::Warp) check_warp(scene, in);
  if (k.mode == SkeletonMode::Ik) check_ik(scene, in);
  return in;
}

int skeleton_output_frames(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  const auto n = static_cast<int>(in.motion.frames.size());
  switch (k.mode) {
    case SkeletonMode::Warp: return k.frames > 0 ? static_cast<int>(k.frames) : n;
    case SkeletonMode::Blend:
      return static_cast<int>(k.a + static_cast<long long>(in.motion_b.frames.size()) - k.b);
    case SkeletonMode::Ik: return static_cast<int>(ik_solved_frames(scene));
    case SkeletonMode::Playback: break;
  }
  return n;
}

std::string check_skeleton_scene(const SceneSpec& scene) {
  const SkeletonInputs in = read_skeleton_inputs(scene);
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  const auto motion_line = [&](const std::string& file, const skeleton::Motion& m) {
    return text_printf("  motion %s: %zu frames at %g fps (%g s)\n", file.c_str(), m.frames.size(),
                       m.fps, static_cast<double>(m.frames.size()) / m.fps);
  };
  std::string out = text_printf("%s: valid. skeleton %s: %zu bones, %d channels (scale %g)\n",
                                scene.name.c_str(), in.asf_file.c_str(), in.skeleton.bones.size(),
                                in.skeleton.channel_count(), k.scale);
  out += motion_line(in.amc_file, in.motion);
  if (k.mode == SkeletonMode::Blend) out += motion_line(in.amc_b_file, in.motion_b);
  const int m = skeleton_output_frames(scene, in);
  if (k.mode == SkeletonMode::Playback) out += text_printf("  plays the motion: %d frames\n", m);
  if (k.mode == SkeletonMode::Warp)
    out += k.keyframe_in >= 0
               ? text_printf("  warp: %zu -> %d frames, keyframe %lld -> %lld\n",
                             in.motion.frames.size(), m, k.keyframe_in, k.keyframe_out)
               : text_printf("  warp: %zu -> %d frames, uniform\n", in.motion.frames.size(), m);
  if (k.mode == SkeletonMode::Blend)
    out += text_printf("  blend: a %lld, b %lld, window %lld: %d frames\n", k.a, k.b, k.window, m);
  if (k.mode == SkeletonMode::Ik) out += ik_check_lines(scene, in);
  out += text_printf("  %zu notes (skipped sections and keys)%s\n", in.notes.size(),
                     in.notes.empty() ? "" : ":");
  for (const std::string& n : in.notes) out += "    " + n + "\n";
  return out;
}

}  // namespace jelly::bodies
