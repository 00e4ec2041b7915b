// The curated knowledge shipped in migrations 0020–0023: 50 diverse personas, an activity
// vocabulary of 100+ activities with effects whose receptacles agree with AI2-THOR's
// object–receptacle compatibility, and furniture programs for the four room types.
#include "core/household/knowledge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

std::set<std::string> words(const std::string& text) {
  std::set<std::string> out;
  std::string cur;
  for (char c : text + " ") {
    if (std::isalpha(static_cast<unsigned char>(c)))
      cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else {
      if (cur.size() > 3) out.insert(cur);
      cur.clear();
    }
  }
  return out;
}

TEST(Knowledge, ShipsFiftyDiversePersonas) {
  const auto& k = knowledge();
  ASSERT_EQ(k.personas.size(), 50u);
  std::set<std::string> ids;
  std::map<WorkPattern, int> patterns;
  int children = 0, elderly = 0, female = 0;
  for (const auto& p : k.personas) {
    ids.insert(persona_id(p));
    ++patterns[infer_traits(p).work];
    children += p.age < 18;
    elderly += p.age >= 65;
    female += p.gender == "female";
  }
  EXPECT_EQ(ids.size(), 50u);
  EXPECT_GE(children, 5);
  EXPECT_GE(elderly, 5);
  EXPECT_GE(female, 20);
  EXPECT_LE(female, 30);
  for (WorkPattern w :
       {WorkPattern::kCommute, WorkPattern::kRemote, WorkPattern::kNightShift, WorkPattern::kCollege,
        WorkPattern::kSchool, WorkPattern::kRetired, WorkPattern::kHomemaker, WorkPattern::kEveningShift})
    EXPECT_GE(patterns[w], 2) << work_pattern_name(w);
  // No near-duplicates: occupation + lifestyle of any two personas share less than 35% of their words.
  for (std::size_t i = 0; i < k.personas.size(); ++i)
    for (std::size_t j = i + 1; j < k.personas.size(); ++j) {
      const auto a = words(k.personas[i].occupation + " " + k.personas[i].lifestyle);
      const auto b = words(k.personas[j].occupation + " " + k.personas[j].lifestyle);
      std::size_t common = 0;
      for (const auto& w : a) common += b.count(w);
      const double jac = static_cast<double>(common) / static_cast<double>(a.size() + b.size() - common);
      EXPECT_LT(jac, 0.35) << k.personas[i].name << " vs " << k.personas[j].name;
    }
}

TEST(Knowledge, ActivityVocabularyIsLargeAndWellFormed) {
  const auto& k = knowledge();
  EXPECT_GE(k.activities.size(), 100u);
  std::set<std::string> names;
  int base = 0;
  for (const auto& a : k.activities) {
    EXPECT_TRUE(names.insert(a.name).second) << a.name;
    for (const auto& s : a.synonyms) EXPECT_TRUE(names.insert(s).second) << s << " is used twice";
    base += a.base;
    EXPECT_LE(a.min_minutes, a.max_minutes) << a.name;
    EXPECT_FALSE(a.windows.empty()) << a.name;
    double room_sum = 0;
    for (double w : a.effects.rooms) room_sum += w;
    if (a.role == ActivityRole::kLeaveHome) {
      EXPECT_EQ(room_sum, 0.0) << a.name;
      continue;
    }
    EXPECT_NEAR(room_sum, 1.0, 1e-9) << a.name << ": p(l|a) of the curated prior sums to 1";
    for (const auto& o : a.effects.objects) {
      EXPECT_TRUE(k.is_movable(o.type)) << a.name << " moves unknown type " << o.type;
      for (const auto& [r, w] : o.receptacles) EXPECT_NE(k.receptacle(r), nullptr) << a.name << " → " << r;
    }
  }
  EXPECT_GE(base, 20) << "the starting list is the everyday core, like HOMER's";
  EXPECT_TRUE(k.activity("leave home"));
  EXPECT_TRUE(k.activity("sleeping"));
}

