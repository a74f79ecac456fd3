// What the skeleton's render tests share: a run of a course scene by name, and its player.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "jelly/skeleton_player.hpp"

namespace jelly::render {

/// A run of the course scene `name` with `tasks` (the scene's assignment's when null).
inline std::unique_ptr<session::SimulationRun> run_of(const std::string& name,
                                                      const TaskTable* tasks = nullptr) {
  SceneResult scene = session::resolve_scene(name, session::default_scenes_dir());
  EXPECT_TRUE(scene) << scene.error->text();
  if (!scene) return nullptr;
  const session::RunSetup setup = session::RunSetup::from_scene(*scene.scene);
  return std::make_unique<session::SimulationRun>(setup,
                                                  tasks ? *tasks : session::tasks_for(setup.scene));
}

/// The skeleton player of a run's world.
inline SkeletonPlayer& player_of(session::SimulationRun& run) {
  SkeletonPlayer* p = find_skeleton_player(run.simulator()->world());
  EXPECT_NE(p, nullptr);
  return *p;
}

}  // namespace jelly::render
