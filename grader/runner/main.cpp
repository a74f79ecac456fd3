// jelly-grade runner: runs ONE grading case and writes its outputs as one JSON object to a file
// descriptor the orchestrator gave it.
//
//   runner --list                                  case ids and descriptions, one per line
//   runner --case ID [--input FILE] [--result-fd N] [--prepare] [--no-sandbox]
//
// --prepare builds the case's input instead (reference runner only, at generate-reference time).
// Everything the case needs is read BEFORE the sandbox goes up; after it, the student's code can
// compute and print but cannot open a file, start a process or signal anyone.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "harness.hpp"
#include "sandbox.hpp"

namespace {

using jelly::grade::Json;

bool write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = write(fd, p, left);
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

int usage() {
  std::fputs("usage: runner --list | --case ID [--input FILE] [--result-fd N] [--prepare] [--no-sandbox]\n",
             stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  jelly::grade::Registry registry;
  jelly::grade::register_spring_cases(registry);
  jelly::grade::register_force_cases(registry);
  jelly::grade::register_terrain_cases(registry);
  jelly::grade::register_integrator_cases(registry);
  jelly::grade::register_scene_cases(registry);

  std::string case_id, input_path;
  int result_fd = 1;
  bool prepare = false, sandbox = true, list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--list") list = true;
    else if (a == "--case" && i + 1 < argc) case_id = argv[++i];
    else if (a == "--input" && i + 1 < argc) input_path = argv[++i];
    else if (a == "--result-fd" && i + 1 < argc) result_fd = std::atoi(argv[++i]);
    else if (a == "--prepare") prepare = true;
    else if (a == "--no-sandbox") sandbox = false;
    else return usage();
  }
  if (list) {
    for (const auto& c : registry.cases()) std::printf("%s\t%s\n", c.id.c_str(), c.description.c_str());
    return 0;
  }
  if (case_id.empty()) return usage();
  const jelly::grade::CaseDef* def = registry.find(case_id);
  if (!def) {
    std::fprintf(stderr, "runner: unknown case '%s' (see --list)\n", case_id.c_str());
    return 2;
  }

  Json input = Json::object();
  if (!input_path.empty()) {
    std::ifstream in(input_path);
    if (!in) {
      std::fprintf(stderr, "runner: cannot read input %s\n", input_path.c_str());
      return 2;
    }
    try {
      input = Json::parse(in);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "runner: input %s is not valid JSON: %s\n", input_path.c_str(), e.what());
      return 2;
    }
  }
  const jelly::TaskTable tasks = jelly::linked_tasks();

  Json result = Json::object();
  if (prepare) {
    Json prepared = Json::object();
    if (def->prepare) def->prepare(tasks, prepared);
    result["input"] = std::move(prepared);
  } else {
    if (sandbox && !jelly::grade::install_sandbox(result_fd)) return 3;
    jelly::grade::Outputs out;
    try {
      def->run(tasks, input, out);
      result["outputs"] = out.json();
    } catch (const std::exception& e) {
      result["error"] = std::string("an exception was thrown: ") + e.what();
    } catch (...) {
      result["error"] = "an exception of unknown type was thrown";
    }
  }
  std::cout.flush();
  std::fflush(nullptr);
  if (!write_all(result_fd, result.dump() + "\n")) return 4;
  return 0;
}
