// KnowledgeBase over the seeded store: lookups, BM25 search with provenance, FTS-injection-safe
// queries, upserts that reindex, dense retrieval fused by RRF, and constraints_for merging.
#include "core/knowledge/knowledge_base.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tests/support/temp_dir.hpp"

namespace socsim::knowledge {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::UnorderedElementsAre;

class KnowledgeBaseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = store::Store::open(dir_.file("knowledge.db"));
    ASSERT_TRUE(s) << s.error().message();
    store_ = std::move(*s);
    kb_ = std::make_unique<KnowledgeBase>(*store_);
  }

  std::vector<std::string> ids(const SearchResult& r) const {
    std::vector<std::string> out;
    for (const auto& h : r.hits) out.push_back(h.provenance.id);
    return out;
  }

  const MergedConstraint* find(const std::vector<MergedConstraint>& all, const std::string& name,
                               ConstraintType type = ConstraintType::kMin) const {
    for (const auto& m : all)
      if (m.constraint.name == name && m.constraint.type == type) return &m;
    return nullptr;
  }

  testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<KnowledgeBase> kb_;
};

TEST_F(KnowledgeBaseTest, PatientBedroomFindsHbn0301First) {
  auto r = kb_->search("patient bedroom", Kind::kBuildingCode, 5);
  ASSERT_TRUE(r) << r.error().message();
  ASSERT_FALSE(r->hits.empty());
  const Provenance& top = r->hits.front().provenance;
  EXPECT_EQ(top.id, "hbn0301_patient_bedroom");
  EXPECT_THAT(top.source, HasSubstr("Health Building Note 03-01"));
  EXPECT_FALSE(top.section.empty());
  EXPECT_EQ(top.url.rfind("https://", 0), 0u);
  EXPECT_EQ(top.method, "bm25");
  EXPECT_EQ(r->method, "bm25");
  EXPECT_GT(top.score, 0.0);
  const auto& code = std::get<BuildingCode>(r->hits.front().entry);
  EXPECT_DOUBLE_EQ(code.constraints.at(0).value, 15.0);
}

TEST_F(KnowledgeBaseTest, QueueAtCounterFindsTheQueueingNodesFirst) {
  auto r = kb_->search("queue at counter", Kind::kBehaviorNode, 5);
  ASSERT_TRUE(r) << r.error().message();
  ASSERT_GE(r->hits.size(), 3u);
  const auto found = ids(*r);
  EXPECT_THAT(std::vector<std::string>(found.begin(), found.begin() + 3),
              UnorderedElementsAre("JoinQueue", "AdvanceQueue", "ServeAtCounter"));
  EXPECT_EQ(r->hits.front().provenance.source, "socsim behaviour-node library");
  EXPECT_EQ(r->hits.front().provenance.section, "queueing");
}

TEST_F(KnowledgeBaseTest, ScoresDescendAndKLimitsTheHits) {
  auto r = kb_->search("corridor width hospital", Kind::kBuildingCode, 3);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->hits.size(), 3u);
  for (std::size_t i = 1; i < r->hits.size(); ++i)
    EXPECT_GE(r->hits[i - 1].provenance.score, r->hits[i].provenance.score);
}

TEST_F(KnowledgeBaseTest, FtsSyntaxInUserTextIsNeutralised) {
  EXPECT_EQ(fts_match_expression("patient\" OR title:* NEAR(a b) -x"),
            "\"patient\" OR \"title\" OR \"near\" OR \"b\" OR \"x\"");
  EXPECT_EQ(fts_match_expression("at the"), "");
  const auto plain = kb_->search("patient bedroom", Kind::kBuildingCode, 5);
  for (const char* hostile : {"patient\" OR \"bedroom", "patient* bedroom^", "(patient) AND NOT bedroom:",
                              "{title description}: patient bedroom", "patient NEAR/2 bedroom \""}) {
    auto r = kb_->search(hostile, Kind::kBuildingCode, 5);
    ASSERT_TRUE(r) << hostile << ": " << r.error().message();
    ASSERT_FALSE(r->hits.empty()) << hostile;
    EXPECT_EQ(r->hits.front().provenance.id, plain->hits.front().provenance.id) << hostile;
  }
}

