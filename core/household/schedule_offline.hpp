#pragma once
// What the offline day planner (day_planner.cpp) and decomposer (day_decomposer.cpp) share: a
// persona's working pattern and commute, seeded random streams, five-minute rounding. Internal to
// core/household.
#include <cmath>
#include <string>
#include <string_view>

#include "core/common/rng.hpp"
#include "core/household/schedule.hpp"

namespace socsim::household::offline {

inline int round5(double minutes) {
  return static_cast<int>(std::lround(minutes / 5.0)) * 5;
}

inline Rng rng_for(std::uint64_t seed, const std::string& persona, std::string_view label, int day) {
  return Rng(seed ^ fnv1a64(persona), fnv1a64(label) + static_cast<std::uint64_t>(day + 10));
}

struct PersonaContext {
  const Persona& persona;
  PersonaTraits traits;
  std::string id;
  int commute = 25;
  explicit PersonaContext(const Persona& p) : persona(p), traits(infer_traits(p)), id(persona_id(p)) {
    commute = 15 + static_cast<int>(fnv1a64(id + ":commute") % 26);
  }
  [[nodiscard]] bool day_sleeper() const { return traits.work == WorkPattern::kNightShift; }
  [[nodiscard]] bool works(Weekday d) const { return traits.work_days[static_cast<std::size_t>(d)]; }
  [[nodiscard]] bool works_away(Weekday d) const {
    if (!works(d)) return false;
    switch (traits.work) {
      case WorkPattern::kRemote:
      case WorkPattern::kFreelance:
        return false;
      case WorkPattern::kHybrid:
        return !traits.home_work_days[static_cast<std::size_t>(d)];
      default:
        return true;
    }
  }
  [[nodiscard]] bool works_home(Weekday d) const {
    return traits.work == WorkPattern::kJobSeeker ? !is_weekend(d) : works(d) && !works_away(d);
  }
};

}  // namespace socsim::household::offline
