// Knowledge entries as JSON: lossless round trips, and every bad field reported with its pointer.
#include "core/knowledge/types.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::knowledge {
namespace {

using ::testing::Contains;
using ::testing::Field;

Json corridor_code() {
  return Json::parse(R"({
    "ref_id": "test_corridor", "building_type": "hospital", "jurisdiction": "US",
    "title": "Test corridor", "description": "A corridor rule.",
    "sources": [{"title": "Some code", "url": "https://example.org/code", "section": "1.2"}],
    "constraints": [{"name": "corridor_clear_width", "type": "min", "value": 2.438, "unit": "m",
                     "confidence": 1.0, "applies_to": "corridor", "original": "96 in"}]})");
}

Json wait_node() {
  return Json::parse(R"({
    "name": "WaitHere", "kind": "action", "origin": "socsim", "category": "activity",
    "description": "Waits.", "when_to_use": "Waiting.", "example": "<WaitHere agent_id=\"{id}\"/>",
    "aliases": ["WaitThere"],
    "ports": [{"name": "agent_id", "direction": "in", "type": "int", "default": "{id}", "description": "Agent."},
              {"name": "seconds", "direction": "in", "type": "double", "default": null, "description": "How long."}]})");
}

std::vector<std::string> pointers(const Error& e) {
  std::vector<std::string> out;
  for (const auto& f : e.errors) out.push_back(f.pointer);
  return out;
}

TEST(KnowledgeTypes, BuildingCodeRoundTripsThroughJson) {
  auto code = building_code_from_json(corridor_code());
  ASSERT_TRUE(code) << code.error().message();
  EXPECT_EQ(code->constraints.at(0).type, ConstraintType::kMin);
  EXPECT_DOUBLE_EQ(code->constraints.at(0).value, 2.438);
  EXPECT_EQ(to_json(*code), corridor_code());
}

TEST(KnowledgeTypes, BehaviorNodeRoundTripsThroughJsonWithRequiredPortAsNullDefault) {
  auto node = behavior_node_from_json(wait_node());
  ASSERT_TRUE(node) << node.error().message();
  EXPECT_EQ(node->kind, NodeKind::kAction);
  EXPECT_FALSE(node->ports.at(1).default_value.has_value());
  EXPECT_EQ(to_json(*node), wait_node());
}

TEST(KnowledgeTypes, BadBuildingCodeFieldsAreAllNamedByPointer) {
  Json j = corridor_code();
  j["building_type"] = "castle";
  j["sources"][0]["url"] = "ftp://example.org";
  j["constraints"][0]["unit"] = "ft";
  j["constraints"][0]["value"] = -1;
  j["constraints"][0]["type"] = "atleast";
  j["extra"] = 1;
  auto code = building_code_from_json(j, "/entry");
  ASSERT_FALSE(code);
  EXPECT_EQ(code.error().code, ErrorCode::kValidation);
  const auto p = pointers(code.error());
  EXPECT_THAT(p, Contains("/entry/building_type"));
  EXPECT_THAT(p, Contains("/entry/sources/0/url"));
  EXPECT_THAT(p, Contains("/entry/constraints/0/unit"));
  EXPECT_THAT(p, Contains("/entry/constraints/0/value"));
  EXPECT_THAT(p, Contains("/entry/constraints/0/type"));
  EXPECT_THAT(p, Contains("/entry/extra"));
}

TEST(KnowledgeTypes, BuildingCodeNeedsSourcesAndConstraints) {
  Json j = corridor_code();
  j["sources"] = Json::array();
  j.erase("constraints");
  auto code = building_code_from_json(j);
  ASSERT_FALSE(code);
  EXPECT_THAT(pointers(code.error()), Contains("/sources"));
  EXPECT_THAT(pointers(code.error()), Contains("/constraints"));
}

TEST(KnowledgeTypes, BadBehaviorNodeFieldsAreNamed) {
  Json j = wait_node();
  j["kind"] = "loop";
  j["name"] = "1bad name";
  j["ports"][0]["direction"] = "sideways";
  j["ports"][1]["type"] = "float";
  j["ports"][1]["name"] = "agent_id";
  auto node = behavior_node_from_json(j);
  ASSERT_FALSE(node);
  const auto p = pointers(node.error());
  EXPECT_THAT(p, Contains("/kind"));
  EXPECT_THAT(p, Contains("/name"));
  EXPECT_THAT(p, Contains("/ports/0/direction"));
  EXPECT_THAT(p, Contains("/ports/1/type"));
  EXPECT_THAT(p, Contains("/ports/1/name"));
}

TEST(KnowledgeTypes, NonObjectsAreRejected) {
  EXPECT_FALSE(building_code_from_json(Json::array()));
  EXPECT_FALSE(behavior_node_from_json(Json("JoinQueue")));
}

TEST(KnowledgeTypes, KindNamesRoundTrip) {
  EXPECT_EQ(kind_from_string(to_string(Kind::kBuildingCode)), Kind::kBuildingCode);
  EXPECT_EQ(kind_from_string(to_string(Kind::kBehaviorNode)), Kind::kBehaviorNode);
  EXPECT_FALSE(kind_from_string("activity").has_value());
  EXPECT_TRUE(is_building_type("warehouse"));
  EXPECT_FALSE(is_building_type("general"));
}

}  // namespace
}  // namespace socsim::knowledge
