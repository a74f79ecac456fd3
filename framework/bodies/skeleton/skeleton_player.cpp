// A skeleton scene played in a World (jelly/skeleton_player.hpp): the output motion through the
// tasks, the playback position, and the shown frames' forward kinematics, each task's answer
// checked before it is used (a wrong answer is a message, never a crash).
#include "jelly/skeleton_player.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "jelly/world.hpp"
#include "skeleton_play.hpp"
#include "skeleton_player_parts.hpp"

namespace jelly {

using skeleton::BoneFrames;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::TimeWarp;

namespace {

std::string missing_slot(const char* slot, const char* what) {
  return std::string("the task ") + slot + " (" + what +
         ") is not implemented in this program's tasks: SkeletonTasks::" + slot + " is null";
}

std::string frame_said(const char* task, int frame) {
  return std::string("task ") + task + ", frame " + std::to_string(frame) + ": ";
}

bool finite(const Posture& p) {
  if (!p.root_translation.allFinite()) return false;
  return std::all_of(p.angles.begin(), p.angles.end(), [](const Vec3& a) { return a.allFinite(); });
}

/// Contract §5's arguments of a warp of `n` input frames; "" when they hold.
std::string warp_refused(const TimeWarp& w) {
  const int n = w.input_frames, m = w.output_frames;
  if (m < 2) return "a warp has at least 2 output frames (kinematics contract §5)";
  if (!w.has_keyframe()) return "";
  if (!(w.keyframe_in > 0 && w.keyframe_in < n - 1))
    return "K_in must satisfy 0 < K_in < N − 1 = " + std::to_string(n - 1);
  if (!(w.keyframe_out > 0 && w.keyframe_out < m - 1))
    return "K_out must satisfy 0 < K_out < M − 1 = " + std::to_string(m - 1);
  return "";
}

}  // namespace

SkeletonPlayer::SkeletonPlayer(const SceneSpec& scene, const SkeletonTasks& tasks)
    : in_(std::make_unique<Inputs>(Inputs{bodies::read_skeleton_inputs(scene)})),
      tasks_(tasks),
      mode_(skeleton_scene(scene).mode),
      fps_(skeleton_scene(scene).fps),
      shown_cache_(std::make_unique<Cache>()),
      input_cache_(std::make_unique<Cache>()) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  warp_.input_frames = static_cast<int>(input().frames.size());
  warp_.output_frames = bodies::skeleton_output_frames(scene, in_->files);
  warp_.keyframe_in = static_cast<int>(k.keyframe_in);
  warp_.keyframe_out = static_cast<int>(k.keyframe_out);
  scene_warp_ = warp_;
  blend_ = {static_cast<int>(k.a), static_cast<int>(k.b), static_cast<int>(k.window)};
  compute_output();
  if (mode_ == SkeletonMode::Ik) start_ik(scene);
}

SkeletonPlayer::~SkeletonPlayer() = default;

const skeleton::Skeleton& SkeletonPlayer::skeleton() const { return in_->files.skeleton; }
const Motion& SkeletonPlayer::input() const { return in_->files.motion; }
const std::string& SkeletonPlayer::motion_file() const { return in_->files.amc_file; }

