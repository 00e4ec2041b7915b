// Offline floor-plan generator over the seeded knowledge store: 20 residential, 10 office and 10
// hospital plans from different seeds are valid, fully reachable, compliant and pairwise
// different; same seed → same bytes; adjacency, code minima and furnishing by room type.
#include "core/floorplan/offline.hpp"

#include <cmath>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/floorplan/rooms.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/geodesic.hpp"
#include "core/world/world_export.hpp"
#include "core/world/world_yaml.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/support/knowledge_suite.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::floorplan {
namespace {

using ::testing::HasSubstr;

OfflineOptions options(std::uint64_t seed) {
  OfflineOptions o;
  o.seed = seed;
  return o;
}

class FloorplanOffline : public socsim::testing::KnowledgeSuite {
 protected:
  static std::vector<knowledge::MergedConstraint> constraints(const std::string& type) {
    auto c = kb_->constraints_for(type);
    EXPECT_TRUE(c.has_value());
    return c.value_or(std::vector<knowledge::MergedConstraint>{});
  }
  static FloorPlan generate(const std::string& domain, std::uint64_t seed) {
    const auto cs = constraints(domain);
    auto plan = generate_floor_plan(room_program(domain), cs, options(seed));
    EXPECT_TRUE(plan.has_value()) << domain << " seed " << seed << ": " << plan.error().message();
    return std::move(plan.value());
  }
};

// Every zone has a cell reachable from the entrance for an agent of radius 0.25 m.
void expect_fully_reachable(const World& w) {
  const auto grid = OccupancyGrid::rasterise(w, {0.1, 0.25, 4'000'000});
  std::vector<Point> sources;
  for (const auto& d : w.doors())
    if (!d.other) {
      const Point c{(d.opening.a.x + d.opening.b.x) / 2, (d.opening.a.y + d.opening.b.y) / 2};
      for (Point off : {Point{0.4, 0}, Point{-0.4, 0}, Point{0, 0.4}, Point{0, -0.4}}) {
        const Point p{c.x + off.x, c.y + off.y};
        if (geometry::contains(w.zone(d.zone).polygon, p)) sources.push_back(p);
      }
    }
  ASSERT_FALSE(sources.empty()) << w.name() << " has no entrance";
  const auto field = GeodesicField::from_points(grid, sources);
  std::vector<bool> reached(w.zones().size(), false);
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x) {
      const Cell c{x, y};
      if (!grid.blocked(c) && std::isfinite(field.at(c)))
        if (auto z = grid.zone_of(c)) reached[z->index()] = true;
    }
  for (std::size_t i = 0; i < reached.size(); ++i)
    EXPECT_TRUE(reached[i]) << w.name() << ": zone " << w.zones()[i].name << " unreachable from the entrance";
}

void expect_plans_valid_compliant_and_different(const std::vector<FloorPlan>& plans) {
  std::set<std::string> texts;
  std::set<std::string> shapes;
  for (const auto& p : plans) {
    EXPECT_TRUE(p.compliance.passed) << p.world.name() << ": " << to_json(p.compliance).dump();
    expect_fully_reachable(p.world);
    texts.insert(world_to_yaml(p.world));
    // The arrangement itself differs, not only the name: zone rectangles as a set.
    std::string shape;
    for (const auto& z : p.world.zones()) {
      const auto b = geometry::bounds(z.polygon.outer);
      shape += z.name + ":" + std::to_string(b.width()) + "x" + std::to_string(b.height()) + ";";
    }
    shapes.insert(shape);
  }
  EXPECT_EQ(texts.size(), plans.size());
  EXPECT_EQ(shapes.size(), plans.size());
}

TEST_F(FloorplanOffline, TwentyResidentialTenOfficeTenHospitalPlansAreValidCompliantAndDifferent) {
  for (const auto& [domain, count] :
       std::vector<std::pair<std::string, int>>{{"residential", 20}, {"office", 10}, {"hospital", 10}}) {
    std::vector<FloorPlan> plans;
    for (int seed = 1; seed <= count; ++seed)
      plans.push_back(generate(domain, static_cast<std::uint64_t>(seed)));
    SCOPED_TRACE(domain);
    expect_plans_valid_compliant_and_different(plans);
  }
}

