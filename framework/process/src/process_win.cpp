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

// A handle closed by close() or when its owner goes; nullptr when there is none.
class Handle {
 public:
  Handle() = default;
  explicit Handle(HANDLE h) : h_(h) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : h_(other.release()) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      close();
      h_ = other.release();
    }
    return *this;
  }
  ~Handle() { close(); }
  HANDLE get() const { return h_; }
  HANDLE* put() { return &h_; }  ///< for a call that creates the handle (this one is empty)
  HANDLE release() {
    HANDLE h = h_;
    h_ = nullptr;
    return h;
  }
  void close() {
    if (h_) CloseHandle(h_);
    h_ = nullptr;
  }

 private:
  HANDLE h_ = nullptr;
};

// The child's standard streams and result channel: its ends (inherited) and ours.
struct ChildPipes {
  Handle out_read, out_write, err_read, err_write, res_read, res_write;
  Handle child_in, in_write;  // its stdin (NUL, or a pipe for Limits::stdin_data) and our end

  // false, with `error`, when a pipe cannot be made.
  bool open(const Limits& limits, std::string& error);
  // Our copies of the child's ends: closed, so the pipes end when the child (and its children) do.
  void close_child_ends() {
    out_write.close();
    err_write.close();
    res_write.close();
    child_in.close();
  }
};

bool ChildPipes::open(const Limits& limits, std::string& error) {
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  if (!CreatePipe(out_read.put(), out_write.put(), &inherit, 0) ||
      !CreatePipe(err_read.put(), err_write.put(), &inherit, 0) ||
      (limits.result_pipe && !CreatePipe(res_read.put(), res_write.put(), &inherit, 0))) {
    error = last_error_text("CreatePipe");
    return false;
  }
  // Only the child's ends are inherited.
  for (HANDLE h : {out_read.get(), err_read.get(), res_read.get()})
    if (h) SetHandleInformation(h, HANDLE_FLAG_INHERIT, 0);
  if (limits.stdin_data.empty()) {
    *child_in.put() = CreateFileW(L"NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE,
                                  &inherit, OPEN_EXISTING, 0, nullptr);
  } else if (!CreatePipe(child_in.put(), in_write.put(), &inherit, 0)) {
    error = last_error_text("CreatePipe");
    return false;
  } else {
    SetHandleInformation(in_write.get(), HANDLE_FLAG_INHERIT, 0);
  }
  return true;
}

// A job: the child and anything it starts die together; memory is capped.
Handle make_job(const Limits& limits) {
  Handle job(CreateJobObjectW(nullptr, nullptr));
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION info{};
  info.BasicLimitInformation.LimitFlags =
      JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE | JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION;
  if (limits.memory_bytes > 0) {
    info.BasicLimitInformation.LimitFlags |= JOB_OBJECT_LIMIT_JOB_MEMORY;
    info.JobMemoryLimit = limits.memory_bytes;
  }
  if (job.get())
    SetInformationJobObject(job.get(), JobObjectExtendedLimitInformation, &info, sizeof info);
  return job;
}

// Exactly these handles reach the child (PROC_THREAD_ATTRIBUTE_HANDLE_LIST): its stdin, stdout,
// stderr and, when there is one, its result channel. get() is nullptr when the list could not be
// made.
class InheritedHandles {
 public:
  explicit InheritedHandles(const ChildPipes& p)
      : handles_{p.child_in.get(), p.out_write.get(), p.err_write.get(), p.res_write.get()} {
    const DWORD handle_count = p.res_write.get() ? 4 : 3;
    SIZE_T attr_size = 0;
    InitializeProcThreadAttributeList(nullptr, 1, 0, &attr_size);
    buffer_.assign(attr_size, '\0');
    attrs_ = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(buffer_.data());
    have_list_ = InitializeProcThreadAttributeList(attrs_, 1, 0, &attr_size) &&
                 UpdateProcThreadAttribute(attrs_, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST, handles_,
                                           handle_count * sizeof(HANDLE), nullptr, nullptr);
  }
  InheritedHandles(const InheritedHandles&) = delete;
  InheritedHandles& operator=(const InheritedHandles&) = delete;
  ~InheritedHandles() {
    if (have_list_) DeleteProcThreadAttributeList(attrs_);
  }
  LPPROC_THREAD_ATTRIBUTE_LIST get() const { return have_list_ ? attrs_ : nullptr; }

