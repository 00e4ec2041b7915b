#pragma once
// Worlds stored by POST /api/v1/worlds (the worlds table): world.yaml with the request, scene
// graph, compliance report and knowledge provenance it was generated from. Beside the card
// catalogue, so that every route and tool that refers to a world by id reads it the same way.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/store/store.hpp"

namespace socsim::cards {

struct StoredWorld {
  std::string id, name, domain, generator, author, created_at, world_yaml, content_hash;
  std::int64_t seed = 0;
  Json request, scene_graph, compliance, provenance;
};

struct WorldPage {
  std::vector<StoredWorld> items;           // newest first
  std::optional<std::int64_t> next_before;  // pass as `before` for the next page
};

class WorldStore {
 public:
  explicit WorldStore(store::Store& store) : store_(store) {}

  // Stores `world`, giving it a new id, its content hash (SHA-256 of world_yaml) and creation
  // time; returns it as stored. A failed write stores nothing.
  Result<StoredWorld> add(StoredWorld world);
  // kNotFound naming the id when there is no such world.
  Result<StoredWorld> get(const std::string& id);
  // Newest first, at most `limit`; `before` continues a previous page; `domain` filters.
  Result<WorldPage> list(std::size_t limit, std::optional<std::int64_t> before,
                         const std::optional<std::string>& domain);

 private:
  store::Store& store_;
};

}  // namespace socsim::cards