TEST_F(FloorplanOffline, SameInputAndSeedGiveIdenticalYamlBytes) {
  for (const char* domain : {"residential", "hospital", "canteen"}) {
    const std::string a = world_to_yaml(generate(domain, 42).world);
    const std::string b = world_to_yaml(generate(domain, 42).world);
    EXPECT_EQ(a, b) << domain;
    EXPECT_NE(a, world_to_yaml(generate(domain, 43).world)) << domain;
  }
}

TEST_F(FloorplanOffline, EveryAdjacencyEdgeIsADoorOnTheSharedWall) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FloorPlan p = generate("canteen", seed);
    for (const auto& [a, b] : p.scene_graph.adjacency) {
      bool found = false;
      for (const auto& d : p.world.doors()) {
        if (!d.other) continue;
        const std::string x = p.world.zone(d.zone).name, y = p.world.zone(*d.other).name;
        found = found || (x == a && y == b) || (x == b && y == a);
      }
      EXPECT_TRUE(found) << "seed " << seed << ": no door between " << a << " and " << b;
    }
    // The storage opens onto the kitchen only, as the canteen programme says.
    const auto storage = p.world.find_zone("storage");
    ASSERT_TRUE(storage);
    for (const auto& d : p.world.doors())
      if (d.zone == *storage || d.other == storage) {
        const ZoneId other = d.zone == *storage ? *d.other : d.zone;
        EXPECT_EQ(p.world.zone(other).name, "kitchen");
      }
  }
}

TEST_F(FloorplanOffline, RoomsCorridorsAndDoorsMeetTheRetrievedMinima) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FloorPlan p = generate("hospital", seed);
    for (const auto& z : p.world.zones()) {
      if (z.type == "patient_room") {
        EXPECT_GE(geometry::area(z.polygon), 15.0);  // HBN 03-01 is stricter than FGI
      }
      if (z.type == "corridor") {
        EXPECT_GE(clear_width(z.polygon), 2.438);  // IBC 1020.2 / NFPA 101
      }
    }
    for (const auto& d : p.world.doors()) EXPECT_GE(d.width, 1.054) << d.name;  // IBC 1010.1.1 (I-2)
  }
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FloorPlan p = generate("residential", seed);
    double largest_bedroom = 0;
    for (const auto& z : p.world.zones()) {
      if (z.type == "bedroom") {
        EXPECT_GE(geometry::area(z.polygon), 7.5);
        largest_bedroom = std::max(largest_bedroom, geometry::area(z.polygon));
      }
      if (z.type == "hallway") {
        EXPECT_GE(clear_width(z.polygon), 0.914);
      }
    }
    EXPECT_GE(largest_bedroom, 11.5);  // NDSS double bedroom
    EXPECT_GE(p.world.area(), 61.0);   // NDSS 2b3p gross internal area
  }
}

TEST_F(FloorplanOffline, RoomsAreFurnishedByType) {
  auto entities_in = [](const World& w, const std::string& zone_type, const std::string& entity_type) {
    int n = 0;
    for (const auto& e : w.entities())
      if (w.zone(e.zone).type == zone_type && e.type == entity_type) ++n;
    return n;
  };
  auto rois_of = [](const World& w, const std::string& kind) { return w.rois_of_kind(kind).size(); };
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const World h = generate("hospital", seed).world;
    EXPECT_EQ(entities_in(h, "lobby", "counter"), 1) << seed;
    EXPECT_GE(rois_of(h, "queue_lane"), 1u);
    EXPECT_GE(rois_of(h, "waiting_zone"), 1u);
    EXPECT_GE(rois_of(h, "corridor"), 1u);
    EXPECT_EQ(entities_in(h, "patient_room", "bed"), 4);
    EXPECT_GE(entities_in(h, "lobby", "chair"), 4);
    const World c = generate("canteen", seed).world;
    EXPECT_GE(entities_in(c, "dining_hall", "table"), 6) << seed;
    EXPECT_GE(rois_of(c, "seating_area"), 1u);
    EXPECT_EQ(entities_in(c, "dining_hall", "counter"), 1);
    const World o = generate("office", seed).world;
    EXPECT_GE(entities_in(o, "open_office", "desk"), 4) << seed;
    EXPECT_EQ(entities_in(o, "kitchenette", "coffee_machine"), 1);
    const World r = generate("residential", seed).world;
    EXPECT_EQ(entities_in(r, "living_room", "sofa"), 1) << seed;
    EXPECT_EQ(entities_in(r, "bedroom", "bed"), 2);
  }
}

