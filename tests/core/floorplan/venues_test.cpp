// Every venue type × 10 seeds: the offline plan is valid, every zone and entity reachable by a
// person 0.5 m wide, no footprint overlapping a wall, a door or another footprint, the
// compliance report passing and the requested features present; each venue has the things that
// make it that venue (platforms and ticket machines, seat rows and a screen, a stage …); 1,000
// plans over all types are clean; 20 seeds of one prompt give at least 15 different
// arrangements (which rooms share a wall: invariant under rotation, mirroring and resizing).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/floorplan/features.hpp"
#include "core/floorplan/offline.hpp"
#include "core/geometry/planar.hpp"
#include "core/knowledge/types.hpp"
#include "core/world/footprint.hpp"
#include "core/world/layout_check.hpp"
#include "core/world/pedsim_import.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/support/knowledge_suite.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::floorplan {
namespace {

class Venues : public socsim::testing::KnowledgeSuite {
 protected:
  static const std::vector<knowledge::MergedConstraint>& constraints(const std::string& type) {
    static std::map<std::string, std::vector<knowledge::MergedConstraint>> cache;
    auto it = cache.find(type);
    if (it == cache.end()) {
      auto c = kb_->constraints_for(type);
      EXPECT_TRUE(c.has_value()) << type;
      it = cache.emplace(type, c.value_or(std::vector<knowledge::MergedConstraint>{})).first;
    }
    return it->second;
  }
};

int entities_of(const World& w, std::string_view type) {
  int n = 0;
  for (const auto& e : w.entities()) n += e.type == type ? 1 : 0;
  return n;
}
int zones_of(const World& w, std::string_view type) {
  int n = 0;
  for (const auto& z : w.zones()) n += z.type == type ? 1 : 0;
  return n;
}

// What a prompt about each venue typically asks for, as typed requirements.
WorldRequirements typical_request(std::string_view type) {
  WorldRequirements r;
  auto want = [&](Feature f, int n, bool at_least) { r.features.push_back({f, n, at_least, ""}); };
  if (type == "train_station") want(Feature::kGate, 4, true);
  if (type == "supermarket") want(Feature::kCheckout, 3, false);
  if (type == "theatre") want(Feature::kScreen, 2, true);
  if (type == "arena") want(Feature::kStage, 1, false);
  if (type == "gym") want(Feature::kLocker, 10, true);
  if (type == "restaurant") want(Feature::kBar, 1, false);
  if (type == "library") want(Feature::kShelf, 10, true);
  if (type == "museum" || type == "mall" || type == "university") want(Feature::kExit, 3, false);
  if (type == "hotel" || type == "care_home") want(Feature::kBed, 8, true);
  if (type == "factory" || type == "community_hall") want(Feature::kExit, 2, true);
  return r;
}

TEST_F(Venues, EveryTypeTenSeedsIsCleanAndCompliantWithItsRequestBuilt) {
  for (std::string_view type : knowledge::building_types()) {
    const auto& cs = constraints(std::string(type));
    const WorldRequirements wants = typical_request(type);
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      o.requirements = wants;
      auto plan = generate_floor_plan(room_program(type), cs, o);
      EXPECT_TRUE(plan) << type << " seed " << seed << ": " << plan.error().message();
      if (!plan) continue;
      EXPECT_TRUE(plan->compliance.passed) << type << " seed " << seed;
      const LayoutCheck check = check_layout(plan->world);
      EXPECT_TRUE(check.ok()) << type << " seed " << seed << ":\n" << check.summary();
      EXPECT_GT(check.entities_checked, 0u) << type;
      EXPECT_EQ(check.reachable_entities, check.entities_checked) << type << " seed " << seed;
      for (const auto& f : wants.features) {
        const int built = count_feature(plan->world, f.feature);
        int code_exits = 0;  // the exits the building code asks for (IBC Table 1006.3.2) may be more
        for (const auto& c : plan->compliance.checks)
          if (c.name == "exit_count") code_exits = static_cast<int>(c.required);
        if (f.feature == Feature::kExit && code_exits > f.count)
          EXPECT_EQ(built, code_exits) << type << " seed " << seed << ": exits the code asks for";
        else if (f.at_least)
          EXPECT_GE(built, f.count) << type << " seed " << seed << ": " << to_string(f.feature);
        else
          EXPECT_EQ(built, f.count) << type << " seed " << seed << ": " << to_string(f.feature);
      }
    }
  }
}

