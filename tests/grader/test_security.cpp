// The red-team suite (CTest label "security"): one hostile submission per route a student could
// take to read the grader's hidden files or to take the grading machine down, all graded in ONE
// `jelly-grade batch` together with a well-behaved submission. Every hostile submission must fail
// with its message, the well-behaved one must be graded normally, and no output anywhere (reports,
// results.json, jelly-grade's own stdout/stderr) may contain any distinctive text of any hidden
// reference file. The hostile sources name the hidden files by their real absolute paths, so every
// route WOULD leak without the sandbox: NoIsolationLetsTheCanaryThrough proves the search finds it.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "shell_quote.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader" / "security";
const fs::path kHidden = kSource / "grader" / "data" / "hidden" / "a1.t4.spring_force.random.json";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
  return s;
}

std::string run(const std::string& args) {
  const std::string cmd = jelly::testing::shell_quoted(JELLY_GRADE_EXE) + " " +
                          jelly::testing::quote_tree_paths(args) + " 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  pclose(p);
  return out;
}

// Distinctive text of the hidden files: their long lines (numbers to 16 digits, notes) that no
// public reference file has.
std::vector<std::string> hidden_needles() {
  std::set<std::string> pub;
  auto lines = [](const fs::path& f) {
    std::vector<std::string> out;
    std::istringstream in(read_text(f));
    std::string l;
    while (std::getline(in, l)) {
      const auto a = l.find_first_not_of(" \t");
      if (a == std::string::npos) continue;
      l = l.substr(a);
      while (!l.empty() && (l.back() == ',' || l.back() == '\r')) l.pop_back();
      if (l.size() >= 14 && l.find_first_of("0123456789") != std::string::npos) out.push_back(l);
    }
    return out;
  };
  for (const auto& e : fs::directory_iterator(kSource / "grader" / "data" / "public"))
    for (const std::string& l : lines(e.path())) pub.insert(l);
  std::set<std::string> needles;
  for (const auto& e : fs::directory_iterator(kSource / "grader" / "data" / "hidden"))
    for (const std::string& l : lines(e.path()))
      if (!pub.count(l) && l.find("\"harness_digest\"") == std::string::npos &&
          l.find("\"commit\"") == std::string::npos && l.find("\"flags\"") == std::string::npos &&
          l.find("\"compiler\"") == std::string::npos &&
          l.find("\"format_version\"") == std::string::npos &&
          l.find("\"case_hash\"") == std::string::npos)
        needles.insert(l);
  return {needles.begin(), needles.end()};
}

// The first hidden text found in `text`, or "".
std::string leak_in(const std::string& text, const std::vector<std::string>& needles) {
  for (const std::string& n : needles)
    if (text.find(n) != std::string::npos) return n;
  return "";
}

std::string leaks_under(const fs::path& dir, const std::vector<std::string>& needles) {
  std::string found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string n = leak_in(read_text(e.path()), needles);
    if (!n.empty()) found += e.path().string() + ": " + n + "\n";
  }
  return found;
}

// Where a route's code goes: at the top of forces.cpp (compile time) or at the start of
// contact_plane in contact.cpp (run time, in the public test a1.t8.contact_plane.eps).
enum class Where { TopOfForces, InContactPlane, Special };

struct Route {
  const char* name;
  Where where;
  const char* code;  // @HIDDEN@: the hidden file's absolute path
  const char*
      expect;  // in the compile output, or in the output of test a1.t8.contact_plane.eps;
               // alternatives separated by | (bwrap hides a file, the user sandbox denies it)
  bool runs = false;  // compiles, and `expect` is in that test's output
  bool test_fails = true;
};