TEST_F(FloorplanOffline, EveryBuildingTypeHasAProgrammeThatLaysOut) {
  for (const char* domain : {"canteen", "retail", "warehouse", "school", "airport"}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const FloorPlan p = generate(domain, seed);
      EXPECT_TRUE(p.compliance.passed) << domain << " " << seed << ": " << to_json(p.compliance).dump();
      expect_fully_reachable(p.world);
    }
  }
}

// IBC 1006.3.3 / 1007.1.1: where the occupant load or the travel distance exceeds what one exit
// may serve, the plan gets a second door to the outside at least half its diagonal from the
// main entrance, with an exit ROI just inside it; where one exit suffices there is one.
TEST_F(FloorplanOffline, PlansGetASecondExitFarFromTheFirstWhereTheCodeAsksForIt) {
  std::map<std::string, int> two_exits;
  for (const char* domain :
       {"office", "hospital", "canteen", "retail", "warehouse", "school", "airport", "residential"}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const FloorPlan p = generate(domain, seed);
      SCOPED_TRACE(std::string(domain) + " seed " + std::to_string(seed));
      EXPECT_TRUE(p.compliance.passed) << to_json(p.compliance).dump();
      std::vector<const Door*> exits;
      for (const Door& d : p.world.doors())
        if (!d.other) exits.push_back(&d);
      const ComplianceCheck* count = nullptr;
      for (const auto& c : p.compliance.checks)
        if (c.name == "exit_count") count = &c;
      if (std::string(domain) == "residential") {
        EXPECT_EQ(count, nullptr);
        EXPECT_EQ(exits.size(), 1u);
        continue;
      }
      ASSERT_NE(count, nullptr);
      EXPECT_GE(static_cast<double>(exits.size()), count->required);
      if (exits.size() < 2) continue;
      // Added only where the main entrance alone did not do (the added exit may be the better single one).
      EXPECT_THAT(p.provenance["notes"].dump(), HasSubstr("emergency_exit"));
      ++two_exits[domain];
      EXPECT_EQ(exits[0]->name, "main_entrance");
      EXPECT_EQ(exits[1]->name, "emergency_exit");
      double diagonal = 0.0;
      for (const Zone& a : p.world.zones())
        for (const Zone& b : p.world.zones())
          for (const Point& u : a.polygon.outer)
            for (const Point& v : b.polygon.outer) diagonal = std::max(diagonal, geometry::distance(u, v));
      EXPECT_GE(geometry::distance(Point{exits[0]->pose.x, exits[0]->pose.y},
                                   Point{exits[1]->pose.x, exits[1]->pose.y}),
                diagonal / 2 - 1e-6);
      const std::string zone = p.world.zone(exits[1]->zone).name;
      const auto roi = p.world.find_roi(zone + "_emergency_exit");
      ASSERT_TRUE(roi.has_value()) << "exit ROI inside " << zone;
      EXPECT_EQ(p.world.roi(*roi).kind, "exit");
      expect_fully_reachable(p.world);
    }
  }
  // Hospitals (I-2: 10 occupants) and canteens (dining at 1.39 m² each) always exceed one exit.
  EXPECT_EQ(two_exits["hospital"], 6);
  EXPECT_EQ(two_exits["canteen"], 6);
}

