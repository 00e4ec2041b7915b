#include "core/crowd/bt_tree.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

namespace socsim::crowd {

std::string_view bt_status_name(BtStatus status) {
  switch (status) {
    case BtStatus::kIdle:
      return "IDLE";
    case BtStatus::kRunning:
      return "RUNNING";
    case BtStatus::kSuccess:
      return "SUCCESS";
    case BtStatus::kFailure:
      return "FAILURE";
    case BtStatus::kSkipped:
      return "SKIPPED";
  }
  return "IDLE";
}

std::string_view bt_port_type_name(BtPortType type) {
  switch (type) {
    case BtPortType::kInt:
      return "int";
    case BtPortType::kUnsigned:
      return "unsigned";
    case BtPortType::kDouble:
      return "double";
    case BtPortType::kBool:
      return "bool";
    case BtPortType::kString:
      return "string";
  }
  return "string";
}

std::optional<BtPortType> bt_port_type_from_name(std::string_view name) {
  if (name == "int") return BtPortType::kInt;
  if (name == "unsigned") return BtPortType::kUnsigned;
  if (name == "double") return BtPortType::kDouble;
  if (name == "bool") return BtPortType::kBool;
  if (name == "string") return BtPortType::kString;
  return std::nullopt;
}

namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::optional<std::int64_t> parse_int(std::string_view text) {
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  std::int64_t v = 0;
  const char* first = t.data();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

std::optional<double> parse_double(std::string_view text) {
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  double v = 0.0;
  const char* first = t.data();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<bool> parse_bool(std::string_view text) {
  const std::string t = trim(text);
  if (t == "true" || t == "True" || t == "TRUE" || t == "1") return true;
  if (t == "false" || t == "False" || t == "FALSE" || t == "0") return false;
  return std::nullopt;
}

tl::unexpected<Error> conversion_error(const BtValue& value, BtPortType type) {
  const std::string shown =
      std::holds_alternative<std::monostate>(value) ? "an empty value" : "'" + bt_to_string(value) + "'";
  return fail(ErrorCode::kValidation, shown + " is not a valid " + std::string(bt_port_type_name(type)) +
                                          (type == BtPortType::kBool ? " (true/false)" : ""));
}

}  // namespace

std::string bt_to_string(const BtValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&value)) {
    char buf[64];
    const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, *d);
    return ec == std::errc() ? std::string(buf, ptr) : std::string("nan");
  }
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  return {};
}

Result<BtValue> bt_convert(const BtValue& value, BtPortType type) {
  switch (type) {
    case BtPortType::kString:
      if (std::holds_alternative<std::monostate>(value)) break;
      return BtValue{bt_to_string(value)};
    case BtPortType::kInt:
    case BtPortType::kUnsigned: {
      std::optional<std::int64_t> v;
      if (const auto* i = std::get_if<std::int64_t>(&value)) v = *i;
      if (const auto* d = std::get_if<double>(&value); d && std::floor(*d) == *d && std::abs(*d) < 9.0e15)
        v = static_cast<std::int64_t>(*d);
      if (const auto* s = std::get_if<std::string>(&value)) v = parse_int(*s);
      if (!v || (type == BtPortType::kUnsigned && *v < 0)) break;
      return BtValue{*v};
    }
    case BtPortType::kDouble: {
      std::optional<double> v;
      if (const auto* i = std::get_if<std::int64_t>(&value)) v = static_cast<double>(*i);
      if (const auto* d = std::get_if<double>(&value)) v = *d;
      if (const auto* s = std::get_if<std::string>(&value)) v = parse_double(*s);
      if (!v) break;
      return BtValue{*v};
    }
    case BtPortType::kBool: {
      std::optional<bool> v;
      if (const auto* b = std::get_if<bool>(&value)) v = *b;
      if (const auto* i = std::get_if<std::int64_t>(&value); i && (*i == 0 || *i == 1)) v = *i == 1;
      if (const auto* s = std::get_if<std::string>(&value)) v = parse_bool(*s);
      if (!v) break;
      return BtValue{*v};
    }
  }
  return conversion_error(value, type);
}

