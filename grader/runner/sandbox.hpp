// The runner's own sandbox: a seccomp filter installed right before student code runs.
#pragma once

namespace jelly::grade {

/// Installs a seccomp filter that traps every system call a task function has no business making
/// (opening, creating, renaming or deleting files, starting processes (threads are allowed), networking,
/// signalling other processes, raising resource limits). A trapped call writes
/// {"forbidden_syscall": N} to `result_fd` and ends the process with status 97, so the
/// orchestrator can say which call it was. Returns false (with a message on stderr) when the
/// kernel refuses the filter.
bool install_sandbox(int result_fd);

}  // namespace jelly::grade
