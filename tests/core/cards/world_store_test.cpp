// Stored worlds over a real SQLite file: what is added reads back identically, pages go newest
// first without repeats, the domain filter holds, and a missing id is kNotFound.
#include "core/cards/world_store.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tests/support/test_database.hpp"

namespace socsim::cards {
namespace {

StoredWorld world(const std::string& name, const std::string& domain) {
  StoredWorld w;
  w.name = name;
  w.domain = domain;
  w.generator = "offline";
  w.seed = 7;
  w.author = "tester";
  w.request = Json{{"prompt", "a " + domain}};
  w.scene_graph = Json{{"rooms", Json::array()}};
  w.world_yaml = "name: " + name + "\n";
  w.compliance = Json{{"passed", true}};
  w.provenance = Json{{"layout_family", "corridor_with_rooms"}};
  return w;
}

class WorldStoreTest : public ::testing::TestWithParam<testing::Backend> {
 protected:
  void SetUp() override {
    db_ = std::make_unique<testing::TestDatabase>(GetParam());
    SOCSIM_REQUIRE_DATABASE(*db_);
    auto s = store::Store::open(db_->target());
    ASSERT_TRUE(s) << s.error().message();
    store_ = std::move(*s);
  }
  std::unique_ptr<testing::TestDatabase> db_;
  std::unique_ptr<store::Store> store_;
};

TEST_P(WorldStoreTest, AddedWorldReadsBackIdentically) {
  WorldStore worlds(*store_);
  auto added = worlds.add(world("clinic_a", "clinic"));
  ASSERT_TRUE(added) << added.error().message();
  EXPECT_EQ(added->id.rfind("wld_", 0), 0u);
  EXPECT_EQ(added->content_hash.size(), 64u);
  EXPECT_FALSE(added->created_at.empty());
  auto got = worlds.get(added->id);
  ASSERT_TRUE(got) << got.error().message();
  EXPECT_EQ(got->name, "clinic_a");
  EXPECT_EQ(got->domain, "clinic");
  EXPECT_EQ(got->seed, 7);
  EXPECT_EQ(got->world_yaml, "name: clinic_a\n");
  EXPECT_EQ(got->request, added->request);
  EXPECT_EQ(got->provenance, added->provenance);
  EXPECT_EQ(got->content_hash, added->content_hash);
}

TEST_P(WorldStoreTest, MissingWorldIsNotFoundNamingTheId) {
  auto got = WorldStore(*store_).get("wld_00000000000000000000");
  ASSERT_FALSE(got);
  EXPECT_EQ(got.error().code, ErrorCode::kNotFound);
  EXPECT_NE(got.error().detail.find("wld_00000000000000000000"), std::string::npos);
}

TEST_P(WorldStoreTest, PagesAreNewestFirstWithoutRepeatsAndFilterByDomain) {
  WorldStore worlds(*store_);
  std::vector<std::string> ids;
  for (int i = 0; i < 7; ++i) {
    auto w = worlds.add(world("w" + std::to_string(i), i % 2 == 0 ? "office" : "clinic"));
    ASSERT_TRUE(w);
    ids.push_back(w->id);
  }
  std::vector<std::string> seen;
  std::optional<std::int64_t> before;
  int pages = 0;
  do {
    auto page = worlds.list(3, before, std::nullopt);
    ASSERT_TRUE(page) << page.error().message();
    for (const auto& w : page->items) seen.push_back(w.id);
    before = page->next_before;
    ++pages;
  } while (before && pages < 10);
  EXPECT_EQ(pages, 3);
  ASSERT_EQ(seen.size(), ids.size());
  EXPECT_TRUE(std::equal(seen.begin(), seen.end(), ids.rbegin()));

  auto offices = worlds.list(20, std::nullopt, std::string("office"));
  ASSERT_TRUE(offices);
  EXPECT_EQ(offices->items.size(), 4u);
  EXPECT_FALSE(offices->next_before);
  for (const auto& w : offices->items) EXPECT_EQ(w.domain, "office");
}

INSTANTIATE_TEST_SUITE_P(Backends, WorldStoreTest,
                         ::testing::Values(testing::Backend::kSqlite, testing::Backend::kPostgres),
                         testing::backend_name);

}  // namespace
}  // namespace socsim::cards
