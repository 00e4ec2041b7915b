#pragma once
// The shared scenario-card catalogue in the SQLite store: create, version, get, list with
// full-text search and cursor pagination, delete by author, export and import.
#include <optional>
#include <string>
#include <vector>

#include "core/cards/card.hpp"
#include "core/store/store.hpp"

namespace socsim::cards {

struct CardQuery {
  std::optional<std::string> text;  // FTS5 over title, description, prompt, tags
  std::optional<std::string> tag;
  std::optional<std::string> author;
  std::optional<std::string> domain;
  std::size_t page_size = 20;
  std::optional<std::string> cursor;  // opaque, from a previous page's next_cursor
};

struct CardPage {
  std::vector<Card> items;  // newest first
  std::optional<std::string> next_cursor;
};

struct ImportOutcome {
  Card card;
  bool created = false;  // false: the same card (same id and hash) was already there
};

class CardCatalogue {
 public:
  explicit CardCatalogue(store::Store& store, CardLimits limits = {}) : store_(store), limits_(limits) {}

  [[nodiscard]] const CardLimits& limits() const { return limits_; }
  Result<Card> create(const CardContent& content, const std::string& author);
  // Creates the card under `id` (a job's card, derived from the job's id), or returns the card
  // already stored under it: a job that runs again after its worker died makes no second card.
  Result<Card> create_once(const std::string& id, const CardContent& content, const std::string& author);
  Result<Card> create_version(const std::string& parent_id, const Json& patch, const std::string& author);
  Result<Card> get(const std::string& id);
  Result<CardPage> list(const CardQuery& query);
  // Deletes when `author` wrote the card (or when `any_author` is set, for open deployments).
  Status remove(const std::string& id, const std::string& author, bool any_author);
  Result<std::string> export_card(const std::string& id);
  // Imports an export file on behalf of `importer` (the author the request was authenticated as),
  // who becomes the card's author: the author written in the file is not part of the content hash,
  // so it proves nothing. Id, creation time, content and hash are kept.
  Result<ImportOutcome> import_card(std::string_view document, const std::string& importer);
  // Stores a complete card as it is, author included (trusted callers: the local CLI).
  Result<ImportOutcome> import_card(const Card& card);
  Result<std::int64_t> count();

 private:
  store::Store& store_;
  CardLimits limits_;
};

// Turns free text into an FTS5 query of quoted terms (so user input cannot inject FTS syntax).
std::string fts_query(std::string_view text);

}  // namespace socsim::cards