TEST_F(KnowledgeBaseTest, BadQueriesAreClearErrorsNamingTheParameter) {
  auto empty = kb_->search("  ?! \"\" ", Kind::kBuildingCode, 5);
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().code, ErrorCode::kBadRequest);
  EXPECT_EQ(empty.error().errors.at(0).parameter, "q");
  auto zero = kb_->search("door", Kind::kBuildingCode, 0);
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error().code, ErrorCode::kValidation);
  EXPECT_EQ(zero.error().errors.at(0).parameter, "k");
  EXPECT_FALSE(kb_->search("door", Kind::kBuildingCode, kMaxSearchResults + 1));
  auto huge = kb_->search(std::string(kMaxQueryBytes + 1, 'a'), Kind::kBehaviorNode, 5);
  ASSERT_FALSE(huge);
  EXPECT_EQ(huge.error().errors.at(0).parameter, "q");
}

TEST_F(KnowledgeBaseTest, NoMatchIsAnEmptyAnswerNotAnError) {
  auto r = kb_->search("xylophone zeppelin", Kind::kBehaviorNode, 5);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->hits.empty());
}

TEST_F(KnowledgeBaseTest, LooksUpEntriesByIdAliasAndBuildingType) {
  auto code = kb_->building_code("irc2021_r304_room_area");
  ASSERT_TRUE(code);
  EXPECT_NEAR(code->constraints.at(0).value, 6.5, 0.01);
  EXPECT_EQ(kb_->building_code("nope").error().code, ErrorCode::kNotFound);

  auto alias = kb_->behavior_node("StopAndWaitTimerAction");
  ASSERT_TRUE(alias);
  EXPECT_EQ(alias->name, "StopAndWait");
  EXPECT_EQ(kb_->behavior_node("Teleport").error().code, ErrorCode::kNotFound);

  auto hospital = kb_->building_codes("hospital");
  ASSERT_TRUE(hospital);
  EXPECT_GE(hospital->size(), 5u);
  for (const auto& c : *hospital) EXPECT_EQ(c.building_type, "hospital");
  auto bad = kb_->building_codes("castle");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().errors.at(0).parameter, "building_type");
}

TEST_F(KnowledgeBaseTest, UpsertedNodeIsSearchableAndClashingAliasesAreRefused) {
  auto node = kb_->behavior_node("WaitAt");
  ASSERT_TRUE(node);
  BehaviorNode board = *node;
  board.name = "BoardTrain";
  board.aliases = {"EnterCarriage"};
  board.description = "Steps through the train doors once the platform doors open.";
  board.keywords = "train platform railway";
  ASSERT_TRUE(kb_->upsert(board));
  auto r = kb_->search("railway platform", Kind::kBehaviorNode, 3);
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->hits.empty());
  EXPECT_EQ(r->hits.front().provenance.id, "BoardTrain");
  EXPECT_EQ(kb_->behavior_node("EnterCarriage")->name, "BoardTrain");

  BehaviorNode clash = board;
  clash.name = "Board";
  clash.aliases = {"GoTo"};
  auto refused = kb_->upsert(clash);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, ErrorCode::kConflict);
  EXPECT_EQ(kb_->behavior_node("Board").error().code, ErrorCode::kNotFound);

  BehaviorNode invalid = board;
  invalid.ports.at(0).type = "vector";
  auto rejected = kb_->upsert(invalid);
  ASSERT_FALSE(rejected);
  EXPECT_EQ(rejected.error().code, ErrorCode::kValidation);
  EXPECT_EQ(rejected.error().errors.at(0).pointer, "/ports/0/type");
}

TEST_F(KnowledgeBaseTest, UpdatedBuildingCodeIsReindexed) {
  const std::size_t before = kb_->building_codes()->size();
  auto code = kb_->building_code("aushfg_icu_room");
  ASSERT_TRUE(code);
  code->keywords += " neonatal incubator";
  ASSERT_TRUE(kb_->upsert(*code));
  auto r = kb_->search("incubator", Kind::kBuildingCode, 5);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->hits.size(), 1u);
  EXPECT_EQ(r->hits.front().provenance.id, "aushfg_icu_room");
  EXPECT_EQ(kb_->building_codes()->size(), before);  // updated in place, not duplicated
}

