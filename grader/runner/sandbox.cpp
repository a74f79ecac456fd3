#include "sandbox.hpp"

#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace jelly::grade {

namespace {

int g_result_fd = -1;

// Async-signal-safe: formats {"forbidden_syscall": N} by hand and writes it.
void on_sigsys(int, siginfo_t* info, void*) {
  char buf[64] = "{\"forbidden_syscall\": ";
  std::size_t len = std::strlen(buf);
  int nr = info->si_syscall;
  char digits[16];
  int nd = 0;
  if (nr < 0) nr = 0;
  do {
    digits[nd++] = static_cast<char>('0' + nr % 10);
    nr /= 10;
  } while (nr > 0 && nd < 15);
  while (nd > 0) buf[len++] = digits[--nd];
  buf[len++] = '}';
  buf[len++] = '\n';
  if (g_result_fd >= 0) {
    ssize_t ignored = write(g_result_fd, buf, len);
    (void)ignored;
  }
  _exit(97);
}

}  // namespace

bool install_sandbox(int result_fd) {
  g_result_fd = result_fd;
  struct sigaction sa {};
  sa.sa_sigaction = &on_sigsys;
  sa.sa_flags = SA_SIGINFO;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGSYS, &sa, nullptr);

  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (!ctx) {
    std::fputs("jelly-grade runner: seccomp_init failed\n", stderr);
    return false;
  }
  const int trapped[] = {
      SCMP_SYS(open),       SCMP_SYS(openat),     SCMP_SYS(openat2),   SCMP_SYS(creat),
      SCMP_SYS(open_by_handle_at), SCMP_SYS(name_to_handle_at),
      SCMP_SYS(unlink),     SCMP_SYS(unlinkat),   SCMP_SYS(rename),    SCMP_SYS(renameat),
      SCMP_SYS(renameat2),  SCMP_SYS(mkdir),      SCMP_SYS(mkdirat),   SCMP_SYS(rmdir),
      SCMP_SYS(link),       SCMP_SYS(linkat),     SCMP_SYS(symlink),   SCMP_SYS(symlinkat),
      SCMP_SYS(truncate),   SCMP_SYS(chmod),      SCMP_SYS(fchmodat),  SCMP_SYS(chown),
      SCMP_SYS(fchownat),   SCMP_SYS(lchown),     SCMP_SYS(chdir),     SCMP_SYS(chroot),
      SCMP_SYS(mknod),      SCMP_SYS(mknodat),    SCMP_SYS(mount),     SCMP_SYS(umount2),
      SCMP_SYS(socket),     SCMP_SYS(socketpair), SCMP_SYS(connect),   SCMP_SYS(bind),
      SCMP_SYS(listen),     SCMP_SYS(accept),     SCMP_SYS(accept4),   SCMP_SYS(sendto),
      SCMP_SYS(execve),     SCMP_SYS(execveat),   SCMP_SYS(fork),      SCMP_SYS(vfork),
      SCMP_SYS(ptrace),    SCMP_SYS(process_vm_writev),
      SCMP_SYS(process_vm_readv), SCMP_SYS(setrlimit), SCMP_SYS(prlimit64), SCMP_SYS(setpgid),
      SCMP_SYS(setsid),     SCMP_SYS(memfd_create), SCMP_SYS(inotify_init1), SCMP_SYS(pidfd_open),
  };
  bool ok = true;
  for (int nr : trapped) ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, nr, 0) == 0;
  // Threads are allowed (a task library may use OpenMP), new processes are not: clone without
  // CLONE_THREAD traps; clone3 (whose flags a filter cannot see) answers ENOSYS, and glibc then
  // falls back to clone.
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(clone), 1,
                              SCMP_A0(SCMP_CMP_MASKED_EQ, static_cast<scmp_datum_t>(CLONE_THREAD), 0)) == 0;
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
  // Signals only to itself (abort() raises SIGABRT with tgkill on its own pid).
  const pid_t self = getpid();
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(kill), 1,
                              SCMP_A0(SCMP_CMP_NE, static_cast<scmp_datum_t>(self))) == 0;
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(tgkill), 1,
                              SCMP_A0(SCMP_CMP_NE, static_cast<scmp_datum_t>(self))) == 0;
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(tkill), 1,
                              SCMP_A0(SCMP_CMP_NE, static_cast<scmp_datum_t>(self))) == 0;
  // The SIGSYS handler must stay: trap attempts to replace it.
  ok = ok && seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(rt_sigaction), 1,
                              SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(SIGSYS))) == 0;
  if (ok) ok = seccomp_load(ctx) == 0;
  seccomp_release(ctx);
  if (!ok) std::fputs("jelly-grade runner: installing the seccomp filter failed\n", stderr);
  return ok;
}

}  // namespace jelly::grade
