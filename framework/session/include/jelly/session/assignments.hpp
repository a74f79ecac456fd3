// Which linked assignment runs a scene, and its manifest and task table
// (jelly/linked_assignments.hpp).
//
// A scene's body ([body] type, a registered body kind: jelly/body_kind.hpp) names what it
// simulates; the assignment whose manifest claims it in `bodies` runs it: an entry "kind" claims
// every scene of the kind, "kind:variant" only those whose variant (the kind's scene_variant) is
// variant, so that two assignments can share a kind. Several assignments can be linked into one
// program (the viewer, the CLI): each runs its own scenes with its own tasks.
#pragma once

#include <cstddef>
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

/// The index in `manifests` of the only one that claims a scene of body kind `kind` and variant
/// `variant` (AssignmentManifest::claims). Throws std::runtime_error when none does (naming the
/// kind, the variant, the entries that would claim it and the manifests' ids) or several do
/// (naming them).
std::size_t claimant(const std::vector<const AssignmentManifest*>& manifests, std::string_view kind,
                     std::string_view variant);

/// The linked assignment that runs `scene`: the claimant among the linked assignments' manifests
/// of its body kind and that kind's scene_variant(scene). Throws as claimant does.
const LinkedAssignment& assignment_for(const SceneSpec& scene);

/// The task table `scene` runs with (assignment_for(scene).tasks()).
TaskTable tasks_for(const SceneSpec& scene);

/// The probe of every task of `assignment` (jelly/task_probe.hpp).
std::vector<TaskStatus> probe_assignment(const LinkedAssignment& assignment);

}  // namespace jelly::session
