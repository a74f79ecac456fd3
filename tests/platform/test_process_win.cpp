// run_child on Windows (framework/process/src/process_win.cpp): the piece the Windows self-check
// runs each grading case through. This program is its own child: `--child MODE ...` behaves as a
// case would (print, write a result, crash, loop, flood), anything else runs the tests. Built by
// the MinGW cross-build and run under wine by tests/platform/check_platform.sh.
#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <jelly/process/process.hpp>

namespace {

std::string g_self;  // this program's path

int child_main(int argc, char** argv) {
  const std::string mode = argv[2];
  if (mode == "echo") {  // prints its arguments, one per line, and the working directory
    for (int i = 3; i < argc; ++i) std::printf("%s\n", argv[i]);
    char dir[MAX_PATH];
    GetCurrentDirectoryA(MAX_PATH, dir);
    std::printf("cwd=%s\n", dir);
    std::fprintf(stderr, "to stderr\n");
    return 7;
  }
  if (mode == "result") {  // the result channel: what fd 3 is on POSIX
    const char* h = std::getenv("JELLY_RESULT_HANDLE");
    if (!h) return 20;
    const auto handle =
        reinterpret_cast<HANDLE>(static_cast<std::uintptr_t>(std::strtoull(h, nullptr, 10)));
    const char text[] = "{\"outputs\":{}}\n";
    DWORD written = 0;
    return WriteFile(handle, text, sizeof text - 1, &written, nullptr) && written == sizeof text - 1
               ? 0
               : 21;
  }
  if (mode == "stdin") {  // reads stdin (binary) to its end and prints its length and first bytes
    _setmode(_fileno(stdin), _O_BINARY);
    _setmode(_fileno(stdout), _O_BINARY);
    std::string all;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, stdin)) > 0) all.append(buf, n);
    std::printf("%zu %s", all.size(), all.substr(0, 6).c_str());
    return 0;
  }
  if (mode == "crash") {
    volatile int* p = nullptr;
    return *p;
  }
  if (mode == "loop") {
    for (;;) Sleep(10);
  }
  if (mode == "flood") {
    std::string line(1000, 'x');
    for (;;) std::puts(line.c_str());
  }
  return 99;
}

using jelly::process::ChildResult;
using jelly::process::Limits;
using jelly::process::run_child;

TEST(ProcessWin, CapturesOutputExitCodeArgumentsAndWorkingDirectory) {
  Limits lim;
  const std::vector<std::string> args = {g_self,     "--child",       "echo", "two words",
                                         "quote\"d", "back\\slash\\", "",     "tab\there"};
  char temp[MAX_PATH];
  GetTempPathA(MAX_PATH, temp);
  const ChildResult r = run_child(args, lim, temp);
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_EQ(r.exit_code, 7);
  EXPECT_EQ(r.signal, 0);
  EXPECT_FALSE(r.timed_out);
  std::string expected;
  for (std::size_t i = 3; i < args.size(); ++i) expected += args[i] + "\r\n";
  EXPECT_EQ(r.out.substr(0, expected.size()), expected);
  std::string dir = temp;
  if (dir.size() > 3 && dir.back() == '\\') dir.pop_back();
  EXPECT_NE(r.out.find("cwd=" + dir), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "to stderr\r\n");
}

TEST(ProcessWin, ResultChannel) {
  const ChildResult r = run_child({g_self, "--child", "result"}, Limits{});
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.result, "{\"outputs\":{}}\n");
}

// The grader hands each case its request on stdin (Limits::stdin_data): larger than a pipe's
// buffer, and byte for byte (a CR LF stays two bytes).
TEST(ProcessWin, StdinDataReachesTheChildWhole) {
  Limits lim;
  lim.stdin_data = "a\r\nb\n" + std::string(300000, 'x');
  const ChildResult r = run_child({g_self, "--child", "stdin"}, lim);
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, std::to_string(lim.stdin_data.size()) + " a\r\nb\nx");
}

TEST(ProcessWin, CrashIsReportedAsTheSignalPosixWouldSend) {
  const ChildResult r = run_child({g_self, "--child", "crash"}, Limits{});
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_NE(jelly::process::describe_signal(r.signal).find("segmentation fault"),
            std::string::npos);
}

TEST(ProcessWin, TimeoutKillsTheChild) {
  Limits lim;
  lim.timeout_s = 1.0;
  const ChildResult r = run_child({g_self, "--child", "loop"}, lim);
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_TRUE(r.timed_out);
  EXPECT_GE(r.seconds, 0.9);
  EXPECT_LT(r.seconds, 30.0);
}

TEST(ProcessWin, OutputFloodKillsTheChildAndKeepsTheStart) {
  Limits lim;
  lim.kill_output = 1 << 20;
  lim.keep_output = 4096;
  const ChildResult r = run_child({g_self, "--child", "flood"}, lim);
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_TRUE(r.output_flood);
  EXPECT_EQ(r.out.size(), 4096u);
  EXPECT_GT(r.out_bytes, std::size_t{1} << 20);
}

TEST(ProcessWin, MissingProgramIsAStartError) {
  const ChildResult r = run_child({"C:\\no\\such\\program.exe"}, Limits{});
  EXPECT_FALSE(r.started);
  EXPECT_NE(r.start_error.find("cannot start"), std::string::npos) << r.start_error;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "--child") == 0) return child_main(argc, argv);
  char self[MAX_PATH];
  GetModuleFileNameA(nullptr, self, MAX_PATH);
  g_self = self;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
