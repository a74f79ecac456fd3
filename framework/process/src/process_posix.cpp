#include "jelly/process/process.hpp"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#include <sys/syscall.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>

namespace jelly::process {

namespace {

void set_limit(int resource, rlim_t value) {
  struct rlimit rl {
    value, value
  };
  setrlimit(resource, &rl);
}

// pipe2(O_CLOEXEC) where the system has it (Linux); elsewhere (macOS) pipe, then FD_CLOEXEC.
bool cloexec_pipe(int fds[2]) {
#ifdef __linux__
  return pipe2(fds, O_CLOEXEC) == 0;
#else
  if (pipe(fds) != 0) return false;
  for (int i = 0; i < 2; ++i) fcntl(fds[i], F_SETFD, FD_CLOEXEC);
  return true;
#endif
}

// A readable descriptor holding `data` that no other process can open by name: an anonymous
// in-memory file on Linux, an already-unlinked temporary file elsewhere. -1 with errno on failure;
// `what` names the call that failed.
int anonymous_input(const std::string& data, const char*& what) {
#ifdef __linux__
  what = "memfd_create";
  const int fd = static_cast<int>(syscall(SYS_memfd_create, "jelly-grade-stdin", MFD_CLOEXEC));
#else
  what = "mkstemp";
  const char* tmp = std::getenv("TMPDIR");
  std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/jelly-grade-stdin.XXXXXX";
  const int fd = mkstemp(name.data());
  if (fd >= 0) {
    unlink(name.c_str());
    fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
#endif
  if (fd < 0) return -1;
  what = "writing the child's input";
  for (std::size_t done = 0; done < data.size();) {
    const ssize_t n = write(fd, data.data() + done, data.size() - done);
    if (n <= 0) {
      close(fd);
      return -1;
    }
    done += static_cast<std::size_t>(n);
  }
  lseek(fd, 0, SEEK_SET);
  return fd;
}

// Closes every descriptor from `first` up (in the child, between fork and exec).
void close_from(int first) {
#ifdef __linux__
  syscall(SYS_close_range, static_cast<unsigned>(first), ~0U, 0U);
#else
  const long max = sysconf(_SC_OPEN_MAX);
  for (int fd = first; fd < (max > 0 && max < 65536 ? max : 65536); ++fd) close(fd);
#endif
}

// The child's stdout, stderr and (Limits::result_pipe) result channel: [0] our end, [1] its end.
struct Pipes {
  int out[2] = {-1, -1}, err[2] = {-1, -1}, res[2] = {-1, -1};
};

// false (errno set) when a pipe cannot be made.
bool open_pipes(Pipes& p, bool result_pipe) {
  return cloexec_pipe(p.out) && cloexec_pipe(p.err) && (!result_pipe || cloexec_pipe(p.res));
}

// The request (or other input) as an anonymous file: no other process can open it by name.
// `fd` is -1 when there is no input; false, with `error`, when it cannot be made.
bool open_input(const std::string& data, int& fd, std::string& error) {
  fd = -1;
  if (data.empty()) return true;
  const char* what = "";
  fd = anonymous_input(data, what);
  if (fd >= 0) return true;
  error = std::string(what) + ": " + std::strerror(errno);
  return false;
}

// What the child does between fork and exec, where it reads only this and its Limits: it may
// allocate nothing and take no lock (async-signal-safe calls only).
struct ChildPlan {
  const Limits& limits;
  Pipes pipes;
  int in_fd = -1;
  std::vector<char*> args, envp;
  std::string dir;
  std::vector<const char*> cgroups;
  rlim_t cpu = 0;
};

// Everything the child needs is prepared before fork (no allocation after it).
ChildPlan plan_child(const std::vector<std::string>& argv, const Limits& limits,
                     const std::filesystem::path& cwd, const Pipes& pipes, int in_fd) {
  ChildPlan plan{limits, pipes, in_fd, {}, {}, {}, {}, 0};
  for (const std::string& a : argv) plan.args.push_back(const_cast<char*>(a.c_str()));
  plan.args.push_back(nullptr);
  for (const std::string& e : limits.env) plan.envp.push_back(const_cast<char*>(e.c_str()));
  plan.envp.push_back(nullptr);
  plan.dir = cwd.string();
  for (const std::string& c : limits.cgroup_procs) plan.cgroups.push_back(c.c_str());
  plan.cpu = static_cast<rlim_t>(limits.cpu_s > 0 ? limits.cpu_s : limits.timeout_s + 1.0);
  return plan;
}

// In the child: joins each cgroup; one it cannot join ends it (124) rather than run uncapped.
void join_cgroups(const std::vector<const char*>& cgroups) {
  for (const char* procs : cgroups) {
    const int fd = open(procs, O_WRONLY | O_CLOEXEC);
    if (fd < 0 || write(fd, "0", 1) != 1) _exit(124);
    close(fd);
  }
}

// In the child: its input on fd 0, the pipes on 1, 2 (and 3), and no other descriptor.
void take_streams(const ChildPlan& plan) {
  const int input = plan.in_fd >= 0 ? plan.in_fd : open("/dev/null", O_RDONLY);
  if (input >= 0) dup2(input, 0);
  dup2(plan.pipes.out[1], 1);
  dup2(plan.pipes.err[1], 2);
  if (plan.limits.result_pipe) dup2(plan.pipes.res[1], 3);
  // Nothing else of the grader is inherited (other jobs' pipes, open files).
  close_from(plan.limits.result_pipe ? 4 : 3);
}

// In the child: its resource limits.
void set_limits(const Limits& limits, rlim_t cpu) {
  set_limit(RLIMIT_CORE, 0);
  set_limit(RLIMIT_CPU, cpu);
  if (limits.memory_bytes > 0) set_limit(RLIMIT_AS, limits.memory_bytes);
  if (limits.limit_files) set_limit(RLIMIT_FSIZE, limits.file_size_bytes);
  if (limits.max_open_files > 0) set_limit(RLIMIT_NOFILE, limits.max_open_files);
  if (limits.max_processes > 0) set_limit(RLIMIT_NPROC, limits.max_processes);
}

// In the child: the sandbox user and group, when asked for (125 when they cannot be taken).
void drop_privileges(const Limits& limits) {
  if (limits.run_as_gid >= 0 || limits.run_as_uid >= 0) {
    // No way back: supplementary groups dropped, then the group, then the user.
    if (setgroups(0, nullptr) != 0) _exit(125);
    if (limits.run_as_gid >= 0 && setgid(static_cast<gid_t>(limits.run_as_gid)) != 0) _exit(125);
    if (limits.run_as_uid >= 0 && setuid(static_cast<uid_t>(limits.run_as_uid)) != 0) _exit(125);
    if (limits.run_as_uid != 0 && setuid(0) == 0) _exit(125);
  }
}

// In the child: 128 when the grader is already gone.
void die_with_parent(pid_t parent) {
#ifdef __linux__
  // The child ends with the grader: a batch stopped by Ctrl-C, a scheduler's SIGTERM or SIGKILL
  // leaves no compiler, renderer or test running (bwrap's --die-with-parent takes the sandbox
  // with it). Set after the change of user, which clears it; the grader may be gone already.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(128);
#else
  (void)parent;
#endif
}

// In the child: the program, in its working folder (126, 127 when they cannot be reached).
[[noreturn]] void exec_program(const ChildPlan& plan) {
  if (!plan.dir.empty() && chdir(plan.dir.c_str()) != 0) _exit(126);
  if (plan.limits.env.empty())
    execv(plan.args[0], plan.args.data());
  else
    execve(plan.args[0], plan.args.data(), plan.envp.data());
  const char msg[] = "jelly-grade: cannot execute the program\n";
  ssize_t ignored = write(2, msg, sizeof msg - 1);
  (void)ignored;
  _exit(127);
}

// The child, from fork to exec: its own process group, its cgroups, streams, limits and user,
// then the program. Only async-signal-safe calls on what the plan prepared.
[[noreturn]] void become_child(const ChildPlan& plan, pid_t parent) {
  setpgid(0, 0);
  join_cgroups(plan.cgroups);
  take_streams(plan);
  set_limits(plan.limits, plan.cpu);
  drop_privileges(plan.limits);
  die_with_parent(parent);
  exec_program(plan);
}

// In the parent, once the child has started: our copies of the child's ends are closed.
void close_child_ends(const ChildPlan& plan) {
  if (plan.in_fd >= 0) close(plan.in_fd);
  close(plan.pipes.out[1]);
  close(plan.pipes.err[1]);
  if (plan.limits.result_pipe) close(plan.pipes.res[1]);
}

// Watches a started child to its end: reads its pipes (keeping what the caps allow), kills its
// process group on timeout or output flood, reaps it, then reads what is left for drain_s.
class ChildWatch {
 public:
  ChildWatch(pid_t pid, const Pipes& pipes, const Limits& limits, ChildResult& r,
             std::chrono::steady_clock::time_point start);
  ChildWatch(const ChildWatch&) = delete;
  ChildWatch& operator=(const ChildWatch&) = delete;
  /// Until the child is reaped and its pipes are read to their end (or abandoned).
  void run();
  /// Closes what is still open; the exit status and the wall time into the result.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  using Deadline = decltype(Clock::time_point{} + std::chrono::duration<double>{});
  struct Stream {
    int fd;
    std::string* keep;
    std::size_t* count;
    bool unlimited;
  };
  void kill_group();
  void reap();
  std::vector<pollfd> poll_set() const;
  int wait_ms(Clock::time_point now) const;
  void read_ready(const std::vector<pollfd>& fds);
  void take_output(Stream& s, const char* buf, std::size_t g);

  pid_t pid_;
  const Limits& limits_;
  ChildResult& r_;
  Clock::time_point start_;
  std::vector<Stream> streams_;
  std::size_t result_bytes_ = 0;
  int pidfd_ = -1;
  Deadline deadline_;
  bool killed_ = false, exited_ = false;
  int status_ = 0;
  Clock::time_point drain_until_{};
};

ChildWatch::ChildWatch(pid_t pid, const Pipes& pipes, const Limits& limits, ChildResult& r,
                       std::chrono::steady_clock::time_point start)
    : pid_(pid), limits_(limits), r_(r), start_(start) {
  streams_ = {{pipes.out[0], &r.out, &r.out_bytes, false},
              {pipes.err[0], &r.err, &r.err_bytes, false}};
  if (limits.result_pipe) streams_.push_back({pipes.res[0], &r.result, &result_bytes_, true});
    // The child's end is watched as well as its pipes: a process it left behind (setsid, double
    // fork) may hold a copy of them, and must neither keep us reading nor outlive the run.
#if defined(__linux__) && defined(SYS_pidfd_open)
  pidfd_ = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
#endif
  deadline_ = start + std::chrono::duration<double>(limits.timeout_s);
}

void ChildWatch::run() {
  while (!streams_.empty() || !exited_) {
    const auto now = Clock::now();
    if (!killed_ && now >= deadline_) {
      r_.timed_out = true;
      kill_group();
    }
    if (!exited_) reap();
    if (exited_ && streams_.empty()) break;
    if (exited_ && Clock::now() >= drain_until_) {
      r_.pipes_held = true;  // someone kept a copy: what was read is all there is
      break;
    }
    std::vector<pollfd> fds = poll_set();
    const int n = poll(fds.data(), fds.size(), wait_ms(now));
    if (n < 0 && errno != EINTR) break;
    read_ready(fds);
  }
}

void ChildWatch::kill_group() {
  kill(-pid_, SIGKILL);
  kill(pid_, SIGKILL);
  killed_ = true;
}

// Once the child has exited (or is gone): what it left behind is ended, its pipes drained.
void ChildWatch::reap() {
  pid_t w;
  while ((w = waitpid(pid_, &status_, WNOHANG)) < 0 && errno == EINTR) {
  }
  if (w == pid_ || (w < 0 && errno == ECHILD)) {
    exited_ = true;
    if (limits_.end_leftovers) limits_.end_leftovers();
    drain_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(limits_.drain_s));
  }
}

// The open pipes, then the child's pidfd while it runs.
std::vector<pollfd> ChildWatch::poll_set() const {
  std::vector<pollfd> fds;
  for (const Stream& s : streams_) fds.push_back({s.fd, POLLIN, 0});
  if (pidfd_ >= 0 && !exited_) fds.push_back({pidfd_, POLLIN, 0});
  return fds;
}

// How long poll waits: until the drain's end, the deadline, or a second once killed.
int ChildWatch::wait_ms(Clock::time_point now) const {
  double left_s = exited_   ? std::chrono::duration<double>(drain_until_ - now).count()
                  : killed_ ? 1.0
                            : std::chrono::duration<double>(deadline_ - now).count();
  if (pidfd_ < 0 && !exited_) left_s = std::min(left_s, 0.05);  // no pidfd: look every 50 ms
  return static_cast<int>(std::max(0.0, left_s) * 1000.0) + 1;
}

// Reads each pipe poll found ready; one at its end is closed and no longer watched.
void ChildWatch::read_ready(const std::vector<pollfd>& fds) {
  char buf[65536];
  for (std::size_t i = streams_.size(); i-- > 0;) {
    if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    const ssize_t got = read(fds[i].fd, buf, sizeof buf);
    Stream& s = streams_[i];
    if (got <= 0) {
      close(s.fd);
      streams_.erase(streams_.begin() + static_cast<long>(i));
      continue;
    }
    take_output(s, buf, static_cast<std::size_t>(got));
  }
}

// Counts `g` bytes read, keeps them up to the stream's cap, kills the child on an output flood.
void ChildWatch::take_output(Stream& s, const char* buf, std::size_t g) {
  *s.count += g;
  const std::size_t cap = s.unlimited ? (16ULL << 20) : limits_.keep_output;
  if (s.keep->size() < cap) s.keep->append(buf, std::min(g, cap - s.keep->size()));
  if (!killed_ && r_.out_bytes + r_.err_bytes > limits_.kill_output) {
    r_.output_flood = true;
    kill_group();
  }
}

void ChildWatch::finish() {
  for (const Stream& s : streams_) close(s.fd);
  if (pidfd_ >= 0) close(pidfd_);
  if (WIFEXITED(status_)) r_.exit_code = WEXITSTATUS(status_);
  if (WIFSIGNALED(status_)) r_.signal = WTERMSIG(status_);
  r_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const Limits& limits,
                      const std::filesystem::path& cwd) {
  ChildResult r;
  Pipes pipes;
  if (!open_pipes(pipes, limits.result_pipe)) {
    r.start_error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  int in_fd = -1;
  if (!open_input(limits.stdin_data, in_fd, r.start_error)) return r;
  const ChildPlan plan = plan_child(argv, limits, cwd, pipes, in_fd);

  const auto start = std::chrono::steady_clock::now();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    r.start_error = std::string("fork: ") + std::strerror(errno);
    if (in_fd >= 0) close(in_fd);
    return r;
  }
  if (pid == 0) become_child(plan, parent);
  setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  r.started = true;
  close_child_ends(plan);

  ChildWatch watch(pid, pipes, limits, r, start);
  watch.run();
  watch.finish();
  return r;
}

}  // namespace jelly::process