// The things that make a venue what it is, in every seed.
TEST_F(Venues, EachVenueHasItsRoomsAndPointsOfInterest) {
  struct Expect {
    std::string_view venue;
    std::vector<std::string_view> zones;
    std::vector<std::string_view> entities;
  };
  const std::vector<Expect> expected = {
      {"train_station", {"ticket_hall", "platform"}, {"ticket_machine", "info_board", "bench"}},
      {"hotel", {"lobby", "hotel_room", "restaurant"}, {"bed", "wardrobe", "bar_counter"}},
      {"library", {"reading_room", "library_stacks", "study_room"}, {"bookshelf", "reading_table"}},
      {"museum", {"foyer", "gallery"}, {"painting", "bench"}},
      {"theatre", {"foyer", "auditorium", "backstage"}, {"seat", "screen", "bar_counter"}},
      {"arena", {"concourse", "arena_floor", "concession"}, {"stage", "seat", "locker"}},
      {"factory", {"production_floor", "loading_bay", "locker_room"}, {"machine", "conveyor", "locker"}},
      {"mall", {"mall_concourse", "shop_unit", "food_court"}, {"counter", "shelf", "table"}},
      {"supermarket", {"sales_floor", "stock_room"}, {"shelf"}},
      {"restaurant", {"restaurant", "kitchen"}, {"bar_counter", "table"}},
      {"university", {"lecture_hall", "seminar_room"}, {"seat", "screen", "desk"}},
      {"gym", {"sports_hall", "fitness_room", "changing_room"}, {"fitness_machine", "locker"}},
      {"care_home", {"resident_room", "day_room", "nurse_station"}, {"bed", "armchair"}},
      {"community_hall", {"main_hall", "kitchen"}, {"voting_booth", "counter"}},
  };
  for (const auto& e : expected) {
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      auto plan = generate_floor_plan(room_program(e.venue), constraints(std::string(e.venue)), o);
      ASSERT_TRUE(plan) << e.venue << " seed " << seed << ": " << plan.error().message();
      for (auto z : e.zones)
        EXPECT_GE(zones_of(plan->world, z), 1) << e.venue << " seed " << seed << ": " << z;
      for (auto t : e.entities)
        EXPECT_GE(entities_of(plan->world, t), 1) << e.venue << " seed " << seed << ": " << t;
    }
  }
}

// One thousand plans over every type (seeds 100 …), each valid, compliant and clean, in ten
// shards of 100 (one CTest entry each, so two cores share them and none nears the timeout).
// A shard takes about 20 s of CPU in the dev (Debug) build, 3 s in release (docs/worlds.md).
class ThousandPlans : public Venues, public ::testing::WithParamInterface<int> {};

TEST_P(ThousandPlans, AreValidCompliantAndClean) {
  const auto types = knowledge::building_types();
  const int n_types = static_cast<int>(types.size());
  int failed = 0, dirty = 0, built = 0;
  for (int i = GetParam() * 100; i < (GetParam() + 1) * 100; ++i) {
    const std::string type(types[static_cast<std::size_t>(i % n_types)]);
    OfflineOptions o;
    o.seed = 100 + static_cast<std::uint64_t>(i / n_types);
    auto plan = generate_floor_plan(room_program(type), constraints(type), o);
    if (!plan) {
      ++failed;
      ADD_FAILURE() << type << " seed " << o.seed << ": " << plan.error().message();
      continue;
    }
    ++built;
    const LayoutCheck check = check_layout(plan->world);
    if (!plan->compliance.passed || !check.ok()) {
      ++dirty;
      ADD_FAILURE() << type << " seed " << o.seed << ": compliance " << plan->compliance.passed << "\n"
                    << check.summary();
    }
  }
  EXPECT_EQ(built, 100);
  EXPECT_EQ(failed, 0);
  EXPECT_EQ(dirty, 0);
}
INSTANTIATE_TEST_SUITE_P(Shards, ThousandPlans, ::testing::Range(0, 10));

