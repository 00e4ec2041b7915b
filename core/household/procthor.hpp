#pragma once
// ProcTHOR house JSON (schema 1.0.0: rooms with floorPolygon, walls, doors, windows, objects with
// assetId/position/children) ↔ House. Import keeps every field it does not model so that export
// writes it back; non-convex floors and "empty" (open) walls are supported.
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/house.hpp"

namespace socsim::household {

// Reads a house; every problem is reported with its JSON pointer. `id` names the house.
Result<House> import_procthor(const Json& json, const HouseholdKnowledge& knowledge,
                              const std::string& id = "procthor");

// Writes ProcTHOR JSON. With `placement` (one receptacle entity index per House::objects entry),
// movable objects are written on those receptacles instead of where the house put them.
Json export_procthor(const House& house, const std::vector<int>* placement = nullptr);

// AI2-THOR object type of a ProcTHOR asset id ("Dining_Table_208_1" → "DiningTable").
std::string object_type_from_asset(std::string_view asset_id, const HouseholdKnowledge& knowledge);

}  // namespace socsim::household
