// "Who copied": the task files of every pair of submissions compared with Dick Grune's lexical
// similarity tester (`sim_c++`, Debian package similarity-tester), which compares token streams and
// so sees through renamed identifiers, moved whitespace and changed comments. Lines of the stubs do
// not count. The result is evidence for a person to read, never a verdict (docs/grader.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "inputs/config.hpp"

namespace jelly::grade {

/// One submission: who (a folder name, an LMS or Gradescope id; shown escaped) and its folder,
/// where the task files are found as the build finds them (by name, else by an LMS bulk-download
/// name, config.hpp lms_name).
struct SimilarityInput {
  std::string id;
  std::filesystem::path folder;
};

struct SimilarityOptions {
  /// A pair is listed when at least this share (percent) of either side's own lines lies in
  /// regions the other side shares. 50: measured in docs/grader.md ("Looking for copied code").
  double threshold = 50.0;
  /// sim_c++ -r: the shortest shared run of tokens that counts. 24 is sim's default.
  int min_run = 24;
  /// Wall-clock limit of one sim_c++ run (one per task file, over the whole class).
  double timeout_s = 600.0;
};

/// sim_c++ on PATH; throws std::runtime_error naming the package to install when it is not there
/// (batch --similarity asks before grading, not after).
std::filesystem::path similarity_tool();

/// Compares the selected assignment's task files of every pair of `inputs` (sim_c++ once per task
/// file, over the whole set) and writes similarity.html and similarity.json into `out` (created;
/// each written atomically). Returns the number of pairs at or above the threshold. Throws
/// std::runtime_error when sim_c++ is missing (naming the package), fails or exceeds its limit.
int write_similarity(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
                     const std::filesystem::path& out, const SimilarityOptions& options = {});

}  // namespace jelly::grade