// A plan's arrangement: which room types share a wall (more than 0.3 m of it), as a sorted
// multiset of type pairs, and which room types have doors to the outside. Rotation, mirroring
// and room sizes do not change it; a different order of rooms along a corridor, other rooms at
// its ends or on its other side, do.
// The length of wall two zones share (collinear edges' overlap), m.
double shared_wall(const Zone& a, const Zone& b) {
  double total = 0;
  const auto& pa = a.polygon.outer;
  const auto& pb = b.polygon.outer;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const Point p = pa[i], q = pa[(i + 1) % pa.size()];
    const double len = std::hypot(q.x - p.x, q.y - p.y);
    if (len < 1e-9) continue;
    const double ux = (q.x - p.x) / len, uy = (q.y - p.y) / len;
    for (std::size_t j = 0; j < pb.size(); ++j) {
      const Point r = pb[j], s = pb[(j + 1) % pb.size()];
      // Collinear: both ends of the other edge on this edge's line.
      const double d1 = (r.x - p.x) * uy - (r.y - p.y) * ux, d2 = (s.x - p.x) * uy - (s.y - p.y) * ux;
      if (std::abs(d1) > 1e-6 || std::abs(d2) > 1e-6) continue;
      const double t1 = (r.x - p.x) * ux + (r.y - p.y) * uy, t2 = (s.x - p.x) * ux + (s.y - p.y) * uy;
      total += std::max(0.0, std::min(len, std::max(t1, t2)) - std::max(0.0, std::min(t1, t2)));
    }
  }
  return total;
}

std::string arrangement(const World& w) {
  std::vector<std::string> pairs;
  const auto& zs = w.zones();
  for (std::size_t a = 0; a < zs.size(); ++a)
    for (std::size_t b = a + 1; b < zs.size(); ++b)
      if (shared_wall(zs[a], zs[b]) > 0.3)
        pairs.push_back(std::min(zs[a].type, zs[b].type) + "|" + std::max(zs[a].type, zs[b].type));
  for (const auto& d : w.doors())
    if (!d.other) pairs.push_back("exit:" + w.zone(d.zone).type);
  // The zones of an open hall (ROIs of kind "area"): which rooms and which exits each touches.
  for (auto id : w.rois_of_kind("area")) {
    const Roi& r = w.roi(id);
    const Zone as_zone{r.name, r.name, "", r.polygon};
    for (const auto& z : zs)
      if (geometry::area(z.polygon) > 0 && shared_wall(as_zone, z) > 0.3)
        pairs.push_back(r.name + "|" + z.type);
    for (const auto& d : w.doors())
      if (!d.other && geometry::contains(r.polygon, d.pose.position(), 0.05))
        pairs.push_back("exit:" + r.name);
  }
  std::sort(pairs.begin(), pairs.end());
  std::string out;
  for (const auto& p : pairs) out += p + ";";
  return out;
}

TEST_F(Venues, TwentySeedsOfOnePromptGiveAtLeastFifteenArrangements) {
  for (const char* prompt :
       {"a hospital ward with six patient rooms, a waiting room and two treatment rooms",
        "guests checking in at a small hotel", "visitors in a museum", "passengers in the station concourse",
        "a family at home in their small flat",
        // Programs of four or five rooms (a hall and three or four rooms).
        "shoppers at the supermarket check-outs", "lunch in the office canteen",
        "dinner at a busy restaurant", "voters at the polling station",
        // The auditorium family (a theatre) and the multi-wing family (26 rooms).
        "an evening at the cinema", "residents of a care home with eighteen residents' rooms"}) {
    auto g = scene_graph_from_prompt(prompt);
    ASSERT_TRUE(g) << prompt;
    std::set<std::string> seen;
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      auto plan = generate_floor_plan(g->graph, constraints(g->graph.domain), o);
      ASSERT_TRUE(plan) << prompt << " seed " << seed << ": " << plan.error().message();
      seen.insert(arrangement(plan->world));
    }
    EXPECT_GE(seen.size(), 15u) << prompt << " (" << g->graph.rooms.size() << " rooms)";
  }
}

