// run_program for Windows (run_program.hpp): CreateProcessW with the arguments quoted the way
// CommandLineToArgvW and the C runtime split them back; no cmd.exe between.
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

#include <cstdlib>
#include <sstream>

#include "run_program.hpp"

namespace jelly::movie {

namespace fs = std::filesystem;

namespace {

// One argument quoted for CommandLineToArgvW (as grader/src/sandbox/process_win.cpp does).
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

}  // namespace

std::optional<fs::path> find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ';')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / (name + ".exe");
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

ProgramResult run_program(const fs::path& program, const std::vector<std::string>& args) {
  ProgramResult r;
  std::wstring command_line;
  append_quoted(command_line, program.wstring());
  // The arguments are narrow text in the code page fs::path::string() uses.
  for (const std::string& a : args) append_quoted(command_line, fs::path(a).wstring());

  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE null_in = CreateFileW(L"NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                               OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
  STARTUPINFOW si{};
  si.cb = sizeof si;
  si.dwFlags = STARTF_USESTDHANDLES;
  si.hStdInput = null_in;
  si.hStdOutput = GetStdHandle(STD_OUTPUT_HANDLE);
  si.hStdError = GetStdHandle(STD_ERROR_HANDLE);
  PROCESS_INFORMATION pi{};
  const std::wstring application = program.wstring();
  const BOOL created = CreateProcessW(application.c_str(), command_line.data(), nullptr, nullptr,
                                      TRUE, 0, nullptr, nullptr, &si, &pi);
  if (null_in != INVALID_HANDLE_VALUE) CloseHandle(null_in);
  if (!created) {
    r.error = "cannot start " + program.string() + " (Windows error " +
              std::to_string(GetLastError()) + ")";
    return r;
  }
  r.started = true;
  CloseHandle(pi.hThread);
  WaitForSingleObject(pi.hProcess, INFINITE);
  DWORD code = 0;
  if (GetExitCodeProcess(pi.hProcess, &code)) r.exit_code = static_cast<int>(code);
  CloseHandle(pi.hProcess);
  return r;
}

}  // namespace jelly::movie
