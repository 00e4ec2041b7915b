// The world document (JSON form for the REST API): round trip World → JSON → World, errors as
// JSON pointers, and agreement with schemas/world.schema.json.
#include "core/world/world_document.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/json_schema.hpp"
#include "core/world/yaml_reader.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using testing::example;
using ::testing::HasSubstr;

JsonSchema world_schema() {
  auto text = testing::read_text(std::string(SOCSIM_SOURCE_DIR) + "/schemas/world.schema.json");
  auto json = parse_json_untrusted(text);
  EXPECT_TRUE(json) << json.error().message();
  auto schema = JsonSchema::compile(*json);
  EXPECT_TRUE(schema) << schema.error().message();
  return *schema;
}

TEST(WorldDocument, JsonRoundTripGivesTheSameWorld) {
  const World w = testing::load(example("world_clinic.yaml"));
  const Json doc = world_to_document(w);
  auto again = world_from_document(parse_json_untrusted(doc.dump()).value());
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_EQ(*again, w);
  EXPECT_EQ(canonical_json(world_to_document(*again)), canonical_json(doc));
}

TEST(WorldDocument, YamlAndJsonOfTheSameDocumentBuildTheSameWorld) {
  auto yaml = parse_yaml_untrusted(example("world_fig3.yaml"));
  ASSERT_TRUE(yaml);
  auto from_json = world_from_document(parse_json_untrusted(yaml->dump()).value());
  ASSERT_TRUE(from_json);
  EXPECT_EQ(*from_json, testing::load(example("world_fig3.yaml")));
}

TEST(WorldDocument, ErrorsArePointersIntoTheBody) {
  const Json doc = {{"zones", Json::array({{{"name", "a"}, {"polygon", {{0, 0}, {1, 0}}}}})},
                    {"doors", Json::array({{{"name", "d"}, {"pose", {1, "x"}}, {"width", 1}}})},
                    {"colour", "red"}};
  auto w = world_from_document(doc);
  ASSERT_FALSE(w);
  std::vector<std::string> pointers;
  for (const auto& fe : w.error().errors) pointers.push_back(fe.pointer);
  EXPECT_THAT(pointers, ::testing::UnorderedElementsAre("/colour", "/zones/0/polygon", "/doors/0/pose/1"));
}

TEST(WorldDocument, RoiKindIsInferredFromKnownNames) {
  EXPECT_EQ(infer_roi_kind("queue_lane"), "queue_lane");
  EXPECT_EQ(infer_roi_kind("queue_lane_2"), "queue_lane");
  EXPECT_EQ(infer_roi_kind("seating_area"), "seating_area");
  EXPECT_EQ(infer_roi_kind("bar"), "area");
  EXPECT_EQ(infer_roi_kind("corridor_b"), "area");
}

TEST(WorldDocument, ExamplesAndWrittenDocumentsConformToTheSchema) {
  const JsonSchema schema = world_schema();
  for (const char* name : {"world_fig3.yaml", "world_clinic.yaml"}) {
    auto doc = parse_yaml_untrusted(example(name));
    ASSERT_TRUE(doc);
    EXPECT_TRUE(schema.check(*doc, name)) << schema.check(*doc, name).error().message();
    const Json written = world_to_document(testing::load(example(name)));
    EXPECT_TRUE(schema.check(written, name)) << schema.check(written, name).error().message();
  }
  const Json generated = world_to_document(testing::row_of_rooms(10).build().value());
  EXPECT_TRUE(schema.check(generated, "generated"));
}

TEST(WorldDocument, SchemaRejectsWhatTheReaderRejects) {
  const JsonSchema schema = world_schema();
  const Json base = parse_yaml_untrusted(testing::kTwoRooms).value();
  auto rejected_by_both = [&](Json doc, const std::string& pointer) {
    const auto errors = schema.validate(doc);
    bool found = false;
    for (const auto& e : errors) found = found || e.pointer.rfind(pointer, 0) == 0;
    EXPECT_TRUE(found) << "schema misses " << pointer << " in " << doc.dump();
    EXPECT_FALSE(builder_from_document(doc)) << pointer;
  };
  Json unknown = base;
  unknown["zones"][0]["colour"] = "red";
  rejected_by_both(unknown, "/zones/0");
  // A zone by name only (paper 001, Fig. 3) is a valid document; the builder infers its region.
  Json no_polygon = base;
  no_polygon["zones"][1].erase("polygon");
  EXPECT_TRUE(schema.validate(no_polygon).empty());
  EXPECT_TRUE(builder_from_document(no_polygon));
  Json no_name = base;
  no_name["zones"][1].erase("name");
  rejected_by_both(no_name, "/zones/1");
  Json bad_width = base;
  bad_width["doors"][0]["width"] = "wide";
  rejected_by_both(bad_width, "/doors/0/width");
  Json bad_kind = base;
  bad_kind["segmentation"] =
      Json::array({{{"name", "r"}, {"kind", "ballroom"}, {"polygon", {{1, 1}, {2, 1}, {2, 2}}}}});
  EXPECT_FALSE(schema.validate(bad_kind).empty());
  EXPECT_FALSE(world_from_document(bad_kind));
}

}  // namespace
}  // namespace socsim::world
