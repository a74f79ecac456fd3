#include "submissions.hpp"

#include <algorithm>

namespace jelly::grade {

namespace fs = std::filesystem;

std::vector<Submission> find_submissions(const fs::path& dir) {
  std::vector<Submission> subs;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_directory()) continue;
    Submission s;
    s.id = e.path().filename().string();
    s.dir = e.path();
    subs.push_back(std::move(s));
  }
  std::sort(subs.begin(), subs.end(),
            [](const Submission& a, const Submission& b) { return a.id < b.id; });
  return subs;
}

}  // namespace jelly::grade