// --- blackboard --------------------------------------------------------------------------------

const BtValue* BtBlackboard::get(std::string_view key) const {
  if (auto r = remap_.find(key); r != remap_.end())
    return parent_ != nullptr ? parent_->get(r->second) : nullptr;
  if (auto e = entries_.find(key); e != entries_.end()) return &e->second;
  if (autoremap_ && parent_ != nullptr) return parent_->get(key);
  return nullptr;
}

void BtBlackboard::set(const std::string& key, BtValue value) {
  if (auto r = remap_.find(key); r != remap_.end() && parent_ != nullptr) {
    parent_->set(r->second, std::move(value));
    return;
  }
  if (autoremap_ && parent_ != nullptr && entries_.find(key) == entries_.end()) {
    parent_->set(key, std::move(value));
    return;
  }
  entries_[key] = std::move(value);
}

void BtTreeContext::report(const BtNodeSpec& spec, const std::string& message) {
  ++error_count;
  if (errors.size() >= 16) return;
  std::string where = spec.file.empty() ? "line " : spec.file + ":";
  errors.push_back(where + std::to_string(spec.line) + ": " + spec.type + ": " + message);
}

// --- node base ---------------------------------------------------------------------------------

BtStatus BtNode::tick() {
  status_ = on_tick();
  return status_;
}

void BtNode::halt() {
  if (status_ == BtStatus::kRunning) on_halt();
  for (auto& c : children_) c->halt();
  status_ = BtStatus::kIdle;
}

void BtNode::reset() {
  halt();
}

void BtNode::halt_children(std::size_t from) {
  for (std::size_t i = from; i < children_.size(); ++i) children_[i]->halt();
}

void BtNode::reset_children() {
  halt_children(0);
}

BtStatus BtNode::failure(const std::string& message) const {
  tree_->report(*spec_, message);
  return BtStatus::kFailure;
}

Result<BtValue> BtNode::input_value(std::string_view port, BtPortType type) const {
  for (const BtPortBinding& b : spec_->ports) {
    if (b.name != port) continue;
    if (!b.key) return bt_convert(b.literal, type);
    const BtValue* v = blackboard_->get(*b.key);
    if (v == nullptr || std::holds_alternative<std::monostate>(*v)) {
      tree_->report(*spec_, "port '" + b.name + "': blackboard key '" + *b.key + "' has no value");
      return fail(ErrorCode::kValidation, "blackboard key '" + *b.key + "' has no value");
    }
    auto converted = bt_convert(*v, type);
    if (!converted)
      tree_->report(*spec_, "port '" + b.name + "' ({" + *b.key + "}): " + converted.error().detail);
    return converted;
  }
  tree_->report(*spec_, "no port '" + std::string(port) + "'");
  return fail(ErrorCode::kInternal, "node " + spec_->type + " has no port " + std::string(port));
}

template <class T>
Result<T> BtNode::input(std::string_view port) const {
  BtPortType type = BtPortType::kString;
  if constexpr (std::is_same_v<T, std::int64_t>) type = BtPortType::kInt;
  if constexpr (std::is_same_v<T, double>) type = BtPortType::kDouble;
  if constexpr (std::is_same_v<T, bool>) type = BtPortType::kBool;
  auto v = input_value(port, type);
  if (!v) return tl::unexpected(v.error());
  return std::get<T>(*v);
}

template Result<std::int64_t> BtNode::input<std::int64_t>(std::string_view) const;
template Result<double> BtNode::input<double>(std::string_view) const;
template Result<bool> BtNode::input<bool>(std::string_view) const;
template Result<std::string> BtNode::input<std::string>(std::string_view) const;