// clang-format off
const Route kRoutes[] = {
  // Preprocessor: the file named by routes a text filter does not see.
  {"computed_include", Where::TopOfForces,
   "#define JELLY_STR(x) #x\n#define JELLY_XSTR(x) JELLY_STR(x)\n#define JELLY_P @HIDDEN@\n#include JELLY_XSTR(JELLY_P)\n",
   "No such file or directory|Permission denied"},
  {"line_splice", Where::TopOfForces, "#inc\\\nlude \"@HIDDEN@\"\n", "No such file or directory|Permission denied"},
  {"has_include_probe", Where::TopOfForces,
   "#if __has_include(\"@HIDDEN@\")\n#error the hidden file is visible to the compiler\n#endif\n#error probe done\n",
   "probe done"},
  {"pragma_dependency", Where::TopOfForces, "#pragma GCC dependency \"@HIDDEN@\"\n#error after the dependency\n",
   "error"},
  {"pragma_message", Where::TopOfForces,
   "_Pragma(\"GCC dependency \\\"@HIDDEN@\\\"\")\n#pragma message(\"looking at @HIDDEN@\")\n#error after the pragmas\n", "error"},
  {"embed", Where::TopOfForces, "#embed \"@HIDDEN@\"\n", "embed"},
  // Assembler and linker: no preprocessor at all.
  {"asm_incbin", Where::TopOfForces,
   "#include <cstdio>\n#include <cstring>\n"
   "asm(\".section .rodata\\n.global jelly_leak\\njelly_leak: .incbin \\\"@HIDDEN@\\\"\\n.byte 0\\n.text\\n\");\n"
   "extern \"C\" const char jelly_leak[];\n"
   "static int jelly_print = [] { const char* o = std::strstr(jelly_leak, \"outputs\"); std::fputs(o ? o : jelly_leak, stdout); return 0; }();\n",
   "@HIDDEN@"},
  {"asm_include", Where::TopOfForces, "asm(\".include \\\"@HIDDEN@\\\"\");\n", "@HIDDEN@"},
  {"linker_warning", Where::TopOfForces,
   "asm(\".section .gnu.warning.jelly_warned\\n.incbin \\\"@HIDDEN@\\\"\\n.text\\n\");\n", "@HIDDEN@"},
  // The compiler as a denial of service.
  {"template_bomb", Where::TopOfForces,
   "template <int N, int M> struct JellyBomb { static constexpr long v = JellyBomb<N - 1, 2 * M>::v + JellyBomb<N - 1, 2 * M + 1>::v; };\n"
   "template <int M> struct JellyBomb<0, M> { static constexpr long v = M; };\nlong jelly_bomb = JellyBomb<26, 0>::v;\n",
   "compiling forces.cpp used more than 512 MiB of memory"},
  {"constexpr_bomb", Where::TopOfForces,
   "template <int N, int M> constexpr long jelly_cb = jelly_cb<N - 1, 2 * M> + jelly_cb<N - 1, 2 * M + 1>;\n"
   "template <int M> constexpr long jelly_cb<0, M> = M;\nlong jelly_bomb = jelly_cb<26, 0>;\n",
   "compiling forces.cpp used more than 512 MiB of memory"},
  {"error_flood", Where::TopOfForces,
   "#define J1 static_assert(sizeof(int) == 3, \"jelly flood\");\n#define J10 J1 J1 J1 J1 J1 J1 J1 J1 J1 J1\n#define J100 J10 J10 J10 J10 J10 J10 J10 J10 J10 J10\n"
   "#define J1000 J100 J100 J100 J100 J100 J100 J100 J100 J100 J100\n"
   "#define J10000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000\n"
   "J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000\n",
   "compiling forces.cpp printed more than 8 MiB of messages"},
  {"include_recursion", Where::TopOfForces, "#include __FILE__\n", "nested depth"},
  // Run time: every way to reach a file or another process without plain open().
  {"static_constructor", Where::TopOfForces,
   "#include <cstdio>\nstatic int jelly_ctor = [] { if (std::FILE* f = std::fopen(\"@HIDDEN@\", \"r\")) { char b[4096];"
   " while (std::fgets(b, sizeof b, f)) std::fputs(b, stdout); } else { std::puts(\"jelly: constructor saw no file\"); } return 0; }();\n",
   "jelly: constructor saw no file", true, false},
  {"io_uring", Where::InContactPlane,
   "{ struct { unsigned a[30]; } p{}; std::printf(\"%ld\\n\", syscall(__NR_io_uring_setup, 4, &p)); }\n", "io_uring_setup", true, true},
  {"open_by_handle_at", Where::InContactPlane,
   "{ char h[128] = {}; int m = 0; ((unsigned*)h)[0] = 120;"
   " syscall(__NR_name_to_handle_at, AT_FDCWD, \"@HIDDEN@\", h, &m, 0); syscall(__NR_open_by_handle_at, AT_FDCWD, h, 0); }\n",
   "name_to_handle_at", true, true},
  {"openat2", Where::InContactPlane,
   "{ unsigned long long how[3] = {0, 0, 0}; syscall(__NR_openat2, AT_FDCWD, \"@HIDDEN@\", how, sizeof how); }\n",
   "openat2", true, true},
  {"proc_self_fd", Where::InContactPlane, "{ char b[256] = {}; syscall(__NR_readlink, \"/proc/self/fd/0\", b, 255); std::puts(b); }\n",
   "readlink", true, true},
  {"proc_parent", Where::InContactPlane, "{ std::printf(\"parent %d\\n\", (int)getppid()); }\n", "getppid", true, true},
  {"inherited_fds", Where::InContactPlane,
   "{ char b[4096]; for (int fd = 0; fd < 64; ++fd) if (fd != 1 && fd != 2) { long n = read(fd, b, sizeof b - 1);"
   " if (n > 0) { b[n] = 0; std::fputs(b, stdout); } } std::puts(\"jelly: read every descriptor\"); }\n",
   "jelly: read every descriptor", true, false},
  {"execve", Where::InContactPlane,
   "{ char* argv[] = {(char*)\"cat\", (char*)\"@HIDDEN@\", nullptr}; execv(\"/bin/cat\", argv); }\n", "start another program", true, true},
  {"fork", Where::InContactPlane, "{ if (syscall(__NR_fork) == 0) _exit(0); }\n", "start a process", true, true},
  {"ptrace", Where::InContactPlane, "{ syscall(__NR_ptrace, 16 /* PTRACE_ATTACH */, 1, 0, 0); }\n", "inspect another process", true, true},
  {"process_vm_readv", Where::InContactPlane, "{ syscall(__NR_process_vm_readv, 1, nullptr, 0, nullptr, 0, 0); }\n",
   "inspect another process", true, true},
  {"socket", Where::InContactPlane, "{ syscall(__NR_socket, 2, 1, 0); }\n", "use the network", true, true},
  // Files that are not files.
  {"symlink", Where::Special, "", "is a symbolic link"},
  {"hardlink", Where::Special, "", "is a hard link"},
  {"fifo", Where::Special, "", "is not a regular file"},
};
// clang-format on

