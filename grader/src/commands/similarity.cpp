#include "similarity.hpp"

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "commands.hpp"

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
  std::vector<SimilarityInput> inputs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory()) inputs.push_back({e.path().filename().string(), e.path()});
  std::sort(inputs.begin(), inputs.end(),
            [](const SimilarityInput& a, const SimilarityInput& b) { return a.folder < b.folder; });
  if (inputs.size() < 2)
    throw std::runtime_error(dir + ": holds " + std::to_string(inputs.size()) +
                             " submission folders; comparing needs at least two (one folder "
                             "per student)");
  return similarity(config, inputs, out, threshold);
}

}  // namespace jelly::grade
