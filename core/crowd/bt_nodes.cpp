#include "core/crowd/bt_nodes.hpp"

#include "core/crowd/bt_library.hpp"

// The node classes live by group in bt_nodes_conditions.cpp, bt_nodes_navigation.cpp,
// bt_nodes_queues.cpp and bt_nodes_places.cpp, each with its registration table.
namespace socsim::crowd {
namespace {

std::vector<BtNodeType> library(BtEnvironment& env) {
  std::vector<BtNodeType> all;
  for (auto* group :
       {nodes::condition_nodes, nodes::navigation_nodes, nodes::queue_nodes, nodes::place_nodes})
    for (BtNodeType& t : group(env)) all.push_back(std::move(t));
  return all;
}

}  // namespace

Result<std::vector<std::int64_t>> parse_agent_ids(std::string_view text) {
  std::vector<std::int64_t> ids;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ';' || text[i] == ',' || text[i] == ' ' || text[i] == '\t')) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && text[j] != ';' && text[j] != ',' && text[j] != ' ' && text[j] != '\t') ++j;
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + j, v);
    if (ec != std::errc() || ptr != text.data() + j || v < 0)
      return fail(ErrorCode::kValidation, "'" + std::string(text.substr(i, j - i)) + "' is not an agent id");
    ids.push_back(v);
    i = j;
  }
  return ids;
}

BtRegistry behavior_registry(BtEnvironment& env) {
  BtRegistry r = BtRegistry::builtins();
  for (BtNodeType& t : library(env)) {
    auto ok = r.add(std::move(t));
    if (!ok) throw std::logic_error(ok.error().detail);  // a duplicate in the table above
  }
  return r;
}

BtLoadOptions behavior_load_options(const BtEnvironment& env, std::filesystem::path base_dir) {
  BtLoadOptions o;
  o.base_dir = std::move(base_dir);
  o.check_literal = [&env](const BtNodeSpec& node, const BtPortBinding& port) -> std::optional<std::string> {
    const std::string& n = port.name;
    if (port.type == BtPortType::kDouble) {
      const double v = std::get<double>(port.literal);
      if (n == "probability" && (v < 0.0 || v > 1.0)) return "must be in [0, 1]";
      const bool non_negative =
          n.find("duration") != std::string::npos || n.find("distance") != std::string::npos ||
          n.find("dist") != std::string::npos || n == "seconds" || n == "tolerance" || n == "threshold" ||
          n == "radius" || n == "spacing" || n == "service_time" || n == "service_spread" || n == "delay" ||
          n.find("vel") != std::string::npos || n == "pause_min" || n == "pause_max" || n == "speed_factor" ||
          n == "advance_interval";
      if (non_negative && v < 0.0) return "must not be negative";
      return std::nullopt;
    }
    if (port.type != BtPortType::kString) return std::nullopt;
    const std::string& v = std::get<std::string>(port.literal);
    if (n == "non_main_agent_ids") {
      auto ids = parse_agent_ids(v);
      if (!ids) return ids.error().detail;
      return std::nullopt;
    }
    if (n == "queue") return env.check_place(v, "queue");
    if (n == "region") return env.check_place(v, "region");
    if (n == "exit") return env.check_place(v, "exit");
    if (n == "field")
      return env.velocity_field(v) != nullptr
                 ? std::nullopt
                 : std::optional<std::string>("no velocity field (ambient group) named '" + v + "'");
    const bool place =
        n == "goal" || n == "counter" || n == "seat" || n == "point" || n == "location" || n == "face";
    if (place && !(v.empty() && (n == "goal" || n == "face"))) return env.check_place(v, "place");
    (void)node;
    return std::nullopt;
  };
  return o;
}

}  // namespace socsim::crowd
