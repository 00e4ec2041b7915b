#pragma once
// What a request asks a world to hold (world::WorldRequirements), made real by the offline
// generator: rooms it names and room-like features (toilets, platforms, airport gates) in the
// scene graph, counts of furniture and the objects it names in the furnishing. Exits are laid
// out with the plan (offline.cpp).
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/floorplan/furnish.hpp"
#include "core/floorplan/scene_graph.hpp"
#include "core/world/requirements.hpp"

namespace socsim::floorplan {

// The room type a named room stands for: its given type when the room vocabulary knows it,
// else the type its words name ("maternity ward" → patient_room), else its name in snake case.
std::string room_type_for(const NamedRoom& room);

// Adds the rooms the requirements name, and rooms for the toilets, platforms and (airports)
// gates they count, to a scene graph laid out from a prompt, each opening onto the circulation
// room; notes say what was added. A given scene graph is laid out as it is: a named room it
// lacks is a kValidation error at /requirements/rooms/<i>.
Status apply_room_requirements(SceneGraph& graph, const WorldRequirements& requirements, bool graph_given,
                               std::vector<std::string>* notes = nullptr);

struct FeatureOutcome {
  std::vector<std::string> notes;    // what was added, removed or placed
  std::vector<std::string> missing;  // what did not fit ("3 of 5 checkouts")
};

// Adds furniture until each counted feature of the requirements is there (exactly, or at
// least), removing the extra pieces (and their queue lanes) of exact counts, and places each
// named object in its room (or the room that suits it). Every piece by footprint, reachable.
FeatureOutcome furnish_requirements(std::span<const Zone> zones, std::span<const DoorSpec> doors,
                                    const WorldRequirements& requirements, const FurnishingRules& rules,
                                    Furnishing& furnishing);

// Entity features counted in a furnishing (before the world is built).
int count_in(const Furnishing& furnishing, Feature feature);

}  // namespace socsim::floorplan
