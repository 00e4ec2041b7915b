#pragma once
// Behaviour-tree runtime in the BehaviorTree.CPP (v3/v4) model: node statuses, a blackboard with
// typed values, the node base class with port access, and a tree instance ticked once per
// decision step. Trees are made from a parsed BtDocument (bt_document.hpp).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::crowd {

// kSkipped is BT.CPP v4's status of a node that decided not to run (RunOnce after its run).
enum class BtStatus : std::uint8_t { kIdle, kRunning, kSuccess, kFailure, kSkipped };
std::string_view bt_status_name(BtStatus status);
inline bool bt_completed(BtStatus s) {
  return s == BtStatus::kSuccess || s == BtStatus::kFailure;
}

enum class BtPortType : std::uint8_t { kInt, kUnsigned, kDouble, kBool, kString };
enum class BtPortDirection : std::uint8_t { kIn, kOut, kInOut };
std::string_view bt_port_type_name(BtPortType type);
std::optional<BtPortType> bt_port_type_from_name(
    std::string_view name);  // int, unsigned, double, bool, string

// A blackboard or port value. Literal port text is converted to the port's type when loading.
using BtValue = std::variant<std::monostate, bool, std::int64_t, double, std::string>;
// Converts as BehaviorTree.CPP's convertFromString does: strings are parsed strictly (whole text),
// integers widen to double, integral doubles narrow to int, bools accept true/false/1/0 in any of
// BT.CPP's spellings. The error message says what did not fit.
Result<BtValue> bt_convert(const BtValue& value, BtPortType type);
std::string bt_to_string(const BtValue& value);

class BtBlackboard {
 public:
  explicit BtBlackboard(BtBlackboard* parent = nullptr) : parent_(parent) {}
  // Follows remappings to the parent; nullptr when the key was never written.
  [[nodiscard]] const BtValue* get(std::string_view key) const;
  void set(const std::string& key, BtValue value);
  // Key `internal` of this blackboard is the parent's key `external` (SubTree port remapping).
  void remap(std::string internal, std::string external) {
    remap_[std::move(internal)] = std::move(external);
  }
  // Keys not found here are read from, and written to, the parent (SubTree _autoremap).
  void set_autoremap(bool on) { autoremap_ = on; }

 private:
  BtBlackboard* parent_;
  bool autoremap_ = false;
  std::map<std::string, BtValue, std::less<>> entries_;
  std::map<std::string, std::string, std::less<>> remap_;
};

struct BtPortSpec {
  std::string name;
  BtPortDirection direction = BtPortDirection::kIn;
  BtPortType type = BtPortType::kString;
  std::optional<std::string> default_value;  // XML text ("{id}" allowed); none → required
};

// How one port of one node instance gets its value: a literal (already converted) or a key.
struct BtPortBinding {
  std::string name;
  BtPortDirection direction = BtPortDirection::kIn;
  BtPortType type = BtPortType::kString;
  std::optional<std::string> key;  // "{key}" → key
  BtValue literal;                 // when no key
};

enum class BtNodeKind : std::uint8_t { kAction, kCondition, kControl, kDecorator, kSubTree };

// One node of a parsed tree (immutable, shared by every instance of the tree).
struct BtNodeSpec {
  std::string type;  // canonical registered name (aliases resolved)
  std::string name;  // the `name` attribute, else the type
  BtNodeKind kind = BtNodeKind::kAction;
  std::string file;  // file the node was read from ("" for inline XML)
  int line = 0;
  std::vector<BtPortBinding> ports;
  std::vector<BtNodeSpec> children;
  // SubTree only.
  std::string subtree_id;
  bool autoremap = false;
  bool shared_blackboard = false;                             // v3 __shared_blackboard
  std::vector<std::pair<std::string, std::string>> remaps;    // subtree key → parent key
  std::vector<std::pair<std::string, std::string>> literals;  // subtree key → literal text
};

// Per-tree state the nodes share: simulated time and the run-time diagnostics.
struct BtTreeContext {
  double now = 0.0;                 // s, simulated time of the current tick
  std::vector<std::string> errors;  // first run-time errors (ill-typed blackboard values …)
  std::size_t error_count = 0;
  void report(const BtNodeSpec& spec, const std::string& message);
};

class BtNode {
 public:
  BtNode(const BtNodeSpec& spec, BtTreeContext& tree, BtBlackboard& blackboard)
      : spec_(&spec), tree_(&tree), blackboard_(&blackboard) {}
  BtNode(const BtNode&) = delete;
  BtNode& operator=(const BtNode&) = delete;
  virtual ~BtNode() = default;

