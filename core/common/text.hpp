#pragma once
// Small text helpers used across modules: ASCII lower case, compact numbers for messages.
#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>

namespace socsim {

inline std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Three significant digits ("0.915", "1.2e+03"), as building-code messages quote values.
inline std::string compact_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace socsim
