// JsonSchema: compiling our schema subset and reporting every violation with its JSON pointer.
#include "core/common/json_schema.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

// A floor-plan-like schema exercising most keywords at once.
const Json kRoomsSchema = Json::parse(R"({
  "$schema": "https://json-schema.org/draft/2020-12/schema",
  "title": "rooms",
  "type": "object",
  "required": ["rooms"],
  "additionalProperties": false,
  "properties": {
    "rooms": {"type": "array", "minItems": 1, "maxItems": 3, "items": {"$ref": "#/$defs/room"}},
    "note": {"type": ["string", "null"], "maxLength": 5}
  },
  "$defs": {
    "point": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2},
    "room": {
      "type": "object",
      "required": ["name", "kind", "area_m2", "polygon"],
      "additionalProperties": false,
      "properties": {
        "name": {"type": "string", "pattern": "^[a-z][a-z0-9_]*$", "description": "snake case"},
        "kind": {"enum": ["bedroom", "kitchen", "corridor"]},
        "area_m2": {"type": "number", "exclusiveMinimum": 0, "maximum": 500},
        "doors": {"type": "integer", "minimum": 0},
        "polygon": {"type": "array", "minItems": 3, "items": {"$ref": "#/$defs/point"}}
      }
    }
  }
})");

JsonSchema compile(const Json& schema) {
  auto s = JsonSchema::compile(schema);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().message());
  return *s;
}

std::vector<std::string> pointers(const std::vector<FieldError>& errors) {
  std::vector<std::string> out;
  for (const auto& e : errors) out.push_back(e.pointer);
  return out;
}

std::string message_at(const std::vector<FieldError>& errors, const std::string& pointer) {
  for (const auto& e : errors)
    if (e.pointer == pointer) return e.message;
  return "<no error at " + pointer + ">";
}

TEST(JsonSchema, AcceptsAConformingDocument) {
  const auto s = compile(kRoomsSchema);
  const Json ok = Json::parse(R"({"rooms": [{"name": "bed_1", "kind": "bedroom", "area_m2": 11.5, "doors": 1,
      "polygon": [[0,0],[3,0],[3,3.5]]}], "note": null})");
  EXPECT_TRUE(s.validate(ok).empty());
  EXPECT_TRUE(s.check(ok, "floor plan").has_value());
}

TEST(JsonSchema, ReportsEveryViolationWithItsPointer) {
  const auto s = compile(kRoomsSchema);
  const Json bad = Json::parse(R"({"rooms": [
      {"name": "Bed 1", "kind": "garage", "area_m2": 0, "doors": 1.5, "polygon": [[0,0],[1,"x"]], "colour": "red"},
      {"kind": "kitchen", "area_m2": 9, "polygon": [[0,0],[1,0],[1,1]]}],
      "note": "far too long", "extra": 1})");
  const auto errors = s.validate(bad);
  const auto p = pointers(errors);
  EXPECT_THAT(p, Contains("/rooms/0/name"));
  EXPECT_THAT(message_at(errors, "/rooms/0/name"), HasSubstr("pattern"));
  EXPECT_THAT(message_at(errors, "/rooms/0/kind"), HasSubstr("must be one of"));
  EXPECT_THAT(message_at(errors, "/rooms/0/area_m2"), HasSubstr("must be > 0"));
  EXPECT_THAT(message_at(errors, "/rooms/0/doors"), HasSubstr("type integer"));
  EXPECT_THAT(message_at(errors, "/rooms/0/polygon"), HasSubstr("at least 3 items"));
  EXPECT_THAT(message_at(errors, "/rooms/0/polygon/1/1"), HasSubstr("type number, got string"));
  EXPECT_THAT(message_at(errors, "/rooms/0/colour"), HasSubstr("not an allowed property"));
  EXPECT_THAT(message_at(errors, "/rooms/0/colour"),
              HasSubstr("allowed: area_m2, doors, kind, name, polygon"));
  EXPECT_THAT(message_at(errors, "/rooms/1/name"), HasSubstr("is required"));
  EXPECT_THAT(message_at(errors, "/note"), HasSubstr("at most 5 characters"));
  EXPECT_THAT(p, Contains("/extra"));
  EXPECT_EQ(errors.size(), 10u);

  const auto status = s.check(bad, "floor plan");
  ASSERT_FALSE(status.has_value());
  EXPECT_EQ(status.error().code, ErrorCode::kValidation);
  EXPECT_THAT(status.error().detail,
              HasSubstr("floor plan does not match its schema: /extra is not an allowed property"));
  EXPECT_EQ(status.error().errors.size(), errors.size());
}

