#pragma once
// Behaviour trees of the offline generator, assembled from the knowledge store's node library:
// every node is looked up there (by name or alias) and every attribute must be one of its ports,
// so a tree the generator writes is one the crowd engine loads. Retrieval hits per category
// (KnowledgeBase::search) are kept for the card's provenance.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/scenario/lexicon.hpp"

namespace socsim::scenario {

class NodeCatalogue {
 public:
  static Result<NodeCatalogue> load(const knowledge::KnowledgeBase& knowledge);

  // Searches the store with the category's query (once per category) and records the hits.
  Status retrieve(const knowledge::KnowledgeBase& knowledge, Category category);
  [[nodiscard]] const knowledge::BehaviorNode* find(std::string_view name) const;
  // Marks a node as used by a tree of the category.
  void use(std::string_view name, Category category);
  // {queries:[{category, query, method, hits:[{name, score, method}]}], nodes_used:[{name, categories,
  // retrieved}]}
  [[nodiscard]] Json provenance() const;

 private:
  std::map<std::string, knowledge::BehaviorNode, std::less<>> nodes_;
  std::map<std::string, std::string, std::less<>> alias_;
  std::vector<std::pair<Category, Json>> queries_;
  std::set<std::string> retrieved_;
  std::map<std::string, std::set<std::string>> used_;
};

using Attributes = std::vector<std::pair<std::string, std::string>>;

// A BT.CPP v4 document with one tree, written element by element.
class TreeXml {
 public:
  TreeXml(NodeCatalogue& catalogue, Category category, std::string id);
  TreeXml& open(std::string_view node, const Attributes& attributes = {});
  TreeXml& leaf(std::string_view node, const Attributes& attributes);
  TreeXml& close();
  // The document; kValidation naming the node or attribute the knowledge store lacks.
  Result<std::string> finish() const;

 private:
  void element(std::string_view node, const Attributes& attributes, bool leaf);

  NodeCatalogue& catalogue_;
  Category category_;
  std::string id_;
  std::string body_;
  std::vector<std::string> stack_;
  std::vector<std::string> problems_;
};

std::string format_number(double v);  // shortest text for XML attributes and descriptions ("2.5")

}  // namespace socsim::scenario