Status BtNode::output(std::string_view port, BtValue value) const {
  for (const BtPortBinding& b : spec_->ports) {
    if (b.name != port) continue;
    if (!b.key) return {};  // validated at load: only an unconnected optional output has no key
    blackboard_->set(*b.key, std::move(value));
    return {};
  }
  tree_->report(*spec_, "no port '" + std::string(port) + "'");
  return fail(ErrorCode::kInternal, "node " + spec_->type + " has no port " + std::string(port));
}

// --- tree --------------------------------------------------------------------------------------

BtTree::BtTree() : context_(std::make_unique<BtTreeContext>()) {}
BtTree::BtTree(BtTree&&) noexcept = default;
BtTree& BtTree::operator=(BtTree&&) noexcept = default;
BtTree::~BtTree() = default;

BtStatus BtTree::tick(double now) {
  context_->now = now;
  if (bt_completed(root_->status()) || root_->status() == BtStatus::kSkipped) root_->reset();
  return root_->tick();
}

void BtTree::halt() {
  root_->halt();
}

namespace {
void collect(BtNode* n, std::vector<BtNode*>& out) {
  out.push_back(n);
  for (const auto& c : n->children()) collect(c.get(), out);
}
}  // namespace

std::vector<BtNode*> BtTree::nodes() const {
  std::vector<BtNode*> out;
  if (root_) collect(root_.get(), out);
  return out;
}

BtNode* BtTree::find(std::string_view name) const {
  for (BtNode* n : nodes())
    if (n->name() == name) return n;
  return nullptr;
}

std::string BtTree::running_leaf() const {
  const BtNode* n = root_.get();
  if (n == nullptr || n->status() != BtStatus::kRunning) return {};
  for (;;) {
    const BtNode* next = nullptr;
    for (const auto& c : n->children())
      if (c->status() == BtStatus::kRunning) {
        next = c.get();
        break;
      }
    if (next == nullptr) return n->type();
    n = next;
  }
}

// --- built-in nodes ----------------------------------------------------------------------------

namespace {

class SequenceNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    if (status() != BtStatus::kRunning) all_skipped_ = true;
    while (current_ < children_.size()) {
      const BtStatus s = children_[current_]->tick();
      all_skipped_ = all_skipped_ && s == BtStatus::kSkipped;
      if (s == BtStatus::kRunning) return s;
      if (s == BtStatus::kFailure) {
        restart();
        return s;
      }
      ++current_;
    }
    restart();
    return all_skipped_ ? BtStatus::kSkipped : BtStatus::kSuccess;
  }
  void on_halt() override { current_ = 0; }

 private:
  void restart() {
    reset_children();
    current_ = 0;
  }
  std::size_t current_ = 0;
  bool all_skipped_ = true;
};

class FallbackNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    if (status() != BtStatus::kRunning) all_skipped_ = true;
    while (current_ < children_.size()) {
      const BtStatus s = children_[current_]->tick();
      all_skipped_ = all_skipped_ && s == BtStatus::kSkipped;
      if (s == BtStatus::kRunning) return s;
      if (s == BtStatus::kSuccess) {
        restart();
        return s;
      }
      ++current_;
    }
    restart();
    return all_skipped_ ? BtStatus::kSkipped : BtStatus::kFailure;
  }
  void on_halt() override { current_ = 0; }

 private:
  void restart() {
    reset_children();
    current_ = 0;
  }
  std::size_t current_ = 0;
  bool all_skipped_ = true;
};

// Reactive controls re-tick from the first child every tick. When child i is RUNNING every other
// child is halted (BT.CPP v3 halts the later ones, v4 resets the earlier ones; both together keep
// exactly one child active).
class ReactiveNode final : public BtNode {
 public:
  ReactiveNode(const BtNodeInit& init, bool sequence)
      : BtNode(init.spec, init.tree, init.blackboard), sequence_(sequence) {}