TEST(JsonSchema, IntegerAcceptsWholeFloatsAndEnumComparesNumbersByValue) {
  const auto s = compile(Json::parse(R"({"type": "integer", "enum": [1, 2, 3]})"));
  EXPECT_TRUE(s.validate(Json::parse("2.0")).empty());
  EXPECT_FALSE(s.validate(Json::parse("2.5")).empty());
  EXPECT_FALSE(s.validate(Json::parse("4")).empty());
}

TEST(JsonSchema, PointerTokensAreEscaped) {
  const auto s = compile(Json::parse(R"({"type": "object", "additionalProperties": {"type": "number"}})"));
  const auto errors = s.validate(Json::parse(R"({"a/b~c": "x"})"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pointer, "/a~1b~0c");
}

TEST(JsonSchema, LengthsCountCodePointsNotBytes) {
  const auto s = compile(Json::parse(R"({"type": "string", "minLength": 3, "maxLength": 3})"));
  EXPECT_TRUE(s.validate(Json("äöü")).empty());  // 6 bytes, 3 characters
  EXPECT_FALSE(s.validate(Json("ab")).empty());
}

TEST(JsonSchema, ConstUniqueItemsMultipleOfAndPropertyCounts) {
  const auto s = compile(Json::parse(R"({"type": "object",
      "properties": {"v": {"const": "v1"}, "tags": {"type": "array", "uniqueItems": true},
                     "step": {"multipleOf": 0.05}, "n": {"multipleOf": 3}},
      "minProperties": 1, "maxProperties": 3})"));
  EXPECT_TRUE(s.validate(Json::parse(R"({"v": "v1", "step": 0.35, "n": 9})")).empty());
  const auto errors =
      s.validate(Json::parse(R"({"v": "v2", "tags": ["a", "b", "a"], "step": 0.33, "n": 10})"));
  EXPECT_THAT(message_at(errors, "/v"), HasSubstr("must be \"v1\""));
  EXPECT_THAT(message_at(errors, "/tags"), HasSubstr("items 0 and 2 are equal"));
  EXPECT_THAT(message_at(errors, "/step"), HasSubstr("multiple of 0.05"));
  EXPECT_THAT(message_at(errors, "/n"), HasSubstr("multiple of 3"));
  EXPECT_THAT(message_at(errors, ""), HasSubstr("at most 3 properties"));
  EXPECT_THAT(pointers(s.validate(Json::object())), Contains(""));
}

TEST(JsonSchema, OneOfQuotesTheClosestAlternative) {
  const auto s = compile(Json::parse(R"({"oneOf": [
      {"type": "object", "required": ["kind", "radius"], "properties": {"kind": {"const": "circle"}, "radius": {"type": "number"}}},
      {"type": "object", "required": ["kind", "w", "h"], "properties": {"kind": {"const": "rect"}, "w": {"type": "number"}, "h": {"type": "number"}}}
  ]})"));
  EXPECT_TRUE(s.validate(Json::parse(R"({"kind": "circle", "radius": 1})")).empty());
  const auto errors = s.validate(Json::parse(R"({"kind": "rect", "w": 1})"));
  EXPECT_THAT(message_at(errors, ""), HasSubstr("none of the 2 alternatives of oneOf"));
  EXPECT_THAT(message_at(errors, "/h"), HasSubstr("is required"));
  EXPECT_EQ(errors.size(), 2u);  // the circle alternative's problems are not quoted

  const auto both = compile(Json::parse(R"({"oneOf": [{"type": "number"}, {"minimum": 0}]})"));
  EXPECT_THAT(message_at(both.validate(Json(5)), ""), HasSubstr("exactly one must match"));
  EXPECT_TRUE(both.validate(Json(-1)).empty());
}

TEST(JsonSchema, AnyOfAllOfNotAndBooleanSchemas) {
  const auto s = compile(Json::parse(R"({"allOf": [{"type": "number"}, {"maximum": 10}],
      "anyOf": [{"minimum": 5}, {"maximum": 1}], "not": {"const": 7}})"));
  EXPECT_TRUE(s.validate(Json(6)).empty());
  EXPECT_TRUE(s.validate(Json(0)).empty());
  EXPECT_THAT(message_at(s.validate(Json(3)), ""), HasSubstr("none of the 2 alternatives of anyOf"));
  EXPECT_THAT(message_at(s.validate(Json(7)), ""), HasSubstr("must not match"));
  EXPECT_THAT(message_at(s.validate(Json(11)), ""), HasSubstr("must be <= 10"));
  EXPECT_FALSE(compile(Json(false)).validate(Json(1)).empty());
  EXPECT_TRUE(compile(Json(true)).validate(Json(1)).empty());
}

