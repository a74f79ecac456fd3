// jelly-grade runner: runs ONE grading case and writes its outputs as one JSON object to a file
// descriptor the orchestrator gave it. The runner knows case GENERATORS only; a case is a
// generator plus its parameters, both from assignments/<id>/grader/cases/*.toml, handed over in
// the request file:
//   { "case": ID, "generator": NAME, "params": {...}, "input": {...prepared input, if any} }
//
//   runner --list                                  generator names and descriptions, one per line
//   runner --request FILE [--result-fd N] [--prepare] [--no-sandbox]
//
// FILE "-" is stdin: jelly-grade hands each case its request that way (an anonymous file only
// that case's sandbox has), and stdin is /dev/null again before student code runs.
//
// --prepare builds the case's input instead (reference runner only, at generate-reference time).
// Everything the case needs is read BEFORE the sandbox goes up; after it, the student's code can
// compute and print but cannot open a file, start a process or signal anyone (the seccomp sandbox,
// Linux only). Elsewhere (the self-check on Windows and macOS) there is no sandbox: it is the
// student's own code on the student's own machine. On Windows the result goes to the inherited
// pipe handle named in the environment variable JELLY_RESULT_HANDLE (process_win.cpp), not fd N.
#include <fcntl.h>
#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <io.h>
#include <windows.h>
#else
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "harness.hpp"
#if JELLY_HAVE_SECCOMP
#include "sandbox.hpp"
#endif

namespace {

using jelly::grade::Json;

// One write(2) (_write on Windows), at most 1 MiB.
long write_some(int fd, const char* p, std::size_t n) {
  n = std::min<std::size_t>(n, 1 << 20);
#ifdef _WIN32
  return _write(fd, p, static_cast<unsigned>(n));
#else
  return static_cast<long>(write(fd, p, n));
#endif
}

bool write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
#ifdef _WIN32
  // The orchestrator's result pipe (process_win.cpp); without it, the descriptor as on POSIX.
  if (const char* handle = std::getenv("JELLY_RESULT_HANDLE"); handle && fd != 1) {
    HANDLE h =
        reinterpret_cast<HANDLE>(static_cast<std::uintptr_t>(std::strtoull(handle, nullptr, 10)));
    DWORD n = 0;
    while (left > 0 &&
           WriteFile(h, p, static_cast<DWORD>(std::min<std::size_t>(left, 1 << 20)), &n, nullptr) &&
           n > 0)
      p += n, left -= n;
    return left == 0;
  }
#endif
  while (left > 0) {
    const long n = write_some(fd, p, left);
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

int usage() {
  std::fputs("usage: runner --list | --request FILE [--result-fd N] [--prepare] [--no-sandbox]\n",
             stderr);
  return 2;
}

/// The command line's choices.
struct Options {
  std::string request_path;
  int result_fd = 1;
  bool prepare = false, sandbox = true, list = false;
};

/// Reads argv into `o`; false on an argument the runner does not know.
bool parse_args(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--list")
      o.list = true;
    else if (a == "--request" && i + 1 < argc)
      o.request_path = argv[++i];
    else if (a == "--result-fd" && i + 1 < argc)
      o.result_fd = std::atoi(argv[++i]);
    else if (a == "--prepare")
      o.prepare = true;
    else if (a == "--no-sandbox")
      o.sandbox = false;
    else
      return false;
  }
  return true;
}

int list_generators(const jelly::grade::Registry& registry) {
  for (const auto& g : registry.generators())
    std::printf("%s\t%s\n", g.name.c_str(), g.description.c_str());
  return 0;
}

/// stdin becomes /dev/null (NUL), so student code cannot read the request.
void detach_stdin() {
#ifdef _WIN32
  if (!std::freopen("NUL", "rb", stdin)) std::fclose(stdin);
#else
  const int null_fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (null_fd >= 0) {
    dup2(null_fd, 0);
    close(null_fd);
  }
#endif
}

/// Reads the request from `path` ("-": stdin), then detaches stdin; false after a message.
bool read_request(const std::string& path, Json& request) {
#ifdef _WIN32
  // The request is JSON bytes: no CR/LF translation, no end at a ^Z.
  _setmode(_fileno(stdin), _O_BINARY);
#endif
  std::ifstream file;
  if (path != "-") file.open(path);
  std::istream& in = path == "-" ? std::cin : file;
  if (!in) {
    std::fprintf(stderr, "runner: cannot read request %s\n", path.c_str());
    return false;
  }
  try {
    request = Json::parse(in);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "runner: request %s is not valid JSON: %s\n", path.c_str(), e.what());
    return false;
  }
  detach_stdin();
  return true;
}