TEST_F(KnowledgeBaseTest, HospitalConstraintsIncludeCorridorAndDoorWidthsFromHospitalCodes) {
  auto all = kb_->constraints_for("hospital");
  ASSERT_TRUE(all) << all.error().message();
  const auto* corridor = find(*all, "corridor_clear_width");
  ASSERT_NE(corridor, nullptr);
  EXPECT_NEAR(corridor->constraint.value, 2.438, 0.001);
  EXPECT_EQ(corridor->building_type, "hospital");
  EXPECT_EQ(corridor->constraint.unit, "m");
  // The general 44-inch and 1200 mm rules were considered and overridden.
  EXPECT_THAT(corridor->also_considered, Contains("ibc2018_1020_corridor_width"));
  const auto* door = find(*all, "door_clear_width");
  ASSERT_NE(door, nullptr);
  EXPECT_NEAR(door->constraint.value, 1.054, 0.001);
  EXPECT_EQ(door->ref_id, "ibc2018_1010_door_i2");
  const auto* bedroom = find(*all, "patient_bedroom_area");
  ASSERT_NE(bedroom, nullptr);
  EXPECT_DOUBLE_EQ(bedroom->constraint.value, 15.0);  // HBN 03-01 beats FGI's 11.15 m²
  // General rules fill what hospital entries do not set.
  const auto* stair = find(*all, "stair_clear_width");
  ASSERT_NE(stair, nullptr);
  EXPECT_EQ(stair->building_type, "general");
  EXPECT_THAT(describe(*corridor), HasSubstr("at least 2.438 m"));
}

TEST_F(KnowledgeBaseTest, ResidentialUsesDwellingRulesOnlyAndMaxConstraintsTakeTheSmallest) {
  auto home = kb_->constraints_for("residential");
  ASSERT_TRUE(home);
  const auto* hallway = find(*home, "corridor_clear_width");
  ASSERT_NE(hallway, nullptr);
  EXPECT_NEAR(hallway->constraint.value, 0.914, 0.001);
  EXPECT_EQ(find(*home, "turning_circle_diameter"), nullptr);  // ADA general rule, not for dwellings
  const auto* bedroom = find(*home, "bedroom_single_area");
  ASSERT_NE(bedroom, nullptr);
  EXPECT_DOUBLE_EQ(bedroom->constraint.value, 7.5);

  auto office = kb_->constraints_for("office");
  ASSERT_TRUE(office);
  const auto* density = find(*office, "occupant_load_factor_business", ConstraintType::kMax);
  ASSERT_NE(density, nullptr);
  EXPECT_DOUBLE_EQ(density->constraint.value, 6.0);  // England's 6 m²/person is stricter than IBC's 13.9
  EXPECT_THAT(density->also_considered, Contains("ibc2018_t1004_business"));
  const auto* workspace = find(*office, "workspace_area_per_person", ConstraintType::kRecommended);
  ASSERT_NE(workspace, nullptr);
  EXPECT_DOUBLE_EQ(workspace->constraint.value, 10.0);

  auto us_office = kb_->constraints_for("office", "us");
  ASSERT_TRUE(us_office);
  const auto* us_density = find(*us_office, "occupant_load_factor_business", ConstraintType::kMax);
  ASSERT_NE(us_density, nullptr);
  EXPECT_NEAR(us_density->constraint.value, 13.935, 0.001);
  EXPECT_EQ(find(*us_office, "workspace_area_per_person", ConstraintType::kRecommended), nullptr);
}

TEST_F(KnowledgeBaseTest, EveryBuildingTypeGetsCorridorDoorAndCeilingConstraints) {
  for (std::string_view type : building_types()) {
    auto all = kb_->constraints_for(type);
    ASSERT_TRUE(all) << type;
    EXPECT_NE(find(*all, "corridor_clear_width"), nullptr) << type;
    EXPECT_NE(find(*all, "door_clear_width"), nullptr) << type;
    EXPECT_NE(find(*all, "ceiling_height"), nullptr) << type;
    for (const auto& m : *all) EXPECT_FALSE(m.sources.empty()) << type << " " << m.constraint.name;
  }
  auto bad = kb_->constraints_for("castle");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kValidation);
  EXPECT_EQ(bad.error().errors.at(0).parameter, "building_type");
}

