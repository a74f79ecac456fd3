// The shared artefacts of the object cache (the stubs' objects, the precompiled task headers) are
// built once when many workers need them at the same time, as at the start of a batch: the others
// wait for that build and take its result (grader/src/build/build.cpp, ArtefactLock). Proved by
// counting the compiler's runs through a wrapper that logs each one and sleeps, so that every
// worker starts while the cache is still empty; two processes of three workers each share one
// cache, as shards on one machine do. A made-up two-file assignment keeps each compile short.
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "build/build.hpp"
#include "grading/parallel.hpp"
#include "inputs/config.hpp"
#include "inputs/files.hpp"

namespace g = jelly::grade;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// The compiler runs the log holds whose command line contains `needle`.
int runs_with(const fs::path& log, const std::string& needle) {
  std::ifstream in(log);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.find(needle) != std::string::npos;
  return n;
}

// An assignment of two task files whose stubs start with their task header (so that the header is
// precompiled), compiled by `compiler`, its cache in `root`/cache.
g::GradeConfig made_up_assignment(const fs::path& root, const fs::path& compiler) {
  write(root / "include/t/a.hpp", "#pragma once\nint task_a(int x);\n");
  write(root / "include/t/b.hpp", "#pragma once\nint task_b(int x);\n");
  write(root / "asg/a.cpp",
        "#include \"t/a.hpp\"\nint task_a(int x) { return x; }\nint main() {}\n");
  write(root / "asg/b.cpp", "#include \"t/b.hpp\"\nint task_b(int x) { return -x; }\n");
  g::GradeConfig c;
  c.compiler = compiler.string();
  c.compiler_id = "GNU";
  c.compile_flags = {"-O1"};
  c.include_dirs = {(root / "include").string()};
  c.source_dir = root;
  c.binary_dir = root / "build";
  g::AssignmentConfig a;
  a.id = "made-up";
  a.dir = root / "asg";
  a.manifest.files = {"a.cpp", "b.cpp"};
  a.include_dirs = c.include_dirs;
  c.assignments = {a};
  c.selected = &c.assignments.front();
  return c;
}

}  // namespace

TEST(GraderBuildCache, EachSharedArtefactIsBuiltOnceWhenManyWorkersNeedItAtOnce) {
  const fs::path root =
      fs::temp_directory_path() / ("jelly-build-once-" + std::to_string(getpid()));
  fs::remove_all(root);
  const fs::path log = root / "compiler-runs.log", wrapper = root / "cc";
  // Every run is logged, then waits a second before compiling: long enough for every worker to
  // find the cache empty, were nothing making them wait.
  write(wrapper, "#!/bin/sh\nprintf '%s\\n' \"$*\" >>'" + log.string() +
                     "'\nsleep 1\nexec " JELLY_TEST_CXX " \"$@\"\n");
  fs::permissions(wrapper, fs::perms::owner_all);
  setenv("JELLY_GRADE_CACHE", (root / "cache").c_str(), 1);
  const g::GradeConfig config = made_up_assignment(root, wrapper);
  // Empty submissions: every file is graded as its stub, so each build compiles the stub text twice
  // (as the student's file and as the stand-in), all six builds the same two objects.
  fs::create_directories(root / "empty");
  constexpr int kProcesses = 2, kWorkers = 3;
  std::vector<pid_t> children;
  for (int p = 0; p < kProcesses; ++p) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      std::atomic<int> failed{0};
      g::parallel_for(kWorkers, kWorkers, [&](std::size_t w) {
        const fs::path work = root / ("work-" + std::to_string(p) + "-" + std::to_string(w));
        const g::BuildResult r =
            g::build_submission(config, root / "empty", work, 2, g::Isolation{});
        if (!r.ok || !r.failed_files.empty()) failed = 1;
      });
      _exit(failed.load());
    }
    children.push_back(pid);
  }
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a build failed: " << status;
  }
  std::ostringstream runs;
  runs << std::ifstream(log).rdbuf();
  EXPECT_EQ(runs_with(log, "-x c++-header"), 2) << "each precompiled header once:\n" << runs.str();
  EXPECT_EQ(runs_with(log, "-c a.cpp"), 1) << "a.cpp's object once:\n" << runs.str();
  EXPECT_EQ(runs_with(log, "-c b.cpp"), 1) << "b.cpp's object once:\n" << runs.str();
  // Every build got the same objects, those of the cache, and no temporary file is left there.
  const std::string a0 = g::read_file(root / "work-0-0/obj/stub-a.cpp.o");
  EXPECT_FALSE(a0.empty());
  for (int p = 0; p < kProcesses; ++p)
    for (int w = 0; w < kWorkers; ++w) {
      const fs::path obj = root / ("work-" + std::to_string(p) + "-" + std::to_string(w)) / "obj";
      EXPECT_EQ(g::read_file(obj / "stub-a.cpp.o"), a0) << obj;
      EXPECT_EQ(g::read_file(obj / "a.cpp.o"), a0) << obj;
    }
  for (const auto& e : fs::recursive_directory_iterator(root / "cache"))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  // The same builds again: every artefact is in the cache, the compiler runs only to link.
  const int before = runs_with(log, "");
  g::parallel_for(kWorkers, kWorkers, [&](std::size_t w) {
    g::build_submission(config, root / "empty", root / ("again-" + std::to_string(w)), 2,
                        g::Isolation{});
  });
  EXPECT_EQ(runs_with(log, ""), before + kWorkers) << "only the three links:\n" << runs.str();
  unsetenv("JELLY_GRADE_CACHE");
  fs::remove_all(root);
}
