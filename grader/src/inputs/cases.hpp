// Case specifications (assignments/<id>/grader/cases/*.toml), named tolerances, the rubric (the
// manifest's [grading] and [[task]] points) and the stored reference data
// (assignments/<id>/grader/data/public/, grader/data/<id>/hidden/: <case>.json).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "inputs/config.hpp"

namespace jelly::grade {

using Json = nlohmann::ordered_json;

/// |a − b| ≤ atol + rtol·|b| (b: the reference), with the reason it is what it is.
struct Tolerance {
  std::string name;
  double atol = 0.0;
  double rtol = 0.0;
  std::string why;
};

/// How one output is judged. Info: stored as reference data and shown, never failed. Frames:
/// neither graded nor stored as reference data (recorded positions the report renders; the
/// reference's are made by running the reference runner when the report is written).
struct Rule {
  enum class Kind { Tolerance, Range, Info, Frames } kind = Kind::Tolerance;
  std::string tolerance;      ///< Kind::Tolerance (text outputs always compare exactly)
  double lo = 0.0, hi = 0.0;  ///< Kind::Range: lo ≤ value ≤ hi (literal, not from the reference)
};

struct CaseSpec {
  std::string id;
  std::string task;     ///< "A1.T4"
  std::string title;    ///< one line for reports
  double weight = 1.0;  ///< share of its task's points
  bool hidden = false;
  double timeout_s = 0.0;  ///< 0: the command-line default
  std::string generator;   ///< the runner's case generator (runner --list)
  /// What a column of a 3×N output is in messages ("[bone 4, y]"); "" numbers entries alone.
  std::string element = "particle";
  Json params = Json::object();  ///< the generator's parameters: every input the case feeds the
                                 ///< student's code
  std::string tolerance;         ///< default rule for every output
  std::vector<std::pair<std::string, Rule>> rules;  ///< output-name pattern → rule (first match)
  std::string source;                               ///< file it came from
  int line = 0;                                     ///< the line of its [[case]] in that file

  const Rule rule_for(const std::string& output) const;
};

struct TaskSpec {
  std::string id;         ///< "A1.T4"
  std::string title;      ///< "Spring force"
  std::string category;   ///< "forces"
  std::string functions;  ///< the student's functions, for crash messages
  std::string file;       ///< the file that holds them ("" for the whole submission)
  double points = 0.0;    ///< rubric points (before scaling)
  bool bonus = false;     ///< its points come on top of autograded_total (manifest `bonus`)
};

struct Rubric {
  double autograded_total = 80.0;   ///< the points the score is scaled to
  double hand_graded_points = 0.0;  ///< graded by hand, apart (manifest grading.hand_graded_points)
  std::string hidden_visibility = "after_due_date";  ///< Gradescope visibility of hidden tests
  std::vector<TaskSpec> tasks;                       ///< in report order
  /// The raw points of the tasks that are not bonus tasks (what autograded_total stands for).
  double raw_total() const;
  /// Raw points → scaled points, for every task (a bonus task's too: its points are on the same
  /// scale as the others', on top of autograded_total).
  double scale() const { return raw_total() > 0 ? autograded_total / raw_total() : 0.0; }
  const TaskSpec* find(const std::string& id) const;
};

struct CaseBook {
  std::map<std::string, Tolerance> tolerances;
  std::vector<CaseSpec> cases;  ///< in file order
  Rubric rubric;
};

/// Loads every case file of the assignment and its manifest's rubric (or `rubric_path`); throws
/// std::runtime_error naming the file and key on any problem (unknown tolerance, task, ...).
CaseBook load_case_book(const GradeConfig& config, const std::string& rubric_path = {});

/// "FILE:LINE" of a case's [[case]] entry, for messages about it (the file's full path).
std::string case_location(const GradeConfig& config, const CaseSpec& spec);

/// The reference data of one case, or nullopt when its file is absent (hidden data in a release).
std::optional<Json> load_reference(const GradeConfig& config, const CaseSpec& spec);
std::filesystem::path reference_path(const GradeConfig& config, const CaseSpec& spec);

/// Format of the reference data files.
inline constexpr int kReferenceFormat = 1;

/// 64-bit FNV-1a (jelly/fnv1a.hpp, with the grader's own offset basis) as 16 hex digits.
std::string fnv_hex(const std::string& text);
/// Digest of the runner's generator code (the files directly in grader/runner/ except the runner's
/// main.cpp and its seccomp sandbox.{hpp,cpp}, which do not change any output; those in
/// framework/bodies/<kind>/grader/ of each kind the manifest's `bodies` claim; those in the
/// assignment's grader/runner/): the reference data records it, and grading refuses data
/// generated from different generator code. It holds no case parameters, so a student release
/// (public cases only) computes the same digest.
std::string harness_digest(const GradeConfig& config);
/// Hash identifying one case: its id, generator, its own parameters and the harness digest. Grading
/// refuses reference data whose case_hash differs (the case's parameters changed).
std::string case_hash(const CaseSpec& spec, const std::string& digest);

}  // namespace jelly::grade
