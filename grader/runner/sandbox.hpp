// The runner's own sandbox: a seccomp filter installed right before student code runs.
#pragma once

namespace jelly::grade {

/// Installs a seccomp filter that allows only what computing, printing and threads need (memory,
/// futexes, clocks, reading and writing the descriptors it has, signals to itself) and traps every
/// other system call: opening files by any interface, starting processes, networking, signalling
/// other processes, raising limits, asynchronous I/O. A trapped call writes
/// {"forbidden_syscall": N} to `result_fd` and ends the process with status 97, so the
/// orchestrator can say which call it was. Returns false (with a message on stderr) when the
/// kernel refuses the filter.
bool install_sandbox(int result_fd);

}  // namespace jelly::grade
