#include "jelly/spring_check.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace jelly {

void check_built_springs(const SpringGroup& group, int lo, int hi, const char* builder) {
  for (std::size_t k = 0; k < group.springs.size(); ++k) {
    const Spring& s = group.springs[k];
    if (s.a < lo || s.a >= hi || s.b < lo || s.b >= hi || s.a == s.b ||
        !std::isfinite(s.rest_length) || s.rest_length < 0.0) {
      throw std::runtime_error(
          std::string(builder) + " produced spring #" + std::to_string(k) + " joining particles " +
          std::to_string(s.a) + " and " + std::to_string(s.b) + " with rest length " +
          std::to_string(s.rest_length) + "; expected two different particles in " +
          std::to_string(lo) + ".." + std::to_string(hi - 1) + " and a finite rest length ≥ 0");
    }
  }
}

}  // namespace jelly
