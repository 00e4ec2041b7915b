#pragma once
// What the REST export route and `socsim card export` share: a card's world and program, its
// trajectory log from the store, and its MCAP recording.
#include <optional>
#include <string>

#include "core/cards/card.hpp"
#include "core/crowd/program.hpp"
#include "core/interop/export_hunav.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/store/store.hpp"
#include "core/world/world.hpp"

namespace socsim::server {

// The card's world and program, checked as they are read.
struct CardExport {
  world::World world;
  crowd::Program program;
};
Result<CardExport> card_export_scenario(const cards::Card& card);

// The card's trajectory log, loaded by the sha256 the card records; kNotFound when it has none.
Result<scenario::TrajectoryLog> card_trajectory_log(store::Store& store, const cards::Card& card);

// The card as MCAP (core/interop/mcap_export.hpp): its log, world, role table and seed.
Result<std::string> card_mcap(store::Store& store, const cards::Card& card, std::optional<bool> scene_people);
// The card as a Gazebo world with an <actor> per person (core/interop/export_gazebo_actors.hpp).
Result<std::string> card_gazebo_actors(store::Store& store, const cards::Card& card);
// The card's world and program as an Arena-Rosnav scenario file (core/interop/export_arena.hpp).
Result<std::string> card_arena(const cards::Card& card);
// The card's world and program for Isaac Sim's Replicator Agent (core/interop/export_isaac.hpp).
Result<std::vector<interop::ExportFile>> card_isaac(const cards::Card& card);

}  // namespace socsim::server
