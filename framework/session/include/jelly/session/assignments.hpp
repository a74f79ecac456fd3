// Which linked assignment runs a scene, and its manifest and task table
// (jelly/linked_assignments.hpp).
//
// A scene's body ([body] type, a registered body kind: jelly/body_kind.hpp) names what it
// simulates; the assignment whose manifest lists that body in `bodies` runs it. Several
// assignments can be linked into one program (the viewer, the CLI): each runs its own scenes with
// its own tasks.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "jelly/linked_assignments.hpp"
#include "jelly/manifest.hpp"
#include "jelly/scene_spec.hpp"
#include "jelly/task_probe.hpp"
#include "jelly/task_table.hpp"

namespace jelly::session {

/// The name a manifest's `bodies` uses for a scene's body kind (the kind's `body.type`).
std::string_view body_name(BodyKind kind);

/// The linked assignment with this id. Throws std::runtime_error listing the linked ones.
const LinkedAssignment& linked_assignment(std::string_view id);

/// The manifest a linked assignment was built with (parsed once).
const AssignmentManifest& manifest_of(const LinkedAssignment& assignment);

/// The linked assignment that runs `scene`: the only one whose manifest lists the scene's body.
/// Throws std::runtime_error when none or several do, naming them.
const LinkedAssignment& assignment_for(const SceneSpec& scene);

/// The task table `scene` runs with (assignment_for(scene).tasks()).
TaskTable tasks_for(const SceneSpec& scene);

/// The probe of every task of `assignment` (jelly/task_probe.hpp).
std::vector<TaskStatus> probe_assignment(const LinkedAssignment& assignment);

}  // namespace jelly::session