 private:
  HANDLE handles_[4];
  std::string buffer_;
  LPPROC_THREAD_ATTRIBUTE_LIST attrs_ = nullptr;
  bool have_list_ = false;
};

// The program started suspended (it runs once it is in the job), with its streams and exactly
// the handles of `pipes` it needs; `start` is when. False (GetLastError) when it cannot start.
bool start_suspended(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                     const ChildPipes& pipes, PROCESS_INFORMATION& pi,
                     std::chrono::steady_clock::time_point& start) {
  std::wstring command_line;
  for (const std::string& a : argv) append_quoted(command_line, widen(a));
  std::wstring env =
      environment_with(L"JELLY_RESULT_HANDLE=" +
                       std::to_wstring(reinterpret_cast<std::uintptr_t>(pipes.res_write.get())));
  const std::wstring dir = cwd.empty() ? std::wstring() : cwd.wstring();
  const InheritedHandles handles(pipes);
  STARTUPINFOEXW si{};
  si.StartupInfo.cb = sizeof si;
  si.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
  si.StartupInfo.hStdInput = pipes.child_in.get();
  si.StartupInfo.hStdOutput = pipes.out_write.get();
  si.StartupInfo.hStdError = pipes.err_write.get();
  si.lpAttributeList = handles.get();
  start = std::chrono::steady_clock::now();
  return CreateProcessW(nullptr, command_line.data(), nullptr, nullptr, TRUE,
                        CREATE_SUSPENDED | CREATE_UNICODE_ENVIRONMENT | CREATE_NO_WINDOW |
                            (handles.get() ? EXTENDED_STARTUPINFO_PRESENT : 0),
                        env.data(), dir.empty() ? nullptr : dir.c_str(), &si.StartupInfo, &pi);
}

// The started child put in its job, then let run; its process handle.
Handle resume_in_job(const PROCESS_INFORMATION& pi, HANDLE job) {
  if (job) AssignProcessToJobObject(job, pi.hProcess);
  ResumeThread(pi.hThread);
  CloseHandle(pi.hThread);
  return Handle(pi.hProcess);
}

// Ends the child and everything in its job (the child alone when there is no job).
void end_child(HANDLE job, HANDLE process) {
  if (job)
    TerminateJobObject(job, 1);
  else
    TerminateProcess(process, 1);
}

// One pipe a thread reads (ChildStreams::read_all).
struct Reader {
  HANDLE pipe = nullptr;
  std::string* text = nullptr;
  std::size_t* bytes = nullptr;
  std::size_t keep = 0;  // 0: keep everything (the result channel)
};

// The child's streams while it runs, each on a thread of its own: its input written, its output
// and result read.
class ChildStreams {
 public:
  ChildStreams(const Limits& limits, HANDLE job, HANDLE process)
      : limits_(limits), job_(job), process_(process) {}
  /// Starts the threads; the stdin pipe's write end is theirs from now on.
  void start(ChildPipes& pipes, ChildResult& r);
  /// Once the child has ended and its job is ended: waits for each stream's end.
  void join();
  bool flood() const { return flood_; }

 private:
  void write_input(HANDLE in_write);
  void read_all(Reader rd);

  const Limits& limits_;
  HANDLE job_, process_;
  std::mutex mutex_;
  std::size_t total_ = 0;
  bool flood_ = false;
  std::size_t result_bytes_ = 0;
  std::thread in_, out_, err_, res_;
};

void ChildStreams::start(ChildPipes& pipes, ChildResult& r) {
  if (pipes.in_write.get())
    in_ = std::thread(&ChildStreams::write_input, this, pipes.in_write.release());
  out_ = std::thread(&ChildStreams::read_all, this,
                     Reader{pipes.out_read.get(), &r.out, &r.out_bytes, limits_.keep_output});
  err_ = std::thread(&ChildStreams::read_all, this,
                     Reader{pipes.err_read.get(), &r.err, &r.err_bytes, limits_.keep_output});
  if (pipes.res_read.get())
    res_ = std::thread(&ChildStreams::read_all, this,
                       Reader{pipes.res_read.get(), &r.result, &result_bytes_, 0});
}

