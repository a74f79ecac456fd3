// find_on_path (jelly/process/process.hpp): the one PATH search, for POSIX and Windows.
#include <cstdlib>

#include "jelly/process/process.hpp"
#ifndef _WIN32
#include <unistd.h>
#endif

namespace jelly::process {

namespace fs = std::filesystem;

std::optional<fs::path> find_on_path(const std::string& name) {
#ifdef _WIN32
  const char separator = ';';
  const std::string file = name + ".exe";
#else
  const char separator = ':';
  const std::string& file = name;
#endif
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "";
  std::size_t start = 0;
  while (start < dirs.size()) {
    std::size_t end = dirs.find(separator, start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = dirs.substr(start, end - start);
    start = end + 1;
    if (dir.empty()) continue;  // the working folder: never searched
    const fs::path candidate = fs::path(dir) / file;
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) continue;
#ifndef _WIN32
    if (::access(candidate.c_str(), X_OK) != 0) continue;
#endif
    return candidate;
  }
  return std::nullopt;
}

}  // namespace jelly::process
