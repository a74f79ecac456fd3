// An ik scene's player (jelly/skeleton_player.hpp): the scene's solves, and the viewer's live
// solves when a target, a chain or a setting changes, warm-started from the shown posture through
// the same solve_ik as `jelly run` (kinematics contract §6, §11.16).
#include <algorithm>
#include <exception>
#include <stdexcept>

#include "jelly/skeleton_ik.hpp"
#include "skeleton_play.hpp"
#include "skeleton_player_parts.hpp"

namespace jelly {

using skeleton::Posture;

namespace {

const IkSolveRecord kNoRecord{};

const std::string& name_of(const skeleton::Skeleton& s, int bone) {
  return s.bones[static_cast<std::size_t>(bone)].name;
}

/// Chain c's bones by ik_chain (checked), or why there are none.
void find_bones(const skeleton::Skeleton& s, const SkeletonTasks& tasks, IkChainState& c) {
  c.bones.clear();
  c.chain_error.clear();
  if (!tasks.ik_chain) {
    c.chain_error = "the task ik_chain is not implemented: SkeletonTasks::ik_chain is null";
    return;
  }
  IkSolveRequest request;
  request.start_bone = c.start;
  request.end_bone = c.end;
  request.where = "the viewer's chain " + name_of(s, c.start) + " -> " + name_of(s, c.end);
  try {
    c.bones = ik_chain_of(s, tasks, request);
  } catch (const std::exception& e) {
    c.chain_error = e.what();
  }
}

}  // namespace

void SkeletonPlayer::start_ik(const SceneSpec& scene) {
  ik_ = std::make_unique<Ik>();
  ik_->scene = scene;
  ik_->specs = ik_chain_specs(scene);
  solve_ik_scene();
}

/// The scene's chains, targets and settings, and its solves (the output motion); on an error the
/// output is empty and problem() says why.
void SkeletonPlayer::solve_ik_scene() {
  Ik& ik = *ik_;
  ik.settings = bodies::ik_settings_of(skeleton_scene(ik.scene));
  ik.chains.clear();
  for (const IkChainSpec& spec : ik.specs) {
    IkChainState c;
    c.start = *skeleton().find(spec.start);
    c.end = *skeleton().find(spec.end);
    find_bones(skeleton(), tasks_, c);
    ik.chains.push_back(std::move(c));
  }
  ik.records.clear();
  ik.dirty = false;
  shown_cache_->key = -1;
  try {
    bodies::IkSceneRun run = bodies::ik_solved_run(ik.scene, in_->files, tasks_);
    output_.frames = std::move(run.postures);
    ik.records.assign(output_.frames.size(), std::vector<IkSolveRecord>(ik.specs.size()));
    for (bodies::IkSceneSolve& s : run.solves) {
      IkSolveRecord& r = ik.records[static_cast<std::size_t>(s.frame)][s.chain];
      r.solved = true;
      r.result = s.result;
      r.errors = std::move(s.errors);
    }
  } catch (const std::runtime_error& e) {
    problem_ = e.what();
    output_.frames.clear();
  }
  position_ = std::min(position_, std::max(0.0, frame_count() - 1.0));
}

std::size_t SkeletonPlayer::ik_chain_count() const { return ik_ ? ik_->chains.size() : 0; }

const IkChainState& SkeletonPlayer::ik_chain(std::size_t c) const { return ik_->chains.at(c); }

Vec3 SkeletonPlayer::ik_target(std::size_t c) const {
  const IkChainState& chain = ik_->chains.at(c);
  if (chain.moved) return chain.target;
  return bodies::ik_target_at(ik_->specs.at(c), static_cast<double>(frame()) / fps_);
}

const IkSolveRecord& SkeletonPlayer::ik_record(std::size_t c) const {
  const auto f = static_cast<std::size_t>(frame());
  if (!ik_ || f >= ik_->records.size() || c >= ik_->records[f].size()) return kNoRecord;
  return ik_->records[f][c];
}

void SkeletonPlayer::set_ik_target(std::size_t c, const Vec3& target) {
  IkChainState& chain = ik_->chains.at(c);
  chain.moved = true;
  chain.target = target;
  playing_ = false;
  ik_->dirty = true;
}

void SkeletonPlayer::set_ik_bones(std::size_t c, int start, int end) {
  IkChainState& chain = ik_->chains.at(c);
  const int n = static_cast<int>(skeleton().bones.size());
  if (start < 0 || start >= n || end < 0 || end >= n) return;
  if (!chain.moved) chain.target = ik_target(c);  // the ball stays where it is
  chain.moved = true;
  chain.start = start;
  chain.end = end;
  find_bones(skeleton(), tasks_, chain);
  playing_ = false;
  ik_->dirty = true;
}

const skeleton::IkSettings& SkeletonPlayer::ik_settings() const {
  static const skeleton::IkSettings none{};
  return ik_ ? ik_->settings : none;
}

void SkeletonPlayer::set_ik_settings(const skeleton::IkSettings& settings) {
  ik_->settings = settings;
  playing_ = false;
  ik_->dirty = true;
}

void SkeletonPlayer::ik_reset() {
  if (!ik_) return;
  problem_.clear();
  solve_ik_scene();
}

bool SkeletonPlayer::ik_update() {
  if (!ik_ || !ik_->dirty) return false;
  ik_->dirty = false;
  const auto f = static_cast<std::size_t>(frame());
  if (f >= output_.frames.size() || f >= ik_->records.size()) return false;
  Posture& posture = output_.frames[f];
  for (std::size_t c = 0; c < ik_->chains.size(); ++c) {
    const IkChainState& chain = ik_->chains[c];
    IkSolveRecord record;
    ++ik_->solves;
    if (!chain.chain_error.empty()) {
      record.error = chain.chain_error;
      ik_->records[f][c] = std::move(record);
      continue;
    }
    IkSolveRequest request;
    request.start_bone = chain.start;
    request.end_bone = chain.end;
    request.target = ik_target(c);
    request.settings = ik_->settings;
    request.where = "the viewer, output frame " + std::to_string(frame()) + ", chain " +
                    std::to_string(c) + " (" + name_of(skeleton(), chain.start) + " -> " +
                    name_of(skeleton(), chain.end) + ")";
    request.errors = &record.errors;
    Posture trial = posture;  // a task that throws half-way leaves the shown posture as it was
    try {
      record.result = solve_ik(skeleton(), tasks_, request, trial);
      record.solved = true;
      posture = std::move(trial);
    } catch (const std::exception& e) {
      record.error = e.what();
    }
    ik_->records[f][c] = std::move(record);
  }
  shown_cache_->key = -1;
  return true;
}

long SkeletonPlayer::ik_solve_count() const { return ik_ ? ik_->solves : 0; }

}  // namespace jelly