const char* const kTaskFiles[] = {"springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp",
                                  "integrators.cpp"};

fs::path make_submission(const fs::path& in, const Route& r) {
  const fs::path dir = in / r.name;
  fs::create_directories(dir);
  for (const char* f : kTaskFiles) fs::copy_file(kSource / "solutions" / f, dir / f);
  const std::string code = replace_all(r.code, "@HIDDEN@", kHidden.string());
  if (r.where == Where::TopOfForces) {
    std::ofstream(dir / "forces.cpp", std::ios::binary)
        << code << read_text(kSource / "solutions" / "forces.cpp");
  } else if (r.where == Where::InContactPlane) {
    std::string text = read_text(kSource / "solutions" / "contact.cpp");
    const std::string sig =
        "bool contact_plane(const Plane& plane, const Vec3& x, const Vec3& v, Vec3& f) {\n";
    const auto at = text.find(sig);
    EXPECT_NE(at, std::string::npos) << "solutions/contact.cpp changed: update the red-team suite";
    // Once per process: contact_plane also runs in every step of the scene cases.
    text.insert(
        at + sig.size(),
        "static bool jelly_once = false;\nif (!jelly_once) {\njelly_once = true;\n" + code + "}\n");
    std::ofstream(dir / "contact.cpp", std::ios::binary)
        << "#include <fcntl.h>\n#include <sys/syscall.h>\n#include <unistd.h>\n#include <cstdio>\n"
        << text;
  } else {
    fs::remove(dir / "forces.cpp");
    const std::string n = r.name;
    if (n == "symlink") fs::create_symlink(kHidden, dir / "forces.cpp");
    if (n == "fifo") {
      EXPECT_EQ(mkfifo((dir / "forces.cpp").c_str(), 0644), 0);
    }
    if (n == "hardlink") {
      // A second name of the hidden file itself where the file systems allow it, else of a copy.
      if (link(kHidden.c_str(), (dir / "forces.cpp").c_str()) != 0) {
        fs::copy_file(kHidden, in / "hardlink-target.json");
        EXPECT_EQ(link((in / "hardlink-target.json").c_str(), (dir / "forces.cpp").c_str()), 0);
      }
    }
  }
  return dir;
}

