// The red-team suite (CTest label "security"), run against EVERY assignment of the build (the
// "assignments" of grade-config.json; each test is instantiated once per assignment id): one
// hostile submission per route a student could take to read the grader's hidden files or to take
// the grading machine down, all graded in ONE `jelly-grade batch` together with a well-behaved
// submission. Where a route goes in an assignment's files is that assignment's red-team hooks,
// grader/tests/hostile/<id>/redteam.toml; the submissions are its reference with the route laid in.
// Every hostile submission must fail with its message, the well-behaved one must be graded
// normally, and no output anywhere (reports, results.json, jelly-grade's own stdout/stderr) may
// contain any distinctive text of any hidden reference file of ANY assignment. The hostile sources
// name the hidden files by their real absolute paths, so every route WOULD leak without the
// sandbox: NoIsolationLetsTheCanaryThrough proves the search finds it.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "jelly/manifest.hpp"

#include "report_text.hpp"
#include "shell_quote.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader" / "security";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One assignment as the suite attacks it: its manifest, its folders, its hooks.
struct Target {
  std::string id;
  jelly::AssignmentManifest manifest;
  fs::path dir, hidden_dir, public_dir;
  fs::path solutions;        // the reference as a submission: every student file (grade-config's
                             // reference_dir)
  fs::path hidden;           // one of its hidden reference files (the routes' canary)
  std::string compile_file;  // compile-time routes go at its top
  std::string run_file, run_signature, run_case;  // run-time routes: start of this function
  std::string error;                              // what is wrong with its hooks ("" when usable)

  // Its task ids whose file is `file` ("A1.T4, A1.T5"), and the others.
  std::vector<std::string> tasks_of(const std::string& file, bool mine) const {
    std::vector<std::string> out;
    for (const jelly::ManifestTask& t : manifest.tasks)
      if (!t.file.empty() && (t.file == file) == mine) out.push_back(t.id);
    return out;
  }
};

