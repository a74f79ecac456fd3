#include "jelly/session/assignments.hpp"

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

const LinkedAssignment& assignment_for(const SceneSpec& scene) {
  const std::string_view body = body_name(scene.body_kind);
  const LinkedAssignment* found = nullptr;
  std::string all;
  for (const LinkedAssignment& a : linked_assignments()) {
    const auto& bodies = manifest_of(a).bodies;
    if (std::find(bodies.begin(), bodies.end(), body) == bodies.end()) continue;
    all += (all.empty() ? "" : ", ") + std::string(a.id);
    if (found)
      throw std::runtime_error("the scene's " + std::string(body) +
                               " body is simulated by several assignments (" + all +
                               "); build one of them only (docs/new-assignment.md)");
    found = &a;
  }
  if (!found)
    throw std::runtime_error("no assignment in this program simulates a " + std::string(body) +
                             " body (it has: " + linked_ids() + ")");
  return *found;
}

TaskTable tasks_for(const SceneSpec& scene) { return assignment_for(scene).tasks(); }

std::vector<TaskStatus> probe_assignment(const LinkedAssignment& assignment) {
  return probe_tasks(manifest_of(assignment), assignment.tasks());
}

}  // namespace jelly::session
