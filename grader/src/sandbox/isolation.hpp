// Where a submission's compiler, assembler, linker and runner run: somewhere the grader's secrets
// (hidden reference data, case files with hidden parameters, the reference runner, solutions/,
// other submissions' objects) cannot be read. The operating system is the defence, chosen once per
// jelly-grade run (docs/grader.md, "The sandbox: threat model"):
//   bwrap  bubblewrap: new user, mount, pid, network and IPC namespaces with a minimal read-only
//          view (toolchain, public headers, the objects it links) plus the submission's own folder;
//   user   when the grader runs as root and bwrap is unusable (containers without user
//          namespaces): every concurrent run drops to a user of its own (jelly-sandbox-N), with
//          its submission's group; the checkout and the build tree are closed to other users
//          except what a submission is compiled and linked with (deny by default, modes restored
//          afterwards); every run gets a private empty temporary folder, and whatever it left
//          (processes, files in /tmp, /var/tmp, /dev/shm, System V IPC) is removed after it;
//   none   neither: grading goes on with a loud warning that hidden tests are not protected.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "inputs/config.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

enum class IsolationKind { Bwrap, User, None };

/// The sandbox's state for one jelly-grade run: its users, cgroups, private scratch folder and the
/// modes it changed (restored when the last copy of the Isolation goes). isolation.cpp.
class SandboxPool;

struct Isolation {
  IsolationKind kind = IsolationKind::None;
  std::string name = "none";      ///< "bwrap", "user" or "none": what reports print
  std::string description;        ///< one sentence for reports
  std::string warning;            ///< non-empty when hidden tests are not protected
  std::string bwrap;              ///< path of bwrap (kind Bwrap)
  int uid = -1, gid = -1;         ///< the unprivileged user (kind User)
  std::string user;               ///< its name
  std::vector<fs::path> secrets;  ///< hidden inside every sandbox
  std::string caps;               ///< how each run's memory and processes are capped (reports)
  std::shared_ptr<SandboxPool> pool;
};

/// What one sandboxed command may see: paths bound read-only (files or folders), folders bound
/// writable, and its working folder. Paths keep their names inside (messages stay readable).
/// `cwd` empty: the run's own private temporary folder. `gid`: the group of the submission the run
/// belongs to (kind User; Workspace::gid()).
struct SandboxView {
  std::vector<fs::path> read_only;
  std::vector<fs::path> writable;
  fs::path cwd;
  int gid = -1;
};

/// The users the "user" mechanism drops to are kSandboxUser + "-" + N, one per concurrent run
/// (jelly-sandbox-0, -1, ...); setup.sh / run_autograder create them, jelly-grade creates any that
/// is missing (useradd).
inline constexpr const char* kSandboxUser = "jelly-sandbox";

/// What each run may use at most, all its processes together (a cgroup where the kernel lets us
/// make one; else RLIMIT_NPROC per sandbox user, or in bwrap's own user namespace).
inline constexpr std::size_t kRunProcesses = 64;

/// One submission's files while it is graded. Kind User: a folder of the sandbox's private
/// scratch, owned by root and a group of its own that only this submission's runs get, so no
/// other submission graded at the same time can read it; removed at the end. Other kinds: `dir`.
class Workspace {
 public:
  Workspace(const Isolation& iso, const fs::path& dir);
  ~Workspace();
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;
  const fs::path& dir() const { return dir_; }
  int gid() const { return gid_; }

 private:
  const Isolation& iso_;
  fs::path dir_;
  int gid_ = -1;
  bool scratch_ = false;
};

/// Picks the mechanism: `mode` is auto, bwrap, user or none. auto tries bwrap (a real probe), then
/// user (when root), then none. A forced mechanism that cannot work is a std::runtime_error saying
/// why. First ends whatever a grader that is gone left (processes in its cgroups, of sandbox users
/// whose lock nobody holds); makes the run's cgroups where it can (every mode) and forks their
/// keeper (lane_keeper.hpp), which ends them if this process dies. For "user", closes the checkout
/// and the build tree to other users except what a submission is compiled and linked with (deny by
/// default; the modes are restored when the last copy of the Isolation goes) and makes a private
/// scratch folder.
Isolation choose_isolation(const GradeConfig& config, const std::string& mode);

/// Runs `argv` isolated, in a lane of its own (a sandbox user in user mode; a cgroup where one can
/// be made): capped as a whole (memory, kRunProcesses, one core's CPU time where there is a cpu
/// cgroup), and when it ends every process it left is
/// killed, its private folder and whatever its user left in /tmp, /var/tmp, /dev/shm and System V
/// IPC removed (ChildResult says what was found). A process that bubblewrap reports as exit
/// status 128 + N is reported as ended by signal N, as it would be without the sandbox.
ChildResult run_isolated(const Isolation& iso, const std::vector<std::string>& argv,
                         const SandboxView& view, Limits limits);

/// Makes `dir` (created) and everything in it writable by the submission's group `gid` (kind User),
/// so that its compiler and linker can write there; throws when the sandbox users cannot reach it.
void give_to_sandbox(const Isolation& iso, const fs::path& dir, int gid = -1);

/// After building: `dir` and everything in it read-only for the group (kind User), so that no test
/// can change the runner or leave a file for a later test.
void seal_for_sandbox(const Isolation& iso, const fs::path& dir, int gid = -1);

}  // namespace jelly::grade