 protected:
  BtStatus on_tick() override {
    bool all_skipped = true;
    const BtStatus stop_on = sequence_ ? BtStatus::kFailure : BtStatus::kSuccess;
    for (std::size_t i = 0; i < children_.size(); ++i) {
      const BtStatus s = children_[i]->tick();
      all_skipped = all_skipped && s == BtStatus::kSkipped;
      if (s == BtStatus::kRunning) {
        for (std::size_t j = 0; j < children_.size(); ++j)
          if (j != i) children_[j]->halt();
        return s;
      }
      if (s == stop_on) {
        reset_children();
        return s;
      }
      if (s == BtStatus::kSkipped) children_[i]->halt();
    }
    reset_children();
    if (all_skipped) return BtStatus::kSkipped;
    return sequence_ ? BtStatus::kSuccess : BtStatus::kFailure;
  }

 private:
  bool sequence_;
};

class ParallelNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    auto success_port = input<std::int64_t>("success_count");
    auto failure_port = input<std::int64_t>("failure_count");
    if (!success_port || !failure_port) return BtStatus::kFailure;
    const auto n = static_cast<std::int64_t>(children_.size());
    const std::int64_t need_success =
        *success_port < 0 ? std::max<std::int64_t>(n + *success_port + 1, 0) : *success_port;
    const std::int64_t need_failure =
        *failure_port < 0 ? std::max<std::int64_t>(n + *failure_port + 1, 0) : *failure_port;
    if (need_success > n || need_failure > n)
      return failure("success_count/failure_count exceed the number of children (" + std::to_string(n) + ")");
    std::int64_t skipped = 0;
    for (std::size_t i = 0; i < children_.size(); ++i) {
      if (done_.count(i) == 0) {
        const BtStatus s = children_[i]->tick();
        if (s == BtStatus::kSkipped) ++skipped;
        if (s == BtStatus::kSuccess) {
          done_.insert(i);
          ++successes_;
        }
        if (s == BtStatus::kFailure) {
          done_.insert(i);
          ++failures_;
        }
      }
      if (successes_ >= need_success || (*success_port < 0 && successes_ + skipped >= need_success)) {
        clear();
        return BtStatus::kSuccess;
      }
      if (n - failures_ < need_success || failures_ == need_failure) {
        clear();
        return BtStatus::kFailure;
      }
    }
    return skipped == n ? BtStatus::kSkipped : BtStatus::kRunning;
  }
  void on_halt() override {
    done_.clear();
    successes_ = failures_ = 0;
  }

 private:
  void clear() {
    reset_children();
    on_halt();
  }
  std::set<std::size_t> done_;
  std::int64_t successes_ = 0;
  std::int64_t failures_ = 0;
};

class InverterNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    const BtStatus s = children_[0]->tick();
    if (s == BtStatus::kSuccess || s == BtStatus::kFailure) {
      children_[0]->reset();
      return s == BtStatus::kSuccess ? BtStatus::kFailure : BtStatus::kSuccess;
    }
    return s;
  }
};

class ForceNode final : public BtNode {
 public:
  ForceNode(const BtNodeInit& init, BtStatus result)
      : BtNode(init.spec, init.tree, init.blackboard), result_(result) {}

 protected:
  BtStatus on_tick() override {
    const BtStatus s = children_[0]->tick();
    if (bt_completed(s)) {
      children_[0]->reset();
      return result_;
    }
    return s;
  }

 private:
  BtStatus result_;
};

// Repeat (repeat_on = SUCCESS) and RetryUntilSuccessful (repeat_on = FAILURE).
class LoopNode final : public BtNode {
 public:
  LoopNode(const BtNodeInit& init, bool repeat)
      : BtNode(init.spec, init.tree, init.blackboard), repeat_(repeat) {}

