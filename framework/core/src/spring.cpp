#include "jelly/spring.hpp"

namespace jelly {

std::string_view to_string(SpringType type) {
  switch (type) {
    case SpringType::Structural: return "structural";
    case SpringType::Shear: return "shear";
    case SpringType::ShearBody: return "shear_body";
    case SpringType::Bending: return "bending";
  }
  return "unknown";
}

}  // namespace jelly