// The signature is not blind: the same seed gives the same arrangement, and it sees the foyer
// beside a gallery and the galleries en suite (each opening onto the one before).
TEST_F(Venues, TheArrangementSignatureSeesOrderNotSize) {
  auto g = scene_graph_from_prompt("visitors in a museum");
  ASSERT_TRUE(g);
  OfflineOptions o;
  o.seed = 3;
  auto a = generate_floor_plan(g->graph, constraints(g->graph.domain), o);
  auto b = generate_floor_plan(g->graph, constraints(g->graph.domain), o);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(arrangement(a->world), arrangement(b->world));
  EXPECT_THAT(arrangement(a->world), ::testing::HasSubstr("foyer|gallery"));
  EXPECT_THAT(arrangement(a->world), ::testing::HasSubstr("gallery|gallery"));  // rooms en suite
}

// Programs large enough for wings: a 19-room hospital, a 20-room university and a 26-room care
// home (always in wings), besides the 16-room hotel of the default program.
std::vector<SceneGraph> large_programs() {
  return {room_program("hospital", {{"patient_room", 12}}),
          room_program("university", {{"seminar_room", 8}, {"private_office", 4}}),
          room_program("care_home", {{"resident_room", 18}}), room_program("hotel")};
}

// An auditorium plan: every audience hall (an auditorium, an arena floor, a large community hall's
// main hall) has seats in rows behind one another, every seat facing the screen or stage at the
// far end, and aisles (walkways) between the blocks.
void expect_audience_halls(const World& w, const std::string& where) {
  int halls = 0;
  for (const auto& z : w.zones()) {
    const bool seated = std::any_of(w.entities().begin(), w.entities().end(), [&](const Entity& e) {
      return e.type == "seat" && e.name.rfind(z.name + "_seat_r", 0) == 0;
    });
    if (z.type != "auditorium" && z.type != "arena_floor" && !(z.type == "main_hall" && seated)) continue;
    ++halls;
    std::vector<const Entity*> seats;
    const Entity* front = nullptr;
    for (const auto& e : w.entities()) {
      if (e.name.rfind(z.name + "_", 0) != 0) continue;
      if (e.type == "seat") seats.push_back(&e);
      if (e.type == "stage" || (e.type == "screen" && !front)) front = &e;
    }
    ASSERT_NE(front, nullptr) << where << ": no screen or stage in " << z.name;
    EXPECT_GE(seats.size(), 20u) << where << ": " << z.name;
    std::set<long> rows;
    for (const Entity* s : seats) {
      const double dx = front->pose.x - s->pose.x, dy = front->pose.y - s->pose.y;
      EXPECT_GT(std::cos(s->pose.yaw) * dx + std::sin(s->pose.yaw) * dy, 0.0)
          << where << ": " << s->name << " faces away from " << front->name;
      rows.insert(std::lround(std::cos(s->pose.yaw) * s->pose.x + std::sin(s->pose.yaw) * s->pose.y));
    }
    EXPECT_GE(rows.size(), 2u) << where << ": " << z.name << " has one row";
    // Aisles a person 0.5 m wide walks along: at least that wide, no seat reaching into them.
    int aisles = 0;
    for (auto id : w.rois_of_kind("walkway")) {
      const Roi& aisle = w.roi(id);
      if (aisle.name.rfind(z.name + "_aisle", 0) != 0) continue;
      ++aisles;
      const auto b = geometry::bounds(aisle.polygon.outer);
      EXPECT_GE(std::min(b.width(), b.height()), 0.5) << where << ": " << aisle.name;
      for (const Entity* s : seats) {
        const auto f = geometry::bounds(footprint_polygon(s->type, s->pose).outer);
        EXPECT_FALSE(f.min.x < b.max.x - 0.01 && b.min.x < f.max.x - 0.01 && f.min.y < b.max.y - 0.01 &&
                     b.min.y < f.max.y - 0.01)
            << where << ": " << s->name << " in " << aisle.name;
      }
    }
    EXPECT_GE(aisles, 2) << where << ": " << z.name;
  }
  EXPECT_GE(halls, 1) << where;
}