 protected:
  BtStatus on_tick() override {
    auto limit = input<std::int64_t>(repeat_ ? "num_cycles" : "num_attempts");
    if (!limit) return BtStatus::kFailure;
    if (status() != BtStatus::kRunning) all_skipped_ = true;
    const BtStatus again = repeat_ ? BtStatus::kSuccess : BtStatus::kFailure;
    int loops = 0;
    while (*limit < 0 || count_ < *limit) {
      const BtStatus s = children_[0]->tick();
      all_skipped_ = all_skipped_ && s == BtStatus::kSkipped;
      if (s == BtStatus::kRunning) return s;
      if (s == BtStatus::kSkipped) {
        children_[0]->reset();
        return s;
      }
      children_[0]->reset();
      if (s != again) {
        count_ = 0;
        return s;
      }
      ++count_;
      if (++loops >= kBtMaxLoopsPerTick && (*limit < 0 || count_ < *limit)) return BtStatus::kRunning;
    }
    count_ = 0;
    if (all_skipped_) return BtStatus::kSkipped;
    return repeat_ ? BtStatus::kSuccess : BtStatus::kFailure;
  }
  void on_halt() override { count_ = 0; }

 private:
  bool repeat_;
  std::int64_t count_ = 0;
  bool all_skipped_ = true;
};

// Timeout(msec): FAILURE (child halted) once the simulated time limit has passed.
class TimeoutNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    auto msec = input<std::int64_t>("msec");
    if (!msec) return BtStatus::kFailure;
    if (status() == BtStatus::kIdle) start_ = now();
    if (now() - start_ >= static_cast<double>(*msec) / 1000.0) {
      children_[0]->halt();
      return BtStatus::kFailure;
    }
    const BtStatus s = children_[0]->tick();
    if (bt_completed(s)) children_[0]->reset();
    return s;
  }

 private:
  double start_ = 0.0;
};

// Delay(delay_msec) and HuNavSim's TimeDelay(delay s): wait, then tick the child. While waiting,
// Delay returns RUNNING and TimeDelay FAILURE (its documented behaviour).
class DelayNode final : public BtNode {
 public:
  DelayNode(const BtNodeInit& init, bool hunav)
      : BtNode(init.spec, init.tree, init.blackboard), hunav_(hunav) {}

 protected:
  BtStatus on_tick() override {
    double delay = 0.0;
    if (hunav_) {
      auto d = input<double>("delay");
      if (!d) return BtStatus::kFailure;
      delay = *d;
    } else {
      auto d = input<std::int64_t>("delay_msec");
      if (!d) return BtStatus::kFailure;
      delay = static_cast<double>(*d) / 1000.0;
    }
    if (!started_) {
      started_ = true;
      start_ = now();
    }
    if (now() - start_ < delay) return hunav_ ? BtStatus::kFailure : BtStatus::kRunning;
    const BtStatus s = children_[0]->tick();
    if (bt_completed(s)) {
      children_[0]->reset();
      if (!hunav_) started_ = false;
    }
    return s;
  }
  void on_halt() override {
    if (!hunav_) started_ = false;
  }

 private:
  bool hunav_;
  bool started_ = false;
  double start_ = 0.0;
};

class RunOnceNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    auto skip = input<bool>("then_skip");
    if (!skip) return BtStatus::kFailure;
    if (done_) return *skip ? BtStatus::kSkipped : result_;
    const BtStatus s = children_[0]->tick();
    if (bt_completed(s)) {
      done_ = true;
      result_ = s;
      children_[0]->reset();
    }
    return s;
  }

 private:
  bool done_ = false;
  BtStatus result_ = BtStatus::kIdle;
};

class SubTreeNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    const BtStatus s = children_[0]->tick();
    if (bt_completed(s)) children_[0]->reset();
    return s;
  }
};

class ConstantNode final : public BtNode {
 public:
  ConstantNode(const BtNodeInit& init, BtStatus result)
      : BtNode(init.spec, init.tree, init.blackboard), result_(result) {}

 protected:
  BtStatus on_tick() override { return result_; }

 private:
  BtStatus result_;
};

class SetBlackboardNode final : public BtNode {
 public:
  using BtNode::BtNode;