/// --prepare: the case's input, or why it could not be built.
Json prepare_input(const jelly::grade::GeneratorDef& def, const jelly::TaskTable& tasks,
                   const jelly::grade::Params& params) {
  Json result = Json::object();
  Json prepared = Json::object();
  try {
    if (def.prepare) def.prepare(tasks, params, prepared);
    result["input"] = std::move(prepared);
  } catch (const std::exception& e) {
    result["error"] = std::string("preparing the input failed: ") + e.what();
  }
  return result;
}

/// Runs the case (in the sandbox unless `sandbox` is false) into `result`; false when the
/// sandbox could not go up.
bool run_case(const jelly::grade::GeneratorDef& def, const jelly::TaskTable& tasks,
              const jelly::grade::Params& params, const Json& input, const Options& o,
              Json& result) {
#if JELLY_HAVE_SECCOMP
  if (o.sandbox && !jelly::grade::install_sandbox(o.result_fd)) return false;
#else
  (void)o;  // no sandbox off Linux: the self-check runs the student's own code
#endif
  jelly::grade::Outputs out;
  try {
    def.run(tasks, params, input, out);
    result["outputs"] = out.json();
  } catch (const std::exception& e) {
    result["error"] = std::string("an exception was thrown: ") + e.what();
  } catch (...) {
    result["error"] = "an exception of unknown type was thrown";
  }
  return true;
}

/// Writes the result as one JSON line to `fd`: exit code 0, or 4 when it cannot.
int write_result(int fd, const Json& result) {
  std::cout.flush();
  std::fflush(nullptr);
  // A message of student code (an exception's what()) may hold any bytes: never a crash here.
  if (!write_all(fd, result.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n")) return 4;
  return 0;
}

/// The request's case, prepared or run, and its result written: the runner's exit code.
int answer_request(const jelly::grade::Registry& registry, Json& request, const Options& o) {
  const std::string case_id = request.value("case", std::string("?"));
  const std::string generator = request.value("generator", std::string());
  const jelly::grade::GeneratorDef* def = registry.find(generator);
  if (!def) {
    std::fprintf(stderr, "runner: case '%s': unknown generator '%s' (see --list)\n",
                 case_id.c_str(), generator.c_str());
    return 2;
  }
  const jelly::grade::Params params(request.contains("params") ? request["params"]
                                                               : Json::object());
  const Json input = request.contains("input") ? request["input"] : Json::object();
  const jelly::TaskTable tasks = jelly::grade::assignment_task_table();

  Json result = Json::object();
  if (o.prepare)
    result = prepare_input(*def, tasks, params);
  else if (!run_case(*def, tasks, params, input, o, result))
    return 3;
  return write_result(o.result_fd, result);
}

}  // namespace

int main(int argc, char** argv) {
  jelly::grade::Registry registry;
  jelly::grade::register_assignment_cases(registry);
  Options o;
  if (!parse_args(argc, argv, o)) return usage();
  if (o.list) return list_generators(registry);
  if (o.request_path.empty()) return usage();
  Json request;
  if (!read_request(o.request_path, request)) return 2;
  return answer_request(registry, request, o);
}
