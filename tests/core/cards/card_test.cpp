// Card validation (a pointer per bad field), the content hash, and the export document.
#include "core/cards/card.hpp"

#include <gtest/gtest.h>

namespace socsim::cards {
namespace {

Json sample() {
  return Json::parse(R"({
    "title": "Reception rush", "description": "Patients queue at reception.",
    "tags": ["queue", "hospital"], "prompt": "patients queue at the reception desk",
    "seed": 7, "generator": {"name": "offline"}, "domain": "hospital",
    "world": {"zones": []}, "metrics": {"agents": 12}})");
}

std::vector<std::string> pointers(const Error& e) {
  std::vector<std::string> p;
  for (const auto& f : e.errors) p.push_back(f.pointer);
  return p;
}

TEST(Card, ValidContentParsesAndTagsAreSortedAndUnique) {
  Json j = sample();
  j["tags"] = {"queue", "hospital", "queue"};
  auto c = parse_card_content(j, {});
  ASSERT_TRUE(c) << c.error().message();
  EXPECT_EQ(c->tags, (std::vector<std::string>{"hospital", "queue"}));
  EXPECT_EQ(c->seed, 7u);
  EXPECT_EQ(c->domain.value(), "hospital");
}

TEST(Card, EveryBadFieldIsReportedWithItsPointer) {
  Json j = sample();
  j["title"] = "";
  j["seed"] = -3;
  j["tags"] = {"ok", "Not Valid!"};
  j["generator"] = {{"name", "gpt"}};
  j["world"] = "a string";
  j["colour"] = "blue";
  auto c = parse_card_content(j, {});
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().code, ErrorCode::kValidation);
  EXPECT_EQ(pointers(c.error()),
            (std::vector<std::string>{"/colour", "/title", "/tags/1", "/seed", "/generator/name", "/world"}));
}

TEST(Card, PromptLengthIsLimited) {
  Json j = sample();
  j["prompt"] = std::string(5000, 'a');
  CardLimits limits;
  limits.max_prompt_bytes = 4000;
  auto c = parse_card_content(j, limits);
  ASSERT_FALSE(c);
  EXPECT_EQ(pointers(c.error()), std::vector<std::string>{"/prompt"});
}

TEST(Card, HashDependsOnContentAndLineageOnly) {
  auto a = parse_card_content(sample(), {}).value();
  auto b = a;
  EXPECT_EQ(content_hash(a, 1, std::nullopt), content_hash(b, 1, std::nullopt));
  b.metrics["agents"] = 13;
  EXPECT_NE(content_hash(a, 1, std::nullopt), content_hash(b, 1, std::nullopt));
  EXPECT_NE(content_hash(a, 1, std::nullopt), content_hash(a, 2, std::string("crd_0000000000000000000a")));
  EXPECT_EQ(content_hash(a, 1, std::nullopt).size(), 64u);
}

TEST(Card, ExportParsesBackToTheSameBytes) {
  Card card;
  card.id = new_card_id();
  card.content = parse_card_content(sample(), {}).value();
  card.author = "alice";
  card.created_at = utc_now_rfc3339();
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  const std::string doc = export_document(card);
  auto back = parse_export_document(doc, {});
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(export_document(*back), doc);
}

TEST(Card, TamperedExportIsRejectedByItsHash) {
  Card card;
  card.id = new_card_id();
  card.content = parse_card_content(sample(), {}).value();
  card.author = "alice";
  card.created_at = utc_now_rfc3339();
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  std::string doc = export_document(card);
  doc.replace(doc.find("Reception rush"), 14, "Reception RUSH");
  auto back = parse_export_document(doc, {});
  ASSERT_FALSE(back);
  EXPECT_EQ(pointers(back.error()), std::vector<std::string>{"/card/content_hash"});
}

// Found by tests/server/bad_input_property_test.cpp: an unknown key beside the card was ignored.
TEST(Card, ExportWithAnUnknownTopLevelFieldIsRefused) {
  Card card;
  card.id = new_card_id();
  card.content = parse_card_content(sample(), {}).value();
  card.author = "alice";
  card.created_at = "2026-01-01T00:00:00.000Z";
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  Json doc = Json::parse(export_document(card));
  doc["signature"] = "trust me";
  auto back = parse_export_document(doc.dump(), {});
  ASSERT_FALSE(back);
  EXPECT_EQ(pointers(back.error()), std::vector<std::string>{"/signature"});
}

TEST(Card, TheIntentIsStoredAndACardWithoutOneKeepsItsHash) {
  const auto plain = parse_card_content(sample(), {}).value();
  EXPECT_TRUE(plain.intent.is_null());
  EXPECT_FALSE(content_to_json(plain).contains("intent"));  // cards from before the field hash as before
  Json body = sample();
  body["intent"] = Json{{"prompt", "patients queue at the reception desk"}, {"groups", Json::array()}};
  const auto with = parse_card_content(body, {}).value();
  EXPECT_EQ(with.intent, body["intent"]);
  EXPECT_NE(content_hash(with, 1, std::nullopt), content_hash(plain, 1, std::nullopt));
  Card card;
  card.id = new_card_id();
  card.content = with;
  card.author = "alice";
  card.created_at = utc_now_rfc3339();
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  auto back = parse_export_document(export_document(card), {});
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back->content.intent, body["intent"]);
  EXPECT_FALSE(summary_json(*back).contains("intent"));
  body["intent"] = "queue";
  auto bad = parse_card_content(body, {});
  ASSERT_FALSE(bad);
  EXPECT_EQ(pointers(bad.error()), std::vector<std::string>{"/intent"});
}

TEST(Card, IdsAreWellFormedAndDistinct) {
  const auto a = new_card_id(), b = new_card_id();
  EXPECT_TRUE(is_card_id(a));
  EXPECT_NE(a, b);
  EXPECT_FALSE(is_card_id("crd_short"));
  EXPECT_FALSE(is_card_id("crd_ILOU0000000000000000"));
}

}  // namespace
}  // namespace socsim::cards
