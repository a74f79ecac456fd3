// describe_signal (process.hpp): one wording of a child's fatal signal for the POSIX launcher
// (process.cpp) and the Windows one (process_win.cpp, which reports crashes as the POSIX signal).
#include <csignal>
#include <cstring>
#include <string>

#include "jelly/process/process.hpp"

namespace jelly::process {

std::string describe_signal(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV (segmentation fault: an invalid memory access, e.g. an index out of range)";
    case SIGABRT: return "SIGABRT (abort: a failed assert or std::terminate)";
    case SIGFPE: return "SIGFPE (arithmetic error, e.g. an integer division by zero)";
    case SIGILL: return "SIGILL (illegal instruction)";
#ifndef _WIN32
    case SIGBUS: return "SIGBUS (bus error: an invalid memory access)";
    case SIGKILL: return "SIGKILL (killed)";
    case SIGXCPU: return "SIGXCPU (CPU time limit exceeded)";
    case SIGXFSZ: return "SIGXFSZ (tried to write a file)";
    case SIGSYS: return "SIGSYS (a forbidden system call)";
    default: return std::string("signal ") + std::to_string(sig) + " (" + strsignal(sig) + ")";
#else
    default: return "signal " + std::to_string(sig);
#endif
  }
}

}  // namespace jelly::process
