// The fields of a student record and of the class summary, read defensively (class_report.cpp
// and the views of class_report_views.cpp).
#pragma once

#include <cstdio>
#include <string>

#include "inputs/cases.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade::class_fields {

// Record fields read defensively: a record is our own file, but one edited by hand must not turn
// the class report into a crash, and its text is shown only through safe_text.
inline std::string str(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? safe_text(it->get<std::string>()) : std::string();
}
inline double num(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : 0.0;
}
inline bool flag(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}
inline const Json& list(const Json& j, const char* key) {
  static const Json empty = Json::array();
  const auto it = j.find(key);
  return it != j.end() && it->is_array() ? *it : empty;
}

inline std::string percent(double share) {
  char b[16];
  std::snprintf(b, sizeof b, "%.0f%%", share * 100.0);
  return b;
}

}  // namespace jelly::grade::class_fields