// Dense retrieval with the real offline embedding: character trigrams survive misspellings that
// BM25's exact terms cannot match, and RRF fusion changes the ranking.
TEST_F(KnowledgeBaseTest, DenseEmbeddingsFindMisspelledQueriesAndChangeTheRanking) {
  const std::string typo = "evakuate emergensy";
  auto lexical = kb_->search(typo, Kind::kBehaviorNode, 5);
  ASSERT_TRUE(lexical);
  EXPECT_TRUE(lexical->hits.empty());  // Porter stems of the typos match no entry

  kb_->set_embedding_provider(hashed_ngram_embedding(512));
  auto fused = kb_->search(typo, Kind::kBehaviorNode, 5);
  ASSERT_TRUE(fused) << fused.error().message();
  EXPECT_EQ(fused->method, "bm25+dense");
  EXPECT_FALSE(fused->dense_error.has_value());
  ASSERT_FALSE(fused->hits.empty());
  EXPECT_EQ(fused->hits.front().provenance.id, "Evacuate");
  EXPECT_EQ(fused->hits.front().provenance.method, "dense");
  EXPECT_NE(ids(*lexical), ids(*fused));

  // The acceptance queries keep their answers under fusion.
  auto bedroom = kb_->search("patient bedroom", Kind::kBuildingCode, 5);
  ASSERT_TRUE(bedroom);
  EXPECT_EQ(bedroom->hits.front().provenance.id, "hbn0301_patient_bedroom");
  EXPECT_EQ(bedroom->hits.front().provenance.method, "bm25+dense");
  auto queue = kb_->search("queue at counter", Kind::kBehaviorNode, 5);
  ASSERT_TRUE(queue);
  const auto q = ids(*queue);
  EXPECT_THAT(std::vector<std::string>(q.begin(), q.begin() + 3),
              UnorderedElementsAre("JoinQueue", "AdvanceQueue", "ServeAtCounter"));
}

TEST_F(KnowledgeBaseTest, EmbeddingsAreStoredOnceAndRefreshedWhenAnEntryChanges) {
  kb_->set_embedding_provider(hashed_ngram_embedding(128));
  auto first = kb_->index_embeddings(Kind::kBehaviorNode);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, kb_->behavior_nodes()->size());
  EXPECT_EQ(*kb_->index_embeddings(Kind::kBehaviorNode), 0u);

  auto node = kb_->behavior_node("Wander");
  node->keywords += " meander meandering";
  ASSERT_TRUE(kb_->upsert(*node));
  // search() notices the change and re-embeds the one entry before ranking.
  auto found = kb_->search("meander", Kind::kBehaviorNode, 3);
  ASSERT_TRUE(found);
  ASSERT_FALSE(found->hits.empty());
  EXPECT_EQ(found->hits.front().provenance.id, "Wander");
  EXPECT_EQ(*kb_->index_embeddings(Kind::kBehaviorNode), 0u);

  auto rows = store_->read([](store::Database& db) -> Result<std::int64_t> {
    auto st = db.prepare(
        "SELECT count(*) FROM knowledge_embeddings WHERE model = 'socsim-hashed-ngram-v1-128' AND "
        "length(vector) = 512");
    if (!st) return tl::unexpected(st.error());
    if (auto r = st->step(); !r) return tl::unexpected(r.error());
    return st->int64(0);
  });
  ASSERT_TRUE(rows);
  EXPECT_EQ(static_cast<std::size_t>(*rows), kb_->behavior_nodes()->size());
}

TEST_F(KnowledgeBaseTest, AFailingProviderLeavesBm25ResultsAndSaysWhy) {
  EmbeddingProvider down;
  down.model = "remote-model";
  down.embed = [](const std::vector<std::string>&) -> Result<std::vector<Embedding>> {
    return fail(ErrorCode::kUpstreamTimeout, "embedding endpoint timed out");
  };
  kb_->set_embedding_provider(down);
  auto r = kb_->search("patient bedroom", Kind::kBuildingCode, 3);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->method, "bm25");
  ASSERT_TRUE(r->dense_error.has_value());
  EXPECT_EQ(r->dense_error->code, ErrorCode::kUpstreamTimeout);
  EXPECT_EQ(r->hits.front().provenance.id, "hbn0301_patient_bedroom");

  EmbeddingProvider short_answer;
  short_answer.model = "broken-model";
  short_answer.embed = [](const std::vector<std::string>&) -> Result<std::vector<Embedding>> {
    return std::vector<Embedding>{{1.0f, 0.0f}};
  };
  kb_->set_embedding_provider(short_answer);
  auto s = kb_->search("patient bedroom", Kind::kBuildingCode, 3);
  ASSERT_TRUE(s);
  ASSERT_TRUE(s->dense_error.has_value());
  EXPECT_EQ(s->dense_error->code, ErrorCode::kUpstream);
  EXPECT_THAT(to_json(*s).dump(), HasSubstr("broken-model"));
}

}  // namespace
}  // namespace socsim::knowledge