// A multi-wing plan: one corridor zone, not a rectangle (an L, T or cross: 6, 8 or 12 corners),
// with rooms along at least two of its wings.
void expect_wings(const World& w, const std::string& where) {
  int corridors = 0;
  for (const auto& z : w.zones()) {
    if (z.type != "corridor") continue;
    ++corridors;
    std::size_t corners = z.polygon.outer.size();
    if (corners > 1 && z.polygon.outer.front() == z.polygon.outer.back()) --corners;
    EXPECT_TRUE(corners == 6 || corners == 8 || corners == 12) << where << ": " << corners << " corners";
  }
  EXPECT_EQ(corridors, 1) << where;
}

// Every layout family is built, and each plan of it is as clean as the others: valid, compliant,
// every zone and thing reachable, doors on shared walls, the scene graph's rooms and adjacencies
// kept exactly (a door for every edge, between the two rooms it names), the family recorded.
TEST_F(Venues, EveryLayoutFamilyIsBuiltCleanAndKeepsTheSceneGraph) {
  std::map<std::string, int> families;
  std::vector<SceneGraph> graphs;
  for (std::string_view type :
       {"supermarket", "retail", "canteen", "warehouse", "train_station", "airport", "residential",
        "hospital", "museum", "theatre", "mall", "factory", "restaurant", "arena"})
    graphs.push_back(room_program(type));
  for (auto& g : large_programs()) graphs.push_back(std::move(g));
  for (const SceneGraph& g : graphs) {
    const std::string type = g.domain;
    const WorldRequirements wants = typical_request(type);
    for (std::uint64_t seed = 0; seed < 8; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      o.requirements = wants;
      auto plan = generate_floor_plan(g, constraints(std::string(type)), o);
      ASSERT_TRUE(plan) << type << " seed " << seed << ": " << plan.error().message();
      const std::string family = plan->provenance.at("layout_family");
      ++families[family];
      EXPECT_TRUE(plan->compliance.passed) << type << " " << seed;
      const LayoutCheck check = check_layout(plan->world);
      EXPECT_TRUE(check.ok()) << type << " seed " << seed << " (" << family << "):\n" << check.summary();
      EXPECT_EQ(plan->scene_graph.rooms, g.rooms) << type << " " << family;
      EXPECT_EQ(plan->scene_graph.adjacency, g.adjacency) << type << " " << family;
      for (const auto& [a, b] : g.adjacency) {
        const auto za = plan->world.find_zone(a), zb = plan->world.find_zone(b);
        ASSERT_TRUE(za && zb) << a << " " << b;
        EXPECT_TRUE(std::any_of(plan->world.doors().begin(), plan->world.doors().end(),
                                [&](const Door& d) {
                                  return d.other && ((d.zone == *za && *d.other == *zb) ||
                                                     (d.zone == *zb && *d.other == *za));
                                }))
            << type << " seed " << seed << ": no door between " << a << " and " << b;
      }
      for (const auto& f : wants.features) {
        if (f.feature == Feature::kExit) continue;  // the code may raise an exit count
        const int built = count_feature(plan->world, f.feature);
        EXPECT_TRUE(f.at_least ? built >= f.count : built == f.count)
            << type << " seed " << seed << ": " << to_string(f.feature);
      }
      if (family == "open_hall_zones") {
        // Its zones are ROIs of kind "area" inside the hall, each with its own things.
        const auto areas = plan->world.rois_of_kind("area");
        EXPECT_GE(areas.size(), 2u) << type << " " << seed;
        for (auto id : areas) {
          const Roi& r = plan->world.roi(id);
          const int things = static_cast<int>(
              std::count_if(plan->world.entities().begin(), plan->world.entities().end(),
                            [&](const Entity& e) { return e.name.rfind(r.name + "_", 0) == 0; }));
          EXPECT_GE(things, 1) << type << " seed " << seed << ": nothing in " << r.name;
        }
      }
      if (family == "home_open_plan") {
        // No hallway: every room but the living room has its door onto the living room.
        EXPECT_EQ(zones_of(plan->world, "hallway"), 0);
        EXPECT_EQ(zones_of(plan->world, "corridor"), 0);
      }
      if (family == "auditorium") expect_audience_halls(plan->world, type + " seed " + std::to_string(seed));
      if (family == "multi_wing") expect_wings(plan->world, type + " seed " + std::to_string(seed));
    }
  }
  for (const char* f : {"corridor_with_rooms", "hall_with_rooms", "open_hall_zones", "home_open_plan",
                        "auditorium", "multi_wing", "rooms_en_suite"})
    EXPECT_GE(families[f], 4) << f;
}

