#include "class/similarity.hpp"

#include <iostream>
#include <set>
#include <stdexcept>

#include "commands/commands.hpp"
#include "inputs/submissions.hpp"

namespace jelly::grade {

int similarity(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
               const std::string& out, double threshold) {
  SimilarityOptions options;
  options.threshold = threshold;
  const int flagged = write_similarity(config, inputs, out, options);
  std::cout << "jelly-grade: compared " << inputs.size() << " submissions; " << flagged
            << (flagged == 1 ? " pair shares" : " pairs share") << " at least " << threshold
            << " % of its code: " << (fs::path(out) / "similarity.html").string()
            << " (evidence for a person to read, not a verdict)\n";
  return 0;
}

std::vector<SimilarityInput> similarity_inputs(const std::vector<Submission>& subs) {
  // One entry per folder: the members of a Gradescope group share one (it is not a copy).
  std::vector<SimilarityInput> inputs;
  std::set<fs::path> seen;
  for (const Submission& s : subs)
    if (s.problem.empty() && seen.insert(s.dir).second) inputs.push_back({s.id, s.dir});
  return inputs;
}

int similarity_command(const GradeConfig& config, const std::string& dir, const std::string& out,
                       double threshold) {
  // The same submissions, with the same ids, as batch grades (a Gradescope export, Classroom
  // clones, a folder of folders).
  const std::vector<SimilarityInput> inputs =
      similarity_inputs(find_submissions(dir, fs::path(out) / ".submissions"));
  if (inputs.size() < 2)
    throw std::runtime_error(dir + ": holds " + std::to_string(inputs.size()) +
                             " submissions that can be read; comparing needs at least two (one "
                             "folder per student)");
  return similarity(config, inputs, out, threshold);
}

}  // namespace jelly::grade
