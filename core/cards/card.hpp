#pragma once
// Scenario card: everything needed to replay a scenario exactly (paper 001 §III-H), immutable
// once stored. This unit converts cards to and from JSON and computes their content hash.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/ids.hpp"
#include "core/common/json_io.hpp"

namespace socsim::cards {

struct Generator {
  std::string name = "offline";  // offline | llm | import | manual
  std::optional<std::string> model;
};

// The fields a client supplies.
struct CardContent {
  std::string title;
  std::string description;
  std::vector<std::string> tags;
  std::string prompt;
  std::uint64_t seed = 0;
  Generator generator;
  std::optional<std::string> domain;
  Json world;    // object or null
  Json program;  // object or null
  Json metrics = Json::object();
  Json trajectory_log;  // {uri, format, frames, sha256} or null
  Json provenance = Json::object();
  // What the prompt was understood to say (schemas/intent.schema.json) or null. Cards made before
  // it existed have none; it is left out of their JSON and their content hash.
  Json intent = nullptr;
};

struct Card {
  std::string id;
  CardContent content;
  std::string author;
  std::int64_t version = 1;
  std::optional<std::string> parent_id;
  std::string created_at;  // RFC 3339, UTC, milliseconds
  std::string content_hash;
};

struct CardLimits {
  std::size_t max_prompt_bytes = 4000;
  std::size_t max_title_bytes = 200;
  std::size_t max_description_bytes = 10000;
  std::size_t max_tags = 32;
};

// Reads the body of POST /cards (client fields only; server fields are refused).
Result<CardContent> parse_card_content(const Json& body, const CardLimits& limits);
// Applies the fields present in `patch` over `base` (for a new version), validated like a POST.
Result<CardContent> merge_card_content(const CardContent& base, const Json& patch, const CardLimits& limits);
// Reads a complete card (for import); checks its content hash.
Result<Card> parse_card(const Json& json, const CardLimits& limits);

Json content_to_json(const CardContent& c);
Json to_json(const Card& card);
Json summary_json(const Card& card);  // without world, program, metrics, provenance, intent

// SHA-256 of the canonical JSON of the content plus lineage (version, parent_id). Server-assigned
// identity (id, author, created_at) is not part of it, so a card keeps its hash across catalogues.
std::string content_hash(const CardContent& content, std::int64_t version,
                         const std::optional<std::string>& parent);

// "crd_" + 20 characters of Crockford base32 (100 random bits).
std::string new_card_id();
bool is_card_id(std::string_view s);

// The self-contained export file: canonical JSON + "\n"; import(export(c)) reproduces the bytes.
std::string export_document(const Card& card);
Result<Card> parse_export_document(std::string_view text, const CardLimits& limits);

}  // namespace socsim::cards
