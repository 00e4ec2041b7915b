#pragma once
// The knowledge store's face: building-code references and behaviour nodes kept in SQLite,
// looked up by id, listed, searched (FTS5 BM25, fused with dense embeddings by reciprocal-rank
// fusion when an embedding provider is set) and merged into the constraints a floor plan must meet.
#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/knowledge/embedding.hpp"
#include "core/knowledge/types.hpp"
#include "core/store/store.hpp"

namespace socsim::knowledge {

// Where a retrieved entry came from and how it was found; cards keep this as provenance.
struct Provenance {
  Kind kind = Kind::kBuildingCode;
  std::string id;       // ref_id or node name
  std::string title;    // entry title (node name for behaviour nodes)
  std::string source;   // first source's title; for nodes the library it comes from
  std::string section;  // sections of the sources, "; "-joined; for nodes the category
  std::string url;      // first source's URL (empty for nodes)
  double score = 0.0;   // BM25 (higher is better) or, when fused, the RRF score
  std::string method;   // "bm25", "dense" or "bm25+dense": which rankings found it
};

struct SearchHit {
  Provenance provenance;
  std::variant<BuildingCode, BehaviorNode> entry;
};

struct SearchResult {
  std::vector<SearchHit> hits;
  std::string method = "bm25";       // "bm25+dense" when the dense ranking took part
  std::optional<Error> dense_error;  // the provider failed: results are BM25 only
};

// One constraint a floor plan must honour, with the entry that set it.
struct MergedConstraint {
  Constraint constraint;
  std::string ref_id;
  std::string building_type;  // of the winning entry ("general" or the requested type)
  std::string jurisdiction;
  std::string title;
  std::vector<Source> sources;
  std::vector<std::string> also_considered;  // other entries with the same (name, type), not chosen
};

Json to_json(const Provenance& p);
Json to_json(const SearchHit& hit);
Json to_json(const SearchResult& result);
Json to_json(const MergedConstraint& c);
// One line of natural language for an LLM prompt, e.g.
// "corridor clear width (corridor): at least 2.438 m [96 in] — IBC 2018 …, 1020.2 …".
std::string describe(const MergedConstraint& c);

inline constexpr std::size_t kMaxSearchResults = 100;
inline constexpr std::size_t kMaxQueryBytes = 2000;

// Turns user text into an FTS5 MATCH expression that cannot carry FTS syntax: every word
// becomes a quoted term, common English stop words are dropped, terms are OR-ed (BM25 ranks
// entries matching more of them higher). Empty when the text has no searchable word.
std::string fts_match_expression(std::string_view text);

class KnowledgeBase {
 public:
  // The store must have been migrated (store::Store::open does it) and outlive this object.
  explicit KnowledgeBase(store::Store& store, EmbeddingProvider embeddings = {});
  KnowledgeBase(const KnowledgeBase&) = delete;
  KnowledgeBase& operator=(const KnowledgeBase&) = delete;

  // Replaces the dense-retrieval provider (an empty one switches dense retrieval off). Call it
  // before the object is shared between threads.
  void set_embedding_provider(EmbeddingProvider embeddings);
  [[nodiscard]] const EmbeddingProvider& embedding_provider() const { return embeddings_; }

  Result<BuildingCode> building_code(const std::string& ref_id) const;
  // All entries of one building type ("general" included only when asked for); "" lists all.
  Result<std::vector<BuildingCode>> building_codes(std::string_view building_type = {}) const;
  // By name or alias (StopAndWaitTimerAction finds StopAndWait).
  Result<BehaviorNode> behavior_node(const std::string& name_or_alias) const;
  Result<std::vector<BehaviorNode>> behavior_nodes() const;

  // Validates and inserts or replaces an entry (by ref_id / name). A node whose name or aliases
  // clash with another node's is a kConflict.
  Status upsert(const BuildingCode& code);
  Status upsert(const BehaviorNode& node);

  // Best k entries of one kind for free text. Errors: kBadRequest for empty or over-long text,
  // kValidation for k outside 1..kMaxSearchResults (each naming the query parameter).
  Result<SearchResult> search(std::string_view query, Kind kind, std::size_t k = 5) const;

  // Embeds the entries of `kind` whose vector for the provider's model is missing or stale
  // (text changed); returns how many were embedded. search() calls it until it has succeeded
  // once, and again after each upsert through this object (entries written to the same file by
  // another process are picked up by calling it explicitly).
  Result<std::size_t> index_embeddings(Kind kind) const;

  // The constraints a floor plan of this building type must honour, in SI. Entries of the type
  // itself come first: for each (name, type) their strictest value wins (largest min, smallest
  // max, most confident recommendation); entries for "general" fill only the (name, type) pairs
  // the type does not set, again strictest first. Residential uses residential entries only
  // (general entries are for non-dwelling buildings). An empty jurisdiction means all.
  Result<std::vector<MergedConstraint>> constraints_for(std::string_view building_type,
                                                        std::string_view jurisdiction = {}) const;

 private:
  store::Store& store_;
  EmbeddingProvider embeddings_;
  // Per Kind: upserts through this object bump generation_; a successful index_embeddings()
  // records the generation it started from, so search() re-indexes only after a change.
  static constexpr std::uint64_t kNeverIndexed = ~std::uint64_t{0};
  std::array<std::atomic<std::uint64_t>, 2> generation_{};
  mutable std::array<std::atomic<std::uint64_t>, 2> indexed_generation_{kNeverIndexed, kNeverIndexed};
};

}  // namespace socsim::knowledge