// A museum's galleries en suite are the way through it: the foyer opens into the first, each
// gallery into the next (its doors on the axis of the enfilade) and the last back into the foyer,
// no gallery has a door to any other room, and the seeds draw the enfilade in two rows, as a U
// round the foyer and as a ring round a core of service rooms. Valid, compliant and clean.
TEST_F(Venues, MuseumGalleriesEnSuiteAreTheCirculation) {
  const SceneGraph g = room_program("museum");
  std::set<std::string> shapes;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    OfflineOptions o;
    o.seed = seed;
    o.requirements = typical_request("museum");
    auto plan = generate_floor_plan(g, constraints("museum"), o);
    ASSERT_TRUE(plan) << seed << ": " << plan.error().message();
    EXPECT_EQ(plan->provenance.at("layout_family"), "rooms_en_suite") << seed;
    EXPECT_TRUE(plan->compliance.passed) << seed;
    const LayoutCheck check = check_layout(plan->world);
    EXPECT_TRUE(check.ok()) << seed << ":\n" << check.summary();
    EXPECT_EQ(plan->scene_graph.adjacency, g.adjacency);
    const World& w = plan->world;
    // The circuit: foyer, the five galleries in the program's order, foyer, each step through a door.
    std::vector<std::string> circuit{"foyer"};
    for (const auto& r : g.rooms)
      if (r.type == "gallery") circuit.push_back(r.name);
    circuit.push_back("foyer");
    for (std::size_t k = 0; k + 1 < circuit.size(); ++k) {
      const auto a = w.find_zone(circuit[k]), b = w.find_zone(circuit[k + 1]);
      ASSERT_TRUE(a && b) << circuit[k] << " " << circuit[k + 1];
      EXPECT_TRUE(std::any_of(w.doors().begin(), w.doors().end(),
                              [&](const Door& d) {
                                return d.other &&
                                       ((d.zone == *a && *d.other == *b) || (d.zone == *b && *d.other == *a));
                              }))
          << seed << ": no door from " << circuit[k] << " into " << circuit[k + 1];
    }
    int touching_foyer = 0;
    bool core = false;
    const Zone& foyer = w.zone(*w.find_zone("foyer"));
    for (const auto& z : w.zones()) {
      if (z.type != "gallery") continue;
      // Inside, a gallery opens only onto galleries and the foyer.
      for (const auto& d : w.doors()) {
        if (!d.other) continue;
        const bool mine = w.zone(d.zone).name == z.name || w.zone(*d.other).name == z.name;
        const std::string& there =
            w.zone(d.zone).name == z.name ? w.zone(*d.other).type : w.zone(d.zone).type;
        if (mine) {
          EXPECT_TRUE(there == "gallery" || there == "foyer") << seed << ": " << d.name;
        }
      }
      if (shared_wall(z, foyer) > 0.3) ++touching_foyer;
      for (const auto& other : w.zones())
        if (other.type != "gallery" && other.type != "foyer" && shared_wall(z, other) > 0.3) core = true;
    }
    shapes.insert(touching_foyer == 5 ? "u" : core ? "ring" : "two_rows");
  }
  EXPECT_EQ(shapes.size(), 3u) << "the enfilade's shapes over 12 seeds";
}

