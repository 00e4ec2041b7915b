#pragma once
// Worlds stored by POST /api/v1/worlds, for the routes that refer to them by id.
#include <string>

#include "core/common/error.hpp"
#include "core/store/store.hpp"

namespace socsim::server {

struct StoredWorldText {
  std::string id;
  std::string domain;
  std::string world_yaml;
};

// kNotFound naming the id when there is no such world.
Result<StoredWorldText> stored_world_text(store::Store& store, const std::string& id);

}  // namespace socsim::server
