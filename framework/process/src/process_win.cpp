// run_child for Windows (process.hpp): CreateProcessW with pipes for stdout and stderr, the
// child in a job object (memory limit; killed as a whole on timeout, output flood or when the
// grader goes away), and the result channel ("fd 3" on POSIX) as an extra inherited pipe whose
// handle value the child finds in the environment variable JELLY_RESULT_HANDLE. Limits::stdin_data
// reaches the child through a pipe on its stdin, written by a thread (NUL when there is none).
// There is no sandbox: on Windows this runs the student's own code on the student's own machine
// (the self-check); the instructor's grader runs on Linux (process.cpp, the seccomp sandbox).
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cwchar>
#include <mutex>
#include <thread>

#include "jelly/process/process.hpp"

namespace jelly::process {

namespace {

std::wstring widen(const std::string& s) {
  if (s.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), nullptr, 0);
  std::wstring w(static_cast<std::size_t>(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), w.data(), n);
  return w;
}

// One argument quoted the way CommandLineToArgvW and the C runtime split it back.
void append_quoted(std::wstring& line, const std::wstring& arg) {
  if (!line.empty()) line += L' ';
  if (!arg.empty() && arg.find_first_of(L" \t\n\v\"") == std::wstring::npos) {
    line += arg;
    return;
  }
  line += L'"';
  for (std::size_t i = 0;; ++i) {
    std::size_t backslashes = 0;
    while (i < arg.size() && arg[i] == L'\\') ++i, ++backslashes;
    if (i == arg.size()) {
      line.append(backslashes * 2, L'\\');
      break;
    }
    if (arg[i] == L'"')
      line.append(backslashes * 2 + 1, L'\\');
    else
      line.append(backslashes, L'\\');
    line += arg[i];
  }
  line += L'"';
}

std::string last_error_text(const char* what) {
  return std::string(what) + " failed (Windows error " + std::to_string(GetLastError()) + ")";
}

// The parent's environment plus JELLY_RESULT_HANDLE=<value>, as a CREATE_UNICODE_ENVIRONMENT block.
std::wstring environment_with(const std::wstring& assignment) {
  std::wstring block;
  if (wchar_t* env = GetEnvironmentStringsW()) {
    for (const wchar_t* p = env; *p; p += std::wcslen(p) + 1)
      if (std::wcsncmp(p, L"JELLY_RESULT_HANDLE=", 20) != 0) block.append(p).push_back(L'\0');
    FreeEnvironmentStringsW(env);
  }
  block.append(assignment).push_back(L'\0');
  block.push_back(L'\0');
  return block;
}

// Reads a pipe to its end, keeping the first `keep` bytes; counts all of them in `total` (shared
// by the streams) and terminates the job once it passes `kill_after`.
struct Reader {
  HANDLE pipe = nullptr;
  std::string* text = nullptr;
  std::size_t* bytes = nullptr;
  std::size_t keep = 0;  // 0: keep everything (the result channel)
};

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const Limits& limits,
                      const std::filesystem::path& cwd) {
  ChildResult r;
  // A crashing child must not open Windows' "program has stopped working" dialog (the error mode
  // is inherited); the job's DIE_ON_UNHANDLED_EXCEPTION below does the same for its children.
  SetErrorMode(GetErrorMode() | SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  if (argv.empty()) {
    r.start_error = "no program to run";
    return r;
  }
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE out_read = nullptr, out_write = nullptr, err_read = nullptr, err_write = nullptr;
  HANDLE res_read = nullptr, res_write = nullptr;
  auto close = [](HANDLE& h) {
    if (h) CloseHandle(h);
    h = nullptr;
  };
  if (!CreatePipe(&out_read, &out_write, &inherit, 0) ||
      !CreatePipe(&err_read, &err_write, &inherit, 0) ||
      (limits.result_pipe && !CreatePipe(&res_read, &res_write, &inherit, 0))) {
    r.start_error = last_error_text("CreatePipe");
    for (HANDLE* h : {&out_read, &out_write, &err_read, &err_write, &res_read, &res_write})
      close(*h);
    return r;
  }
  // Only the child's ends are inherited.
  for (HANDLE h : {out_read, err_read, res_read})
    if (h) SetHandleInformation(h, HANDLE_FLAG_INHERIT, 0);
  HANDLE child_in = nullptr, in_write = nullptr;
  if (limits.stdin_data.empty()) {
    child_in = CreateFileW(L"NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                           OPEN_EXISTING, 0, nullptr);
  } else if (!CreatePipe(&child_in, &in_write, &inherit, 0)) {
    r.start_error = last_error_text("CreatePipe");
    for (HANDLE* h : {&out_read, &out_write, &err_read, &err_write, &res_read, &res_write})
      close(*h);
    return r;
  } else {
    SetHandleInformation(in_write, HANDLE_FLAG_INHERIT, 0);
  }

  // A job: the child and anything it starts die together; memory is capped.
  HANDLE job = CreateJobObjectW(nullptr, nullptr);
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION info{};
  info.BasicLimitInformation.LimitFlags =
      JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE | JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION;
  if (limits.memory_bytes > 0) {
    info.BasicLimitInformation.LimitFlags |= JOB_OBJECT_LIMIT_JOB_MEMORY;
    info.JobMemoryLimit = limits.memory_bytes;
  }
  if (job) SetInformationJobObject(job, JobObjectExtendedLimitInformation, &info, sizeof info);

  std::wstring command_line;
  for (const std::string& a : argv) append_quoted(command_line, widen(a));
  std::wstring env = environment_with(L"JELLY_RESULT_HANDLE=" +
                                      std::to_wstring(reinterpret_cast<std::uintptr_t>(res_write)));
  const std::wstring dir = cwd.empty() ? std::wstring() : cwd.wstring();

  // Exactly these handles reach the child.
  HANDLE handles[4] = {child_in, out_write, err_write, res_write};
  const DWORD handle_count = res_write ? 4 : 3;
  SIZE_T attr_size = 0;
  InitializeProcThreadAttributeList(nullptr, 1, 0, &attr_size);
  std::string attr_buffer(attr_size, '\0');
  auto attrs = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(attr_buffer.data());
  const bool have_list =
      InitializeProcThreadAttributeList(attrs, 1, 0, &attr_size) &&
      UpdateProcThreadAttribute(attrs, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST, handles,
                                handle_count * sizeof(HANDLE), nullptr, nullptr);
  STARTUPINFOEXW si{};
  si.StartupInfo.cb = sizeof si;
  si.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
  si.StartupInfo.hStdInput = child_in;
  si.StartupInfo.hStdOutput = out_write;
  si.StartupInfo.hStdError = err_write;
  si.lpAttributeList = have_list ? attrs : nullptr;
  PROCESS_INFORMATION pi{};
  const auto start = std::chrono::steady_clock::now();
  const BOOL created =
      CreateProcessW(nullptr, command_line.data(), nullptr, nullptr, TRUE,
                     CREATE_SUSPENDED | CREATE_UNICODE_ENVIRONMENT | CREATE_NO_WINDOW |
                         (have_list ? EXTENDED_STARTUPINFO_PRESENT : 0),
                     env.data(), dir.empty() ? nullptr : dir.c_str(), &si.StartupInfo, &pi);
  if (have_list) DeleteProcThreadAttributeList(attrs);
  // Our copies of the child's ends: closed, so the pipes end when the child (and its children) do.
  close(out_write);
  close(err_write);
  close(res_write);
  close(child_in);
  if (!created) {
    r.start_error = "cannot start " + argv[0] + ": " + last_error_text("CreateProcess");
    for (HANDLE* h : {&out_read, &err_read, &res_read, &job, &in_write}) close(*h);
    return r;
  }
  if (job) AssignProcessToJobObject(job, pi.hProcess);
  ResumeThread(pi.hThread);
  CloseHandle(pi.hThread);
  r.started = true;

  std::mutex mutex;
  std::size_t total = 0;
  bool flood = false;
  auto read_all = [&](Reader rd) {
    char buf[4096];
    DWORD n = 0;
    while (ReadFile(rd.pipe, buf, sizeof buf, &n, nullptr) && n > 0) {
      std::lock_guard<std::mutex> lock(mutex);
      *rd.bytes += n;
      if (rd.keep == 0) {
        rd.text->append(buf, n);
        continue;
      }
      if (rd.text->size() < rd.keep)
        rd.text->append(buf, std::min<std::size_t>(n, rd.keep - rd.text->size()));
      total += n;
      if (limits.kill_output > 0 && total > limits.kill_output && !flood) {
        flood = true;
        if (job)
          TerminateJobObject(job, 1);
        else
          TerminateProcess(pi.hProcess, 1);
      }
    }
  };
  // The input, written while the child runs (a pipe holds only a few KiB); the write fails and
  // the thread ends when the child exits without reading it all.
  std::thread t_in;
  if (in_write)
    t_in = std::thread([&limits, in_write]() {
      const char* p = limits.stdin_data.data();
      std::size_t left = limits.stdin_data.size();
      DWORD n = 0;
      while (left > 0 &&
             WriteFile(in_write, p, static_cast<DWORD>(std::min<std::size_t>(left, 1 << 16)), &n,
                       nullptr) &&
             n > 0)
        p += n, left -= n;
      CloseHandle(in_write);
    });
  std::size_t result_bytes = 0;
  std::thread t_out(read_all, Reader{out_read, &r.out, &r.out_bytes, limits.keep_output});
  std::thread t_err(read_all, Reader{err_read, &r.err, &r.err_bytes, limits.keep_output});
  std::thread t_res;
  if (res_read) t_res = std::thread(read_all, Reader{res_read, &r.result, &result_bytes, 0});

  const double timeout_ms = limits.timeout_s > 0 ? limits.timeout_s * 1000.0 : double(INFINITE);
  if (WaitForSingleObject(pi.hProcess, static_cast<DWORD>(std::min(timeout_ms, 4.0e9))) ==
      WAIT_TIMEOUT) {
    r.timed_out = true;
    if (job)
      TerminateJobObject(job, 1);
    else
      TerminateProcess(pi.hProcess, 1);
    WaitForSingleObject(pi.hProcess, INFINITE);
  }
  // Anything the child started is ended with it, so the pipes reach their end.
  if (job) TerminateJobObject(job, 1);
  t_out.join();
  t_err.join();
  if (t_res.joinable()) t_res.join();
  if (t_in.joinable()) t_in.join();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.output_flood = flood;

  DWORD code = 0;
  GetExitCodeProcess(pi.hProcess, &code);
  // An unhandled exception ends a Windows process with its NTSTATUS code: report it as the
  // signal a POSIX system would have sent, so the grader's messages are the same.
  switch (code) {
    case 0xC0000005u:  // access violation
    case 0xC00000FDu:  // stack overflow
    case 0xC0000374u:  // heap corruption
      r.signal = SIGSEGV;
      break;
    case 0xC0000094u:  // integer division by zero
    case 0xC0000095u:  // integer overflow
      r.signal = SIGFPE;
      break;
    case 0xC000001Du:  // illegal instruction
      r.signal = SIGILL;
      break;
    case 0xC0000409u:  // __fastfail / stack buffer overrun (abort() in the UCRT)
      r.signal = SIGABRT;
      break;
    default: r.exit_code = static_cast<int>(code);
  }
  if (r.timed_out || r.output_flood) r.exit_code = -1, r.signal = 0;
  for (HANDLE* h : {&out_read, &err_read, &res_read, &job}) close(*h);
  CloseHandle(pi.hProcess);
  return r;
}

}  // namespace jelly::process
