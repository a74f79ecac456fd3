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

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const Limits& limits,
                      const std::filesystem::path& cwd) {
  ChildResult r;
  int out_pipe[2], err_pipe[2], res_pipe[2] = {-1, -1};
  if (!cloexec_pipe(out_pipe) || !cloexec_pipe(err_pipe) ||
      (limits.result_pipe && !cloexec_pipe(res_pipe))) {
    r.start_error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  // The request (or other input) as an anonymous file: no other process can open it by name.
  int in_fd = -1;
  if (!limits.stdin_data.empty()) {
    const char* what = "";
    in_fd = anonymous_input(limits.stdin_data, what);
    if (in_fd < 0) {
      r.start_error = std::string(what) + ": " + std::strerror(errno);
      return r;
    }
  }
  // Everything the child needs is prepared before fork (no allocation after it).
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<char*> envp;
  for (const std::string& e : limits.env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  const std::string dir = cwd.string();
  std::vector<const char*> cgroups;
  for (const std::string& c : limits.cgroup_procs) cgroups.push_back(c.c_str());
  const rlim_t cpu = static_cast<rlim_t>(limits.cpu_s > 0 ? limits.cpu_s : limits.timeout_s + 1.0);

  const auto start = std::chrono::steady_clock::now();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    r.start_error = std::string("fork: ") + std::strerror(errno);
    if (in_fd >= 0) close(in_fd);
    return r;
  }
  if (pid == 0) {
    setpgid(0, 0);
    for (const char* procs : cgroups) {
      const int fd = open(procs, O_WRONLY | O_CLOEXEC);
      if (fd < 0 || write(fd, "0", 1) != 1) _exit(124);
      close(fd);
    }
    const int input = in_fd >= 0 ? in_fd : open("/dev/null", O_RDONLY);
    if (input >= 0) dup2(input, 0);
    dup2(out_pipe[1], 1);
    dup2(err_pipe[1], 2);
    if (limits.result_pipe) dup2(res_pipe[1], 3);
    // Nothing else of the grader is inherited (other jobs' pipes, open files).
    close_from(limits.result_pipe ? 4 : 3);
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_CPU, cpu);
    if (limits.memory_bytes > 0) set_limit(RLIMIT_AS, limits.memory_bytes);
    if (limits.limit_files) set_limit(RLIMIT_FSIZE, limits.file_size_bytes);
    if (limits.max_open_files > 0) set_limit(RLIMIT_NOFILE, limits.max_open_files);
    if (limits.max_processes > 0) set_limit(RLIMIT_NPROC, limits.max_processes);
    if (limits.run_as_gid >= 0 || limits.run_as_uid >= 0) {
      // No way back: supplementary groups dropped, then the group, then the user.
      if (setgroups(0, nullptr) != 0) _exit(125);
      if (limits.run_as_gid >= 0 && setgid(static_cast<gid_t>(limits.run_as_gid)) != 0) _exit(125);
      if (limits.run_as_uid >= 0 && setuid(static_cast<uid_t>(limits.run_as_uid)) != 0) _exit(125);
      if (limits.run_as_uid != 0 && setuid(0) == 0) _exit(125);
    }
#ifdef __linux__
    // The child ends with the grader: a batch stopped by Ctrl-C, a scheduler's SIGTERM or SIGKILL
    // leaves no compiler, renderer or test running (bwrap's --die-with-parent takes the sandbox
    // with it). Set after the change of user, which clears it; the grader may be gone already.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(128);
#else
    (void)parent;
#endif
    if (!dir.empty() && chdir(dir.c_str()) != 0) _exit(126);
    if (limits.env.empty())
      execv(args[0], args.data());
    else
      execve(args[0], args.data(), envp.data());
    const char msg[] = "jelly-grade: cannot execute the program\n";
    ssize_t ignored = write(2, msg, sizeof msg - 1);
    (void)ignored;
    _exit(127);
  }
  setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  r.started = true;
  if (in_fd >= 0) close(in_fd);
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (limits.result_pipe) close(res_pipe[1]);

  struct Stream {
    int fd;
    std::string* keep;
    std::size_t* count;
    bool unlimited;
  };
  std::vector<Stream> streams = {{out_pipe[0], &r.out, &r.out_bytes, false},
                                 {err_pipe[0], &r.err, &r.err_bytes, false}};
  std::size_t result_bytes = 0;
  if (limits.result_pipe) streams.push_back({res_pipe[0], &r.result, &result_bytes, true});
  // The child's end is watched as well as its pipes: a process it left behind (setsid, double
  // fork) may hold a copy of them, and must neither keep us reading nor outlive the run.
  int pidfd = -1;
#if defined(__linux__) && defined(SYS_pidfd_open)
  pidfd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
#endif
  const auto deadline = start + std::chrono::duration<double>(limits.timeout_s);
  bool killed = false, exited = false;
  int status = 0;
  std::chrono::steady_clock::time_point drain_until{};
  char buf[65536];
  while (!streams.empty() || !exited) {
    const auto now = std::chrono::steady_clock::now();
    if (!killed && now >= deadline) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      killed = true;
    }
    if (!exited) {
      pid_t w;
      while ((w = waitpid(pid, &status, WNOHANG)) < 0 && errno == EINTR) {
      }
      if (w == pid || (w < 0 && errno == ECHILD)) {
        exited = true;
        if (limits.end_leftovers) limits.end_leftovers();
        drain_until = std::chrono::steady_clock::now() +
                      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                          std::chrono::duration<double>(limits.drain_s));
      }
    }
    if (exited && streams.empty()) break;
    if (exited && std::chrono::steady_clock::now() >= drain_until) {
      r.pipes_held = true;  // someone kept a copy: what was read is all there is
      break;
    }
    std::vector<pollfd> fds;
    for (const Stream& s : streams) fds.push_back({s.fd, POLLIN, 0});
    if (pidfd >= 0 && !exited) fds.push_back({pidfd, POLLIN, 0});
    double left_s = exited   ? std::chrono::duration<double>(drain_until - now).count()
                    : killed ? 1.0
                             : std::chrono::duration<double>(deadline - now).count();
    if (pidfd < 0 && !exited) left_s = std::min(left_s, 0.05);  // no pidfd: look every 50 ms
    const int wait_ms = static_cast<int>(std::max(0.0, left_s) * 1000.0) + 1;
    const int n = poll(fds.data(), fds.size(), wait_ms);
    if (n < 0 && errno != EINTR) break;
    for (std::size_t i = streams.size(); i-- > 0;) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t got = read(fds[i].fd, buf, sizeof buf);
      Stream& s = streams[i];
      if (got <= 0) {
        close(s.fd);
        streams.erase(streams.begin() + static_cast<long>(i));
        continue;
      }
      const std::size_t g = static_cast<std::size_t>(got);
      *s.count += g;
      const std::size_t cap = s.unlimited ? (16ULL << 20) : limits.keep_output;
      if (s.keep->size() < cap) s.keep->append(buf, std::min(g, cap - s.keep->size()));
      if (!killed && r.out_bytes + r.err_bytes > limits.kill_output) {
        r.output_flood = true;
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        killed = true;
      }
    }
  }
  for (const Stream& s : streams) close(s.fd);
  if (pidfd >= 0) close(pidfd);
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace jelly::process