TEST(JsonSchema, RecursiveRefsFollowTheInstance) {
  const auto s = compile(Json::parse(R"({"$ref": "#/$defs/node", "$defs": {"node": {"type": "object",
      "required": ["name"], "properties": {"name": {"type": "string"}, "children": {"type": "array", "items": {"$ref": "#/$defs/node"}}}}}})"));
  EXPECT_TRUE(
      s.validate(Json::parse(R"({"name": "root", "children": [{"name": "a", "children": [{"name": "b"}]}]})"))
          .empty());
  const auto errors =
      s.validate(Json::parse(R"({"name": "root", "children": [{"children": [{"name": 3}]}]})"));
  EXPECT_THAT(pointers(errors), ::testing::ElementsAre("/children/0/name", "/children/0/children/0/name"));
}

TEST(JsonSchema, ARefCycleThatConsumesNothingIsReportedNotFollowedForever) {
  const auto s = compile(Json::parse(R"({"$ref": "#/$defs/a", "$defs": {"a": {"$ref": "#/$defs/a"}}})"));
  const auto errors = s.validate(Json(1));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_THAT(errors[0].message, HasSubstr("recursion deeper"));
}

TEST(JsonSchema, PatternSubjectsTooLongToCheckSafelyAreReported) {
  const auto s = compile(Json::parse(R"({"type": "string", "pattern": "^(a|b)*$"})"));
  EXPECT_TRUE(s.validate(Json(std::string(1000, 'a'))).empty());
  const auto errors = s.validate(Json(std::string(100000, 'a')));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_THAT(errors[0].message, HasSubstr("too long"));
}

TEST(JsonSchema, ErrorCountIsCapped) {
  const auto s = compile(Json::parse(R"({"type": "array", "items": {"type": "string"}})"));
  const auto errors = s.validate(Json(std::vector<int>(500, 1)), 10);
  ASSERT_EQ(errors.size(), 11u);
  EXPECT_THAT(errors.back().message, HasSubstr("490 more"));
}

TEST(JsonSchema, BadSchemasAreRefusedWithPointersIntoTheSchema) {
  const auto refused = [](const char* text) {
    auto s = JsonSchema::compile(Json::parse(text));
    EXPECT_FALSE(s.has_value()) << text;
    return s ? std::vector<FieldError>{FieldError{"<accepted>", "<accepted>"}} : s.error().errors;
  };
  EXPECT_EQ(refused(R"({"type": "text"})")[0].pointer, "/type");
  EXPECT_EQ(refused(R"({"properties": {"a": {"$ref": "#/$defs/missing"}}})")[0].pointer,
            "/properties/a/$ref");
  EXPECT_THAT(refused(R"({"pattern": "([a-z"})")[0].message, HasSubstr("invalid regular expression"));
  EXPECT_THAT(refused(R"({"prefixItems": [{"type": "number"}]})")[0].message, HasSubstr("not supported"));
  EXPECT_THAT(refused(R"({"if": {"type": "number"}, "then": {"minimum": 0}})")[0].message,
              HasSubstr("not supported"));
  EXPECT_EQ(refused(R"({"minItems": -1})")[0].pointer, "/minItems");
  EXPECT_EQ(refused(R"({"anyOf": []})")[0].pointer, "/anyOf");
  EXPECT_EQ(refused(R"({"items": 3})")[0].pointer, "/items");
  EXPECT_EQ(refused(R"({"required": "name"})")[0].pointer, "/required");
  EXPECT_EQ(refused(R"({"$ref": "http://example.com/schema"})")[0].pointer, "/$ref");
}

TEST(JsonSchema, UnknownExtensionKeywordsAndAnnotationsAreIgnored) {
  const auto s = compile(
      Json::parse(R"({"type": "string", "format": "email", "x-socsim": {"ui": 1}, "examples": ["a"]})"));
  EXPECT_TRUE(s.validate(Json("not an email")).empty());
}

}  // namespace
}  // namespace socsim
