#include "similarity.hpp"

#include <iostream>
#include <stdexcept>

#include "commands.hpp"
#include "submissions.hpp"

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

int similarity_command(const GradeConfig& config, const std::string& dir, const std::string& out,
                       double threshold) {
  // The same submissions, with the same ids, as batch grades (a Gradescope export, Classroom
  // clones, a folder of folders).
  std::vector<SimilarityInput> inputs;
  for (const Submission& s : find_submissions(dir))
    if (s.problem.empty()) inputs.push_back({s.id, s.dir});
  if (inputs.size() < 2)
    throw std::runtime_error(dir + ": holds " + std::to_string(inputs.size()) +
                             " submission folders; comparing needs at least two (one folder "
                             "per student)");
  return similarity(config, inputs, out, threshold);
}

}  // namespace jelly::grade
