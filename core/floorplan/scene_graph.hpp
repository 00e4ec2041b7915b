#pragma once
// Input of the floor-plan generators (paper 001 §III-C): rooms (type, name, optional area),
// adjacency edges and the building type — read from JSON (schemas/scene_graph.schema.json) or
// derived from a prompt through a curated room program per building type.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/knowledge/building_type.hpp"

namespace socsim::floorplan {

struct SceneRoom {
  std::string name;
  std::string type;            // canonical room type when known (floorplan_rooms.hpp)
  std::optional<double> area;  // wanted net area, m²
  friend bool operator==(const SceneRoom&, const SceneRoom&) = default;
};

struct SceneGraph {
  std::string domain;  // building type (knowledge::building_types())
  std::vector<SceneRoom> rooms;
  std::vector<std::pair<std::string, std::string>> adjacency;  // each edge: a door on a shared wall
  std::string entrance;                                        // room with the door to the outside
  friend bool operator==(const SceneGraph&, const SceneGraph&) = default;
};

inline constexpr std::size_t kMaxSceneRooms = 60;
inline constexpr int kMaxRoomsPerType = 30;

// Schema, then rules the schema cannot say: unique names, edges naming two different rooms,
// no duplicate edge, one connected graph, the entrance naming a room. Every problem is a
// FieldError with its pointer (prefixed by `pointer`). Fills the domain by classifying the room
// names and the entrance by the domain's convention when they are absent.
Result<SceneGraph> scene_graph_from_json(const Json& j, const std::string& pointer = "");
Json to_json(const SceneGraph& graph);

// The curated room program of a building type with the given number of rooms per type (types
// not in the program are added, with an edge to the circulation room): residential — hallway,
// living room, kitchen, bedrooms, bathroom, storage; office — reception, corridor, open office,
// meeting rooms, kitchenette, toilets; hospital — lobby (reception and waiting area), corridor,
// patient rooms, nurse station, treatment rooms, toilets; canteen, retail, warehouse, school, airport,
// and the venues of the worlds issue (station, hotel, library, museum, theatre, arena, factory, mall,
// supermarket, restaurant, university, gym, care home, community hall).
SceneGraph room_program(std::string_view domain, const std::map<std::string, int>& counts = {});

struct PromptSceneGraph {
  SceneGraph graph;
  knowledge::BuildingTypeGuess classification;  // also when the domain was given
  std::map<std::string, int> counts;            // room counts read from the prompt ("six patient rooms")
};

// Classifies the prompt (unless `domain` is given), reads room counts and mentioned room types
// ("a clinic with six patient rooms and a waiting room") and builds the domain's room program.
// kValidation naming /prompt or /domain for empty text, an unknown domain or too many rooms.
Result<PromptSceneGraph> scene_graph_from_prompt(std::string_view prompt,
                                                 std::optional<std::string> domain = {});

}  // namespace socsim::floorplan
