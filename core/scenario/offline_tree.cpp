#include "core/scenario/offline_tree.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/world/xml_reader.hpp"

namespace socsim::scenario {

std::string format_number(double v) {
  if (!std::isfinite(v)) return "0";
  if (v == 0.0) return "0";
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) return "0";
  return std::string(buf, end);
}

Result<NodeCatalogue> NodeCatalogue::load(const knowledge::KnowledgeBase& knowledge) {
  auto nodes = knowledge.behavior_nodes();
  if (!nodes) return tl::unexpected(nodes.error());
  NodeCatalogue c;
  for (knowledge::BehaviorNode& n : *nodes) {
    for (const std::string& a : n.aliases) c.alias_[a] = n.name;
    std::string name = n.name;
    c.nodes_.emplace(std::move(name), std::move(n));
  }
  return c;
}

Status NodeCatalogue::retrieve(const knowledge::KnowledgeBase& knowledge, Category category) {
  for (const auto& [c, q] : queries_)
    if (c == category) return {};
  const std::string_view query = node_query(category);
  auto found = knowledge.search(query, knowledge::Kind::kBehaviorNode, 10);
  if (!found) return tl::unexpected(found.error());
  Json hits = Json::array();
  for (const knowledge::SearchHit& h : found->hits) {
    hits.push_back(
        Json{{"name", h.provenance.id}, {"score", h.provenance.score}, {"method", h.provenance.method}});
    retrieved_.insert(h.provenance.id);
  }
  Json q{{"category", std::string(to_string(category))},
         {"query", std::string(query)},
         {"method", found->method},
         {"hits", hits}};
  if (found->dense_error) q["dense_error"] = found->dense_error->detail;
  queries_.emplace_back(category, std::move(q));
  return {};
}

const knowledge::BehaviorNode* NodeCatalogue::find(std::string_view name) const {
  if (auto it = nodes_.find(name); it != nodes_.end()) return &it->second;
  if (auto a = alias_.find(name); a != alias_.end())
    if (auto it = nodes_.find(a->second); it != nodes_.end()) return &it->second;
  return nullptr;
}

void NodeCatalogue::use(std::string_view name, Category category) {
  used_[std::string(name)].insert(std::string(to_string(category)));
}

Json NodeCatalogue::provenance() const {
  Json queries = Json::array();
  for (const auto& [c, q] : queries_) queries.push_back(q);
  Json used = Json::array();
  for (const auto& [name, cats] : used_) {
    const knowledge::BehaviorNode* n = find(name);
    used.push_back(Json{{"name", name},
                        {"categories", std::vector<std::string>(cats.begin(), cats.end())},
                        {"retrieved", retrieved_.count(name) != 0},
                        {"origin", n != nullptr ? n->origin : std::string()}});
  }
  return Json{{"queries", queries}, {"nodes_used", used}};
}

TreeXml::TreeXml(NodeCatalogue& catalogue, Category category, std::string id)
    : catalogue_(catalogue), category_(category), id_(std::move(id)) {}

void TreeXml::element(std::string_view node, const Attributes& attributes, bool leaf) {
  const knowledge::BehaviorNode* n = catalogue_.find(node);
  if (n == nullptr) {
    problems_.push_back("the knowledge store has no behaviour node '" + std::string(node) + "'");
  } else {
    catalogue_.use(n->name, category_);
    for (const auto& attribute : attributes) {
      const auto& key = attribute.first;  // clang 14 cannot capture structured bindings
      const bool known = std::any_of(n->ports.begin(), n->ports.end(),
                                     [&](const knowledge::Port& p) { return p.name == key; });
      if (!known)
        problems_.push_back("behaviour node '" + n->name + "' has no port '" + key +
                            "' in the knowledge store");
    }
  }
  body_.append(2 * (stack_.size() + 2), ' ');
  body_ += "<" + std::string(node);
  for (const auto& [key, value] : attributes) body_ += " " + key + "=\"" + world::xml_escape(value) + "\"";
  body_ += leaf ? "/>\n" : ">\n";
}

TreeXml& TreeXml::open(std::string_view node, const Attributes& attributes) {
  element(node, attributes, false);
  stack_.emplace_back(node);
  return *this;
}

TreeXml& TreeXml::leaf(std::string_view node, const Attributes& attributes) {
  element(node, attributes, true);
  return *this;
}

TreeXml& TreeXml::close() {
  if (stack_.empty()) {
    problems_.push_back("tree '" + id_ + "': close() without open()");
    return *this;
  }
  body_.append(2 * (stack_.size() + 1), ' ');
  body_ += "</" + stack_.back() + ">\n";
  stack_.pop_back();
  return *this;
}

Result<std::string> TreeXml::finish() const {
  std::vector<std::string> problems = problems_;
  if (!stack_.empty())
    problems.push_back("tree '" + id_ + "': element <" + stack_.back() + "> is not closed");
  if (!problems.empty()) {
    std::vector<FieldError> errors;
    for (const std::string& p : problems) errors.push_back(FieldError{"", p});
    return fail(ErrorCode::kValidation, problems.front(), std::move(errors));
  }
  const std::string id = world::xml_escape(id_);
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"" + id + "\">\n  <BehaviorTree ID=\"" + id +
         "\">\n" + body_ + "  </BehaviorTree>\n</root>";
}

}  // namespace socsim::scenario
