#pragma once
// Offline floor-plan generator (paper 001 §III-C without an LLM): a seeded procedural layout —
// a corridor or hall with rooms in bands along it and end rooms — that honours the scene
// graph's adjacency, sizes rooms to the building-code minima retrieved for the domain, puts
// doors on shared walls, furnishes rooms by type and returns a validated, compliant World.
#include <cstdint>
#include <span>

#include "core/common/json_io.hpp"
#include "core/floorplan/compliance.hpp"
#include "core/floorplan/scene_graph.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/world/requirements.hpp"
#include "core/world/world_builder.hpp"

namespace socsim::floorplan {

// Floor plans are built of the world model's types (World, Zone, Point, …).
using namespace socsim::world;

struct FloorPlan {
  World world;
  ComplianceReport compliance;
  SceneGraph scene_graph;  // as laid out: with the circulation room when one had to be added
  Json provenance;         // generator, seed, domain, attempts, knowledge used (ref_id, sections)
};

struct OfflineOptions {
  std::uint64_t seed = 0;
  int max_attempts = 8;  // layouts tried until one builds and passes its compliance report
  BuildOptions build;
  // What the request asks the world to hold: exits (as many as asked and as the code requires,
  // far apart), counted furniture (exactly, or at least), named objects, the scenario's people
  // (egress checked for them). Named rooms must be in the graph (apply_room_requirements).
  WorldRequirements requirements;
};

// Same graph, constraints and seed → the same World (identical world.yaml bytes).
// kValidation (with /adjacency/<i> or /rooms/<i> pointers) when the graph cannot be laid out
// this way (a room that must touch more than two rooms besides the circulation, a cycle of
// rooms) or no attempt produced a compliant plan (the last report's failures are listed).
Result<FloorPlan> generate_floor_plan(const SceneGraph& graph,
                                      std::span<const knowledge::MergedConstraint> constraints,
                                      const OfflineOptions& options = {});

// The knowledge behind a plan, for its provenance: one item per code entry used, with the
// constraint names it set and its sources' sections.
Json knowledge_provenance(std::span<const knowledge::MergedConstraint> constraints);

}  // namespace socsim::floorplan