// A caller's graph keeps its galleries en suite exactly: an open chain (only the first gallery
// on the foyer) is a single enfilade, two galleries that both open onto the foyer a short circuit,
// and a large museum's twelve galleries a long one.
TEST_F(Venues, GalleriesEnSuiteOfACallersGraphAreKeptExactly) {
  SceneGraph open{
      "museum",
      {{"foyer", "foyer", std::nullopt},
       {"gallery_a", "gallery", std::nullopt},
       {"gallery_b", "gallery", std::nullopt},
       {"gallery_c", "gallery", std::nullopt},
       {"toilet", "toilet", std::nullopt}},
      {{"foyer", "gallery_a"}, {"gallery_a", "gallery_b"}, {"gallery_b", "gallery_c"}, {"foyer", "toilet"}},
      "foyer"};
  SceneGraph pair = open;
  pair.rooms.erase(pair.rooms.begin() + 3);
  pair.adjacency = {
      {"foyer", "gallery_a"}, {"gallery_a", "gallery_b"}, {"foyer", "gallery_b"}, {"foyer", "toilet"}};
  for (const SceneGraph& g : {open, pair, room_program("museum", {{"gallery", 12}})}) {
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      auto plan = generate_floor_plan(g, constraints("museum"), o);
      ASSERT_TRUE(plan) << g.rooms.size() << " rooms, seed " << seed << ": " << plan.error().message();
      EXPECT_EQ(plan->provenance.at("layout_family"), "rooms_en_suite");
      EXPECT_TRUE(plan->compliance.passed) << g.rooms.size() << " rooms, seed " << seed;
      const LayoutCheck check = check_layout(plan->world);
      EXPECT_TRUE(check.ok()) << g.rooms.size() << " rooms, seed " << seed << ":\n" << check.summary();
      EXPECT_EQ(plan->scene_graph.rooms, g.rooms);
      EXPECT_EQ(plan->scene_graph.adjacency, g.adjacency);
      int inner = 0;
      for (const auto& d : plan->world.doors()) inner += d.other ? 1 : 0;
      EXPECT_EQ(inner, static_cast<int>(g.adjacency.size())) << "one door per edge, no other";
    }
  }
}

// The two newest families (the quick check run in CI; the tests above run them over more seeds):
// a theatre laid out round its auditoria, a 26-room care home in wings and a community hall for
// 300 people whose main hall is set out with seat rows, each valid, compliant, clean and with the
// things its family promises.
TEST_F(Venues, AnAuditoriumAndAMultiWingPlanAreClean) {
  for (const auto& [g, family, seed] :
       {std::tuple{room_program("theatre"), "auditorium", 1},
        std::tuple{large_programs()[2], "multi_wing", 1},
        // A community hall for 300 people: its main hall set out as the audience hall.
        std::tuple{room_program("community_hall"), "auditorium", 1},
        std::tuple{room_program("community_hall"), "auditorium", 2}}) {
    OfflineOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    o.requirements = typical_request(g.domain);
    if (g.domain == "community_hall") o.requirements.occupants = 300;
    auto plan = generate_floor_plan(g, constraints(g.domain), o);
    ASSERT_TRUE(plan) << g.domain << ": " << plan.error().message();
    EXPECT_EQ(plan->provenance.at("layout_family"), family);
    EXPECT_TRUE(plan->compliance.passed) << g.domain;
    const LayoutCheck check = check_layout(plan->world);
    EXPECT_TRUE(check.ok()) << g.domain << ":\n" << check.summary();
    EXPECT_EQ(plan->scene_graph.rooms, g.rooms);
    EXPECT_EQ(plan->scene_graph.adjacency, g.adjacency);
    if (std::string(family) == "auditorium") expect_audience_halls(plan->world, g.domain);
    if (std::string(family) == "multi_wing") expect_wings(plan->world, g.domain);
  }
}

