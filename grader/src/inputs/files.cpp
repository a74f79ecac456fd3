#include "inputs/files.hpp"

#include <fstream>
#include <sstream>

namespace jelly::grade {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();  // an unopened file sets failbit on s and leaves it empty
  return s.str();
}

}  // namespace jelly::grade