/// The output motion: the input (playback), every warped frame (time_map, then warped_posture,
/// each answer checked), or the blend. On a problem the output is empty and problem() says why.
void SkeletonPlayer::compute_output() {
  problem_.clear();
  output_ = Motion{};
  output_.fps = fps_;
  shown_cache_->key = input_cache_->key = -1;
  extent_done_ = false;
  const std::size_t bones = skeleton().bones.size();
  if (!tasks_.forward_kinematics)
    problem_ = missing_slot("forward_kinematics", "forward kinematics, kinematics contract §4");
  if (mode_ == SkeletonMode::Playback) {
    output_ = input();
  } else if (mode_ == SkeletonMode::Ik) {
    return;  // solved by the constructor and Reset: the scene's chains (solve_ik_scene)
  } else if (mode_ == SkeletonMode::Blend) {
    if (!tasks_.blend_motions) {
      problem_ += std::string(problem_.empty() ? "" : "; ") +
                  missing_slot("blend_motions", "the motion blend, kinematics contract §5");
      return;
    }
    tasks_.blend_motions(skeleton(), input(), in_->files.motion_b, blend_, output_);
    for (std::size_t i = 0; i < output_.frames.size(); ++i)
      if (output_.frames[i].angles.size() != bones || !finite(output_.frames[i])) {
        problem_ = frame_said("blend_motions", static_cast<int>(i)) +
                   "returned a posture of the wrong size or not finite";
        output_.frames.clear();
        return;
      }
  } else {
    if (!tasks_.time_map || !tasks_.warped_posture) {
      problem_ +=
          std::string(problem_.empty() ? "" : "; ") +
          (!tasks_.time_map
               ? missing_slot("time_map", "the time map s(i), kinematics contract §5")
               : missing_slot("warped_posture", "the warped posture, kinematics contract §5"));
      return;
    }
    const double last = warp_.input_frames - 1;
    output_.frames.reserve(static_cast<std::size_t>(warp_.output_frames));
    for (int i = 0; i < warp_.output_frames; ++i) {
      const double s = tasks_.time_map(i, warp_);
      if (!(s >= 0.0 && s <= last)) {
        problem_ = frame_said("time_map", i) + "returned s = " + std::to_string(s) +
                   "; expected 0 ≤ s ≤ N − 1 = " + std::to_string(warp_.input_frames - 1);
        output_.frames.clear();
        return;
      }
      Posture p = Posture::zero(bones);
      tasks_.warped_posture(skeleton(), input(), s, p);
      if (p.angles.size() != bones || !finite(p)) {
        problem_ =
            frame_said("warped_posture", i) + "returned a posture of the wrong size or not finite";
        output_.frames.clear();
        return;
      }
      output_.frames.push_back(std::move(p));
    }
  }
  position_ = std::min(position_, std::max(0.0, frame_count() - 1.0));
}

std::string SkeletonPlayer::set_warp(const TimeWarp& wanted) {
  TimeWarp w = wanted;
  w.input_frames = warp_.input_frames;
  if (std::string why = warp_refused(w); !why.empty()) return why;
  warp_ = w;
  if (mode_ == SkeletonMode::Warp) compute_output();
  return "";
}

void SkeletonPlayer::seek(int frame) {
  position_ = std::clamp(frame, 0, std::max(0, frame_count() - 1));
}

void SkeletonPlayer::stop() {
  playing_ = false;
  position_ = 0.0;
}

void SkeletonPlayer::step(int frames) {
  playing_ = false;
  const int n = frame_count();
  if (n == 0) return;
  position_ = ((frame() + frames) % n + n) % n;
}

void SkeletonPlayer::advance(double seconds) {
  const int n = frame_count();
  if (!playing_ || n == 0) return;
  position_ = std::fmod(position_ + seconds * speed_ * fps_, static_cast<double>(n));
  if (position_ < 0.0) position_ += n;
}

/// The forward kinematics of `posture` through the tasks, checked; cached under `key`.
const BoneFrames* SkeletonPlayer::fk(const Posture& posture, int frame, Cache& cache,
                                     int key) const {
  if (!tasks_.forward_kinematics) return nullptr;
  if (cache.key == key) return cache.ok ? &cache.frames : nullptr;
  cache.key = key;
  cache.ok = false;
  tasks_.forward_kinematics(skeleton(), posture, cache.frames);
  const BoneFrames& f = cache.frames;
  const std::size_t bones = skeleton().bones.size();
  if (f.start.size() != bones || f.end.size() != bones || f.rotation.size() != bones) {
    problem_ = frame_said("forward_kinematics", frame) + "returned " +
               std::to_string(f.start.size()) + " starts and " + std::to_string(f.end.size()) +
               " ends; the skeleton has " + std::to_string(bones) + " bones";
    return nullptr;
  }
  for (std::size_t b = 0; b < bones; ++b)
    if (!f.start[b].allFinite() || !f.end[b].allFinite()) {
      problem_ = frame_said("forward_kinematics", frame) + "bone " + skeleton().bones[b].name +
                 " is not at a finite position";
      return nullptr;
    }
  cache.ok = true;
  return &cache.frames;
}

