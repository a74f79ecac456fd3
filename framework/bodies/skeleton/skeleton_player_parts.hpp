// Internal to the skeleton kind: the parts of a SkeletonPlayer (jelly/skeleton_player.hpp) that
// skeleton_player.cpp and skeleton_player_ik.cpp (an ik scene's live solves) share.
#pragma once

#include <vector>

#include "jelly/skeleton_player.hpp"
#include "skeleton_play.hpp"

namespace jelly {

struct SkeletonPlayer::Inputs {
  bodies::SkeletonInputs files;
};

/// The bone frames of one frame, kept until another frame is asked for.
struct SkeletonPlayer::Cache {
  int key = -1;
  bool ok = false;
  skeleton::BoneFrames frames;
};

/// What the viewer edits of an ik scene, and each solve's record per output frame and chain.
struct SkeletonPlayer::Ik {
  SceneSpec scene;                   ///< as built (Reset's chains, targets and settings)
  std::vector<IkChainSpec> specs;    ///< the scene's chains (names, schedules)
  std::vector<IkChainState> chains;  ///< as the viewer edits them
  skeleton::IkSettings settings;     ///< as the viewer edits them
  std::vector<std::vector<IkSolveRecord>> records;  ///< [output frame][chain]
  bool dirty = false;                               ///< something changed since the last solve
  long solves = 0;                                  ///< live solves made
};

}  // namespace jelly