struct BatchRun {
  fs::path out;
  std::string console;
};

BatchRun run_batch(const std::string& tag, const std::vector<const Route*>& routes,
                   const std::string& isolation) {
  const fs::path root = kWork / tag, in = root / "in";
  fs::remove_all(root);
  fs::create_directories(in);
  for (const Route* r : routes) make_submission(in, *r);
  fs::create_directories(in / "zz_well_behaved");
  for (const char* f : kTaskFiles)
    fs::copy_file(kSource / "solutions" / f, in / "zz_well_behaved" / f);
  BatchRun b;
  b.out = root / "out";
  b.console = run("batch " + in.string() + " --out " + b.out.string() +
                  " --jobs 2 --visibility public --timeout 10 --compile-memory 512 --compile-cpu "
                  "30 --isolation " +
                  isolation);
  std::ofstream(root / "console.txt") << b.console;
  return b;
}

const Json* find_test(const Json& results, const std::string& id) {
  for (const Json& t : results["tests"])
    if (t["name"].get<std::string>().find("[" + id + "]") != std::string::npos) return &t;
  return nullptr;
}

bool has_any(const std::string& text, const std::string& alternatives) {
  std::istringstream in(alternatives);
  std::string a;
  while (std::getline(in, a, '|'))
    if (text.find(a) != std::string::npos) return true;
  return false;
}

// Each route failed as it should, the well-behaved submission got full marks, nothing leaked.
void check_batch(const BatchRun& b, const std::vector<const Route*>& routes,
                 const std::string& mechanism) {
  const std::vector<std::string> needles = hidden_needles();
  ASSERT_GT(needles.size(), 100u) << "too few distinctive hidden lines to search for";
  EXPECT_EQ(leak_in(b.console, needles), "") << "hidden text in jelly-grade's output";
  EXPECT_EQ(leaks_under(b.out, needles), "");
  for (const Route* r : routes) {
    SCOPED_TRACE(r->name);
    const fs::path res = b.out / r->name / "results.json";
    ASSERT_TRUE(fs::exists(res)) << b.console;
    const Json j = Json::parse(read_text(res));
    EXPECT_NE(j["output"].get<std::string>().find("Sandbox: " + mechanism), std::string::npos)
        << j["output"];
    const std::string expect = replace_all(r->expect, "@HIDDEN@", kHidden.filename().string());
    const Json& compile = j["tests"][0];
    if (r->runs) {
      ASSERT_EQ(compile["status"], "passed") << compile["output"];
      const Json* t = find_test(j, "a1.t8.contact_plane.eps");
      ASSERT_NE(t, nullptr);
      EXPECT_EQ((*t)["status"], r->test_fails ? "failed" : "passed");
      EXPECT_TRUE(has_any((*t)["output"].get<std::string>(), expect)) << (*t)["output"];
    } else {
      EXPECT_EQ(compile["status"], "failed");
      const std::string o = compile["output"];
      EXPECT_TRUE(has_any(o, expect)) << o.substr(0, 3000);
      EXPECT_EQ(o.find("the hidden file is visible"), std::string::npos) << o.substr(0, 3000);
      EXPECT_LT(o.size(), 300000u);
    }
  }
  const Json good = Json::parse(read_text(b.out / "zz_well_behaved" / "results.json"));
  double max = 0;
  for (const Json& t : good["tests"])
    if (t.contains("max_score")) max += t["max_score"].get<double>();
  EXPECT_GT(max, 0.0);
  EXPECT_NEAR(good["score"].get<double>(), max, 1e-3) << good.dump(1).substr(0, 4000);
}

