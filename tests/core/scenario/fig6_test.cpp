// The same prompt adapts to each world (paper 001 Fig. 6, issue 6): a queue forms at the
// reception counter in a hospital and at the water dispenser in a corridor world without a
// reception; "for water" is honoured over the default counter; an evacuation in a generated
// plan with two exits (IBC 1006.3) uses both. Measured on simulated frames (ScenarioRunner).
#include <algorithm>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/geometry/planar.hpp"
#include "core/scenario/program_offline.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/scenario/offline_worlds.hpp"

namespace socsim::scenario {
namespace {

using crowd::Activity;
using crowd::PedestrianState;

using testing::Frame;
using testing::has_tag;
using testing::Simulated;
using testing::speed;

// A 20 m corridor with a water dispenser and its queue lane, a door to the outside at one end and
// an office off it: no reception, no counter.
const char* kCorridorYaml = R"(name: "corridor_with_water"
zones:
  - {name: "corridor", type: "corridor", polygon: [[0, 0], [20, 0], [20, 3], [0, 3]]}
  - {name: "office", type: "private_office", polygon: [[8, 3], [13, 3], [13, 7], [8, 7]]}
walls:
  - {start: [0, 0], end: [20, 0]}
  - {start: [20, 0], end: [20, 3]}
  - {start: [20, 3], end: [13, 3]}
  - {start: [8, 3], end: [0, 3]}
  - {start: [0, 3], end: [0, 2]}
  - {start: [0, 1], end: [0, 0]}
  - {start: [8, 3], end: [8, 7]}
  - {start: [8, 7], end: [13, 7]}
  - {start: [13, 7], end: [13, 3]}
  - {start: [8, 3], end: [10, 3]}
  - {start: [11, 3], end: [13, 3]}
doors:
  - {name: "corridor_exit", pose: [0, 1.5, 0], width: 1.0, connects: ["corridor"]}
  - {name: "office_door", pose: [10.5, 3, 1.5707963267948966], width: 1.0, connects: ["corridor", "office"]}
segmentation:
  - {name: "water_queue", kind: "queue_lane", polygon: [[14.6, 0.1], [18.2, 0.1], [18.2, 1.1], [14.6, 1.1]]}
entities:
  - {type: "water_dispenser", name: "corridor_water_dispenser", pose: [19.6, 0.5, 3.141592653589793], affordances: ["drink", "queue_target"]}
  - {type: "desk", name: "office_desk", pose: [10.5, 6.2, 0], affordances: ["work", "sit"]}
)";

class Fig6 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { worlds_ = new testing::OfflineWorlds(); }
  static void TearDownTestSuite() {
    delete worlds_;
    worlds_ = nullptr;
  }

  static Simulated run(const world::World& w, const std::string& prompt, double seconds,
                       std::uint64_t seed = 3) {
    return testing::simulate(w, worlds_->kb(), prompt, seconds, seed);
  }

  static std::vector<std::string> used(const Simulated& r, const std::string& purpose) {
    std::vector<std::string> out;
    for (const Json& p : r.generated.provenance["places_used"])
      if (p["purpose"] == purpose) out.push_back(p["place"].get<std::string>());
    return out;
  }

  static const world::World& corridor() {
    static const world::World w = world::world_from_yaml(kCorridorYaml).value();
    return w;
  }

  static testing::OfflineWorlds* worlds_;
};
testing::OfflineWorlds* Fig6::worlds_ = nullptr;

// Standing queuers are inside the lane in distinct places along it, at most one is served at a
// time and each is served once; returns how many were served.
std::size_t expect_orderly_queue(const Simulated& r, const world::World& w, const std::string& lane) {
  crowd::BtEnvironment& env = r.runner->environment();
  const crowd::BtEnvironment::Queue* q = env.queue(lane);
  EXPECT_NE(q, nullptr) << lane;
  if (q == nullptr) return 0;
  const world::Polygon& polygon = w.roi(*w.find_roi(lane)).polygon;
  std::size_t long_lines = 0;
  for (const Frame& f : r.frames) {
    std::vector<double> along;
    int at_counter = 0;
    for (const PedestrianState& s : f.states) {
      if (s.activity == Activity::kInteracting &&
          std::hypot(s.pose.x - q->service.x, s.pose.y - q->service.y) < 0.8)
        ++at_counter;
      if (s.activity != Activity::kQueuing || speed(s) > 0.25 || !has_tag(s, "queuing")) continue;
      const double d = (s.pose.x - q->head.x) * q->to_tail.x + (s.pose.y - q->head.y) * q->to_tail.y;
      if (d < -0.3) continue;  // stepping up to be served
      along.push_back(d);
      if (d < 2.0) {
        EXPECT_TRUE(geometry::contains(polygon, {s.pose.x, s.pose.y}, 0.35))
            << "queuer at (" << s.pose.x << ", " << s.pose.y << ") outside " << lane << " at t=" << f.t;
      }
    }
    EXPECT_LE(at_counter, 1) << "t=" << f.t;
    std::sort(along.begin(), along.end());
    for (std::size_t k = 1; k < along.size(); ++k) EXPECT_GT(along[k] - along[k - 1], 0.35) << "t=" << f.t;
    if (along.size() >= 3) ++long_lines;
  }
  EXPECT_GT(long_lines, 10u) << "a line of three or more should stand in " << lane;
  std::vector<std::uint32_t> served;
  for (const auto& [name, id] : env.service_log())
    if (name == lane) served.push_back(id.value());
  EXPECT_EQ(std::set<std::uint32_t>(served.begin(), served.end()).size(), served.size()) << "served twice";
  return served.size();
}