TEST_F(FloorplanOffline, PromptCountsAreHonoured) {
  auto derived = scene_graph_from_prompt("a clinic with six patient rooms and a waiting room");
  ASSERT_TRUE(derived) << derived.error().message();
  const auto cs = constraints(derived->graph.domain);
  auto plan = generate_floor_plan(derived->graph, cs, options(7));
  ASSERT_TRUE(plan) << plan.error().message();
  int patient_rooms = 0, waiting_rooms = 0;
  for (const auto& z : plan->world.zones()) {
    patient_rooms += z.type == "patient_room";
    waiting_rooms += z.type == "waiting_room";
  }
  EXPECT_EQ(patient_rooms, 6);
  EXPECT_EQ(waiting_rooms, 1);
  EXPECT_TRUE(plan->compliance.passed);
}

TEST_F(FloorplanOffline, ACorridorIsAddedWhereTheDomainNeedsOne) {
  auto g = scene_graph_from_json(Json::parse(R"({"domain": "office", "rooms": [
      {"name": "a", "type": "private_office"}, {"name": "b", "type": "private_office"}, {"name": "c", "type": "meeting_room"}],
      "adjacency": [["a", "b"], ["b", "c"]]})"));
  ASSERT_TRUE(g) << g.error().message();
  auto plan = generate_floor_plan(*g, constraints("office"), options(3));
  ASSERT_TRUE(plan) << plan.error().message();
  EXPECT_TRUE(plan->world.find_zone("corridor"));
  EXPECT_EQ(plan->provenance["notes"].size(), 1u);
  EXPECT_TRUE(plan->compliance.passed);
}

TEST_F(FloorplanOffline, AGraphTheLayoutCannotPlaceIsRefusedNamingTheEdge) {
  auto g = scene_graph_from_json(Json::parse(R"({"domain": "residential", "rooms": [
      {"name": "hall", "type": "hallway"}, {"name": "living", "type": "living_room"}, {"name": "k", "type": "kitchen"},
      {"name": "d", "type": "dining_room"}, {"name": "s", "type": "study"}],
      "adjacency": [["hall", "living"], ["living", "k"], ["living", "d"], ["living", "s"]]})"));
  ASSERT_TRUE(g) << g.error().message();
  auto plan = generate_floor_plan(*g, constraints("residential"), options(1));
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().code, ErrorCode::kValidation);
  ASSERT_FALSE(plan.error().errors.empty());
  EXPECT_EQ(plan.error().errors[0].pointer, "/adjacency/3");
  EXPECT_THAT(plan.error().errors[0].message, HasSubstr("living"));
}

TEST_F(FloorplanOffline, ExportsOfGeneratedPlansAreWellFormed) {
  const World w = generate("hospital", 11).world;
  auto sdf = parse_xml(export_sdf(w));
  ASSERT_TRUE(sdf) << sdf.error().message();
  int links = 0;
  std::function<void(const XmlElement&)> walk = [&](const XmlElement& e) {
    if (e.name == "link") {
      ++links;
      bool pose = false, geometry = false;
      for (const auto& c : e.children) {
        pose = pose || c.name == "pose";
        for (const auto& g : c.children) geometry = geometry || g.name == "geometry";
      }
      EXPECT_TRUE(pose && geometry);
    }
    for (const auto& c : e.children) walk(c);
  };
  walk(*sdf);
  EXPECT_GE(links, static_cast<int>(w.walls().size()));
  auto pedsim = parse_xml(export_pedsim(w));
  ASSERT_TRUE(pedsim) << pedsim.error().message();
  const std::set<std::string> known = {"scenario",   "obstacle", "waypoint",    "queue",
                                       "attraction", "agent",    "addwaypoint", "source"};
  for (const auto& c : pedsim->children) EXPECT_TRUE(known.count(c.name)) << c.name;
}

}  // namespace
}  // namespace socsim::floorplan