// Every assignment of the build (grade-config.json), read once.
const std::vector<Target>& targets() {
  static const std::vector<Target> all = [] {
    std::vector<Target> v;
    const Json cfg =
        Json::parse(read_text(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json"));
    for (const auto& [id, a] : cfg.at("assignments").items()) {
      Target t;
      t.id = id;
      t.dir = a.at("dir").get<std::string>();
      t.solutions = a.value("reference_dir", a.at("solutions_dir").get<std::string>());
      t.hidden_dir = kSource / "grader" / "data" / id / "hidden";
      t.public_dir = t.dir / "grader" / "data" / "public";
      const fs::path hooks = kSource / "grader" / "tests" / "hostile" / id / "redteam.toml";
      try {
        t.manifest = jelly::read_manifest(t.dir / "assignment.toml");
        const toml::table h = toml::parse_file(hooks.string());
        t.compile_file = h["compile_file"].value_or(t.manifest.files.front());
        t.run_file = h["run_file"].value_or(std::string());
        t.run_signature = h["run_signature"].value_or(std::string());
        t.run_case = h["run_case"].value_or(std::string());
        if (t.run_file.empty() || t.run_signature.empty() || t.run_case.empty())
          t.error = hooks.string() + ": run_file, run_signature and run_case: expected strings";
      } catch (const std::exception& e) {
        t.error = hooks.string() + ": " + e.what() +
                  " (every assignment needs its red-team hooks: see grader/tests/hostile/a1/)";
      }
      std::set<fs::path> hidden;
      std::error_code ec;
      for (fs::directory_iterator it(t.hidden_dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json") hidden.insert(it->path());
      if (hidden.empty())
        t.error += " no hidden reference data in " + t.hidden_dir.string();
      else
        t.hidden = *hidden.begin();
      v.push_back(std::move(t));
    }
    return v;
  }();
  return all;
}

std::vector<std::string> target_ids() {
  std::vector<std::string> ids;
  for (const Target& t : targets()) ids.push_back(t.id);
  return ids;
}

// The assignment the running test attacks (set by the fixtures' SetUp).
const Target* T = nullptr;

void select_target(const std::string& id) {
  T = nullptr;
  for (const Target& t : targets())
    if (t.id == id) T = &t;
  ASSERT_NE(T, nullptr) << id;
  ASSERT_EQ(T->error, "") << "assignment " << id << " cannot be attacked";
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
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

// Whether `line` is a bare number k/q with q ≤ 1000 (13.333333333333334 = 40/3): such a value is
// not distinctive, since a report's scores are such fractions too (40 points × 1/3), and A3's
// hidden time maps are full of them.
bool simple_fraction(const std::string& line) {
  char* end = nullptr;
  const double v = std::strtod(line.c_str(), &end);
  if (end == line.c_str() || *end != '\0' || !std::isfinite(v)) return false;
  for (int q = 1; q <= 1000; ++q) {
    const double k = v * q;
    if (std::abs(k) < 1e9 && std::abs(k - std::round(k)) <= 1e-9 * std::max(1.0, std::abs(k)))
      return true;
  }
  return false;
}

// Distinctive text of the hidden files of every assignment: their long lines (numbers to 16 digits,
// notes) that no public reference file has, and no simple fraction.
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
  // Every assignment's: a submission of one must not show another's hidden data either.
  for (const Target& t : targets())
    for (const auto& e : fs::directory_iterator(t.public_dir))
      for (const std::string& l : lines(e.path())) pub.insert(l);
  std::set<std::string> needles;
  for (const Target& t : targets())
    for (const auto& e : fs::directory_iterator(t.hidden_dir))
      for (const std::string& l : lines(e.path()))
        if (!pub.count(l) && l.find("\"harness_digest\"") == std::string::npos &&
            l.find("\"commit\"") == std::string::npos && l.find("\"flags\"") == std::string::npos &&
            l.find("\"compiler\"") == std::string::npos &&
            l.find("\"format_version\"") == std::string::npos &&
            l.find("\"case_hash\"") == std::string::npos && !simple_fraction(l))
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

// Where a route's code goes: at the top of the assignment's compile_file (compile time), or at the
// start of its run_signature's body in run_file (run time, in the public test run_case): the
// assignment's hooks, grader/tests/hostile/<id>/redteam.toml. In code and messages, @FILE@ is the
// compile_file, @NS@ the tasks' namespace, @HIDDEN@ the canary's absolute path.
enum class Where { TopOfFile, InRunFunction, Special, WellBehaved };

struct Route {
  const char* name;
  Where where;
  const char* code;  // @HIDDEN@: the hidden file's absolute path
  const char*
      expect;  // in the compile output, or in the output of the assignment's run_case;
               // alternatives separated by | (bwrap hides a file, the user sandbox denies it)
  bool runs = false;  // compiles, and `expect` is in that test's output
  bool test_fails = true;
};

// clang-format off
const Route kRoutes[] = {
  // Preprocessor: the file named by routes a text filter does not see.
  {"computed_include", Where::TopOfFile,
   "#define JELLY_STR(x) #x\n#define JELLY_XSTR(x) JELLY_STR(x)\n#define JELLY_P @HIDDEN@\n#include JELLY_XSTR(JELLY_P)\n",
   "No such file or directory|Permission denied"},
  {"line_splice", Where::TopOfFile, "#inc\\\nlude \"@HIDDEN@\"\n", "No such file or directory|Permission denied"},
  {"has_include_probe", Where::TopOfFile,
   "#if __has_include(\"@HIDDEN@\")\n#error the hidden file is visible to the compiler\n#endif\n#error probe done\n",
   "probe done"},
  {"pragma_dependency", Where::TopOfFile, "#pragma GCC dependency \"@HIDDEN@\"\n#error after the dependency\n",
   "error"},
  {"pragma_message", Where::TopOfFile,
   "_Pragma(\"GCC dependency \\\"@HIDDEN@\\\"\")\n#pragma message(\"looking at @HIDDEN@\")\n#error after the pragmas\n", "error"},
  {"embed", Where::TopOfFile, "#embed \"@HIDDEN@\"\n", "embed"},
  // Assembler and linker: no preprocessor at all.
  {"asm_incbin", Where::TopOfFile,
   "#include <cstdio>\n#include <cstring>\n"
   "asm(\".section .rodata\\njelly_leak: .incbin \\\"@HIDDEN@\\\"\\n.byte 0\\n.text\\n\");\n"
   "extern \"C\" const char jelly_leak[];\n"
   "static int jelly_print = [] { const char* o = std::strstr(jelly_leak, \"outputs\"); std::fputs(o ? o : jelly_leak, stdout); return 0; }();\n",
   "@HIDDEN@"},
  {"asm_include", Where::TopOfFile, "asm(\".include \\\"@HIDDEN@\\\"\");\n", "@HIDDEN@"},
  {"linker_warning", Where::TopOfFile,
   "asm(\".section .gnu.warning.jelly_warned\\n.incbin \\\"@HIDDEN@\\\"\\n.text\\n\");\n", "@HIDDEN@"},
  // The compiler as a denial of service.
  {"template_bomb", Where::TopOfFile,
   "template <int N, int M> struct JellyBomb { static constexpr long v = JellyBomb<N - 1, 2 * M>::v + JellyBomb<N - 1, 2 * M + 1>::v; };\n"
   "template <int M> struct JellyBomb<0, M> { static constexpr long v = M; };\nlong jelly_bomb = JellyBomb<26, 0>::v;\n",
   "compiling @FILE@ used more than 512 MiB of memory"},
  {"constexpr_bomb", Where::TopOfFile,
   "template <int N, int M> constexpr long jelly_cb = jelly_cb<N - 1, 2 * M> + jelly_cb<N - 1, 2 * M + 1>;\n"
   "template <int M> constexpr long jelly_cb<0, M> = M;\nlong jelly_bomb = jelly_cb<26, 0>;\n",
   "compiling @FILE@ used more than 512 MiB of memory"},
  {"error_flood", Where::TopOfFile,
   "#define J1 static_assert(sizeof(int) == 3, \"jelly flood\");\n#define J10 J1 J1 J1 J1 J1 J1 J1 J1 J1 J1\n#define J100 J10 J10 J10 J10 J10 J10 J10 J10 J10 J10\n"
   "#define J1000 J100 J100 J100 J100 J100 J100 J100 J100 J100 J100\n"
   "#define J10000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000 J1000\n"
   "J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000 J10000\n",
   "compiling @FILE@ printed more than 8 MiB of messages"},
  {"include_recursion", Where::TopOfFile, "#include __FILE__\n", "nested depth"},
  // Run time: every way to reach a file or another process without plain open().
  {"static_constructor", Where::TopOfFile,
   "#include <cstdio>\nstatic int jelly_ctor = [] { if (std::FILE* f = std::fopen(\"@HIDDEN@\", \"r\")) { char b[4096];"
   " while (std::fgets(b, sizeof b, f)) std::fputs(b, stdout); } else { std::puts(\"jelly: constructor saw no file\"); } return 0; }();\n",
   "jelly: constructor saw no file", true, false},
  {"io_uring", Where::InRunFunction,
   "{ struct { unsigned a[30]; } p{}; std::printf(\"%ld\\n\", syscall(__NR_io_uring_setup, 4, &p)); }\n", "io_uring_setup", true, true},
  {"open_by_handle_at", Where::InRunFunction,
   "{ char h[128] = {}; int m = 0; ((unsigned*)h)[0] = 120;"
   " syscall(__NR_name_to_handle_at, AT_FDCWD, \"@HIDDEN@\", h, &m, 0); syscall(__NR_open_by_handle_at, AT_FDCWD, h, 0); }\n",
   "name_to_handle_at", true, true},
  {"openat2", Where::InRunFunction,
   "{ unsigned long long how[3] = {0, 0, 0}; syscall(__NR_openat2, AT_FDCWD, \"@HIDDEN@\", how, sizeof how); }\n",
   "openat2", true, true},
  {"proc_self_fd", Where::InRunFunction, "{ char b[256] = {}; syscall(__NR_readlink, \"/proc/self/fd/0\", b, 255); std::puts(b); }\n",
   "readlink", true, true},
  {"proc_parent", Where::InRunFunction, "{ std::printf(\"parent %d\\n\", (int)getppid()); }\n", "getppid", true, true},
  {"inherited_fds", Where::InRunFunction,
   "{ char b[4096]; for (int fd = 0; fd < 64; ++fd) if (fd != 1 && fd != 2) { long n = read(fd, b, sizeof b - 1);"
   " if (n > 0) { b[n] = 0; std::fputs(b, stdout); } } std::puts(\"jelly: read every descriptor\"); }\n",
   "jelly: read every descriptor", true, false},
  {"execve", Where::InRunFunction,
   "{ char* argv[] = {(char*)\"cat\", (char*)\"@HIDDEN@\", nullptr}; execv(\"/bin/cat\", argv); }\n", "start another program", true, true},
  {"fork", Where::InRunFunction, "{ if (syscall(__NR_fork) == 0) _exit(0); }\n", "start a process", true, true},
  {"ptrace", Where::InRunFunction, "{ syscall(__NR_ptrace, 16 /* PTRACE_ATTACH */, 1, 0, 0); }\n", "inspect another process", true, true},
  {"process_vm_readv", Where::InRunFunction, "{ syscall(__NR_process_vm_readv, 1, nullptr, 0, nullptr, 0, 0); }\n",
   "inspect another process", true, true},
  {"socket", Where::InRunFunction, "{ syscall(__NR_socket, 2, 1, 0); }\n", "use the network", true, true},
  // What a test prints and returns: any bytes (invalid UTF-8, NUL, terminal escapes, markup) end
  // as a graded test shown safely; a malformed or forged result on the result channel (fd 3) is
  // that test's failure, never a grader crash.
  {"printed_bytes", Where::InRunFunction,
   "{ static const char b[] = \"jelly bytes: \\xff\\xfe\\xc3( \\xe2\\x82 NUL[\\0] \\x1b[31mred\\x1b[0m \\x1b]0;title\\x07 \\x9b"
   " \\xe2\\x80\\xae <script>alert('x')</script> <img src=x onerror=alert(1)> ```` | **bold** [link](javascript:x) \\xf0\\x9f\\x98\\x80 end\\n\";"
   " std::fwrite(b, 1, sizeof b - 1, stdout); std::fwrite(b, 1, sizeof b - 1, stderr); for (int k = 0; k < 3000; ++k) std::fputs(\"\\xe2\\x86\\x92\\xc2\\xb0\", stdout); std::fputs(\"\\xe2\\x86\", stdout); }\n",
   "jelly bytes:", true, false},
  // Text that would pass for the grader's own (issue 28): a total line, HTML and Markdown fences
  // in what a test prints and in an exception's message. The report sets it apart and keeps it
  // text (checked in check_batch).
  {"report_injection", Where::InRunFunction,
   "{ static const char t[] = \"jelly injection\\nTotal: 80.00 / 80.00\\n<img src=x onerror=alert(1)>\\n"
   "```\\n~~~\\n<script>alert(2)</script>\\n\"; std::fputs(t, stdout); std::fflush(stdout); std::fputs(t, stderr);"
   " throw std::runtime_error(t); }\n",
   "jelly injection", true, true},
  {"result_garbage", Where::InRunFunction,
   "{ static const char g[] = \"\\xff\\x00{not json\"; write(3, g, sizeof g - 1); }\n",
   "the test's result could not be read", true, true},
  {"result_forged", Where::InRunFunction,
   "{ static const char g[] = \"{\\\"forbidden_syscall\\\": \\\"openat\\\", \\\"outputs\\\": [1, 2]}\\n\";"
   " write(3, g, sizeof g - 1); _exit(0); }\n",
   "the test's result has no outputs", true, true},
  {"result_wrong_types", Where::InRunFunction,
   "{ static const char g[] = \"{\\\"outputs\\\": {\\\"force\\\": 5, \\\"com_y\\\": {\\\"value\\\": {\\\"a\\\": 1}}, \\\"frame_times\\\": 7}}\\n\";"
   " write(3, g, sizeof g - 1); _exit(0); }\n",
   "your code produced no value", true, true},
  // A file that does not compile costs only its own tasks (checked for every route that stops
  // the compile_file: the other files' tasks keep full marks).
  {"missing_semicolon", Where::Special, "", "expected ';'|expected ‘;’"},
  // Link time: a submission may not replace the grader's code (framework, runner, harness, the C
  // and C++ libraries); a non-static helper of its own is fine.
  {"redefine_sandbox", Where::TopOfFile,
   "namespace jelly::grade { bool install_sandbox(int) { return true; } }\n",
   "jelly::grade::install_sandbox(int)|defined by the grader's own code"},
  {"redefine_libc", Where::TopOfFile,
   "extern \"C\" int seccomp_load(void*) { return 0; }\n",
   "defines the external symbol seccomp_load, which"},
  {"extern_c_function", Where::TopOfFile,
   "extern \"C\" long jelly_c_helper(long x) { return x; }\n",
   "jelly_c_helper, which is not a C++ function"},
  {"redefine_task_table", Where::TopOfFile,
   "#include \"jelly/task_table.hpp\"\nnamespace jelly::@NS@ { TaskTable task_table(); }\n"
   "namespace jelly { TaskTable @NS@::task_table() { return {}; } }\n",
   "jelly::@NS@::task_table()"},
  {"nonstatic_helper", Where::WellBehaved, "", ""},
  // Folder names that would break or forge a CSV file, or collide with the batch's own files.
  {"scores.csv", Where::WellBehaved, "", ""},
  {"=HYPERLINK(\"http:,x\")", Where::WellBehaved, "", ""},
  {"a,b \"quoted\"\nrow,99.00", Where::WellBehaved, "", ""},
  // Files that are not files.
  {"symlink", Where::Special, "", "is a symbolic link"},
  {"hardlink", Where::Special, "", "is a hard link"},
  {"fifo", Where::Special, "", "is not a regular file"},
};
// clang-format on

// A route's text for the running test's assignment.
std::string for_target(const std::string& text) {
  std::string out = replace_all(text, "@HIDDEN@", T->hidden.string());
  out = replace_all(out, "@FILE@", T->compile_file);
  return replace_all(out, "@NS@", T->manifest.ns);
}

// The assignment's files from `from` (its reference or its stubs) into `dir`.
void copy_files(const fs::path& from, const fs::path& dir) {
  for (const std::string& f : T->manifest.files) fs::copy_file(from / f, dir / f);
}

fs::path make_submission(const fs::path& in, const Route& r) {
  const fs::path dir = in / r.name;
  fs::create_directories(dir);
  copy_files(T->solutions, dir);
  const std::string code = for_target(r.code);
  const fs::path top = dir / T->compile_file, reference_top = T->solutions / T->compile_file;
  if (r.where == Where::TopOfFile) {
    std::ofstream(top, std::ios::binary) << code << read_text(reference_top);
  } else if (r.where == Where::InRunFunction) {
    std::string text = read_text(T->solutions / T->run_file);
    const auto at = text.find(T->run_signature);
    EXPECT_NE(at, std::string::npos) << T->solutions / T->run_file << " has no run_signature "
                                     << T->run_signature << ": update its redteam.toml";
    // Once per process: the function may also run in every step of the scene cases.
    text.insert(
        at + T->run_signature.size(),
        "static bool jelly_once = false;\nif (!jelly_once) {\njelly_once = true;\n" + code + "}\n");
    std::ofstream(dir / T->run_file, std::ios::binary)
        << "#include <fcntl.h>\n#include <sys/syscall.h>\n#include <unistd.h>\n#include <cstdio>\n"
        << "#include <stdexcept>\n"
        << text;
  } else if (r.where == Where::WellBehaved) {
    if (std::string(r.name) == "nonstatic_helper") {
      // An honest helper with external linkage: allowed.
      std::string text = read_text(reference_top);
      const std::string ns = "namespace jelly::" + T->manifest.ns + " {\n";
      const auto at = text.find(ns);
      EXPECT_NE(at, std::string::npos) << reference_top << " changed: update the red-team suite";
      text.insert(at + ns.size(),
                  "double jelly_helper_twice(double x);\n"
                  "double jelly_helper_twice(double x) { return 2.0 * x; }\n");
      std::ofstream(top, std::ios::binary) << text;
    }
  } else {
    fs::remove(top);
    const std::string n = r.name;
    if (n == "missing_semicolon") {
      // One missing ';' in the body of a task function.
      std::string text = read_text(reference_top);
      const auto ret = text.find("return ");
      const auto semi = text.find(";\n", ret);
      EXPECT_NE(ret, std::string::npos) << reference_top << " changed: update the red-team suite";
      text.erase(semi, 1);
      std::ofstream(top, std::ios::binary) << text;
    }
    if (n == "symlink") fs::create_symlink(T->hidden, top);
    if (n == "fifo") {
      EXPECT_EQ(mkfifo(top.c_str(), 0644), 0);
    }
    if (n == "hardlink") {
      // A second name of the hidden file itself where the file systems allow it, else of a copy.
      if (link(T->hidden.c_str(), top.c_str()) != 0) {
        // (in the submission: a loose file in the class folder would be a row of its own)
        fs::copy_file(T->hidden, dir / "hardlink-target.json");
        EXPECT_EQ(link((dir / "hardlink-target.json").c_str(), top.c_str()), 0);
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
  const fs::path root = kWork / T->id / tag, in = root / "in";
  fs::remove_all(root);
  fs::create_directories(in);
  for (const Route* r : routes) make_submission(in, *r);
  fs::create_directories(in / "zz_well_behaved");
  copy_files(T->solutions, in / "zz_well_behaved");
  BatchRun b;
  b.out = root / "out";
  b.console = run("batch " + in.string() + " --out " + b.out.string() + " --assignment " + T->id +
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

// Whether `s` is valid UTF-8 (well-formed sequences only).
bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned c = static_cast<unsigned char>(s[i]);
    std::size_t n = c < 0x80             ? 1
                    : (c & 0xE0) == 0xC0 ? 2
                    : (c & 0xF0) == 0xE0 ? 3
                    : (c & 0xF8) == 0xF0 ? 4
                                         : 0;
    if (n == 0 || i + n > s.size() || (n == 2 && c < 0xC2)) return false;
    unsigned cp = n == 1 ? c : c & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) ||
        (cp >= 0xD800 && cp <= 0xDFFF))
      return false;
    i += n;
  }
  return true;
}

// RFC 4180 records (quoted fields may hold commas, quotes and line breaks).
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        field += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        field += c;
    } else if (c == '"' && field.empty() && !was_quoted) {
      quoted = was_quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field), field.clear(), was_quoted = false;
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
    } else if (c == '\n') {
      rows.back().push_back(field), field.clear(), was_quoted = false;
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

double task_score(const Json& results, const std::string& task) {
  double sum = 0;
  for (const Json& t : results["tests"])
    if (t.contains("tags") && t["tags"][0] == task) sum += t["score"].get<double>();
  return sum;
}

// Each route failed as it should, the well-behaved submissions got full marks, nothing leaked,
// every output is valid UTF-8 without terminal controls, and scores.csv has one correct row per
// submission whatever its folder's name.
void check_batch(const BatchRun& b, const std::vector<const Route*>& routes,
                 const std::string& mechanism) {
  const std::vector<std::string> needles = hidden_needles();
  ASSERT_GT(needles.size(), 100u) << "too few distinctive hidden lines to search for";
  EXPECT_EQ(leak_in(b.console, needles), "") << "hidden text in jelly-grade's output";
  EXPECT_EQ(leaks_under(b.out, needles), "");
  for (const auto& e : fs::recursive_directory_iterator(b.out)) {
    if (!e.is_regular_file() || e.path().extension() == ".png" || e.path().extension() == ".svg")
      continue;
    const std::string text = read_text(e.path());
    EXPECT_TRUE(valid_utf8(text)) << e.path();
    EXPECT_EQ(text.find('\x1b'), std::string::npos) << "a terminal escape in " << e.path();
    EXPECT_EQ(text.find('\0'), std::string::npos) << "a NUL byte in " << e.path();
  }
  EXPECT_TRUE(valid_utf8(b.console));
  EXPECT_EQ(b.console.find("\x1b["), std::string::npos) << "a terminal escape on the console";
  const Json good = Json::parse(read_text(b.out / "students" / "zz_well_behaved" / "results.json"));
  double max = 0;
  for (const Json& t : good["tests"])
    if (t.contains("max_score")) max += t["max_score"].get<double>();
  EXPECT_GT(max, 0.0);
  // A bonus task (A2's friction) is on top of the tests' maximum in Gradescope's score, and
  // extra_data says how much (docs/new-assignment.md, `bonus`); scores.csv's score leaves it out.
  const auto bonus_of = [](const Json& j) {
    return j.contains("extra_data") && j["extra_data"].contains("bonus_score")
               ? j["extra_data"]["bonus_score"].get<double>()
               : 0.0;
  };
  const double bonus_max = good.contains("extra_data") && good["extra_data"].contains("bonus_max")
                               ? good["extra_data"]["bonus_max"].get<double>()
                               : 0.0;
  EXPECT_NEAR(good["score"].get<double>(), max + bonus_max, 1e-3) << good.dump(1).substr(0, 4000);
  EXPECT_NEAR(bonus_of(good), bonus_max, 1e-9)
      << "the well-behaved submission gets the whole bonus";
  const auto csv = parse_csv(read_text(b.out / "scores.csv"));
  ASSERT_FALSE(csv.empty());
  EXPECT_EQ(csv.size(), routes.size() + 2) << read_text(b.out / "scores.csv");
  std::map<std::string, std::vector<std::string>> rows;
  for (std::size_t i = 1; i < csv.size(); ++i) {
    EXPECT_EQ(csv[i].size(), csv[0].size()) << "row " << i << " of scores.csv";
    if (!csv[i].empty()) rows[csv[i][0]] = csv[i];
  }
  // The class report counts every submission as graded (a hostile one is a student with a low
  // score, never a hole in the class result), and the well-behaved one among the full marks.
  const Json cls = Json::parse(read_text(b.out / "class.json"));
  EXPECT_EQ(cls["students"], routes.size() + 1) << cls.dump(1).substr(0, 3000);
  EXPECT_EQ(cls["graded"], routes.size() + 1);
  EXPECT_TRUE(cls["could_not_grade"].empty()) << cls["could_not_grade"].dump(1);
  EXPECT_GE(cls["score"]["full_marks"].get<int>(), 1) << cls["score"].dump(1);
  // The id batch gives a folder name: control characters and what Windows refuses in a name
  // become '_' (docs/grader.md, "Batch inputs").
  const auto id_of = [](std::string name) {
    for (char& c : name)
      if (static_cast<unsigned char>(c) < 0x20 ||
          std::string("/\\<>:\"|?*").find(c) != std::string::npos)
        c = '_';
    return name;
  };
  for (const Route* r : routes) {
    SCOPED_TRACE(r->name);
    const fs::path res = b.out / "students" / id_of(r->name) / "results.json";
    ASSERT_TRUE(fs::exists(res)) << b.console;
    const Json j = Json::parse(read_text(res));
    EXPECT_NE(j["output"].get<std::string>().find("Sandbox: " + mechanism), std::string::npos)
        << j["output"];
    // Its row: the id from the folder name (a spreadsheet formula marked as text), its score.
    std::string name = id_of(r->name);
    if (name[0] == '=') name = "'" + name;
    ASSERT_TRUE(rows.count(name)) << "no row for " << name << " in\n"
                                  << read_text(b.out / "scores.csv");
    EXPECT_NEAR(std::stod(rows[name][1]), j["score"].get<double>() - bonus_of(j), 0.006);
    const std::string expect =
        replace_all(for_target(r->expect), T->hidden.string(), T->hidden.filename().string());
    const Json& compile = j["tests"][0];
    if (r->where == Where::WellBehaved) {
      EXPECT_EQ(compile["status"], "passed") << compile["output"];
      EXPECT_NEAR(j["score"].get<double>(), max + bonus_max, 1e-3) << j.dump(1).substr(0, 4000);
    } else if (r->runs) {
      ASSERT_EQ(compile["status"], "passed") << compile["output"];
      const Json* t = find_test(j, T->run_case);
      ASSERT_NE(t, nullptr) << T->run_case;
      EXPECT_EQ((*t)["status"], r->test_fails ? "failed" : "passed");
      EXPECT_TRUE(has_any((*t)["output"].get<std::string>(), expect)) << (*t)["output"];
    } else {
      EXPECT_EQ(compile["status"], "failed");
      const std::string o = compile["output"];
      EXPECT_TRUE(has_any(o, expect)) << o.substr(0, 3000);
      EXPECT_EQ(o.find("the hidden file is visible"), std::string::npos) << o.substr(0, 3000);
      EXPECT_LT(o.size(), 300000u);
      // Every route here stops the compile_file only: it costs that file's tasks, the others
      // keep their points (graded with the stub of that file in its place), and the report says
      // so.
      const std::vector<std::string> mine = T->tasks_of(T->compile_file, true);
      ASSERT_FALSE(mine.empty()) << T->compile_file << " has no task in the manifest";
      EXPECT_NE(o.find(T->compile_file + " "), std::string::npos) << o.substr(0, 3000);
      EXPECT_NE(o.find(join(mine)), std::string::npos) << o.substr(0, 3000);
      for (const std::string& task : mine) EXPECT_EQ(task_score(j, task), 0.0) << task;
      for (const std::string& task : T->tasks_of(T->compile_file, false))
        EXPECT_NEAR(task_score(j, task), task_score(good, task), 1e-6) << task;
    }
  }
  // Issue 28: the injection route's text is set apart and stays text. No line of the plain-text
  // outputs starts with its "Total:" (Gradescope shows them as text); Markdown renders none of
  // its markup outside a fenced block; HTML escapes it.
  for (const Route* r : routes)
    if (std::string(r->name) == "report_injection") {
      const fs::path dir = b.out / "students" / r->name;
      const Json j = Json::parse(read_text(dir / "results.json"));
      EXPECT_EQ(j.value("output_format", ""), "text");
      EXPECT_EQ(j.value("test_output_format", ""), "text");
      std::string plain = j["output"].get<std::string>();
      for (const Json& t : j["tests"]) plain += t["output"].get<std::string>() + "\n";
      EXPECT_NE(plain.find("Total: 80.00 / 80.00"), std::string::npos) << plain.substr(0, 4000);
      EXPECT_EQ(jelly::testing::lines_starting(plain, "Total:"), 0) << plain.substr(0, 4000);
      const std::string md = read_text(dir / "report.md");
      const std::string rendered = jelly::testing::outside_code_blocks(md);
      EXPECT_EQ(rendered.find("<img"), std::string::npos) << md.substr(0, 4000);
      EXPECT_EQ(rendered.find("<script"), std::string::npos) << md.substr(0, 4000);
      EXPECT_EQ(jelly::testing::lines_starting(rendered, "Total:"), 0) << md.substr(0, 4000);
      const std::string html = read_text(dir / "report.html");
      EXPECT_EQ(html.find("<img src=x"), std::string::npos);
      EXPECT_EQ(html.find("<script>alert(2)"), std::string::npos);
      EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
    }
  // What the bytes route printed reached the report, made safe.
  for (const Route* r : routes)
    if (std::string(r->name) == "printed_bytes") {
      const std::string md = read_text(b.out / "students" / r->name / "report.md");
      EXPECT_NE(md.find("jelly bytes: \xEF\xBF\xBD"), std::string::npos) << md.substr(0, 3000);
      EXPECT_NE(md.find("\xE2\x90\x9B[31mred"), std::string::npos) << "ESC shown as ␛";
      EXPECT_NE(md.find("\xF0\x9F\x98\x80"), std::string::npos) << "the emoji kept";
      const std::string o =
          Json::parse(read_text(b.out / "students" / r->name / "results.json")).dump();
      EXPECT_NE(o.find("jelly bytes"), std::string::npos);
    }
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
// Each test below runs once per assignment of the build (Assignments/...: its id).
class GraderSecurity : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { select_target(GetParam()); }
};

TEST_P(GraderSecurity, NoIsolationLetsTheCanaryThroughAndSaysSo) {
  const auto routes = named({"asm_incbin", "computed_include", "asm_include"});
  const BatchRun b = run_batch("none", routes, "none");
  // Compiler messages are filtered even without a sandbox: the hidden file was read by the compiler
  // and the assembler here, yet no line of it reaches the messages.
  for (const char* name : {"computed_include", "asm_include"}) {
    const std::string o =
        Json::parse(read_text(b.out / "students" / name / "results.json"))["tests"][0]["output"];
    EXPECT_NE(o.find("[hidden: a message about a file that is not part of your submission]"),
              std::string::npos)
        << o;
    EXPECT_EQ(leaks_under(b.out / "students" / name, hidden_needles()), "") << name;
  }
  EXPECT_NE(b.console.find("WARNING: hidden tests are NOT protected"), std::string::npos)
      << b.console;
  const Json j = Json::parse(read_text(b.out / "students" / "asm_incbin" / "results.json"));
  EXPECT_NE(j["output"].get<std::string>().find("Sandbox: none"), std::string::npos);
  EXPECT_NE(j["output"].get<std::string>().find("NOT protected"), std::string::npos);
  EXPECT_NE(leaks_under(b.out, hidden_needles()), "")
      << "the canary search found nothing even without isolation";
}

// The default mechanism of this machine (bubblewrap where user namespaces work, as in CI).
TEST_P(GraderSecurity, EveryRouteFailsWithItsMessageAndNothingLeaks) {
  const auto routes = all_routes();
  const BatchRun b = run_batch("auto", routes, "auto");
  const fs::path good = b.out / "students" / "zz_well_behaved" / "results.json";
  ASSERT_TRUE(fs::exists(good)) << b.console;
  const std::string mechanism = Json::parse(read_text(good))["extra_data"]["isolation"];
  if (mechanism == "none") GTEST_SKIP() << "no isolation available on this machine:\n" << b.console;
  check_batch(b, routes, mechanism);
}

// The fallback used where user namespaces are forbidden (Gradescope, Docker): an unprivileged user.
TEST_P(GraderSecurity, UnprivilegedUserFallbackStopsTheMainRoutes) {
  if (geteuid() != 0) GTEST_SKIP() << "--isolation user needs root";
  const auto routes = named({"computed_include", "asm_incbin", "static_constructor", "io_uring",
                             "symlink", "template_bomb", "printed_bytes", "result_forged",
                             "missing_semicolon", "redefine_sandbox", "scores.csv"});
  const BatchRun b = run_batch("user", routes, "user");
  check_batch(b, routes, "user");
}

// A forced mechanism that cannot work stops the run with the reason, before anything is compiled:
// never a silent fall back to less isolation.
TEST_P(GraderSecurity, ForcedSandboxThatCannotWorkIsAGraderError) {
  setenv("JELLY_GRADE_BWRAP", "/bin/false", 1);  // a bubblewrap that cannot create a sandbox
  const fs::path out_dir = kWork / T->id / "forced";
  const std::string out = run("grade " + T->dir.string() + " --assignment " + T->id +
                              " --isolation bwrap --out " + out_dir.string());
  unsetenv("JELLY_GRADE_BWRAP");
  EXPECT_NE(out.find("--isolation bwrap: /bin/false cannot create a sandbox here"),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(out_dir / "results.json"));
}

INSTANTIATE_TEST_SUITE_P(Assignments, GraderSecurity, ::testing::ValuesIn(target_ids()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// ---------------------------------------------------------------------------------------------
// The operating-system side (issue 18, items 3-5): what a submission can do to the machine and to
// the submissions graded beside it, in bubblewrap and in the user-drop mode. Each batch runs on a
// copy of the tree under /tmp (as a fresh clone would be), configured with JELLY_TASKS=solutions,
// so that the build tree holds binaries linked with the reference (jelly-grade-student-runner), a
// Gradescope zip and a stale staging folder of one. Every hostile submission is graded in ONE batch
// with two well-behaved ones, which must get full marks.
namespace {

// The request of this test, read from fd 0 without moving its offset (before the runner does).
const char* const kReadRequest =
    "#include <dirent.h>\n#include <errno.h>\n#include <fcntl.h>\n#include <poll.h>\n#include "
    "<signal.h>\n"
    "#include <sys/stat.h>\n#include <sys/wait.h>\n#include <unistd.h>\n#include <cstdio>\n"
    "#include <cstdlib>\n#include <cstring>\n#include <string>\n"
    "static std::string jelly_request() { std::string s; char b[4096]; off_t o = 0; long n;"
    " while ((n = pread(0, b, sizeof b, o)) > 0) { s.append(b, static_cast<std::size_t>(n)); o += "
    "n; }"
    " return s; }\n"
    "static bool jelly_target() { return jelly_request().find(\"\\\"@CASE@\\\"\") "
    "!="
    " std::string::npos; }\n";

struct OsRoute {
  const char* name;
  bool stubs;        // on the stubs (assignments/<id>/): a forged result would be the only points
  const char* code;  // a static constructor at the top of the compile_file: it runs before the
                     // runner reads its request and installs its seccomp filter
};

// clang-format off
const OsRoute kOsRoutes[] = {
  // Runs a binary of the build tree linked with the reference and hands in its result as its own.
  {"os_reference_binary", true,
   "static int jelly_forge = [] {\n"
   "  const char* bins[] = {\"@BUILD@/grader/jelly-grade-@ID@-reference-runner\", \"@BUILD@/grader/jelly-grade-@ID@-student-runner\", nullptr};\n"
   "  for (int i = 0; bins[i]; ++i) {\n"
   "    if (access(bins[i], X_OK) != 0) { std::fprintf(stderr, \"jelly-forge: cannot run %s: %s\\n\", std::strrchr(bins[i], '/') + 1, std::strerror(errno)); continue; }\n"
   "    const pid_t p = fork();\n"
   "    if (p == 0) { execl(bins[i], bins[i], \"--request\", \"-\", \"--result-fd\", \"3\", (char*)nullptr); _exit(127); }\n"
   "    int st = 0; waitpid(p, &st, 0);\n"
   "    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) _exit(0);\n"
   "    std::fprintf(stderr, \"jelly-forge: %s failed (status %d)\\n\", std::strrchr(bins[i], '/') + 1, st);\n"
   "  }\n  return 0; }();\n"},
  // Reads what derives from the reference or the hidden data, and the neighbours' files.
  {"os_read_secrets", false,
   "static int jelly_peek = [] {\n"
   "  if (!jelly_target()) return 0;\n"
   "  const char* paths[] = {@PATHS@ nullptr};\n"
   "  int denied = 0;\n"
   "  auto peek = [&](const char* p) { const int fd = open(p, O_RDONLY); if (fd < 0) { ++denied; return; } struct stat st{}; char b[64]; const long n = read(fd, b, sizeof b);"
   " if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) std::printf(\"jelly-OPENED %s (%ld bytes)\\n\", p, n); close(fd); };\n"
   "  for (int i = 0; paths[i]; ++i) peek(paths[i]);\n"
   "  // Other submissions' files named on the command lines of their compilers and runners (this\n"
   "  // batch's: gradings of other trees on the machine are not this batch's to protect).\n"
   "  char self[4096] = {}; if (readlink(\"/proc/self/exe\", self, sizeof self - 1) < 0) self[0] = 0;\n"
   "  std::string own = self; own = own.substr(0, own.rfind(\"/build/runner\") + 1);  // this submission's own folder\n"
   "  if (DIR* d = opendir(\"/proc\")) { while (dirent* e = readdir(d)) { char f[300]; std::snprintf(f, sizeof f, \"/proc/%s/cmdline\", e->d_name);"
   " const int fd = open(f, O_RDONLY); if (fd < 0) continue; char c[8192]; const long n = read(fd, c, sizeof c - 1); close(fd); if (n <= 0) continue; c[n] = 0;"
   " for (char* a = c; a < c + n; a += std::strlen(a) + 1) { const std::string s(a); if (s.size() > 4 && s[0] == '/' && (s.find(\".cpp\") != std::string::npos || s.find(\"/runner\") != std::string::npos) && s.rfind(own, 0) != 0 && (s.rfind(\"@ROOT@\", 0) == 0 || s.find(\"/jelly-grade-\") != std::string::npos)) peek(a); } } closedir(d); }\n"
   "  std::printf(\"jelly-peek: %d denied\\n\", denied);\n"
   "  return 0; }();\n"},
  // Leaves a process behind (setsid + double fork) that kills every process it may and holds the
  // pipes.
  {"os_daemon", false,
   "static int jelly_daemon = [] {\n"
   "  if (!jelly_target()) return 0;\n"
   "  if (fork() == 0) { setsid(); if (fork() == 0) { for (int i = 0; i < 30000; ++i) { kill(-1, SIGKILL); usleep(1000); } _exit(0); } _exit(0); }\n"
   "  usleep(300000);\n  return 0; }();\n"},
  // Every test leaves its request (a hidden test's parameters) in the shared folders and prints
  // what earlier tests left there.
  {"os_tmp_channel", false,
   "static int jelly_channel = [] {\n"
   "  const std::string req = jelly_request();\n"
   "  const char* env = std::getenv(\"TMPDIR\");\n"
   "  const char* dirs[] = {\"/tmp\", \"/var/tmp\", \"/dev/shm\", env ? env : \"/tmp\", \".\"};\n"
   "  const std::string mine = \"jelly-channel-\" + std::to_string(getpid());\n"
   "  for (const char* d : dirs) { DIR* dd = opendir(d); if (!dd) continue; while (dirent* e = readdir(dd)) {"
   " if (std::strncmp(e->d_name, \"jelly-channel-\", 14) != 0 || mine == e->d_name) continue; std::string f = std::string(d) + \"/\" + e->d_name;"
   " if (FILE* i = std::fopen(f.c_str(), \"r\")) { char b[400] = {}; std::fread(b, 1, sizeof b - 1, i); std::fclose(i); std::printf(\"jelly-channel-found: %s\\n\", b); } } closedir(dd); }\n"
   "  for (const char* d : dirs) if (FILE* o = std::fopen((std::string(d) + \"/\" + mine).c_str(), \"w\")) { std::fputs(req.c_str(), o); std::fclose(o); }\n"
   "  return 0; }();\n"},
  // Fills /tmp with symbolic links.
  {"os_symlink_flood", false,
   "static int jelly_flood = [] {\n"
   "  if (!jelly_target()) return 0;\n"
   "  for (int i = 0; i < 20000; ++i) { const std::string n = \"/tmp/jelly-flood-\" + std::to_string(getpid()) + \"-\" + std::to_string(i); if (symlink(\"/etc/passwd\", n.c_str()) != 0) break; }\n"
   "  return 0; }();\n"},
  // Four processes of 700 MiB each (each under the 1 GiB per-process limit; in pieces, as one block
  // of 700 MiB may not fit beside the runner's own mappings).
  {"os_fork_memory", false,
   "static int jelly_memory = [] {\n"
   "  if (!jelly_target()) return 0;\n"
   "  int ready[2]; if (pipe(ready) != 0) return 0;\n"
   "  for (int i = 0; i < 4; ++i) if (fork() == 0) { close(ready[0]); for (int k = 0; k < 10; ++k) { char* p = static_cast<char*>(std::malloc(70u << 20)); if (!p) break; std::memset(p, 1, 70u << 20); }"
   " if (write(ready[1], \"x\", 1) != 1) _exit(1); pause(); _exit(0); }\n"
   "  close(ready[1]);\n"
   "  // Until each of the four holds its memory or was stopped at the cap (and never says so). No\n"
   "  // clock: on a loaded machine the memory takes its time.\n"
   "  char b[4]; int got = 0, gone = 0;\n"
   "  while (got + gone < 4) { pollfd p{ready[0], POLLIN, 0}; if (poll(&p, 1, 100) > 0) { const long n = read(ready[0], b, sizeof b); if (n > 0) got += static_cast<int>(n); }"
   " while (waitpid(-1, nullptr, WNOHANG) > 0) ++gone; }\n"
   "  std::printf(\"jelly-memory: %d of 4 hold 700 MiB\\n\", got);\n  return 0; }();\n"},
  // 600 processes.
  {"os_fork_many", false,
   "static int jelly_many = [] {\n"
   "  if (!jelly_target()) return 0;\n"
   "  int n = 0;\n  for (; n < 600; ++n) { const pid_t p = fork(); if (p == 0) { pause(); _exit(0); } if (p < 0) break; }\n"
   "  std::printf(\"jelly-forked %d\\n\", n);\n  return 0; }();\n"},
};
// clang-format on

int sh(const std::string& command) {
  const int s = std::system(command.c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

// A copy of the tree as a clone under /tmp would have it: the sources the grader reads and the
// build tree's grader and framework (with the binaries and libraries linked with solutions/), and
// grade-config.json pointing there.
struct Clone {
  fs::path root, src, build, config;
};

Clone make_clone(const std::string& tag) {
  Clone c;
  char templ[] = "/tmp/jelly-sec-XXXXXX";
  const char* made = mkdtemp(templ);
  EXPECT_NE(made, nullptr);
  c.root = fs::path(made ? made : "/tmp/jelly-sec-failed") / tag;
  c.src = c.root / "src";
  c.build = c.root / "build";
  fs::create_directories(c.src);
  fs::create_directories(c.build);
  chmod(c.root.parent_path().c_str(), 0755);  // the sandbox users must reach the public headers
  const fs::path bin = JELLY_BINARY_DIR;
  for (const char* item :
       {"CMakeLists.txt", "cmake", "framework", "assignments", "solutions", "grader", "docs"})
    EXPECT_EQ(sh("cp -a '" + (kSource / item).string() + "' '" + c.src.string() + "/'"), 0);
  EXPECT_EQ(sh("cp -a '" + (bin / "framework").string() + "' '" + c.build.string() + "/'"), 0);
  // build/grader entry by entry, without the folders another test may be writing meanwhile
  // (gradescope-zip's staging, the object cache): copying them raced with it under ctest -j.
  fs::create_directories(c.build / "grader");
  for (const auto& e : fs::directory_iterator(bin / "grader")) {
    const std::string name = e.path().filename().string();
    if (name == "gradescope-zip" || name == "object-cache") continue;
    EXPECT_EQ(sh("cp -a '" + e.path().string() + "' '" + (c.build / "grader").string() + "/'"), 0);
  }
  // The references as submissions (build/assignments/<id>/reference: the assignment's own reference
  // files and its task modules' copies), which grade-config's reference_dir names.
  if (fs::exists(bin / "assignments")) {
    EXPECT_EQ(sh("cp -a '" + (bin / "assignments").string() + "' '" + c.build.string() + "/'"), 0);
  }
  // The assignments' task libraries (libjelly_<id>_tasks_solutions.a, ...) sit at the top.
  EXPECT_EQ(sh("cp -a '" + bin.string() + "'/libjelly_*.a '" + c.build.string() + "/'"), 0);
  fs::remove_all(c.build / "grader" / "object-cache");
  fs::remove_all(c.build / "grader" / "gradescope-zip");
  Json cfg = Json::parse(read_text(bin / "grader" / "grade-config.json"));
  std::function<void(Json&)> move = [&](Json& j) {
    if (j.is_string()) {
      std::string s = j.get<std::string>();
      if (s.rfind(bin.string(), 0) == 0)
        s = c.build.string() + s.substr(bin.string().size());
      else if (s.rfind(kSource.string(), 0) == 0)
        s = c.src.string() + s.substr(kSource.string().size());
      j = s;
    } else if (j.is_array() || j.is_object()) {
      for (Json& e : j) move(e);
    }
  };
  move(cfg);
  c.config = c.build / "grader" / "grade-config.json";
  std::ofstream(c.config) << cfg.dump(1);
  return c;
}

// A path of the source tree, in the clone.
fs::path in_clone(const Clone& c, const fs::path& p) {
  const std::string s = p.string(), bin = fs::path(JELLY_BINARY_DIR).string();
  if (s.rfind(bin, 0) == 0) return fs::path(c.build.string() + s.substr(bin.size()));
  EXPECT_EQ(s.rfind(kSource.string(), 0), 0u) << p << " is not in the source or build tree";
  return fs::path(c.src.string() + s.substr(kSource.string().size()));
}

std::string hidden_case_ids() {
  std::string ids;
  for (const auto& e : fs::directory_iterator(T->hidden_dir))
    ids += e.path().stem().string() + "\n";
  return ids;
}

// Processes whose command line names `marker` (other than this test's own).
std::string processes_naming(const std::string& marker) {
  std::string found;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos || pid == std::to_string(getpid()))
      continue;
    std::string cmd = read_text(e.path() / "cmdline");
    for (char& ch : cmd)
      if (ch == '\0') ch = ' ';
    if (cmd.find(marker) != std::string::npos) found += pid + ": " + cmd.substr(0, 200) + "\n";
  }
  return found;
}

// Processes of the users jelly-sandbox-N.
std::string sandbox_user_processes() {
  std::set<std::string> uids;
  std::istringstream pw(read_text("/etc/passwd"));
  for (std::string l; std::getline(pw, l);)
    if (l.rfind("jelly-sandbox-", 0) == 0) {
      std::istringstream f(l);
      std::string name, x, uid;
      std::getline(f, name, ':');
      std::getline(f, x, ':');
      std::getline(f, uid, ':');
      uids.insert(uid);
    }
  std::string found;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string st = read_text(e.path() / "status");
    const auto at = st.find("\nUid:\t");
    if (at == std::string::npos) continue;
    std::istringstream u(st.substr(at + 6));
    std::string real;
    u >> real;
    if (uids.count(real)) found += e.path().filename().string() + " (uid " + real + ")\n";
  }
  return found;
}

std::vector<std::string> names_in(const fs::path& dir, const std::string& prefix) {
  std::vector<std::string> v;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(prefix, 0) == 0) v.push_back(it->path().string());
  return v;
}

void hostile_neighbours(const std::string& isolation) {
  const Clone c = make_clone(isolation);
  const std::string grade = std::string(JELLY_GRADE_EXE) + " ";
  // A Gradescope zip in the build tree; its staging folder must be gone once it is written.
  const std::string zip = c.build / "jelly-gradescope.zip";
  const std::string made =
      run("gradescope-zip " + zip + " --assignment " + T->id + " --config " + c.config.string());
  ASSERT_TRUE(fs::exists(zip)) << made;
  EXPECT_FALSE(fs::exists(c.build / "grader" / "gradescope-zip"))
      << "gradescope-zip left its staging folder (a world-readable copy of the hidden data)";
  // ...and a stale one, as an older grader left it.
  const fs::path stale =
      c.build / "grader" / "gradescope-zip" / "source" / "grader" / "data" / T->id;
  fs::create_directories(stale);
  fs::copy(in_clone(c, T->hidden_dir), stale / "hidden",
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const fs::path src_dir = in_clone(c, T->dir), src_solutions = in_clone(c, T->solutions);
  const fs::path mutants = src_dir / "grader" / "mutants", cases = src_dir / "grader" / "cases";
  const std::string runner = "jelly-grade-" + T->id + "-";
  const fs::path in = c.root / "in", out = c.root / "out";
  fs::create_directories(in);
  std::string paths;
  for (const fs::path& p :
       {c.build / ("libjelly_" + T->id + "_tasks_solutions.a"),
        c.build / "grader" / (runner + "student-runner"),
        c.build / "grader" / (runner + "reference-runner"), c.src / "docs" / "mutation-table.md",
        mutants / fs::directory_iterator(mutants)->path().filename(),
        stale / "hidden" / T->hidden.filename(), fs::path(zip), in_clone(c, T->hidden),
        cases / fs::directory_iterator(cases)->path().filename(), src_solutions / T->compile_file,
        in / "a0_neighbour" / T->compile_file, out / "students" / "a0_neighbour" / "results.json",
        out / "students" / "a0_neighbour" / "report.md"}) {
    ASSERT_TRUE(p.filename() == "results.json" || p.filename() == "report.md" ||
                p.string().find("a0_neighbour") != std::string::npos || fs::exists(p))
        << p;
    paths += "\"" + p.string() + "\", ";
  }
  std::map<std::string, fs::perms> modes_before;
  for (const fs::path& p : {c.src, c.src / "grader" / "data", c.build / "grader",
                            c.build / "grader" / (runner + "student-runner"), fs::path(zip)})
    modes_before[p.string()] = fs::status(p).permissions();
  for (const OsRoute& r : kOsRoutes) {
    const fs::path dir = in / r.name;
    fs::create_directories(dir);
    const fs::path base = r.stubs ? src_dir : src_solutions;
    copy_files(base, dir);
    std::string code = replace_all(r.code, "@BUILD@", c.build.string());
    code = replace_all(code, "@PATHS@", paths);
    code = replace_all(code, "@ROOT@", c.root.string());
    code = replace_all(code, "@ID@", T->id);
    std::ofstream(dir / T->compile_file, std::ios::binary)
        << replace_all(kReadRequest, "@CASE@", T->run_case) << code
        << read_text(base / T->compile_file);
  }
  for (const char* good : {"a0_neighbour", "zz_well_behaved"}) {
    fs::create_directories(in / good);
    copy_files(src_solutions, in / good);
  }
  const std::string console = run("batch " + in.string() + " --out " + out.string() + " --config " +
                                  c.config.string() + " --assignment " + T->id +
                                  " --jobs 2 --visibility all --timeout 30 --no-frames "
                                  "--isolation " +
                                  isolation);
  std::ofstream(c.root / "console.txt") << console;
  SCOPED_TRACE("console: " + (c.root / "console.txt").string());

  // The neighbours are graded exactly.
  for (const char* good : {"a0_neighbour", "zz_well_behaved"}) {
    SCOPED_TRACE(good);
    ASSERT_TRUE(fs::exists(out / "students" / good / "results.json")) << console;
    const Json j = Json::parse(read_text(out / "students" / good / "results.json"));
    EXPECT_NE(j["output"].get<std::string>().find("Sandbox: " + isolation), std::string::npos);
    double max = 0;
    for (const Json& t : j["tests"])
      if (t.contains("max_score")) max += t["max_score"].get<double>();
    EXPECT_GT(max, 0.0);
    // Full marks, and a bonus task's points on top (A2's friction; extra_data says how many).
    const double bonus = j.contains("extra_data") && j["extra_data"].contains("bonus_max")
                             ? j["extra_data"]["bonus_max"].get<double>()
                             : 0.0;
    EXPECT_NEAR(j["score"].get<double>(), max + bonus, 1e-3) << j.dump(1).substr(0, 4000);
  }
  auto target = [&](const char* name) {
    const Json j = Json::parse(read_text(out / "students" / name / "results.json"));
    const Json* t = find_test(j, T->run_case);
    return t ? *t : Json();
  };
  const std::string description =
      Json::parse(read_text(out / "students" / "zz_well_behaved" /
                            "results.json"))["extra_data"]["isolation_description"];
  SCOPED_TRACE(description);
  // The reference's binaries cannot be run: the stubs score 0.
  {
    const Json j =
        Json::parse(read_text(out / "students" / "os_reference_binary" / "results.json"));
    EXPECT_EQ(j["score"].get<double>(), 0.0) << "a reference binary was run and its result taken";
    const std::string o = target("os_reference_binary")["output"];
    EXPECT_NE(o.find("jelly-forge: cannot run " + runner + "student-runner"), std::string::npos)
        << o;
    EXPECT_NE(o.find("jelly-forge: cannot run " + runner + "reference-runner"), std::string::npos)
        << o;
  }
  // Nothing derived from the reference or the hidden data, and nothing of a neighbour, opens.
  {
    const std::string o = target("os_read_secrets")["output"];
    EXPECT_NE(o.find("jelly-peek: "), std::string::npos) << o;
    EXPECT_EQ(o.find("jelly-OPENED"), std::string::npos) << o;
  }
  // The process left behind is stopped with its test: the batch ended, the neighbours (graded at
  // the same time and after) kept their marks.
  {
    const Json t = target("os_daemon");
    EXPECT_EQ(t["status"], "failed");
    EXPECT_TRUE(has_any(t["output"], "crashed with SIGKILL|left")) << t["output"];
  }
  // No public test sees what a hidden test left.
  {
    const Json j = Json::parse(read_text(out / "students" / "os_tmp_channel" / "results.json"));
    std::istringstream ids(hidden_case_ids());
    std::vector<std::string> hidden;
    for (std::string id; std::getline(ids, id);) hidden.push_back("\"" + id + "\"");
    ASSERT_GT(hidden.size(), 5u);
    int public_tests = 0;
    for (const Json& t : j["tests"]) {
      const std::string name = t["name"];
      if (name.find("[" + T->id + ".") == std::string::npos) continue;
      const std::string o = t.value("output", std::string());
      bool is_hidden = false;
      for (const std::string& h : hidden)
        if (name.find("[" + h.substr(1, h.size() - 2) + "]") != std::string::npos) is_hidden = true;
      if (is_hidden) continue;
      ++public_tests;
      for (const std::string& h : hidden)
        EXPECT_EQ(o.find(h), std::string::npos) << name << " shows hidden case " << h << ":\n" << o;
    }
    EXPECT_GT(public_tests, 10);
  }
  // Per-test caps: memory of all processes together, and their number.
  const bool cgroup_memory = description.find("cgroup v") != std::string::npos &&
                             description.find("memory per process only") == std::string::npos;
  if (cgroup_memory) {
    const Json t = target("os_fork_memory");
    EXPECT_EQ(t["status"], "failed");
    EXPECT_NE(t["output"].get<std::string>().find("memory with all its processes together"),
              std::string::npos)
        << t["output"];
  }
  if (description.find("pids.max") != std::string::npos) {
    const Json t = target("os_fork_many");
    EXPECT_EQ(t["status"], "failed");
    EXPECT_NE(t["output"].get<std::string>().find("more than 64 processes or threads"),
              std::string::npos)
        << t["output"];
  }
  if (isolation == "user") {
    const Json t = target("os_symlink_flood");
    EXPECT_EQ(t["status"], "failed");
    EXPECT_NE(t["output"].get<std::string>().find("file(s) in /tmp"), std::string::npos)
        << t["output"];
  }
  // Nothing is left behind: no process, no file in the shared folders, the tree's modes as they
  // were, the private scratch folder gone.
  EXPECT_EQ(processes_naming(c.root.string()), "");
  EXPECT_EQ(sandbox_user_processes(), "");
  for (const char* d : {"/tmp", "/var/tmp", "/dev/shm"})
    for (const char* prefix : {"jelly-flood-", "jelly-channel-"})
      EXPECT_EQ(names_in(d, prefix).size(), 0u) << d << "/" << prefix << "*";
  for (const auto& [p, m] : modes_before)
    EXPECT_EQ(fs::status(p).permissions(), m) << p << ": mode not restored";
  EXPECT_FALSE(fs::exists(c.build / "grader" / ".sandbox-modes"));
  std::error_code ec;
  fs::remove_all(c.root.parent_path(), ec);
}

bool bwrap_usable(std::string& why) {
  if (access("/usr/bin/bwrap", X_OK) != 0) {
    why = "no /usr/bin/bwrap";
    return false;
  }
  if (sh("/usr/bin/bwrap --unshare-all --unshare-user --ro-bind /usr /usr --symlink usr/lib /lib "
         "--symlink usr/lib64 /lib64 --symlink usr/bin /bin /usr/bin/true >/dev/null 2>&1") != 0) {
    why = "bwrap cannot create a sandbox here (user namespaces disabled?)";
    return false;
  }
  return true;
}

}  // namespace

class GraderSecurityOs : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { select_target(GetParam()); }
};

TEST_P(GraderSecurityOs, HostileNeighboursInUserMode) {
  if (geteuid() != 0)
    GTEST_SKIP() << "the user-drop mode needs root (it makes its sandbox users with useradd)";
  hostile_neighbours("user");
}

TEST_P(GraderSecurityOs, HostileNeighboursInBubblewrap) {
  std::string why;
  if (!bwrap_usable(why)) GTEST_SKIP() << why;
  hostile_neighbours("bwrap");
}

// A process that keeps the pipes of its test open after the test ended stalls nothing: the read
// stops once the test's process is gone (here without any sandbox). The holder keeps them for 400
// s; grading, about a minute on a loaded machine, must end long before it lets go (a grader that
// waited for the pipes would take those 400 s, still within the test's TIMEOUT, so that this
// message and not CTest's timeout says what went wrong).
TEST_P(GraderSecurityOs, PipesHeldByALeftoverDoNotStallTheGrader) {
  const Clone c = make_clone("pipes");
  const fs::path in = c.root / "in", solutions = in_clone(c, T->solutions);
  fs::create_directories(in / "holder");
  copy_files(solutions, in / "holder");
  std::ofstream(in / "holder" / T->compile_file, std::ios::binary)
      << replace_all(kReadRequest, "@CASE@", T->run_case)
      << "static int jelly_hold = [] { if (!jelly_target()) return 0; if (fork() == 0) { setsid();"
         " if (fork() == 0) { sleep(400); _exit(0); } _exit(0); } return 0; }();\n"
      << read_text(solutions / T->compile_file);
  const auto start = std::chrono::steady_clock::now();
  const std::string console =
      run("grade " + (in / "holder").string() + " --out " + (c.root / "out").string() +
          " --config " + c.config.string() + " --assignment " + T->id +
          " --visibility public --format gradescope --isolation none");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(s, 300.0) << "a leftover holding the pipes stalled jelly-grade\n" << console;
  EXPECT_TRUE(fs::exists(c.root / "out" / "results.json")) << console;
  // Where jelly-grade can make a cgroup (root here), the holder was found and stopped as well;
  // elsewhere the test stops it.
  if (geteuid() == 0) {
    EXPECT_EQ(processes_naming(c.root.string()), "");
  } else {
    std::istringstream left(processes_naming(c.root.string()));
    for (std::string line; std::getline(left, line);) kill(std::stoi(line), SIGKILL);
  }
  std::error_code ec;
  fs::remove_all(c.root.parent_path(), ec);
}

INSTANTIATE_TEST_SUITE_P(Assignments, GraderSecurityOs, ::testing::ValuesIn(target_ids()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// ---------------------------------------------------------------------------------------------
// Lanes (issue 28, items 1 and 2): a batch killed by SIGKILL leaves no process of any submission
// running, and one submission's busy processes take no more than a core from the student graded
// beside it; in both sandboxes. The lanes are the grader's, not an assignment's: each case runs on
// the first assignment of the build only (a minute or two each).
namespace {

// A static constructor at the top of the compile_file: every test of the submission starts `n`
// busy processes named `name` (comm), detached (setsid + double fork) when `detach`, then waits
// `wait_s` seconds before the test goes on.
std::string busy_code(const char* name, int n, bool detach, int wait_s) {
  const std::string spin = "{ prctl(PR_SET_NAME, \"" + std::string(name) +
                           "\"); volatile unsigned long x = 0; for (;;) x = x + 1; }";
  const std::string child = detach ? "{ setsid(); if (fork() == 0) " + spin + " _exit(0); }" : spin;
  return "#include <sys/prctl.h>\n"
         "static int jelly_busy = [] {\n"
         "  for (int i = 0; i < " +
         std::to_string(n) + "; ++i) if (fork() == 0) " + child +
         "\n"
         "  sleep(" +
         std::to_string(wait_s) + ");\n  return 0; }();\n";
}

// A submission of the reference with `code` at the top of its compile_file.
void busy_submission(const Clone& c, const fs::path& dir, const std::string& code) {
  const fs::path solutions = in_clone(c, T->solutions);
  fs::create_directories(dir);
  copy_files(solutions, dir);
  std::ofstream(dir / T->compile_file, std::ios::binary)
      << replace_all(kReadRequest, "@CASE@", T->run_case) << code
      << read_text(solutions / T->compile_file);
}

// The processes whose name (comm) is `name`: their ids, each followed by a space.
std::string processes_called(const std::string& name) {
  std::string found;
  std::error_code ec;
  for (fs::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    std::string comm = read_text(it->path() / "comm");
    while (!comm.empty() && comm.back() == '\n') comm.pop_back();
    if (comm == name) found += it->path().filename().string() + " ";
  }
  return found;
}

// The cgroup folders of the jelly-grade process `pid` (jelly-grade-PID, in every hierarchy).
std::vector<fs::path> grader_cgroups(pid_t pid) {
  std::vector<fs::path> found;
  const std::string mine = "jelly-grade-" + std::to_string(pid);
  std::error_code ec;
  for (fs::recursive_directory_iterator it("/sys/fs/cgroup", ec), end; !ec && it != end;
       it.increment(ec)) {
    if (!it->is_directory(ec) || it->is_symlink(ec)) continue;
    if (it->path().filename() == mine) found.push_back(it->path());
    if (it->path().filename() == mine || it.depth() > 5 ||
        it->path().filename().string().rfind("jelly-grade-", 0) == 0)
      it.disable_recursion_pending();
  }
  return found;
}

// The processes in `cgroup` and below it that still run (not zombies).
std::string live_processes_in(const fs::path& cgroup) {
  std::string found;
  std::error_code ec;
  std::vector<fs::path> dirs = {cgroup};
  for (fs::recursive_directory_iterator it(cgroup, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec)) dirs.push_back(it->path());
  for (const fs::path& d : dirs) {
    std::istringstream in(read_text(d / "cgroup.procs"));
    for (std::string p; in >> p;) {
      const std::string st = read_text("/proc/" + p + "/stat");
      const auto paren = st.rfind(')');
      if (paren != std::string::npos && paren + 2 < st.size() && st[paren + 2] != 'Z')
        found += d.string() + ": " + p + "\n";
    }
  }
  return found;
}

// jelly-grade started in the background, its output in `log`.
pid_t start_grade(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> argv = {JELLY_GRADE_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> a;
  for (std::string& s : argv) a.push_back(s.data());
  a.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    execv(a[0], a.data());
    _exit(127);
  }
  return pid;
}

// Waits up to `s` seconds for `done`, every 100 ms; `each` is called at every look.
bool wait_for(double s, const std::function<bool()>& done, const std::function<void()>& each = {}) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(s);
  while (std::chrono::steady_clock::now() < until) {
    if (each) each();
    if (done()) return true;
    usleep(100000);
  }
  return false;
}

// What must be gone 5 s after the batch `pid` was killed: every process of its submissions (named
// `busy`, of a sandbox user, in its cgroups), its keeper (its command line names the clone), and
// its cgroup folders.
void expect_nothing_left(pid_t pid, const Clone& c, const std::string& busy) {
  sleep(5);
  EXPECT_EQ(processes_called(busy), "") << "busy processes of a submission outlived the batch";
  EXPECT_EQ(sandbox_user_processes(), "");
  EXPECT_EQ(processes_naming(c.root.string()), "");
  for (const fs::path& g : grader_cgroups(pid)) {
    EXPECT_EQ(live_processes_in(g), "") << g;
    EXPECT_FALSE(fs::exists(g)) << g << ": the dead grader's cgroup folder is still there";
  }
}

std::vector<std::string> batch_args(const Clone& c, const std::string& isolation) {
  return {"batch",        (c.root / "in").string(),
          "--out",        (c.root / "out").string(),
          "--config",     c.config.string(),
          "--assignment", T->id,
          "--jobs",       "2",
          "--visibility", "public",
          "--timeout",    "10",
          "--no-frames",  "--isolation",
          isolation};
}

// An honest student's results beside a busy neighbour: every test passed, none took longer than
// its limit, full marks (and the bonus), and the lanes had their CPU share.
void expect_full_marks_in_time(const fs::path& results) {
  SCOPED_TRACE(results.string());
  ASSERT_TRUE(fs::exists(results));
  const Json j = Json::parse(read_text(results));
  const std::string description = j["extra_data"]["isolation_description"];
  EXPECT_EQ(description.find("no CPU share per lane"), std::string::npos) << description;
  double max = 0;
  for (const Json& t : j["tests"]) {
    if (t.contains("max_score")) max += t["max_score"].get<double>();
    const std::string o = t.value("output", std::string());
    EXPECT_EQ(o.find("took longer than"), std::string::npos) << t["name"] << ": " << o;
    EXPECT_NE(t.value("status", std::string()), "failed") << t["name"] << ": " << o;
  }
  const double bonus = j.contains("extra_data") && j["extra_data"].contains("bonus_max")
                           ? j["extra_data"]["bonus_max"].get<double>()
                           : 0.0;
  EXPECT_GT(max, 0.0);
  EXPECT_NEAR(j["score"].get<double>(), max + bonus, 1e-3) << j.dump(1).substr(0, 4000);
}

bool sandbox_available(const std::string& isolation, std::string& why) {
  if (isolation == "bwrap") return bwrap_usable(why);
  why = "the user-drop mode needs root (it makes its sandbox users with useradd)";
  return geteuid() == 0;
}

}  // namespace

class GraderSecurityLanes : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { select_target(target_ids().front()); }
};

// A batch killed by SIGKILL while a submission's test has forked busy detached processes (setsid,
// double fork: reparented to init, out of reach of PR_SET_PDEATHSIG): 5 s later none of them runs,
// nor anything else of the batch, and its cgroup folders are gone.
TEST_P(GraderSecurityLanes, SigkilledBatchLeavesNoProcess) {
  const std::string isolation = GetParam();
  std::string why;
  if (!sandbox_available(isolation, why)) GTEST_SKIP() << why;
  const Clone c = make_clone("kill-" + isolation);
  busy_submission(c, c.root / "in" / "a_detached", busy_code("jelly-busy", 8, true, 5));
  fs::create_directories(c.root / "in" / "b_honest");
  copy_files(in_clone(c, T->solutions), c.root / "in" / "b_honest");
  const fs::path log = c.root / "console.txt";
  const pid_t pid = start_grade(batch_args(c, isolation), log);
  ASSERT_GT(pid, 0);
  const bool busy = wait_for(300, [] {
    const std::string p = processes_called("jelly-busy");
    return std::count(p.begin(), p.end(), ' ') >= 8;
  });
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  ASSERT_TRUE(busy) << "the detached busy processes never started:\n" << read_text(log);
  expect_nothing_left(pid, c, "jelly-busy");
  std::error_code ec;
  fs::remove_all(c.root.parent_path(), ec);
}

// A neighbour whose every test keeps 48 busy processes for 9 s (under the cap of 64) beside honest
// submissions in a --jobs 2 batch: each lane has one core's quota (read from its cgroup while the
// batch runs), and every honest student gets full marks with no test timed out. There are three
// of them, graded one after the other in the second lane, so that the neighbour's processes run
// while one of them is still being graded (a single one can be done before the neighbour's build
// is). The batch is killed once they are graded (the neighbour's 9 s tests would take minutes).
TEST_P(GraderSecurityLanes, BusyNeighbourDoesNotStarveTheNextStudent) {
  const std::string isolation = GetParam();
  std::string why;
  if (!sandbox_available(isolation, why)) GTEST_SKIP() << why;
  const Clone c = make_clone("hog-" + isolation);
  busy_submission(c, c.root / "in" / "a_hog", busy_code("jelly-hog", 48, false, 9));
  const std::vector<std::string> honest = {"b_honest", "c_honest", "d_honest"};
  for (const std::string& name : honest) {
    fs::create_directories(c.root / "in" / name);
    copy_files(in_clone(c, T->solutions), c.root / "in" / name);
  }
  const auto results = [&](const std::string& name) {
    return c.root / "out" / "students" / name / "results.json";
  };
  const fs::path log = c.root / "console.txt";
  const pid_t pid = start_grade(batch_args(c, isolation), log);
  ASSERT_GT(pid, 0);
  std::set<std::string> quotas;    // the lanes' CPU quotas seen while the batch runs
  bool hog_beside_honest = false;  // the neighbour's processes seen before the last was graded
  const bool graded = wait_for(
      // Ten times what the honest students take on a busy 2-core machine, and more than all their
      // tests' time limits together would be if the neighbour starved them.
      600, [&] { return fs::exists(results(honest.back())); },
      [&] {
        hog_beside_honest = hog_beside_honest || (!processes_called("jelly-hog").empty() &&
                                                  !fs::exists(results(honest.back())));
        for (const fs::path& g : grader_cgroups(pid))
          for (const char* f : {"cpu.cfs_quota_us", "cpu.max"}) {
            std::error_code ec;
            for (fs::directory_iterator it(g, ec), end; !ec && it != end; it.increment(ec)) {
              std::string q = read_text(it->path() / f);
              while (!q.empty() && q.back() == '\n') q.pop_back();
              if (!q.empty()) quotas.insert(q);
            }
          }
      });
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  SCOPED_TRACE("console: " + log.string());
  ASSERT_TRUE(graded) << "the honest students were not graded beside the busy neighbour:\n"
                      << read_text(log);
  EXPECT_TRUE(hog_beside_honest)
      << "the neighbour's busy processes never ran while an honest student was graded";
  EXPECT_TRUE(quotas.count("100000") || quotas.count("100000 100000"))
      << "no lane had one core's quota; seen: " << ::testing::PrintToString(quotas);
  for (const std::string& name : honest) expect_full_marks_in_time(results(name));
  expect_nothing_left(pid, c, "jelly-hog");
  std::error_code ec;
  fs::remove_all(c.root.parent_path(), ec);
}

INSTANTIATE_TEST_SUITE_P(Sandboxes, GraderSecurityLanes, ::testing::Values("user", "bwrap"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });
