// An assignment's manifest: assignments/<id>/assignment.toml (docs/new-assignment.md).
//
// One file says everything that differs between assignments: the id and title, the files a
// student edits, the reference's extra files, the scene bodies it simulates, its default scene,
// its handout, what its studies measure, its grading policy and its tasks (id, title, file,
// functions, points, handout page, probe). CMake, jelly-grade, the viewer's hints, `jelly probe`,
// the release tool and the self-check read it; general code names no task ID and no file list.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace jelly {

/// A manifest that cannot be used: the message names the file, the line and key, and what was
/// expected ("assignments/hw1/assignment.toml:12: task[3].points: expected a number ≥ 0").
class ManifestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One entry of a manifest's `bodies`: the scenes an assignment's tasks run. `"kind"` claims every
/// scene whose body kind (`[body] type`) is kind; `"kind:variant"` only those of its scenes whose
/// variant (BodyKindModule::scene_variant, jelly/body_kind.hpp) is variant, so that two
/// assignments can share a kind, each running its own variants (docs/new-assignment.md).
struct BodyClaim {
  std::string kind;     ///< a body kind's name (`[body] type`)
  std::string variant;  ///< "" for every scene of the kind
  /// Whether it claims a scene of body kind `scene_kind` whose variant is `scene_variant`.
  bool claims(std::string_view scene_kind, std::string_view scene_variant) const {
    return kind == scene_kind && (variant.empty() || variant == scene_variant);
  }
  /// As the manifest writes it: "kind" or "kind:variant".
  std::string text() const { return variant.empty() ? kind : kind + ":" + variant; }
};

/// One task of an assignment.
struct ManifestTask {
  std::string id;                      ///< "HW.T1"
  std::string title;                   ///< "Spring force" (reports, handout)
  std::string short_name;              ///< "spring force" (the viewer's hint); title if absent
  std::string category;                ///< "forces" (the report groups by it)
  std::string file;                    ///< "forces.cpp" (empty: the whole submission)
  std::vector<std::string> functions;  ///< {"spring_force"}
  double points = 0.0;                 ///< raw points (scaled to grading.autograded_total)
  std::string handout;                 ///< "handout/T4-spring-force.md", relative to the folder
  std::string probe;                   ///< the TaskTable slot the probe smoke-tests; "" = none
  /// A bonus task (`bonus = true`): its points come on top of grading.autograded_total; they
  /// are scaled as the other tasks' points are but are not part of the total the score is
  /// scaled to, and reports show them apart ("+ bonus 5.00 / 5.00").
  bool bonus = false;

  /// "spring_force (forces.cpp)", or "your code" for a task with no function of its own.
  std::string functions_text() const;
};

struct AssignmentManifest {
  std::string id;                            ///< folder name and CLI name: "hw1"
  std::string ns;                            ///< C++ namespace of the tasks: jelly::<ns>
  std::string title;                         ///< "The course's first homework"
  std::vector<std::string> files;            ///< the files a student edits, in build order
  std::vector<std::string> reference_files;  ///< the reference's extra files
  std::vector<std::string> task_modules;     ///< shared tasks' modules (solutions/tasks/<module>/)
  std::vector<BodyClaim> bodies;             ///< the scenes it runs (`bodies`), in its order
  std::string default_scene;                 ///< a scene name ("course-2023"); may be empty
  /// `draft = true`: an assignment in preparation, built but never graded, linked or released
  /// (docs/new-assignment.md, "A draft"). CMake reads it from tools/jelly_manifest.py.
  bool draft = false;
  std::string handout;                      ///< the handout's front page, relative
  std::vector<std::string> study_measures;  ///< what `jelly study effects` reports
  double autograded_total = 0.0;            ///< the points the score is scaled to
  /// The points graded by hand, apart from the autograder (A1's report): `grading.
  /// hand_graded_points`, 0 when absent. The assignment is worth autograded_total + this (bonus
  /// on top); scores.csv gives it as `hand_graded_max`, the handout quotes it.
  double hand_graded_points = 0.0;
  std::string hidden_visibility = "after_due_date";
  /// The contracts its grader's messages cite by name besides the physics contract
  /// (`contracts`): a report links "<name> contract §N" to the handout's #<name>-contract-N.
  std::vector<std::string> contracts;
  std::vector<ManifestTask> tasks;
  /// The folder the manifest was read from (empty for a manifest compiled into a program).
  std::filesystem::path dir;

  /// Whether one of its `bodies` claims a scene of kind `scene_kind` and variant `scene_variant`.
  bool claims(std::string_view scene_kind, std::string_view scene_variant) const;
  /// The task with this id, or nullptr.
  const ManifestTask* find_task(std::string_view task_id) const;
  /// The common prefix of the task IDs, e.g. "HW." (what the self-check and the release use to
  /// tell this assignment's tests from another's).
  std::string task_prefix() const;
};

/// Parses and checks a manifest's text; `source` names it in errors (a path). Throws ManifestError.
AssignmentManifest parse_manifest(std::string_view text, const std::string& source);

/// Reads `file` (…/assignment.toml) and sets `dir` to its folder. Throws ManifestError.
AssignmentManifest read_manifest(const std::filesystem::path& file);

/// Every assignment under `assignments_root` (each subfolder with an assignment.toml), sorted by
/// id, drafts included (AssignmentManifest::draft). Throws ManifestError on the first bad manifest,
/// or when two share a namespace (ids are folder names, so unique).
std::vector<AssignmentManifest> find_assignments(const std::filesystem::path& assignments_root);

/// The one assignment whose `files` are exactly `present` (file names, any order); nullptr if none
/// or several match. What jelly-grade uses to infer --assignment from a submission's files.
const AssignmentManifest* assignment_for_files(const std::vector<AssignmentManifest>& all,
                                               const std::vector<std::string>& present);

}  // namespace jelly
