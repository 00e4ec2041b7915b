#pragma once
// What a live session reads from a request (simulations and co-simulations): the world (stored, a
// document or world.yaml text), behaviour trees only inline, and a card's world and program.
#include <memory>
#include <string>

#include "core/crowd/program.hpp"
#include "core/world/world.hpp"
#include "server/routes.hpp"

namespace socsim::server {

// The world of a program session: `world_id` (stored), `world` (document or world.yaml text), or
// none (null). Errors point at /world_id or under /world.
Result<std::shared_ptr<const world::World>> session_world(RouteContext& ctx, const Json& body);
// Behaviour trees must come inline: the server reads no files named by a client.
Status no_tree_files(const crowd::Program& p);

struct CardScenario {
  std::shared_ptr<const world::World> world;  // null when the card has none
  crowd::Program program;
};
// The world and program a card records (404 at /card_id for an unknown card, 422 when it has no
// program).
Result<CardScenario> card_scenario(RouteContext& ctx, const std::string& card_id);

}  // namespace socsim::server
