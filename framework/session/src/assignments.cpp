#include "jelly/session/assignments.hpp"

#include "jelly/body_kind.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <stdexcept>

namespace jelly::session {

namespace {

std::string linked_ids() {
  std::string out;
  for (const LinkedAssignment& a : linked_assignments())
    out += (out.empty() ? "" : ", ") + std::string(a.id);
  return out.empty() ? "none" : out;
}

}  // namespace

std::string_view body_name(BodyKind kind) { return kind.name; }

const LinkedAssignment& linked_assignment(std::string_view id) {
  for (const LinkedAssignment& a : linked_assignments())
    if (a.id == id) return a;
  throw std::runtime_error("no assignment \"" + std::string(id) +
                           "\" in this program (it has: " + linked_ids() + ")");
}

const AssignmentManifest& manifest_of(const LinkedAssignment& assignment) {
  // The compiled-in manifests never change: each is parsed the first time it is asked for.
  static std::mutex mutex;
  static std::map<std::string_view, AssignmentManifest> parsed;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = parsed.find(assignment.id);
  if (it == parsed.end())
    it = parsed
             .emplace(assignment.id, parse_manifest(assignment.manifest_text,
                                                    std::string(assignment.manifest_path)))
             .first;
  return it->second;
}

std::size_t claimant(const std::vector<const AssignmentManifest*>& manifests, std::string_view kind,
                     std::string_view variant) {
  const std::string body = std::string(kind) + " body" +
                           (variant.empty() ? "" : " of variant \"" + std::string(variant) + "\"");
  std::size_t found = manifests.size();
  std::string all, ids;
  for (std::size_t i = 0; i < manifests.size(); ++i) {
    ids += (ids.empty() ? "" : ", ") + manifests[i]->id;
    if (!manifests[i]->claims(kind, variant)) continue;
    all += (all.empty() ? "" : ", ") + manifests[i]->id;
    if (found < manifests.size())
      throw std::runtime_error("the scene's " + body + " is simulated by several assignments (" +
                               all + "); build one of them only (docs/new-assignment.md)");
    found = i;
  }
  if (found == manifests.size()) {
    const std::string claim = variant.empty() ? ""
                                              : " (a manifest's bodies = [\"" + std::string(kind) +
                                                    ":" + std::string(variant) + "\"] or [\"" +
                                                    std::string(kind) + "\"])";
    throw std::runtime_error("no assignment in this program simulates a " + body + claim +
                             " (it has: " + (ids.empty() ? "none" : ids) + ")");
  }
  return found;
}

const LinkedAssignment& assignment_for(const SceneSpec& scene) {
  const BodyKindModule* kind = find_body_kind(scene.body_kind.name);
  const std::string variant = kind ? kind->scene_variant(scene) : "";
  const std::vector<LinkedAssignment>& linked = linked_assignments();
  std::vector<const AssignmentManifest*> manifests;
  for (const LinkedAssignment& a : linked) manifests.push_back(&manifest_of(a));
  return linked[claimant(manifests, body_name(scene.body_kind), variant)];
}

TaskTable tasks_for(const SceneSpec& scene) { return assignment_for(scene).tasks(); }

std::vector<TaskStatus> probe_assignment(const LinkedAssignment& assignment) {
  return probe_tasks(manifest_of(assignment), assignment.tasks());
}

}  // namespace jelly::session