  // Ticks the node and records its status (BT.CPP executeTick).
  BtStatus tick();
  // Stops a RUNNING node (and its running descendants); every halted node becomes IDLE.
  void halt();
  // halt() when running, then IDLE (BT.CPP resetStatus after a completed run).
  void reset();

  [[nodiscard]] BtStatus status() const { return status_; }
  [[nodiscard]] const BtNodeSpec& spec() const { return *spec_; }
  [[nodiscard]] const std::string& name() const { return spec_->name; }
  [[nodiscard]] const std::string& type() const { return spec_->type; }
  [[nodiscard]] const std::vector<std::unique_ptr<BtNode>>& children() const { return children_; }
  void add_child(std::unique_ptr<BtNode> child) { children_.push_back(std::move(child)); }

  // Port access. An input bound to a key reads the blackboard and converts; an error (key never
  // written, value of the wrong type) is reported to the tree and returned.
  template <class T>
  Result<T> input(std::string_view port) const;
  Status output(std::string_view port, BtValue value) const;

 protected:
  virtual BtStatus on_tick() = 0;
  virtual void on_halt() {}
  [[nodiscard]] double now() const { return tree_->now; }
  [[nodiscard]] BtTreeContext& tree() const { return *tree_; }
  [[nodiscard]] BtBlackboard& blackboard() const { return *blackboard_; }
  // Reports a run-time problem of this node (the tree keeps the first few) and returns FAILURE.
  BtStatus failure(const std::string& message) const;
  void halt_children(std::size_t from = 0);
  void reset_children();

  std::vector<std::unique_ptr<BtNode>> children_;

 private:
  Result<BtValue> input_value(std::string_view port, BtPortType type) const;

  const BtNodeSpec* spec_;
  BtTreeContext* tree_;
  BtBlackboard* blackboard_;
  BtStatus status_ = BtStatus::kIdle;
};

extern template Result<std::int64_t> BtNode::input<std::int64_t>(std::string_view) const;
extern template Result<double> BtNode::input<double>(std::string_view) const;
extern template Result<bool> BtNode::input<bool>(std::string_view) const;
extern template Result<std::string> BtNode::input<std::string>(std::string_view) const;

// What a factory gets to build one node instance.
struct BtNodeInit {
  const BtNodeSpec& spec;
  BtTreeContext& tree;
  BtBlackboard& blackboard;
};
using BtFactory = std::function<std::unique_ptr<BtNode>(const BtNodeInit&)>;

// One tree instance (e.g. one agent's): its nodes, blackboards and clock.
class BtTree {
 public:
  BtTree();
  BtTree(BtTree&&) noexcept;
  BtTree& operator=(BtTree&&) noexcept;
  ~BtTree();

  // One tick of the root at simulated time `now` (s). A root that completed is IDLE again on
  // the next tick, so the tree restarts (as BT.CPP's tickOnce loop in HuNavSim).
  BtStatus tick(double now);
  void halt();

  [[nodiscard]] BtBlackboard& blackboard() { return *blackboards_.front(); }
  [[nodiscard]] const BtTreeContext& context() const { return *context_; }
  [[nodiscard]] BtNode& root() { return *root_; }
  // Every node, depth first in document order (subtrees expanded).
  [[nodiscard]] std::vector<BtNode*> nodes() const;
  // The first node with this `name` attribute (or type when unnamed); nullptr when none.
  [[nodiscard]] BtNode* find(std::string_view name) const;
  // Type of the deepest RUNNING leaf (the behaviour in progress); empty when none runs.
  [[nodiscard]] std::string running_leaf() const;

 private:
  friend class BtDocument;
  std::shared_ptr<const void> document_;  // keeps the specs alive
  std::unique_ptr<BtTreeContext> context_;
  std::vector<std::unique_ptr<BtBlackboard>> blackboards_;
  std::unique_ptr<BtNode> root_;
};

// The built-in BT.CPP nodes: controls, decorators, SubTree and the blackboard/constant actions.
struct BtBuiltinNode {
  std::string name;
  BtNodeKind kind;
  std::vector<BtPortSpec> ports;
  BtFactory factory;
};
const std::vector<BtBuiltinNode>& bt_builtin_nodes();

// Decorators that loop (Repeat, RetryUntilSuccessful) complete their child at most this many
// times within one tick and then return RUNNING, so a child that always succeeds at once cannot
// hang the simulation (BT.CPP would loop forever).
inline constexpr int kBtMaxLoopsPerTick = 64;

}  // namespace socsim::crowd