// Every (object type, receptacle type) pair the priors or the furnishing tables use is allowed
// by AI2-THOR's compatible-receptacle lists (Shelf ≈ ShelvingUnit, SinkBasin ≈ Sink).
TEST(Knowledge, PriorsRespectAi2ThorCompatibility) {
  const std::string path = testing::shared_file("peers/ai2thor/ai2thor_object_types.csv");
  std::ifstream in(path);
  if (!in) GTEST_SKIP() << "peer file not present: " << path;
  std::map<std::string, std::set<std::string>> compat;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cols.push_back(c);
    if (cols.size() < 4 || cols[3].empty()) continue;
    std::stringstream rs(cols[3]);
    while (std::getline(rs, c, ';'))
      compat[cols[0]].insert(c == "Shelf" ? "ShelvingUnit" : c == "SinkBasin" ? "Sink" : c);
  }
  ASSERT_GT(compat.size(), 50u);
  const auto& k = knowledge();
  int checked = 0;
  for (const auto& a : k.activities)
    for (const auto& o : a.effects.objects) {
      auto it = compat.find(o.type);
      if (it == compat.end()) continue;  // AI2-THOR gives no list for this type
      for (const auto& [r, w] : o.receptacles) {
        EXPECT_TRUE(it->second.count(r)) << a.name << ": " << o.type << " on " << r;
        ++checked;
      }
    }
  for (const auto& r : k.receptacles)
    for (const auto& [o, w] : r.contents)
      if (auto it = compat.find(o); it != compat.end()) {
        EXPECT_TRUE(it->second.count(r.type)) << o << " kept on " << r.type;
      }
  EXPECT_GT(checked, 500);
}

TEST(Knowledge, RoomProgramsFurnishEveryRoomType) {
  const auto& k = knowledge();
  for (RoomType t : kRoomTypes) {
    const auto& prog = k.room_programs[index_of(t)];
    EXPECT_FALSE(prog.furniture.empty()) << room_type_name(t);
    EXPECT_LT(prog.min_area, prog.max_area);
    for (const auto& f : prog.furniture) {
      const auto* spec = k.receptacle(f.type);
      ASSERT_NE(spec, nullptr) << f.type;
      EXPECT_TRUE(spec->allowed_in(t)) << f.type << " in " << room_type_name(t);
    }
  }
}

TEST(Knowledge, BadActivityRowsAreRejectedWithPointers) {
  Json body = Json::parse(R"({"synonyms":[],"duration":[30,10],"windows":[[5,3]],
                              "effects":{"rooms":{"Garage":1},"objects":[{"type":"Mug","p":2,"receptacles":{}}]}})");
  auto a = activity_from_json("x", "dancing", body);
  ASSERT_FALSE(a);
  std::set<std::string> ptrs;
  for (const auto& f : a.error().errors) ptrs.insert(f.pointer);
  for (const char* p : {"/role", "/duration", "/windows/0", "/effects/rooms/Garage", "/effects/objects/0/p",
                        "/effects/objects/0/receptacles"})
    EXPECT_TRUE(ptrs.count(p)) << p;
}

TEST(Knowledge, PostedPersonasAreStoredOnceAndListed) {
  socsim::testing::TempDir dir;
  auto store = store::Store::open(dir.file("p.db"));
  ASSERT_TRUE(store);
  Persona p{"Zed Example",  30,
            "non-binary",   "Zed goes to bed at 11 pm and wakes at 7 am.",
            {"calm"},       "Zed is a librarian.",
            "Reads a lot.", "Cycles to work."};
  ASSERT_TRUE(store_persona(**store, p));
  auto again = store_persona(**store, p);
  ASSERT_FALSE(again);
  EXPECT_EQ(again.error().code, ErrorCode::kConflict);
  auto builtin_clash = store_persona(**store, knowledge().personas.front());
  ASSERT_FALSE(builtin_clash);
  auto posted = list_stored_personas(**store, false);
  ASSERT_TRUE(posted);
  ASSERT_EQ(posted->size(), 1u);
  EXPECT_EQ(posted->front(), p);
  auto k = load_household_knowledge(**store);
  ASSERT_TRUE(k);
  EXPECT_EQ(k->personas.size(), 51u);
  EXPECT_NE(k->persona("zed-example"), nullptr);
}

}  // namespace
}  // namespace socsim::household
