// The catalogue over a real SQLite file: versions, search, filters, pagination, deletion by
// author, and export → import into another database.
#include "core/cards/catalogue.hpp"

#include <gtest/gtest.h>

#include <set>
#include <thread>

#include "tests/support/test_database.hpp"

namespace socsim::cards {
namespace {

CardContent content(const std::string& title, const std::string& prompt, std::vector<std::string> tags,
                    std::optional<std::string> domain = std::nullopt) {
  CardContent c;
  c.title = title;
  c.prompt = prompt;
  c.tags = std::move(tags);
  c.domain = std::move(domain);
  c.world = Json{{"zones", Json::array()}};
  return c;
}

class CatalogueTest : public ::testing::TestWithParam<testing::Backend> {
 protected:
  void SetUp() override {
    db_ = std::make_unique<testing::TestDatabase>(GetParam());
    SOCSIM_REQUIRE_DATABASE(*db_);
    auto s = store::Store::open(db_->target());
    ASSERT_TRUE(s) << s.error().message();
    store_ = std::move(*s);
    catalogue_ = std::make_unique<CardCatalogue>(*store_);
  }
  std::unique_ptr<testing::TestDatabase> db_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<CardCatalogue> catalogue_;
};

TEST_P(CatalogueTest, CreatedCardReadsBackIdentically) {
  auto c =
      catalogue_->create(content("Coffee break", "staff chat near the coffee machine", {"social"}), "alice");
  ASSERT_TRUE(c) << c.error().message();
  auto back = catalogue_->get(c->id);
  ASSERT_TRUE(back);
  EXPECT_EQ(to_json(*back), to_json(*c));
  EXPECT_EQ(back->content_hash, c->content_hash);
  EXPECT_EQ(catalogue_->get("crd_00000000000000000000").error().code, ErrorCode::kNotFound);
}

TEST_P(CatalogueTest, NewVersionPointsToItsParentAndInheritsFields) {
  auto v1 = catalogue_->create(content("Queue", "patients queue", {"queue"}, "hospital"), "alice").value();
  auto v2 = catalogue_->create_version(v1.id, Json{{"title", "Queue, longer"}}, "bob");
  ASSERT_TRUE(v2) << v2.error().message();
  EXPECT_EQ(v2->version, 2);
  EXPECT_EQ(v2->parent_id.value(), v1.id);
  EXPECT_EQ(v2->content.prompt, "patients queue");
  EXPECT_EQ(v2->content.domain.value(), "hospital");
  EXPECT_NE(v2->content_hash, v1.content_hash);
  EXPECT_EQ(catalogue_->get(v1.id)->content.title, "Queue") << "the parent must not change";
  auto bad = catalogue_->create_version(v1.id, Json{{"seed", "x"}}, "bob");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().errors.at(0).pointer, "/seed");
}

TEST_P(CatalogueTest, PageWalkVisitsEveryCardExactlyOnce) {
  std::set<std::string> ids;
  for (int i = 0; i < 23; ++i)
    ids.insert(catalogue_->create(content("Card " + std::to_string(i), "p", {}), "alice").value().id);
  std::set<std::string> seen;
  CardQuery q;
  q.page_size = 5;
  int pages = 0;
  for (;;) {
    auto page = catalogue_->list(q);
    ASSERT_TRUE(page);
    ++pages;
    for (const auto& c : page->items) EXPECT_TRUE(seen.insert(c.id).second) << "visited twice: " << c.id;
    if (!page->next_cursor) break;
    q.cursor = page->next_cursor;
  }
  EXPECT_EQ(seen, ids);
  EXPECT_EQ(pages, 5);
  q.cursor = "garbage";
  EXPECT_EQ(catalogue_->list(q).error().code, ErrorCode::kBadRequest);
}

TEST_P(CatalogueTest, SearchAndFiltersFindTheRightCards) {
  auto evac =
      catalogue_
          ->create(content("Fire drill", "everyone evacuates to the exits", {"emergency"}, "office"), "alice")
          .value();
  auto queue =
      catalogue_->create(content("Check-in", "visitors queue at the counter", {"queue"}, "hospital"), "bob")
          .value();
  catalogue_
      ->create(content("Party", "friends gather in the living room", {"social"}, "residential"), "alice")
      .value();
  auto ids = [&](CardQuery q) {
    std::vector<std::string> out;
    const CardPage page = catalogue_->list(q).value();
    for (const auto& c : page.items) out.push_back(c.id);
    return out;
  };
  CardQuery q;
  q.text = "evacuate";  // porter stemming matches "evacuates"
  EXPECT_EQ(ids(q), std::vector<std::string>{evac.id});
  q = {};
  q.text = "queue\" NEAR(*";  // FTS syntax in user text is neutralised, not an error
  EXPECT_TRUE(ids(q).empty()) << "all words must match, NEAR included";
  q.text = "counter: visitors*";  // every word must match, in any order
  EXPECT_EQ(ids(q), std::vector<std::string>{queue.id});
  q = {};
  q.tag = "queue";
  EXPECT_EQ(ids(q), std::vector<std::string>{queue.id});
  q = {};
  q.author = "alice";
  EXPECT_EQ(ids(q).size(), 2u);
  q = {};
  q.domain = "office";
  EXPECT_EQ(ids(q), std::vector<std::string>{evac.id});
}

TEST_P(CatalogueTest, OnlyTheAuthorDeletesAndSearchForgetsDeletedCards) {
  auto c = catalogue_->create(content("Mine", "unique wombat prompt", {"x"}), "alice").value();
  auto r = catalogue_->remove(c.id, "bob", false);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kForbidden);
  ASSERT_TRUE(catalogue_->remove(c.id, "alice", false));
  EXPECT_EQ(catalogue_->get(c.id).error().code, ErrorCode::kNotFound);
  CardQuery q;
  q.text = "wombat";
  EXPECT_TRUE(catalogue_->list(q).value().items.empty());
  q = {};
  q.tag = "x";
  EXPECT_TRUE(catalogue_->list(q).value().items.empty());
}

