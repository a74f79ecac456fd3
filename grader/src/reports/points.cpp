#include "reports/points.hpp"

#include <cstdio>

namespace jelly::grade {

std::string pts(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

}  // namespace jelly::grade
