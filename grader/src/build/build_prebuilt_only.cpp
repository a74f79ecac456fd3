// Compiling a submission off POSIX (Windows): jelly-grade does not call the compiler there. The
// student's runner is built by CMake (target jelly-grade-student-runner) and graded with
// `jelly-grade grade DIR --runner FILE`, which is what the `selfcheck` target does.
#include <stdexcept>

#include "build/build.hpp"

namespace jelly::grade {

BuildResult build_submission(const GradeConfig&, const fs::path& submission, const fs::path&, int,
                             const Isolation&, const BuildLimits&, int) {
  throw std::runtime_error(
      "on Windows jelly-grade does not compile " + submission.string() +
      " itself: build and run the self-check with `cmake --build --preset student --target "
      "selfcheck` (or the `selfcheck` target in your IDE), or pass a runner built by CMake "
      "with --runner FILE");
}

}  // namespace jelly::grade