// A community hall for 300 people × 10 seeds: the auditorium family with the main hall set out
// with seat rows facing a stage (or a screen), clean, compliant, the scene graph kept (heavy).
TEST_F(Venues, EveryLayoutFamilyHoldsALargeCommunityHall) {
  const SceneGraph g = room_program("community_hall");
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    OfflineOptions o;
    o.seed = seed;
    o.requirements = typical_request("community_hall");
    o.requirements.occupants = 300;
    auto plan = generate_floor_plan(g, constraints("community_hall"), o);
    ASSERT_TRUE(plan) << seed << ": " << plan.error().message();
    EXPECT_EQ(plan->provenance.at("layout_family"), "auditorium") << seed;
    EXPECT_TRUE(plan->compliance.passed) << seed;
    const LayoutCheck check = check_layout(plan->world);
    EXPECT_TRUE(check.ok()) << seed << ":\n" << check.summary();
    EXPECT_EQ(plan->scene_graph.rooms, g.rooms);
    EXPECT_EQ(plan->scene_graph.adjacency, g.adjacency);
    expect_audience_halls(plan->world, "community hall seed " + std::to_string(seed));
  }
}

// Every simulator and map format is produced for a plan of every family and reads back: SVG and
// SDF are well-formed XML with their root, the ROS map is a P5 image of the size its header says
// with metadata naming it, and the pedsim scenario re-imports with one obstacle per wall.
TEST_F(Venues, EveryLayoutFamilyExportsToEveryFormat) {
  std::map<std::string, int> exported;
  std::vector<SceneGraph> graphs;
  for (std::string_view type :
       {"supermarket", "train_station", "residential", "hospital", "museum", "theatre"})
    graphs.push_back(room_program(type));
  graphs.push_back(large_programs().front());
  for (const SceneGraph& g : graphs) {
    const std::string type = g.domain;
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      o.requirements = typical_request(type);
      auto plan = generate_floor_plan(g, constraints(type), o);
      ASSERT_TRUE(plan) << type << " seed " << seed << ": " << plan.error().message();
      const std::string family = plan->provenance.at("layout_family");
      if (exported[family] >= 2) continue;
      ++exported[family];
      const std::string where = std::string(type) + " seed " + std::to_string(seed) + " (" + family + ")";
      auto svg = world::parse_xml(world::export_svg(plan->world));
      ASSERT_TRUE(svg) << where << ": " << svg.error().message();
      EXPECT_EQ(svg->name, "svg") << where;
      auto sdf = world::parse_xml(world::export_sdf(plan->world));
      ASSERT_TRUE(sdf) << where << ": " << sdf.error().message();
      EXPECT_EQ(sdf->name, "sdf") << where;
      const world::RosMap map = world::export_ros_map(plan->world);
      // P5 header: magic, width, height, maxval, with '#' comment lines between; one byte a pixel.
      std::vector<long> fields;
      std::size_t at = 0;
      while (fields.size() < 4 && at < map.pgm.size()) {
        if (map.pgm[at] == '#') {
          at = map.pgm.find('\n', at);
        } else if (std::isspace(static_cast<unsigned char>(map.pgm[at])) != 0) {
          ++at;
        } else {
          std::size_t end = at;
          while (end < map.pgm.size() && std::isspace(static_cast<unsigned char>(map.pgm[end])) == 0) ++end;
          const std::string token = map.pgm.substr(at, end - at);
          fields.push_back(fields.empty() ? (token == "P5" ? 5 : -1) : std::stol(token));
          at = end;
        }
      }
      ASSERT_EQ(fields.size(), 4u) << where;
      EXPECT_EQ(fields[0], 5) << where;
      EXPECT_EQ(fields[3], 255) << where;
      EXPECT_GT(fields[1] * fields[2], 0) << where;
      EXPECT_EQ(map.pgm.size(), at + 1 + static_cast<std::size_t>(fields[1] * fields[2])) << where;
      EXPECT_NE(map.yaml.find("image: map.pgm"), std::string::npos) << where;
      const std::string pedsim = world::export_pedsim(plan->world);
      auto back = world::import_pedsim(pedsim);
      ASSERT_TRUE(back) << where << ": " << back.error().message();
      auto xml = world::parse_xml(pedsim);
      ASSERT_TRUE(xml);
      EXPECT_EQ(xml->children_named("obstacle").size(), plan->world.walls().size()) << where;
    }
  }
  for (const char* f :
       {"corridor_with_rooms", "open_hall_zones", "home_open_plan", "auditorium", "multi_wing"})
    EXPECT_GE(exported[f], 1) << f << " not exported";
}

}  // namespace
}  // namespace socsim::floorplan
