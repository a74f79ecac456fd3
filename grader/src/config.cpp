#include "config.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace jelly::grade {

const std::vector<std::string>& task_files() {
  static const std::vector<std::string> files = {"springs.cpp", "forces.cpp", "collision.cpp",
                                                 "contact.cpp", "integrators.cpp"};
  return files;
}

fs::path GradeConfig::cache_dir() const {
  if (const char* env = std::getenv("JELLY_GRADE_CACHE")) return env;
  return binary_dir / "grader" / "object-cache";
}

GradeConfig load_config(const std::string& path) {
  std::string p = path;
  if (p.empty()) {
    if (const char* env = std::getenv("JELLY_GRADE_CONFIG")) p = env;
  }
#ifdef JELLY_GRADE_DEFAULT_CONFIG
  if (p.empty()) p = JELLY_GRADE_DEFAULT_CONFIG;
#endif
  std::ifstream in(p);
  if (!in)
    throw std::runtime_error("cannot read the grader config " + p +
                             " (build the jelly-grade target first; CMake writes it)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(p + ": not valid JSON: " + e.what());
  }
  auto strings = [&](const char* key) {
    std::vector<std::string> out;
    if (!j.contains(key) || !j[key].is_array())
      throw std::runtime_error(p + ": missing array '" + key + "'");
    for (const auto& s : j[key]) {
      const std::string v = s.get<std::string>();
      // /usr/include is searched anyway; naming it with -I breaks libstdc++'s #include_next.
      if (!v.empty() && v != "/usr/include") out.push_back(v);
    }
    return out;
  };
  GradeConfig c;
  c.compiler = j.at("compiler").get<std::string>();
  c.compiler_id = j.value("compiler_id", "");
  c.compile_flags = strings("compile_flags");
  c.defines = strings("defines");
  c.include_dirs = strings("include_dirs");
  c.link_objects = strings("link_objects");
  c.link_libraries = strings("link_libraries");
  c.link_flags = strings("link_flags");
  c.source_dir = j.at("source_dir").get<std::string>();
  c.binary_dir = j.at("binary_dir").get<std::string>();
  c.reference_runner = j.value("reference_runner", "");
  c.jelly_cli = j.value("jelly_cli", "");
  if (const char* env = std::getenv("JELLY_GRADE_JELLY")) c.jelly_cli = env;
  c.config_path = p;
  return c;
}

}  // namespace jelly::grade