// The input, written while the child runs (a pipe holds only a few KiB); the write fails and
// the thread ends when the child exits without reading it all.
void ChildStreams::write_input(HANDLE in_write) {
  const char* p = limits_.stdin_data.data();
  std::size_t left = limits_.stdin_data.size();
  DWORD n = 0;
  while (left > 0 &&
         WriteFile(in_write, p, static_cast<DWORD>(std::min<std::size_t>(left, 1 << 16)), &n,
                   nullptr) &&
         n > 0)
    p += n, left -= n;
  CloseHandle(in_write);
}

// Reads a pipe to its end, keeping the first `keep` bytes; counts all of them in `total` (shared
// by the streams) and terminates the job once it passes `kill_after`.
void ChildStreams::read_all(Reader rd) {
  char buf[4096];
  DWORD n = 0;
  while (ReadFile(rd.pipe, buf, sizeof buf, &n, nullptr) && n > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    *rd.bytes += n;
    if (rd.keep == 0) {
      rd.text->append(buf, n);
      continue;
    }
    if (rd.text->size() < rd.keep)
      rd.text->append(buf, std::min<std::size_t>(n, rd.keep - rd.text->size()));
    total_ += n;
    if (limits_.kill_output > 0 && total_ > limits_.kill_output && !flood_) {
      flood_ = true;
      end_child(job_, process_);
    }
  }
}

void ChildStreams::join() {
  out_.join();
  err_.join();
  if (res_.joinable()) res_.join();
  if (in_.joinable()) in_.join();
}

// Waits for the child until the timeout, when it is ended; then whatever it started is ended too.
void wait_for_child(const Limits& limits, HANDLE job, HANDLE process, ChildResult& r) {
  const double timeout_ms = limits.timeout_s > 0 ? limits.timeout_s * 1000.0 : double(INFINITE);
  if (WaitForSingleObject(process, static_cast<DWORD>(std::min(timeout_ms, 4.0e9))) ==
      WAIT_TIMEOUT) {
    r.timed_out = true;
    end_child(job, process);
    WaitForSingleObject(process, INFINITE);
  }
  // Anything the child started is ended with it, so the pipes reach their end.
  if (job) TerminateJobObject(job, 1);
}

// The child's exit code, or the signal it stands for; neither when it was killed.
void set_exit_status(HANDLE process, ChildResult& r) {
  DWORD code = 0;
  GetExitCodeProcess(process, &code);
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
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const Limits& limits,
                      const std::filesystem::path& cwd) {
  ChildResult r;
  // A crashing child must not open Windows' "program has stopped working" dialog (the error mode
  // is inherited); the job's DIE_ON_UNHANDLED_EXCEPTION (make_job) does the same for its children.
  SetErrorMode(GetErrorMode() | SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  if (argv.empty()) {
    r.start_error = "no program to run";
    return r;
  }
  ChildPipes pipes;
  if (!pipes.open(limits, r.start_error)) return r;
  Handle job = make_job(limits);
  PROCESS_INFORMATION pi{};
  std::chrono::steady_clock::time_point start;
  const bool created = start_suspended(argv, cwd, pipes, pi, start);
  pipes.close_child_ends();
  if (!created) {
    r.start_error = "cannot start " + argv[0] + ": " + last_error_text("CreateProcess");
    return r;
  }
  Handle process = resume_in_job(pi, job.get());
  r.started = true;

  ChildStreams streams(limits, job.get(), process.get());
  streams.start(pipes, r);
  wait_for_child(limits, job.get(), process.get(), r);
  streams.join();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.output_flood = streams.flood();
  set_exit_status(process.get(), r);
  for (Handle* h : {&pipes.out_read, &pipes.err_read, &pipes.res_read, &job}) h->close();
  process.close();
  return r;
}

}  // namespace jelly::process
