// Isolation off Linux (Windows, macOS): there is no bubblewrap and no sandbox user, so the only
// mechanism is "none". jelly-grade runs there as the student's self-check, on the student's own
// code on the student's own machine (docs/platforms.md); the course's grader runs on Linux
// (isolation.cpp).
#include <stdexcept>

#include "sandbox/isolation.hpp"

namespace jelly::grade {

Isolation choose_isolation(const GradeConfig&, const std::string& mode) {
  if (mode != "auto" && mode != "none")
    throw std::runtime_error("--isolation " + mode +
                             " needs Linux (bubblewrap or a sandbox user); here only "
                             "--isolation none (the self-check on your own code) is available");
  Isolation iso;
  iso.description = "none (not Linux: no sandbox here)";
  iso.caps = "memory per process only; no process cap";
  return iso;
}

ChildResult run_isolated(const Isolation& iso, const std::vector<std::string>& argv,
                         const SandboxView& view, Limits limits) {
  (void)iso;
  return run_child(argv, limits, view.cwd);
}

Workspace::Workspace(const Isolation& iso, const fs::path& dir) : iso_(iso), dir_(dir) {
  fs::create_directories(dir_);
}

Workspace::~Workspace() = default;

void give_to_sandbox(const Isolation&, const fs::path& dir, int) { fs::create_directories(dir); }

void seal_for_sandbox(const Isolation&, const fs::path&, int) {}

}  // namespace jelly::grade