TEST_F(Fig6, TheSameQueuePromptFormsAtTheReceptionInAHospitalAndAtTheWaterDispenserInACorridor) {
  const std::string prompt = "Eight people queue and wait their turn";
  const world::World& hospital = worlds_->plan("hospital");
  Simulated h = run(hospital, prompt, 40.0);
  ASSERT_TRUE(h.runner);
  EXPECT_EQ(h.generated.categories.front(), "queuing");
  EXPECT_THAT(used(h, "queue lane"), ::testing::ElementsAre("lobby_reception_counter_queue"));
  EXPECT_THAT(used(h, "counter"), ::testing::ElementsAre("lobby_reception_counter"));
  EXPECT_GE(expect_orderly_queue(h, hospital, "lobby_reception_counter_queue"), 3u);

  const world::World& hall = corridor();
  Simulated c = run(hall, prompt, 40.0);
  ASSERT_TRUE(c.runner);
  EXPECT_EQ(c.generated.categories.front(), "queuing");
  EXPECT_THAT(used(c, "queue lane"), ::testing::ElementsAre("water_queue"));
  EXPECT_THAT(used(c, "counter"), ::testing::ElementsAre("corridor_water_dispenser"));
  EXPECT_GE(expect_orderly_queue(c, hall, "water_queue"), 3u);
}

TEST_F(Fig6, ThePromptsPlaceIsHonouredOverTheDefaultCounter) {
  // The office plan has a reception counter and a water dispenser with a furnished lane.
  const world::World& office = worlds_->plan("office");
  ASSERT_TRUE(office.find_roi("open_office_water_dispenser_queue").has_value());
  Simulated plain = run(office, "People queue and wait their turn", 5.0);
  EXPECT_THAT(used(plain, "queue lane"), ::testing::ElementsAre("reception_reception_counter_queue"));
  Simulated water = run(office, "Eight people queue for water", 40.0);
  ASSERT_TRUE(water.runner);
  EXPECT_EQ(water.generated.categories.front(), "queuing");
  EXPECT_THAT(used(water, "queue lane"), ::testing::ElementsAre("open_office_water_dispenser_queue"));
  EXPECT_GE(expect_orderly_queue(water, office, "open_office_water_dispenser_queue"), 3u);

  // A machine without a lane: people wait by the named one instead of the reception's lane, and
  // no place outside the world is named.
  Simulated coffee = run(office, "People queue at the coffee machine", 5.0);
  EXPECT_THAT(used(coffee, "queue lane"), ::testing::IsEmpty());
  EXPECT_THAT(used(coffee, "wait by"), ::testing::ElementsAre("kitchenette_coffee_machine"));
  for (const Json& p : coffee.generated.provenance["places_used"]) {
    const std::string name = p["place"];
    const bool entity = std::any_of(office.entities().begin(), office.entities().end(),
                                    [&](const world::Entity& e) { return e.name == name; });
    EXPECT_TRUE(entity || office.find_roi(name) || office.find_zone(name) || office.find_door(name))
        << p.dump();
  }
}

TEST_F(Fig6, TheSameEvacuationUsesBothExitsOfAGeneratedPlanThatHasTwo) {
  const world::World& w = worlds_->plan("hospital");
  std::vector<const world::Door*> exits;
  for (const world::Door& d : w.doors())
    if (!d.other) exits.push_back(&d);
  ASSERT_EQ(exits.size(), 2u) << "the hospital plan needs a second exit (IBC 1006.3.3)";
  const double bound = 60.0;
  Simulated r = run(w, "Fire alarm after 2 seconds: everyone evacuates", bound);
  ASSERT_TRUE(r.runner);
  EXPECT_EQ(r.generated.categories.front(), "emergency");
  std::map<std::uint32_t, world::Point> last;
  std::set<std::uint32_t> out;
  for (const Frame& f : r.frames)
    for (const PedestrianState& s : f.states) {
      if (s.activity == Activity::kExited)
        out.insert(s.id.value());
      else
        last[s.id.value()] = {s.pose.x, s.pose.y};
    }
  ASSERT_GE(last.size(), 8u);
  EXPECT_EQ(out.size(), last.size()) << "everyone must be out within " << bound << " s";
  // Each person left by the exit nearest their last position.
  std::map<std::string, std::size_t> by_exit;
  for (const auto& [id, p] : last) {
    const world::Door* nearest = nullptr;
    double best = 1e18;
    for (const world::Door* d : exits) {
      const double dd = std::hypot(p.x - d->pose.x, p.y - d->pose.y);
      if (dd < best) {
        best = dd;
        nearest = d;
      }
    }
    EXPECT_LT(best, 2.5) << "person " << id << " last seen " << best << " m from an exit";
    ++by_exit[nearest->name];
  }
  for (const world::Door* d : exits)
    EXPECT_GE(static_cast<double>(by_exit[d->name]), 0.25 * static_cast<double>(last.size()))
        << d->name << " taken by " << by_exit[d->name] << " of " << last.size();
}

}  // namespace
}  // namespace socsim::scenario
