#pragma once
// Dataset statistics in the shape of paper 000 §V-A: personas' age (mean ± sd), activity counts
// before and after synonym merging, objects an event may involve (mean ± sd and distribution,
// Fig. 3c) and how many receptacle types each object type can go to (Fig. 4), as JSON.
#include <cstdint>
#include <span>

#include "core/common/json_io.hpp"
#include "core/household/scene.hpp"

namespace socsim::household {

// `residents` are scene-agnostic profiles (schedule + activity database); the location of each
// event is drawn from p(l|a) with `seed` to count the objects it may involve.
Json statistics_report(std::span<const ResidentProfile> residents, std::uint64_t seed);

// Waking activities per persona-day, their median length and the share of "leave home" entries,
// with DynamicTHOR's figures beside them (also part of statistics_report as "days_of_activities").
Json day_statistics(std::span<const ResidentProfile> residents);
Json dynamic_thor_statistics();

// The paper's figures, for comparison.
Json paper_statistics();

}  // namespace socsim::household
