#pragma once
// A household as a request and a document: the request (rooms or a ProcTHOR house, residents,
// days, first weekday, seed, generator) is validated with JSON pointers; generation turns it into
// a document (the request plus the residents' profiles and the scene seed) from which the
// dynamic scene is rebuilt exactly; documents are stored in the `households` table.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/household/scene.hpp"
#include "core/store/store.hpp"

namespace socsim::household {

struct HouseholdRequest {
  int rooms = 0;                          // procedural house of 1 … 10 rooms, or
  std::optional<Json> house;              // a ProcTHOR house (exactly one of the two)
  int resident_count = 0;                 // 0: 1 … min(4, bedrooms) at random
  std::vector<std::string> resident_ids;  // or these personas (built-in or stored), ≤ bedrooms
  int days = 5;                           // 1 … 28
  Weekday start_weekday = Weekday::kWednesday;
  std::uint64_t seed = 0;
  std::string generator = "offline";  // offline | llm
  std::optional<std::string> model;   // llm only
};

// Reads {rooms | house, residents: count | [persona ids], days, start_weekday, seed, generator, model}.
Result<HouseholdRequest> household_request_from_json(const Json& json);
Json to_json(const HouseholdRequest& request);

struct HouseholdDocument {
  std::string id;  // "hh_" + 20 hex digits
  HouseholdRequest request;
  std::vector<std::shared_ptr<const ResidentProfile>> residents;
  std::uint64_t scene_seed = 0;
};

// The house of a request: generated from rooms and seed, or imported.
Result<House> household_house(const HouseholdRequest& request, const HouseholdKnowledge& knowledge);

// Generators for the residents' profiles; null members mean the offline ones.
struct ProfileGenerators {
  DayPlanGenerator* planner = nullptr;
  ScheduleDecomposer* decomposer = nullptr;
  ActivityDatabaseGenerator* activity_db = nullptr;
};
using HouseholdProgress = std::function<void(double fraction, const std::string& message)>;

// Chooses the residents (by id from `personas`, else at random from the built-in ones by the
// number of bedrooms), generates their profiles and checks that the scene configures.
Result<HouseholdDocument> generate_household(const HouseholdRequest& request,
                                             const HouseholdKnowledge& knowledge,
                                             std::span<const Persona> personas,
                                             const ProfileGenerators& generators,
                                             const HouseholdProgress& progress, const std::string& id);

// Rebuilds the house and configures the scene (same document → identical events).
Result<DynamicScene> instantiate_household(const HouseholdDocument& document,
                                           const HouseholdKnowledge& knowledge);

Json to_json(const HouseholdDocument& document);
Result<HouseholdDocument> household_document_from_json(const Json& json, const HouseholdKnowledge& knowledge);

// A deterministic id for a request made by a job (or a CLI run).
std::string household_id(const HouseholdRequest& request, std::string_view salt);

// JSON views shared by the REST API, the CLI and the viewer.
// Rooms (polygons), walls, doors (centre on the floor), windows and receptacles (position,
// footprint, yaw): the one JSON shape of a house plan (households, navbench episodes, the viewer).
// With `floors`, each room's floor is listed as a receptacle too ("synthetic": true), for views
// in which objects lying on the floor are searched for.
Json house_plan_json(const House& house, bool floors = false);
// Every movable object at time t: its receptacle, room and a floor position on that receptacle
// (objects sharing a receptacle are spread over its footprint, deterministically).
Json objects_at_json(const DynamicScene& scene, Seconds t);
Json event_json(const DynamicScene& scene, int event);
// Residents (persona, bedroom, bathroom), their schedules (entries), counts of events and moves.
Json household_summary_json(const HouseholdDocument& document, const DynamicScene& scene);

// Rows of the `households` table.
struct HouseholdRow {
  std::string id, author, generator, created_at;
  std::optional<std::string> job_id;
  Json summary;
};
Status store_household(store::Store& store, const HouseholdDocument& document, const Json& summary,
                       const std::string& author, const std::optional<std::string>& job_id);
Result<Json> load_household_document(store::Store& store, const std::string& id);  // kNotFound when unknown
// kNotFound when after_id names no stored household.
Result<std::vector<HouseholdRow>> list_households(store::Store& store, std::size_t limit,
                                                  const std::optional<std::string>& after_id);

}  // namespace socsim::household