TEST_P(CatalogueTest, ExportImportIntoAnotherDatabaseKeepsHashAndBytes) {
  auto c = catalogue_->create(content("Bottleneck", "crowd squeezes through a door", {"bottleneck"}), "alice")
               .value();
  const std::string doc = catalogue_->export_card(c.id).value();
  testing::TestDatabase other_db(GetParam());
  auto other_store = store::Store::open(other_db.target()).value();
  CardCatalogue other(*other_store);
  auto imported = other.import_card(doc, "alice");
  ASSERT_TRUE(imported) << imported.error().message();
  EXPECT_TRUE(imported->created);
  EXPECT_EQ(imported->card.content_hash, c.content_hash);
  EXPECT_EQ(other.export_card(c.id).value(), doc);
  auto again = other.import_card(doc, "alice");
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->created) << "importing the same card twice is a no-op";
}

TEST_P(CatalogueTest, ImportRecordsTheImporterAsAuthorNotTheFile) {
  auto c = catalogue_->create(content("Queue", "a queue", {}), "alice").value();
  const std::string doc = catalogue_->export_card(c.id).value();
  testing::TestDatabase other_db(GetParam());
  auto other_store = store::Store::open(other_db.target()).value();
  CardCatalogue other(*other_store);
  auto imported = other.import_card(doc, "bob");
  ASSERT_TRUE(imported) << imported.error().message();
  EXPECT_EQ(imported->card.author, "bob");
  EXPECT_EQ(imported->card.content_hash, c.content_hash);
  EXPECT_EQ(other.get(c.id)->author, "bob");
}

TEST_P(CatalogueTest, ImportOfADifferentCardUnderAnExistingIdConflicts) {
  auto c = catalogue_->create(content("A", "a", {}), "alice").value();
  Card forged = c;
  forged.content.title = "B";
  forged.content_hash = content_hash(forged.content, forged.version, forged.parent_id);
  auto r = catalogue_->import_card(export_document(forged), "alice");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kConflict);
  EXPECT_EQ(catalogue_->get(c.id)->content.title, "A");
}

TEST_P(CatalogueTest, ConcurrentCreatesAreAllKept) {
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 25; ++i)
        EXPECT_TRUE(catalogue_->create(content("T" + std::to_string(t), "p", {}), "alice"));
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(catalogue_->count().value(), 100);
}

INSTANTIATE_TEST_SUITE_P(Backends, CatalogueTest,
                         ::testing::Values(testing::Backend::kSqlite, testing::Backend::kPostgres),
                         testing::backend_name);

}  // namespace
}  // namespace socsim::cards
