// Activity databases: offline ones are valid (p(l|a) and p(r|o,a,l) sum to 1, receptacles stand in
// their room), personalised by traits and seed, deterministic, and bad databases are refused
// with JSON pointers.
#include "core/household/activity_db.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

ActivityDatabase db_for(const char* id, std::uint64_t seed) {
  const Persona& p = *knowledge().persona(id);
  auto vocab = ActivityVocabulary::initial(knowledge());
  auto s = generate_schedule_offline(p, knowledge(), {5, Weekday::kWednesday, seed}, vocab);
  EXPECT_TRUE(s);
  OfflineActivityDatabaseGenerator gen(knowledge());
  auto db = gen.generate(p, primaries_of(*s), seed);
  EXPECT_TRUE(db) << db.error().message();
  return *db;
}

TEST(ActivityDb, EveryPersonasDatabaseIsValidAndSumsToOne) {
  OfflineActivityDatabaseGenerator gen(knowledge());
  for (const auto& p : knowledge().personas) {
    auto vocab = ActivityVocabulary::initial(knowledge());
    auto s = generate_schedule_offline(p, knowledge(), {}, vocab);
    ASSERT_TRUE(s);
    auto db = gen.generate(p, primaries_of(*s), 1);
    ASSERT_TRUE(db) << p.name << ": " << db.error().message();
    EXPECT_GE(db->activities.size(), 20u) << p.name;
    for (const auto& a : db->activities) {
      double sl = 0;
      for (const auto& l : a.locations) {
        sl += l.p;
        for (const auto& o : l.objects) {
          double sr = 0;
          for (const auto& [r, x] : o.receptacles) sr += x;
          EXPECT_NEAR(sr, 1.0, 1e-9) << a.activity << "/" << o.type;
          EXPECT_GT(o.p, 0.0);
          EXPECT_LT(o.p, 1.0);
        }
      }
      if (!a.locations.empty()) {
        EXPECT_NEAR(sl, 1.0, 1e-9) << a.activity;
      }
    }
    ASSERT_NE(db->find("leave home"), nullptr);
    EXPECT_TRUE(db->find("leave home")->locations.empty());
  }
}

TEST(ActivityDb, DeterministicPerSeedAndPersonal) {
  EXPECT_EQ(db_for("amara-diallo", 3), db_for("amara-diallo", 3));
  EXPECT_NE(db_for("amara-diallo", 3), db_for("amara-diallo", 4));
  // A meticulous persona puts things away more often than a messy one.
  auto storage_share = [](const ActivityDatabase& db) {
    double storage = 0, all = 0;
    for (const auto& a : db.activities)
      for (const auto& l : a.locations)
        for (const auto& o : l.objects)
          for (const auto& [r, p] : o.receptacles) {
            all += p;
            if (r == "ShelvingUnit" || r == "Dresser" || r == "Sink" || r == "Fridge" || r == "LaundryHamper")
              storage += p;
          }
    return storage / all;
  };
  EXPECT_GT(storage_share(db_for("sakura-ito", 1)), storage_share(db_for("mateo-alvarez", 1)) + 0.02);
}

TEST(ActivityDb, JsonRoundTripAndPointedErrors) {
  const auto db = db_for("helen-park", 9);
  auto back = activity_db_from_json(to_json(db), knowledge());
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back->activities.size(), db.activities.size());
  Json bad = to_json(db);
  Json& loc = bad["activities"][1]["locations"][0];
  loc["p"] = 0.9;  // p(l|a) no longer sums to 1 (unless alone; we add a second below)
  loc["objects"] =
      Json::array({{{"type", "Mug"}, {"p", 0.5}, {"receptacles", {{"Fridge", 0.5}, {"Bed", 0.2}}}},
                   {{"type", "Spaceship"}, {"p", 0.5}, {"receptacles", {{"Desk", 1.0}}}}});
  loc["room"] = "Kitchen";
  bad["activities"][1]["locations"].push_back({{"room", "Garage"}, {"p", 0.5}, {"objects", Json::array()}});
  auto r = activity_db_from_json(bad, knowledge());
  ASSERT_FALSE(r);
  std::set<std::string> ptrs;
  for (const auto& f : r.error().errors) ptrs.insert(f.pointer);
  EXPECT_TRUE(ptrs.count("/activities/1/locations/1/room")) << "unknown room type";
  // Fix the room and look at the sums and types.
  bad["activities"][1]["locations"].erase(1);
  r = activity_db_from_json(bad, knowledge());
  ASSERT_FALSE(r);
  ptrs.clear();
  for (const auto& f : r.error().errors) ptrs.insert(f.pointer);
  EXPECT_TRUE(ptrs.count("/activities/1/locations")) << "p(l|a) must sum to 1";
  EXPECT_TRUE(ptrs.count("/activities/1/locations/0/objects/0/receptacles")) << "p(r|o,a,l) must sum to 1";
  EXPECT_TRUE(ptrs.count("/activities/1/locations/0/objects/0/receptacles/0"))
      << "a bed does not stand in a kitchen";
  EXPECT_TRUE(ptrs.count("/activities/1/locations/0/objects/1/type"));
}

}  // namespace
}  // namespace socsim::household
