// Hints: "this looks like <a mistake of the mutation table>" on a failed test whose outputs are
// those of a known mutant. The signatures are the mutants' outputs on the PUBLIC cases they fail
// (assignments/<id>/grader/hints.json, made by `jelly-grade hints`); a student's failed public case
// whose every graded output is within the case's tolerance of a mutant's gets that mutant's
// description. Grader-side only: the file is made from the mutants (instructor-only) and the
// student release leaves it out (tools/make-student-release), so the self-check of a release shows
// no hints (docs/grader.md, "Hints").
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "grading/grade.hpp"
#include "inputs/cases.hpp"

namespace jelly::grade {

/// Format of hints.json.
inline constexpr int kHintsFormat = 1;

/// One mutant's signature: its outputs on the public cases it fails.
struct HintSignature {
  std::string mutant;       ///< "t13-wrong-weights"
  std::string task;         ///< "A1.T13"
  std::string description;  ///< "RK4 with equal weights (h/4 each)"
  /// case id → {case_hash, graded outputs ({"name": {"value": ...}})}
  std::map<std::string, std::pair<std::string, Json>> cases;
};

struct HintBook {
  std::vector<HintSignature> signatures;  ///< in mutant-name order
  bool empty() const { return signatures.empty(); }
};

/// assignments/<id>/grader/hints.json of the selected assignment.
std::filesystem::path hints_path(const GradeConfig& config);

/// Reads `path`; an absent file is an empty book (a student release). Throws std::runtime_error
/// naming the file and key when it is present but malformed.
HintBook load_hints(const std::filesystem::path& path);

/// Whether the outputs `mine` are those of `theirs` for case `spec`: every output `theirs` has,
/// within the case's tolerance for it (a range output within 1e-9; text exactly; NaN or infinity
/// only against NaN or infinity, which JSON stores as null).
bool same_outputs(const CaseSpec& spec, const Json& mine, const Json& theirs,
                  const std::map<std::string, Tolerance>& tolerances);

/// Fills CaseResult::hints of every failed case of `rep` whose outputs match a signature of the
/// same case (and the same case_hash: a case whose parameters changed since never gets a hint).
void apply_hints(const HintBook& hints, const CaseBook& book, const std::string& digest,
                 GradeReport& rep);

/// The graded outputs of a case result (the reference's names, minus informational ones), with
/// values only: what a signature stores.
Json graded_outputs(const CaseResult& c);

}  // namespace jelly::grade
