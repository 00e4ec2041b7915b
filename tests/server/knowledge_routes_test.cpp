// The knowledge API over HTTP, answering the examples.
#include <gtest/gtest.h>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

using socsim::testing::get_json;

TEST(KnowledgeRoutes, PatientBedroomFindsHbn0301First) {
  testing::TestServer s;
  auto c = s.client();
  Json r = get_json(c, "/api/v1/knowledge/search?q=patient+bedroom&kind=building_code");
  const Json& hits = r["results"]["building_code"]["hits"];
  ASSERT_FALSE(hits.empty());
  EXPECT_EQ(hits[0]["provenance"]["id"], "hbn0301_patient_bedroom") << hits[0].dump();
  EXPECT_FALSE(hits[0]["provenance"]["source"].get<std::string>().empty());
}

TEST(KnowledgeRoutes, QueueAtCounterFindsTheQueueingNodes) {
  testing::TestServer s;
  auto c = s.client();
  Json r = get_json(c, "/api/v1/knowledge/search?q=queue+at+counter&kind=behavior_node&k=3");
  std::set<std::string> top;
  for (const auto& h : r["results"]["behavior_node"]["hits"])
    top.insert(h["provenance"]["id"].get<std::string>());
  EXPECT_EQ(top, (std::set<std::string>{"JoinQueue", "AdvanceQueue", "ServeAtCounter"}));
}

TEST(KnowledgeRoutes, LookupsConstraintsAndClassification) {
  testing::TestServer s;
  auto c = s.client();
  Json codes = get_json(c, "/api/v1/knowledge/building-codes?building_type=hospital");
  ASSERT_FALSE(codes["items"].empty());
  for (const auto& code : codes["items"]) {
    EXPECT_FALSE(code["sources"].empty());
    for (const auto& k : code["constraints"]) EXPECT_FALSE(k["unit"].get<std::string>().empty());
  }
  Json node = get_json(c, "/api/v1/knowledge/behavior-nodes/StopAndWaitTimerAction");
  EXPECT_EQ(node["name"], "StopAndWait");
  get_json(c, "/api/v1/knowledge/behavior-nodes/NoSuchNode", 404);
  Json cons = get_json(c, "/api/v1/knowledge/constraints?building_type=hospital");
  EXPECT_FALSE(cons["constraints"].empty());
  Json guess = get_json(c, "/api/v1/knowledge/classify?text=patients+wait+in+the+ER+waiting+room");
  EXPECT_EQ(guess["type"], "hospital");
  get_json(c, "/api/v1/knowledge/search?q=", 422);
  get_json(c, "/api/v1/knowledge/search?q=x&kind=recipes", 422);
  get_json(c, "/api/v1/knowledge/search?q=x&k=500", 422);
}

}  // namespace
}  // namespace socsim::server
