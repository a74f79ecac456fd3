// Where a submission's compiler, assembler, linker and runner run: somewhere the grader's secrets
// (hidden reference data, case files with hidden parameters, the reference runner, solutions/,
// other submissions' objects) cannot be read. The operating system is the defence, chosen once per
// jelly-grade run (docs/grader.md, "The sandbox: threat model"):
//   bwrap  bubblewrap: new user, mount, pid, network and IPC namespaces with a minimal read-only
//          view (toolchain, public headers, the objects it links) plus the submission's own folder;
//   user   when the grader runs as root and bwrap is unusable (containers without user
//          namespaces): the child drops to a dedicated unprivileged user, the secrets are made
//          root-only (0700);
//   none   neither: grading goes on with a loud warning that hidden tests are not protected.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "config.hpp"
#include "process.hpp"

namespace jelly::grade {

enum class IsolationKind { Bwrap, User, None };

struct Isolation {
  IsolationKind kind = IsolationKind::None;
  std::string name = "none";      ///< "bwrap", "user" or "none": what reports print
  std::string description;        ///< one sentence for reports
  std::string warning;            ///< non-empty when hidden tests are not protected
  std::string bwrap;              ///< path of bwrap (kind Bwrap)
  int uid = -1, gid = -1;         ///< the unprivileged user (kind User)
  std::string user;               ///< its name
  std::vector<fs::path> secrets;  ///< hidden inside every sandbox
};

/// What one sandboxed command may see: paths bound read-only (files or folders), folders bound
/// writable, and its working folder. Paths keep their names inside (messages stay readable).
struct SandboxView {
  std::vector<fs::path> read_only;
  std::vector<fs::path> writable;
  fs::path cwd;
};

/// The dedicated user the "user" mechanism drops to; setup.sh / run_autograder create it.
inline constexpr const char* kSandboxUser = "jelly-sandbox";

/// Picks the mechanism: `mode` is auto, bwrap, user or none. auto tries bwrap (a real probe), then
/// user (when root), then none. A forced mechanism that cannot work is a std::runtime_error saying
/// why. For "user", makes the secrets root-only (chmod 0700) first.
Isolation choose_isolation(const GradeConfig& config, const std::string& mode);

/// The command line that runs `argv` isolated; for "user" it also sets the user, group and a clean
/// environment in `limits` (and a process limit, which only a dedicated user makes meaningful).
std::vector<std::string> isolate(const Isolation& iso, const std::vector<std::string>& argv,
                                 const SandboxView& view, Limits& limits);

/// run_child(isolate(...)): a process that bubblewrap reports as exit status 128 + N is reported
/// as ended by signal N, as it would be without the sandbox.
ChildResult run_isolated(const Isolation& iso, const std::vector<std::string>& argv,
                         const SandboxView& view, Limits limits);

/// Makes `dir` (created) and everything in it belong to the unprivileged user (kind User), so the
/// compiler and the runner can write there; throws when the user could not reach it.
void give_to_sandbox(const Isolation& iso, const fs::path& dir);

}  // namespace jelly::grade
