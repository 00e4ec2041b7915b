#pragma once
// The behaviour-node library: HuNavSim's nodes (navigation, goals, gaze, speech, groups,
// robot reactions) and socsim's queue, seat, wander, gather, evacuation and velocity-field
// nodes, acting on a BtEnvironment. Every name and port matches the knowledge store's library.
#include <filesystem>
#include <string>
#include <vector>

#include "core/crowd/bt_document.hpp"
#include "core/crowd/bt_environment.hpp"

namespace socsim::crowd {

// The BT.CPP built-ins plus every library node, bound to `env` (which must outlive the trees).
BtRegistry behavior_registry(BtEnvironment& env);

// Load options that also check literal port values against the environment: place names
// (ROIs, POIs, doors, zones), queue lanes, exits, velocity-field names, probabilities and
// non-negative durations and distances, agent-id lists.
BtLoadOptions behavior_load_options(const BtEnvironment& env, std::filesystem::path base_dir = {});

// Parses HuNavSim's id lists ("2;3;4", also with commas or spaces).
Result<std::vector<std::int64_t>> parse_agent_ids(std::string_view text);

}  // namespace socsim::crowd