 protected:
  BtStatus on_tick() override {
    // The value keeps its blackboard type when it comes from a key ({id} stays an int).
    // output_key names the entry: "agentid" (BT.CPP) or "{agentid}".
    const BtValue* from = nullptr;
    std::string target;
    for (const BtPortBinding& b : spec().ports) {
      if (b.name == "value" && b.key) from = blackboard().get(*b.key);
      if (b.name == "output_key") target = b.key ? *b.key : bt_to_string(b.literal);
    }
    if (target.empty()) return failure("output_key is empty");
    if (from != nullptr) {
      blackboard().set(target, *from);
      return BtStatus::kSuccess;
    }
    auto value = input<std::string>("value");
    if (!value) return BtStatus::kFailure;
    blackboard().set(target, *value);
    return BtStatus::kSuccess;
  }
};

template <class Node, class... Args>
BtFactory make(Args... args) {
  return [=](const BtNodeInit& init) -> std::unique_ptr<BtNode> {
    if constexpr (sizeof...(Args) == 0) {
      return std::make_unique<Node>(init.spec, init.tree, init.blackboard);
    } else {
      return std::make_unique<Node>(init, args...);
    }
  };
}

BtPortSpec in(std::string name, BtPortType type, std::optional<std::string> def = std::nullopt) {
  return BtPortSpec{std::move(name), BtPortDirection::kIn, type, std::move(def)};
}

}  // namespace

const std::vector<BtBuiltinNode>& bt_builtin_nodes() {
  using K = BtNodeKind;
  using T = BtPortType;
  static const std::vector<BtBuiltinNode> nodes = {
      {"Sequence", K::kControl, {}, make<SequenceNode>()},
      {"Fallback", K::kControl, {}, make<FallbackNode>()},
      {"ReactiveSequence", K::kControl, {}, make<ReactiveNode>(true)},
      {"ReactiveFallback", K::kControl, {}, make<ReactiveNode>(false)},
      {"Parallel",
       K::kControl,
       {in("success_count", T::kInt, "-1"), in("failure_count", T::kInt, "1")},
       make<ParallelNode>()},
      // SubTree's attributes are read by the loader (ID, _autoremap, remappings); the ports are
      // listed for the node library's description.
      {"SubTree",
       K::kSubTree,
       {in("ID", T::kString), in("_autoremap", T::kBool, "false")},
       make<SubTreeNode>()},
      {"Inverter", K::kDecorator, {}, make<InverterNode>()},
      {"Repeat", K::kDecorator, {in("num_cycles", T::kInt)}, make<LoopNode>(true)},
      {"RetryUntilSuccessful", K::kDecorator, {in("num_attempts", T::kInt)}, make<LoopNode>(false)},
      {"Timeout", K::kDecorator, {in("msec", T::kUnsigned)}, make<TimeoutNode>()},
      {"Delay", K::kDecorator, {in("delay_msec", T::kUnsigned)}, make<DelayNode>(false)},
      {"ForceSuccess", K::kDecorator, {}, make<ForceNode>(BtStatus::kSuccess)},
      {"ForceFailure", K::kDecorator, {}, make<ForceNode>(BtStatus::kFailure)},
      {"RunOnce", K::kDecorator, {in("then_skip", T::kBool, "true")}, make<RunOnceNode>()},
      {"TimeDelay", K::kDecorator, {in("delay", T::kDouble, "1.0")}, make<DelayNode>(true)},
      {"SetBlackboard",
       K::kAction,
       {in("value", T::kString), BtPortSpec{"output_key", BtPortDirection::kInOut, T::kString, std::nullopt}},
       make<SetBlackboardNode>()},
      {"AlwaysSuccess", K::kAction, {}, make<ConstantNode>(BtStatus::kSuccess)},
      {"AlwaysFailure", K::kAction, {}, make<ConstantNode>(BtStatus::kFailure)},
  };
  return nodes;
}

}  // namespace socsim::crowd
