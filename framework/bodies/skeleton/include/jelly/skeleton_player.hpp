// A skeleton scene played in a World (the viewer and `jelly render`; `jelly run` plays it without
// one: docs/skeleton-scenes.md). The skeleton kind's `build` reads the scene's files and installs
// a SkeletonPhysics, whose only state is a SkeletonPlayer: the output motion (the motion as read,
// its time warp or its blend, computed through the world's SkeletonTasks), where the playback is,
// and each shown frame's forward kinematics. The simulator's steps advance the playback
// (end_step), so the simulator owns time as for every other kind; the viewer's controls pause,
// seek, change the speed and change the warp's keyframe and frame count. No GL.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jelly/body_physics.hpp"
#include "jelly/scene_spec.hpp"
#include "jelly/skeleton_scene.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly {

class World;

/// One chain of an ik scene as the viewer edits it: its bones and, once the viewer moved it, its
/// own target.
struct IkChainState {
  int start = 0;               ///< the start bone
  int end = 0;                 ///< the end bone, whose end reaches for the target
  std::vector<int> bones;      ///< the chain ik_chain gives, end bone first; empty when it failed
  std::string chain_error;     ///< why ik_chain gave no chain (the task's message), or ""
  bool moved = false;          ///< the target is the viewer's (else the scene's at the shown frame)
  Vec3 target = Vec3::Zero();  ///< the viewer's target [scene units] (when moved)
};

/// The last solve of one chain at one frame: what it returned, |x* − p| at each end-effector
/// evaluation it asked for (the first before any update, the last after the last), or why it
/// failed.
struct IkSolveRecord {
  bool solved = false;  ///< false: failed (error says why) or never solved
  skeleton::IkResult result;
  std::vector<double> errors;
  std::string error;
};

/// The playback of a skeleton scene: its output motion, a position in it, and the bone frames of
/// the shown frame. A task that is missing or answers wrongly never throws here: problem() says
/// what is wrong, and the frames it could not compute are null. The read-outs are const (the
/// renderer reads a const World) and cache what they compute.
class SkeletonPlayer {
 public:
  /// Reads the scene's files (skeleton_inputs.cpp: the errors name the file and line, or the
  /// scene's key; thrown as std::runtime_error) and computes the output motion through `tasks`.
  SkeletonPlayer(const SceneSpec& scene, const SkeletonTasks& tasks);
  ~SkeletonPlayer();
  SkeletonPlayer(const SkeletonPlayer&) = delete;
  SkeletonPlayer& operator=(const SkeletonPlayer&) = delete;

  const skeleton::Skeleton& skeleton() const;
  /// The motion as read (motion A of a blend), and the output (the motion itself in playback).
  const skeleton::Motion& input() const;
  const skeleton::Motion& output() const { return output_; }
  SkeletonMode mode() const { return mode_; }
  double fps() const { return fps_; }
  /// The AMC file the scene plays (as messages name it).
  const std::string& motion_file() const;
  /// Output frames (0 when a task could not compute them).
  int frame_count() const { return static_cast<int>(output_.frames.size()); }

  // ----- the warp (mode warp) -----
  const skeleton::TimeWarp& warp() const { return warp_; }
  /// The scene's own warp (what Reset restores).
  const skeleton::TimeWarp& scene_warp() const { return scene_warp_; }
  /// Recomputes the output with `warp` (its input_frames is the motion's). Returns "" or why the
  /// warp is refused (contract §5: M ≥ 2, 0 < K_in < N − 1, 0 < K_out < M − 1); a refused warp
  /// changes nothing. The playback keeps its frame (clamped to the new count).
  std::string set_warp(const skeleton::TimeWarp& warp);

  // ----- the playback -----
  /// [frames] 0 ≤ position < frame_count; the shown frame is its whole part.
  double position() const { return position_; }
  int frame() const { return static_cast<int>(position_); }
  bool playing() const { return playing_; }
  void set_playing(bool playing) { playing_ = playing; }
  /// Playback speed (1: the scene's fps in simulated time).
  double speed() const { return speed_; }
  void set_speed(double speed) { speed_ = speed; }
  /// Shows frame `frame` (clamped to the output).
  void seek(int frame);
  /// Pause and back to frame 0.
  void stop();
  /// One frame forward (+1) or back (−1), wrapping at the ends; pauses.
  void step(int frames);
  /// While playing: `seconds` of simulated time × speed × fps frames further, wrapping at the end.
  void advance(double seconds);

