// Dynamic scenes: residents get their own bedroom (and bathroom when there are enough), events
// move objects only onto receptacles of the event's room, P(o, t) from the index agrees with
// replaying the events, the same request gives bit-identical events, and hints come from the
// resident's own recent events.
#include "core/household/scene.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "core/household/procthor.hpp"
#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

const std::vector<std::shared_ptr<const ResidentProfile>>& pool() {
  static const auto p = [] {
    std::vector<std::shared_ptr<const ResidentProfile>> out;
    auto vocab = ActivityVocabulary::initial(knowledge());
    for (const char* id : {"grace-whitfield", "tobias-brenner", "aiyana-redcloud", "ben-okafor",
                           "rosa-bianchi", "kofi-mensah"}) {
      auto r =
          make_resident_offline(*knowledge().persona(id), knowledge(), {5, Weekday::kWednesday, 21}, vocab);
      if (!r) throw std::runtime_error(r.error().message());
      out.push_back(std::make_shared<const ResidentProfile>(std::move(*r)));
    }
    return out;
  }();
  return p;
}

DynamicScene scene(int rooms, int residents, std::uint64_t seed) {
  auto h = generate_house({rooms, std::nullopt, seed}, knowledge());
  EXPECT_TRUE(h);
  auto s =
      configure_scene(std::make_shared<const House>(std::move(*h)), pool(), {residents, seed}, knowledge());
  EXPECT_TRUE(s) << s.error().message();
  return std::move(*s);
}

TEST(Scene, ResidentsGetTheirOwnBedroomAndBathroomsWhenThereAreEnough) {
  const auto s = scene(9, 3, 2);
  ASSERT_EQ(s.residents().size(), 3u);
  std::set<int> beds, baths;
  for (const auto& r : s.residents()) {
    ASSERT_GE(r.bedroom, 0);
    EXPECT_EQ(s.house().rooms[static_cast<std::size_t>(r.bedroom)].type, RoomType::kBedroom);
    beds.insert(r.bedroom);
    baths.insert(r.bathroom);
  }
  EXPECT_EQ(beds.size(), 3u);
  EXPECT_EQ(baths.size(), std::min<std::size_t>(3, s.house().rooms_of(RoomType::kBathroom).size()));
  for (const auto& e : s.events()) {
    if (e.room < 0) continue;
    const Room& room = s.house().rooms[static_cast<std::size_t>(e.room)];
    if (room.type == RoomType::kBedroom) {
      EXPECT_EQ(e.room, s.residents()[static_cast<std::size_t>(e.resident)].bedroom);
    }
    if (room.type == RoomType::kBathroom) {
      EXPECT_EQ(e.room, s.residents()[static_cast<std::size_t>(e.resident)].bathroom);
    }
  }
}

TEST(Scene, TooManyResidentsForTheBedroomsIsRefused) {
  auto h = generate_house({4, std::nullopt, 1}, knowledge());
  auto s = configure_scene(std::make_shared<const House>(std::move(*h)), pool(), {3, 1}, knowledge());
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().errors.at(0).pointer, "/residents");
}

TEST(Scene, ObjectsMoveOntoReceptaclesOfTheEventsRoom) {
  const auto s = scene(7, 2, 5);
  EXPECT_GT(s.relocations().size(), 100u);
  for (const auto& r : s.relocations()) {
    const SceneEvent& e = s.events()[static_cast<std::size_t>(r.event)];
    const Entity& to = s.house().entities[static_cast<std::size_t>(r.to)];
    EXPECT_EQ(to.room, e.room);
    EXPECT_EQ(to.kind, EntityKind::kReceptacle);
    EXPECT_EQ(r.time, e.end);
    EXPECT_NE(r.from, r.to);
    const auto& prior =
        *s.residents()[static_cast<std::size_t>(e.resident)].profile->activity_db.find(s.entry(e).primary);
    bool allowed = false;
    for (const auto& l : prior.locations)
      for (const auto& o : l.objects)
        if (o.type ==
            s.house()
                .entities[static_cast<std::size_t>(s.house().objects[static_cast<std::size_t>(r.object)])]
                .type)
          for (const auto& [rt, p] : o.receptacles) allowed |= rt == to.type && p > 0;
    EXPECT_TRUE(allowed);
  }
  for (const auto& e : s.events())
    if (s.entry(e).role == ActivityRole::kLeaveHome) {
      EXPECT_EQ(e.relocation_count, 0u);
    }
}

