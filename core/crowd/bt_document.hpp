#pragma once
// Loading BehaviorTree.CPP XML (v3 and v4 dialects, <include> relative to the file) into a
// checked document, and the registry of node types it may use. Unknown nodes, unknown, missing
// or ill-typed ports and dangling SubTree ids are errors naming the file and line, before any
// tree is ticked; a document then makes any number of independent tree instances.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/crowd/bt_tree.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::crowd {

struct BtNodeType {
  std::string name;
  BtNodeKind kind = BtNodeKind::kAction;
  std::vector<BtPortSpec> ports;
  BtFactory factory;
  std::vector<std::string> aliases;  // other names accepted in XML (HuNavSim's TimeExpiredCondition …)
};

class BtRegistry {
 public:
  // The BT.CPP controls, decorators, SubTree, SetBlackboard, AlwaysSuccess and AlwaysFailure.
  static BtRegistry builtins();
  // kConflict when the name or an alias is taken.
  Status add(BtNodeType type);
  [[nodiscard]] const BtNodeType* find(std::string_view name_or_alias) const;
  [[nodiscard]] std::vector<const BtNodeType*> types() const;

 private:
  std::vector<std::shared_ptr<const BtNodeType>> types_;
  std::map<std::string, std::size_t, std::less<>> by_name_;
};

struct BtLoadOptions {
  // Directory <include path="…"/> is resolved against for XML given as text (a file's own
  // directory is used for the includes inside it). Empty: includes are refused.
  std::filesystem::path base_dir;
  // Includes must resolve to files under base_dir (no absolute paths or ".." escapes).
  bool confine_includes = true;
  int max_include_depth = 8;
  // One instance of a tree holds a copy of every SubTree it uses: a few trees that each use the
  // next one twice expand exponentially. Nodes and levels of an instance, SubTrees expanded.
  std::size_t max_instance_nodes = 10'000;
  int max_instance_depth = 256;
  // Blackboard entries every instance starts with and their types ({id} and {dt}).
  std::vector<std::pair<std::string, BtPortType>> seeded_keys = {{"id", BtPortType::kInt},
                                                                 {"dt", BtPortType::kDouble}};
  // Extra check of each literal port value (e.g. that an ROI name exists); returns a message
  // for a bad value.
  std::function<std::optional<std::string>(const BtNodeSpec& node, const BtPortBinding& port)> check_literal;
  world::XmlLimits limits;
};

class BtDocument {
 public:
  // Errors: kBadRequest for XML syntax, kValidation for everything else; each FieldError has
  // the line and column and its message starts with "<file>:<line>: ".
  static Result<BtDocument> parse(std::string_view xml, const BtRegistry& registry,
                                  const BtLoadOptions& options = {});
  // A document built in code as elements (the same checks as parse, lines are 0).
  static Result<BtDocument> from_element(world::XmlElement root, const BtRegistry& registry,
                                         const BtLoadOptions& options = {});
  static Result<BtDocument> load(const std::filesystem::path& file, const BtRegistry& registry,
                                 BtLoadOptions options = {});

  [[nodiscard]] const std::string& main_tree() const;
  [[nodiscard]] std::vector<std::string> tree_ids() const;
  [[nodiscard]] const BtNodeSpec* tree(std::string_view id) const;
  // A fresh instance of a tree (the main tree when id is empty) with its own blackboard; the
  // document's registry factories must still be valid.
  [[nodiscard]] BtTree instantiate(std::string_view id = {}) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace socsim::crowd