  // ----- inverse kinematics (mode ik): the viewer's live solves -----
  /// The scene's chains (none outside mode ik), as the viewer edits them.
  std::size_t ik_chain_count() const;
  const IkChainState& ik_chain(std::size_t c) const;
  /// Chain c's target at the shown frame: the viewer's once moved, else the scene's (its schedule's
  /// at the frame's time).
  Vec3 ik_target(std::size_t c) const;
  /// Chain c's last solve at the shown frame (the scene's solve until the viewer solves again).
  const IkSolveRecord& ik_record(std::size_t c) const;
  /// The viewer's target for chain c; pauses, and the next ik_update solves.
  void set_ik_target(std::size_t c, const Vec3& target);
  /// New start and end bones for chain c (ik_chain's answer checked: chain_error says why it is
  /// refused); the next ik_update solves.
  void set_ik_bones(std::size_t c, int start, int end);
  const skeleton::IkSettings& ik_settings() const;
  /// New settings (step, epsilon, max_iterations, limits); the next ik_update solves.
  void set_ik_settings(const skeleton::IkSettings& settings);
  /// The scene's chains, targets and settings again, and the scene's solves from its frame.
  void ik_reset();
  /// When a target, a chain or the settings changed since the last solve: solves every chain in
  /// order at the shown frame, each warm-started from the posture the one before left (contract
  /// §11.16), through solve_ik (as `jelly run`); a chain whose task fails keeps the posture and
  /// its record says why. Returns whether it solved; without a change it does nothing.
  bool ik_update();
  /// The live solves ik_update made (each chain's solve counts one).
  long ik_solve_count() const;

  // ----- what is shown -----
  /// The bone frames of output frame `i` (the played posture's forward kinematics), or null
  /// when the tasks cannot give them (problem() says why). Cached for the last frame asked.
  const skeleton::BoneFrames* output_frames(int i) const;
  /// The bone frames of the input motion's frame at output frame `i` (clamped to N − 1): the
  /// original beside a warp. Null as above.
  const skeleton::BoneFrames* input_frames(int i) const;
  /// Why nothing (or not everything) can be shown: a task slot the tasks do not fill, or a task's
  /// answer of the wrong size, out of range or not finite. "" when all is well.
  const std::string& problem() const { return problem_; }
  /// Every bone end of every input and output frame (empty without forward kinematics): what a
  /// view frames and stands on the ground.
  const std::vector<Vec3>& extent() const;

 private:
  struct Cache;
  void compute_output();
  const skeleton::BoneFrames* fk(const skeleton::Posture& posture, int frame, Cache& cache,
                                 int key) const;

  struct Inputs;
  struct Ik;
  void start_ik(const SceneSpec& scene);
  void solve_ik_scene();
  std::unique_ptr<Inputs> in_;
  std::unique_ptr<Ik> ik_;  // mode ik only
  SkeletonTasks tasks_;
  SkeletonMode mode_;
  double fps_;
  skeleton::TimeWarp warp_, scene_warp_;
  skeleton::Blend blend_;
  skeleton::Motion output_;
  mutable std::string problem_;  // also a task's wrong answer met while drawing
  double position_ = 0.0;
  double speed_ = 1.0;
  bool playing_ = true;
  // What the const read-outs compute once and keep (logically const).
  std::unique_ptr<Cache> shown_cache_, input_cache_;
  mutable std::vector<Vec3> extent_;
  mutable bool extent_done_ = false;
};

/// What a plot of one bone over the output frames shows: an angle of its AMC line (degrees) or
/// the height of its end (scene units).
enum class BoneQuantity { Rx, Ry, Rz, Height };

/// Bone `bone`'s `q` at every output frame of `player`: of the output motion, or (`original`) of
/// the input frame beside it (frame i, clamped to N − 1). Heights come from forward kinematics, 0
/// where it gives none. The original's series does not change with the warp's keyframe (a
/// viewer keeps it while a slider moves).
std::vector<float> bone_series(const SkeletonPlayer& player, int bone, BoneQuantity q,
                               bool original);

/// A skeleton world's physics: no particles, no forces; each step advances its player.
class SkeletonPhysics final : public BodyPhysics {
 public:
  SkeletonPhysics(World& world, const SceneSpec& scene);
  void acceleration(const State& s, Vec3Array& a) override;
  void apply_collisions(State&) override {}
  void end_step(double h) override { player_.advance(h); }
  SkeletonPlayer& player() { return player_; }
  const SkeletonPlayer& player() const { return player_; }

 private:
  SkeletonPlayer player_;
};

/// The skeleton kind's `build`: installs a SkeletonPhysics for `scene` in the empty `world` and
/// adds the ground, a plane (terrain "ground") under the lowest bone end of the input and output
/// motions (y = 0 without forward kinematics). Throws std::runtime_error when a file or the
/// scene's arguments are wrong (the file and line, or the scene's key).
void build_skeleton_world(const SceneSpec& scene, World& world);

/// The player of a skeleton world, null for a world of another kind.
SkeletonPlayer* find_skeleton_player(World& world);
const SkeletonPlayer* find_skeleton_player(const World& world);

}  // namespace jelly
