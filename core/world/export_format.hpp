#pragma once
// Number formatting shared by the exporters: shortest text that reads back to the same double.
#include <charconv>
#include <cmath>
#include <string>

namespace socsim::world {

inline std::string shortest(double v) {
  if (v == 0.0) return "0";
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

// Rounded to a micrometre first: exports carry no float noise such as 2.6000000000000005.
inline std::string micro(double v) {
  if (!(std::abs(v) < 1e9)) return shortest(v);
  return shortest(std::round(v * 1e6) / 1e6);
}

}  // namespace socsim::world