const BoneFrames* SkeletonPlayer::output_frames(int i) const {
  if (i < 0 || i >= frame_count()) return nullptr;
  return fk(output_.frames[static_cast<std::size_t>(i)], i, *shown_cache_, i);
}

const BoneFrames* SkeletonPlayer::input_frames(int i) const {
  const int n = static_cast<int>(input().frames.size());
  if (n == 0) return nullptr;
  const int k = std::clamp(i, 0, n - 1);
  return fk(input().frames[static_cast<std::size_t>(k)], k, *input_cache_, k);
}

const std::vector<Vec3>& SkeletonPlayer::extent() const {
  if (extent_done_) return extent_;
  extent_done_ = true;
  extent_.clear();
  Cache scratch;
  const auto add = [&](const Motion& m) {
    for (std::size_t i = 0; i < m.frames.size(); ++i) {
      scratch.key = -1;
      if (const BoneFrames* f = fk(m.frames[i], static_cast<int>(i), scratch, 0))
        extent_.insert(extent_.end(), f->end.begin(), f->end.end());
    }
  };
  add(input());
  if (mode_ != SkeletonMode::Playback) add(output_);
  return extent_;
}

// ------------------------------------------------------------------------------------------------

SkeletonPhysics::SkeletonPhysics(World& world, const SceneSpec& scene)
    : BodyPhysics(world), player_(scene, skeleton_tasks(world.tasks())) {}

void SkeletonPhysics::acceleration(const State&, Vec3Array& a) { a.setZero(); }

void build_skeleton_world(const SceneSpec& scene, World& world) {
  auto physics = std::make_unique<SkeletonPhysics>(world, scene);
  const std::vector<Vec3>& ends = physics->player().extent();
  world.set_physics(std::move(physics));
  Plane ground;
  if (!ends.empty()) {
    Vec3 lo = ends.front(), hi = ends.front();
    for (const Vec3& e : ends) {
      lo = lo.cwiseMin(e);
      hi = hi.cwiseMax(e);
    }
    ground.point = Vec3(0.5 * (lo.x() + hi.x()), lo.y(), 0.5 * (lo.z() + hi.z()));
  }
  Terrain t;
  t.name = "ground";
  t.shape = ground;
  world.add_terrain(std::move(t));
}

std::vector<float> bone_series(const SkeletonPlayer& player, int bone, BoneQuantity q,
                               bool original) {
  const int n = player.frame_count(), last = static_cast<int>(player.input().frames.size()) - 1;
  const std::size_t b = static_cast<std::size_t>(bone);
  const Motion& m = original ? player.input() : player.output();
  std::vector<float> out;
  out.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int i = 0; i < n; ++i) {
    const int k = original ? std::min(i, last) : i;
    if (q != BoneQuantity::Height) {
      out.push_back(
          static_cast<float>(m.frames[static_cast<std::size_t>(k)].angles[b][static_cast<int>(q)]));
      continue;
    }
    const BoneFrames* f = original ? player.input_frames(k) : player.output_frames(k);
    out.push_back(f ? static_cast<float>(f->end[b].y()) : 0.0f);
  }
  return out;
}

SkeletonPlayer* find_skeleton_player(World& world) {
  auto* p = dynamic_cast<SkeletonPhysics*>(&world.physics());
  return p ? &p->player() : nullptr;
}

const SkeletonPlayer* find_skeleton_player(const World& world) {
  const auto* p = dynamic_cast<const SkeletonPhysics*>(&world.physics());
  return p ? &p->player() : nullptr;
}

}  // namespace jelly