TEST(Scene, IndexedPlacementAgreesWithReplayingTheEvents) {
  const auto s = scene(8, 3, 11);
  std::vector<int> replay(s.house().objects.size());
  for (std::size_t o = 0; o < replay.size(); ++o)
    replay[o] = s.house().entities[static_cast<std::size_t>(s.house().objects[o])].parent;
  std::size_t next = 0;
  for (Seconds t = 0; t <= s.end(); t += 1800) {
    while (next < s.relocations().size() && s.relocations()[next].time <= t) {
      const auto& r = s.relocations()[next++];
      EXPECT_EQ(replay[static_cast<std::size_t>(r.object)], r.from) << "relocations chain";
      replay[static_cast<std::size_t>(r.object)] = r.to;
    }
    ASSERT_EQ(s.placement_at(t), replay) << "t = " << t;
  }
  // Exactly at a relocation's time the object is already there; a second before it is not.
  const auto& r = s.relocations()[s.relocations().size() / 2];
  EXPECT_EQ(s.receptacle_at(r.object, r.time), r.to);
  EXPECT_EQ(s.receptacle_at(r.object, r.time - 1), r.from);
  const auto window = s.relocations_between(kSecondsPerDay, 2 * kSecondsPerDay);
  for (const auto& x : window) EXPECT_TRUE(x.time >= kSecondsPerDay && x.time < 2 * kSecondsPerDay);
  std::size_t count = 0;
  for (const auto& x : s.relocations()) count += x.time >= kSecondsPerDay && x.time < 2 * kSecondsPerDay;
  EXPECT_EQ(window.size(), count);
}

TEST(Scene, SameRequestSameEventsBitForBit) {
  const auto a = scene(6, 2, 99).to_json().dump();
  const auto b = scene(6, 2, 99).to_json().dump();
  EXPECT_EQ(a, b);
  EXPECT_NE(a, scene(6, 2, 100).to_json().dump());
}

TEST(Scene, EventsOfAResidentAndInAWindow) {
  const auto s = scene(8, 2, 3);
  for (int r = 0; r < 2; ++r) {
    Seconds last_end = 0;
    for (int e : s.events_of(r)) {
      const auto& ev = s.events()[static_cast<std::size_t>(e)];
      EXPECT_EQ(ev.resident, r);
      EXPECT_EQ(ev.start, last_end) << "a resident's events tile the span";
      last_end = ev.end;
    }
    EXPECT_EQ(last_end, s.end());
  }
  for (int e : s.events_between(36000, 39600)) {
    const auto& ev = s.events()[static_cast<std::size_t>(e)];
    EXPECT_TRUE(ev.start < 39600 && ev.end > 36000);
  }
}

TEST(Scene, HintsComeFromTheResidentsOwnRecentEvents) {
  const auto s = scene(7, 2, 8);
  // Just after moving an object, the resident mostly remembers using it (HintStyle::recall).
  int asked = 0, used = 0;
  for (const auto& r : s.relocations()) {
    const auto& e = s.events()[static_cast<std::size_t>(r.event)];
    const auto& type =
        s.house()
            .entities[static_cast<std::size_t>(s.house().objects[static_cast<std::size_t>(r.object)])]
            .type;
    const Hint h = s.hint(e.resident, type, r.time + 60);
    EXPECT_NE(h.text.find(object_words(type)), std::string::npos) << h.text;
    if (h.used) {
      ++used;
      EXPECT_EQ(s.events()[static_cast<std::size_t>(h.event)].resident, e.resident);
      EXPECT_LE(h.when, r.time + 60);
    }
    if (++asked > 40) break;
  }
  EXPECT_GE(used * 10, asked * 7) << used << " of " << asked;
  const Hint none = s.hint(0, "TennisRacket", 3600);
  EXPECT_FALSE(none.used);
  EXPECT_NE(none.text.find("tennis racket"), std::string::npos);
  OfflineHintGenerator gen;
  EXPECT_FALSE(gen.hint({&s, 7, "Mug", 0, 3600}));
}

TEST(Scene, ConfiguresRealProcThorHouses) {
  std::ifstream in(testing::shared_file("peers/procthor/quinlan_hallway_houses_3.json"));
  if (!in) GTEST_SKIP() << "peer house not present";
  std::stringstream ss;
  ss << in.rdbuf();
  auto h = import_procthor(*parse_json_untrusted(ss.str()), knowledge());
  ASSERT_TRUE(h);
  auto s = configure_scene(std::make_shared<const House>(std::move(*h)), pool(), {3, 4}, knowledge());
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_GT(s->relocations().size(), 50u);
  auto exported = import_procthor(export_procthor(s->house(), nullptr), knowledge());
  ASSERT_TRUE(exported);
  const auto at_noon = s->placement_at(2 * kSecondsPerDay + 12 * 3600);
  auto moved = import_procthor(export_procthor(s->house(), &at_noon), knowledge());
  ASSERT_TRUE(moved);
  EXPECT_EQ(moved->objects.size(), s->house().objects.size());
}

}  // namespace
}  // namespace socsim::household