std::vector<const Route*> all_routes() {
  std::vector<const Route*> v;
  for (const Route& r : kRoutes) v.push_back(&r);
  return v;
}

std::vector<const Route*> named(std::initializer_list<const char*> names) {
  std::vector<const Route*> v;
  for (const char* n : names)
    for (const Route& r : kRoutes)
      if (std::string(r.name) == n) v.push_back(&r);
  return v;
}

}  // namespace

// Without isolation the search below does find the hidden text (so it can fail), the run says
// loudly that hidden tests were not protected, and compiler messages still show no hidden line. It
// runs first on purpose: its object, which holds the hidden file, is in the object cache when the
// sandboxed batches below compile the same text, and must not be reused by them.
TEST(GraderSecurity, NoIsolationLetsTheCanaryThroughAndSaysSo) {
  const auto routes = named({"asm_incbin", "computed_include", "asm_include"});
  const BatchRun b = run_batch("none", routes, "none");
  // Compiler messages are filtered even without a sandbox: the hidden file was read by the compiler
  // and the assembler here, yet no line of it reaches the messages.
  for (const char* name : {"computed_include", "asm_include"}) {
    const std::string o =
        Json::parse(read_text(b.out / name / "results.json"))["tests"][0]["output"];
    EXPECT_NE(o.find("[hidden: a message about a file that is not part of your submission]"),
              std::string::npos)
        << o;
    EXPECT_EQ(leaks_under(b.out / name, hidden_needles()), "") << name;
  }
  EXPECT_NE(b.console.find("WARNING: hidden tests are NOT protected"), std::string::npos)
      << b.console;
  const Json j = Json::parse(read_text(b.out / "asm_incbin" / "results.json"));
  EXPECT_NE(j["output"].get<std::string>().find("Sandbox: none"), std::string::npos);
  EXPECT_NE(j["output"].get<std::string>().find("NOT protected"), std::string::npos);
  EXPECT_NE(leaks_under(b.out, hidden_needles()), "")
      << "the canary search found nothing even without isolation";
}

// The default mechanism of this machine (bubblewrap where user namespaces work, as in CI).
TEST(GraderSecurity, EveryRouteFailsWithItsMessageAndNothingLeaks) {
  const auto routes = all_routes();
  const BatchRun b = run_batch("auto", routes, "auto");
  const fs::path good = b.out / "zz_well_behaved" / "results.json";
  ASSERT_TRUE(fs::exists(good)) << b.console;
  const std::string mechanism = Json::parse(read_text(good))["extra_data"]["isolation"];
  if (mechanism == "none") GTEST_SKIP() << "no isolation available on this machine:\n" << b.console;
  check_batch(b, routes, mechanism);
}

// The fallback used where user namespaces are forbidden (Gradescope, Docker): an unprivileged user.
TEST(GraderSecurity, UnprivilegedUserFallbackStopsTheMainRoutes) {
  if (geteuid() != 0) GTEST_SKIP() << "--isolation user needs root";
  const auto routes = named({"computed_include", "asm_incbin", "static_constructor", "io_uring",
                             "symlink", "template_bomb"});
  const BatchRun b = run_batch("user", routes, "user");
  check_batch(b, routes, "user");
}

// A forced mechanism that cannot work stops the run with the reason, before anything is compiled:
// never a silent fall back to less isolation.
TEST(GraderSecurity, ForcedSandboxThatCannotWorkIsAGraderError) {
  setenv("JELLY_GRADE_BWRAP", "/bin/false", 1);  // a bubblewrap that cannot create a sandbox
  const std::string out = run("grade " + (kSource / "assignments").string() +
                              " --isolation bwrap --out " + (kWork / "forced").string());
  unsetenv("JELLY_GRADE_BWRAP");
  EXPECT_NE(out.find("--isolation bwrap: /bin/false cannot create a sandbox here"),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(kWork / "forced" / "results.json"));
}
