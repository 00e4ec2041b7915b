#include "core/crowd/bt_document.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace socsim::crowd {

// --- registry ----------------------------------------------------------------------------------

BtRegistry BtRegistry::builtins() {
  BtRegistry r;
  for (const BtBuiltinNode& n : bt_builtin_nodes())
    (void)r.add(BtNodeType{n.name, n.kind, n.ports, n.factory, {}});
  return r;
}

Status BtRegistry::add(BtNodeType type) {
  std::vector<std::string> names = type.aliases;
  names.insert(names.begin(), type.name);
  for (const std::string& n : names)
    if (by_name_.count(n) != 0)
      return fail(ErrorCode::kConflict, "behaviour node name '" + n + "' is already registered");
  const std::size_t index = types_.size();
  types_.push_back(std::make_shared<const BtNodeType>(std::move(type)));
  for (const std::string& n : names) by_name_.emplace(n, index);
  return {};
}

const BtNodeType* BtRegistry::find(std::string_view name_or_alias) const {
  auto it = by_name_.find(name_or_alias);
  return it == by_name_.end() ? nullptr : types_[it->second].get();
}

std::vector<const BtNodeType*> BtRegistry::types() const {
  std::vector<const BtNodeType*> out;
  for (const auto& t : types_) out.push_back(t.get());
  return out;
}

// --- document ----------------------------------------------------------------------------------

// The parsed document; BtDocument::Impl is one (a named namespace: a base of a class declared in
// the header cannot have internal linkage).
namespace document_detail {
struct DocumentData {
  std::map<std::string, BtNodeSpec, std::less<>> trees;
  std::string main;
  std::map<std::string, BtFactory, std::less<>> factories;
};
}  // namespace document_detail
using document_detail::DocumentData;

namespace {

using world::XmlElement;

struct RawTree {
  const XmlElement* element;
  std::string file;
  int version;
};

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(3, name.size() / 3) + 1;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(name, k);
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

std::optional<std::string> key_of(std::string_view text) {
  if (text.size() >= 2 && text.front() == '{' && text.back() == '}')
    return std::string(text.substr(1, text.size() - 2));
  return std::nullopt;
}

class Loader {
 public:
  Loader(const BtRegistry& registry, const BtLoadOptions& options) : registry_(registry), options_(options) {
    for (const BtNodeType* t : registry.types()) {
      known_.push_back(t->name);
      for (const auto& a : t->aliases) known_.push_back(a);
    }
  }

  // Reads one file's (or text's) root: trees, includes; returns false on a fatal problem.
  bool read_root(std::string_view text, const std::string& file, const std::filesystem::path& dir, int depth,
                 std::string* main_out) {
    auto root = world::parse_xml(text, options_.limits);
    if (!root) {
      syntax_error_ = true;
      for (const FieldError& e : root.error().errors) error(file, e.line, e.column, "XML: " + e.message);
      if (root.error().errors.empty()) error(file, 0, 0, root.error().detail);
      return false;
    }
    return read_element(std::move(*root), file, dir, depth, main_out);
  }

  // The same for a document already held as elements (built in code, never written out).
  bool read_element(XmlElement root, const std::string& file, const std::filesystem::path& dir, int depth,
                    std::string* main_out) {
    documents_.push_back(std::make_unique<XmlElement>(std::move(root)));
    const XmlElement& r = *documents_.back();
    if (r.name != "root") {
      error(file, r.line, r.column, "the document element must be <root>, not <" + r.name + ">");
      return false;
    }
    int version = 3;
    if (const std::string* f = r.attribute("BTCPP_format")) {
      if (*f == "4") {
        version = 4;
      } else if (*f != "3") {
        error(file, r.line, r.column, "BTCPP_format must be 3 or 4, not '" + *f + "'");
        return false;
      }
    }
    for (const auto& [k, v] : r.attributes)
      if (k != "BTCPP_format" && k != "main_tree_to_execute")
        error(file, r.line, r.column, "unknown attribute '" + k + "' of <root>");
    if (main_out != nullptr)
      if (const std::string* m = r.attribute("main_tree_to_execute")) *main_out = *m;
    std::vector<std::string> local_trees;
    for (const XmlElement& c : r.children) {
      if (c.name == "TreeNodesModel") continue;  // documentation for editors (Groot); not needed
      if (c.name == "include") {
        include(c, file, dir, depth);
        continue;
      }
      if (c.name != "BehaviorTree") {
        error(file, c.line, c.column,
              "unexpected <" + c.name + "> in <root> (expected BehaviorTree, include or TreeNodesModel)");
        continue;
      }
      const std::string* id = c.attribute("ID");
      std::string tree_id = id != nullptr ? *id : std::string();
      if (tree_id.empty()) {
        if (version == 4 && main_out != nullptr && r.children_named("BehaviorTree").size() == 1) {
          tree_id = "MainTree";
        } else {
          error(file, c.line, c.column, "<BehaviorTree> needs an ID attribute");
          continue;
        }
      }
      if (raw_.count(tree_id) != 0) {
        error(file, c.line, c.column, "BehaviorTree ID '" + tree_id + "' is defined twice");
        continue;
      }
      std::vector<const XmlElement*> nodes;
      for (const XmlElement& n : c.children) nodes.push_back(&n);
      if (nodes.size() != 1) {
        error(file, c.line, c.column, "BehaviorTree '" + tree_id + "' must have exactly one root node");
        continue;
      }
      raw_.emplace(tree_id, RawTree{nodes[0], file, version});
      order_.push_back(tree_id);
      local_trees.push_back(tree_id);
    }
    if (main_out != nullptr && main_out->empty()) {
      if (local_trees.size() == 1) {
        *main_out = local_trees[0];
      } else {
        error(file, r.line, r.column,
              local_trees.empty() ? "the document has no <BehaviorTree>"
                                  : "several trees and no main_tree_to_execute attribute on <root>");
      }
    }
    return true;
  }

  void build(DocumentData& impl) {
    if (!impl.main.empty() && raw_.count(impl.main) == 0 && errors_.empty())
      error("", 0, 0, "main_tree_to_execute names '" + impl.main + "', which is not defined");
    for (const std::string& id : order_) {
      const RawTree& raw = raw_.at(id);
      version_ = raw.version;
      file_ = raw.file;
      BtNodeSpec spec = convert(*raw.element);
      impl.trees.emplace(id, std::move(spec));
    }
    for (const BtNodeType* t : registry_.types()) impl.factories.emplace(t->name, t->factory);
    check_keys();
    check_instances(impl);
  }

  [[nodiscard]] bool ok() const { return errors_.empty(); }
  [[nodiscard]] Error failure() const {
    std::string detail = details_.empty() ? "invalid behaviour tree" : details_.front();
    if (errors_.size() > 1) detail += " (and " + std::to_string(errors_.size() - 1) + " more)";
    return Error(syntax_error_ ? ErrorCode::kBadRequest : ErrorCode::kValidation, detail, errors_);
  }

 private:
  void error(const std::string& file, int line, int column, const std::string& message) {
    if (errors_.size() >= 50) return;
    errors_.push_back(FieldError{"", (file.empty() ? "" : file + ": ") + message, {}, line, column});
    details_.push_back((file.empty() ? "line " : file + ":") + std::to_string(line) + ": " + message);
  }
  void error(const XmlElement& e, const std::string& message) { error(file_, e.line, e.column, message); }

  void include(const XmlElement& c, const std::string& file, const std::filesystem::path& dir, int depth) {
    if (c.attribute("ros_pkg") != nullptr) {
      error(file, c.line, c.column,
            "<include ros_pkg=…> is not supported; give a path relative to this file");
      return;
    }
    const std::string* path = c.attribute("path");
    if (path == nullptr || path->empty()) {
      error(file, c.line, c.column, "<include> needs a path attribute");
      return;
    }
    if (dir.empty()) {
      error(file, c.line, c.column, "<include path=\"" + *path + "\"> cannot be resolved: no base directory");
      return;
    }
    if (depth >= options_.max_include_depth) {
      error(file, c.line, c.column,
            "includes nested deeper than " + std::to_string(options_.max_include_depth));
      return;
    }
    const std::filesystem::path rel(*path);
    std::filesystem::path target = (dir / rel).lexically_normal();
    if (options_.confine_includes) {
      const std::filesystem::path base =
          std::filesystem::weakly_canonical(options_.base_dir.empty() ? dir : options_.base_dir);
      const std::filesystem::path resolved = std::filesystem::weakly_canonical(target);
      const auto mismatch = std::mismatch(base.begin(), base.end(), resolved.begin(), resolved.end());
      if (rel.is_absolute() || mismatch.first != base.end()) {
        error(file, c.line, c.column, "<include path=\"" + *path + "\"> leaves the scenario directory");
        return;
      }
      target = resolved;
    }
    const std::string key = target.string();
    if (std::find(include_stack_.begin(), include_stack_.end(), key) != include_stack_.end()) {
      error(file, c.line, c.column, "<include path=\"" + *path + "\"> includes itself");
      return;
    }
    if (included_.count(key) != 0) return;  // already read (diamond includes)
    std::ifstream in(target, std::ios::binary);
    if (!in) {
      error(file, c.line, c.column, "<include path=\"" + *path + "\">: cannot read " + key);
      return;
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (text.str().size() > options_.limits.max_bytes) {
      error(file, c.line, c.column, "<include path=\"" + *path + "\">: file too large");
      return;
    }
    included_.insert(key);
    include_stack_.push_back(key);
    read_root(text.str(), target.filename().string(), target.parent_path(), depth + 1, nullptr);
    include_stack_.pop_back();
  }

  BtNodeSpec convert(const XmlElement& e) {
    BtNodeSpec spec;
    spec.file = file_;
    spec.line = e.line;
    std::string type_name = e.name;
    const bool generic =
        e.name == "Action" || e.name == "Condition" || e.name == "Control" || e.name == "Decorator";
    if (generic) {
      const std::string* id = e.attribute("ID");
      if (id == nullptr) {
        error(e, "<" + e.name + "> needs an ID attribute naming the node");
        return spec;
      }
      type_name = *id;
    }
    if (version_ == 3 && type_name == "RetryUntilSuccesful")
      type_name = "RetryUntilSuccessful";  // v3 spelling
    const BtNodeType* type = registry_.find(type_name);
    if (type == nullptr) {
      error(e, "unknown node '" + type_name + "'" + did_you_mean(type_name, known_));
      return spec;
    }
    spec.type = type->name;
    spec.kind = type->kind;
    spec.name = e.attribute("name") != nullptr ? *e.attribute("name") : type->name;

    const std::size_t children = e.children.size();
    switch (type->kind) {
      case BtNodeKind::kAction:
      case BtNodeKind::kCondition:
      case BtNodeKind::kSubTree:
        if (children != 0) error(e, spec.type + " cannot have child nodes");
        break;
      case BtNodeKind::kDecorator:
        if (children != 1)
          error(e, "decorator " + spec.type + " needs exactly one child, it has " + std::to_string(children));
        break;
      case BtNodeKind::kControl:
        if (children == 0) error(e, "control node " + spec.type + " needs at least one child");
        break;
    }
    if (type->kind == BtNodeKind::kSubTree) {
      subtree(e, spec);
      return spec;
    }

    std::set<std::string> given;
    for (const auto& [raw_key, value] : e.attributes) {
      if (raw_key == "name" || (generic && raw_key == "ID")) continue;
      std::string key = raw_key;
      if (version_ == 3 && spec.type == "Parallel") {
        if (key == "success_threshold") key = "success_count";
        if (key == "failure_threshold") key = "failure_count";
      }
      if (!key.empty() && key[0] == '_') {
        error(e, "attribute '" + key + "' (BT.CPP scripting/pre-conditions) is not supported");
        continue;
      }
      const auto port = std::find_if(type->ports.begin(), type->ports.end(),
                                     [&](const BtPortSpec& p) { return p.name == key; });
      if (port == type->ports.end()) {
        std::string names;
        for (const BtPortSpec& p : type->ports) names += (names.empty() ? "" : ", ") + p.name;
        error(e, spec.type + " has no port '" + key + "' (ports: " + (names.empty() ? "none" : names) + ")");
        continue;
      }
      given.insert(key);
      bind(e, spec, *port, value, false);
    }
    for (const BtPortSpec& p : type->ports) {
      if (given.count(p.name) != 0) continue;
      if (p.default_value) {
        bind(e, spec, p, *p.default_value, true);
      } else if (p.direction == BtPortDirection::kOut) {
        spec.ports.push_back(BtPortBinding{p.name, p.direction, p.type, std::nullopt, {}});
      } else {
        error(e, spec.type + " is missing the required port '" + p.name + "' (" +
                     std::string(bt_port_type_name(p.type)) + ")");
      }
    }
    for (const XmlElement& c : e.children) spec.children.push_back(convert(c));
    return spec;
  }

  void bind(const XmlElement& e, BtNodeSpec& spec, const BtPortSpec& port, const std::string& text,
            bool is_default) {
    BtPortBinding b{port.name, port.direction, port.type, std::nullopt, {}};
    if (auto key = key_of(text)) {
      b.key = *key == "=" ? port.name : *key;
      if (b.key->empty()) error(e, "port '" + port.name + "': empty blackboard key {}");
      if (port.direction != BtPortDirection::kOut)
        reads_.push_back({file_, e.line, e.column, spec.type, port.name, *b.key, port.type});
      if (port.direction != BtPortDirection::kIn) written_.insert(*b.key);
    } else {
      if (port.direction == BtPortDirection::kOut) {
        error(e, "output port '" + port.name + "' must name a blackboard entry like {" + port.name +
                     "}, not '" + text + "'");
        return;
      }
      auto v = bt_convert(BtValue{text}, port.type);
      if (!v) {
        error(e, std::string(is_default ? "default of port '" : "port '") + port.name +
                     "': " + v.error().detail);
        return;
      }
      b.literal = *v;
      if (spec.type == "SetBlackboard" && port.name == "output_key") written_.insert(text);
      if (options_.check_literal && !is_default)
        if (auto problem = options_.check_literal(spec, b)) error(e, "port '" + port.name + "': " + *problem);
    }
    spec.ports.push_back(std::move(b));
  }

  void subtree(const XmlElement& e, BtNodeSpec& spec) {
    const std::string* id = e.attribute("ID");
    if (id == nullptr || id->empty()) {
      error(e, "SubTree needs an ID attribute");
      return;
    }
    spec.subtree_id = *id;
    if (raw_.count(*id) == 0) {
      std::vector<std::string> ids(order_.begin(), order_.end());
      error(e, "SubTree ID '" + *id + "' is not a BehaviorTree of this document" + did_you_mean(*id, ids));
    }
    for (const auto& [key, value] : e.attributes) {
      if (key == "ID" || key == "name") continue;
      if (key == "_autoremap" || key == "__autoremap") {
        auto b = bt_convert(BtValue{value}, BtPortType::kBool);
        if (!b)
          error(e, "_autoremap: " + b.error().detail);
        else
          spec.autoremap = std::get<bool>(*b);
        continue;
      }
      if (key == "__shared_blackboard") {
        auto b = bt_convert(BtValue{value}, BtPortType::kBool);
        if (!b)
          error(e, "__shared_blackboard: " + b.error().detail);
        else
          spec.shared_blackboard = std::get<bool>(*b);
        continue;
      }
      if (!key.empty() && key[0] == '_') {
        error(e, "attribute '" + key + "' of SubTree is not supported");
        continue;
      }
      auto k = key_of(value);
      written_.insert(key);
      if (version_ == 3) {
        // v3: every attribute remaps the subtree's key to the parent's key of that name.
        const std::string parent = k ? *k : value;
        spec.remaps.emplace_back(key, parent);
        written_.insert(parent);  // remaps are two-way: the subtree may write it
      } else if (k) {
        const std::string parent = *k == "=" ? key : *k;
        spec.remaps.emplace_back(key, parent);
        written_.insert(parent);
      } else {
        spec.literals.emplace_back(key, value);
      }
    }
  }

  void check_keys() {
    std::set<std::string> available = written_;
    std::map<std::string, BtPortType> seeded;
    for (const auto& [k, t] : options_.seeded_keys) {
      available.insert(k);
      seeded[k] = t;
    }
    for (const Read& r : reads_) {
      if (available.count(r.key) == 0) {
        std::string known;
        for (const std::string& k : available) known += (known.empty() ? "" : ", ") + k;
        error(r.file, r.line, r.column,
              r.node + " port '" + r.port + "' reads blackboard key '{" + r.key +
                  "}', which nothing writes (known: " + known + ")");
        continue;
      }
      auto s = seeded.find(r.key);
      if (s == seeded.end() || written_.count(r.key) != 0) continue;
      const bool fits = r.type == BtPortType::kString || r.type == s->second ||
                        (s->second == BtPortType::kInt &&
                         (r.type == BtPortType::kDouble || r.type == BtPortType::kUnsigned));
      if (!fits)
        error(r.file, r.line, r.column,
              r.node + " port '" + r.port + "' is " + std::string(bt_port_type_name(r.type)) + " but {" +
                  r.key + "} holds " + std::string(bt_port_type_name(s->second)));
    }
  }

  // Size and depth of one instance of each tree (SubTrees copied in), and recursive SubTrees,
  // before anything is instantiated: 2 KB of trees that each use the next twice made 2^25 nodes
  // per agent, and a long chain of SubTrees nested deeper than the stack holds. Each tree is
  // measured once; the walk stops at max_instance_depth, so it cannot exhaust the stack itself.
  void check_instances(const DocumentData& impl) {
    struct Shape {
      std::size_t nodes = 0;
      int depth = 0;
    };
    const std::size_t max_nodes = options_.max_instance_nodes;
    const int max_depth = options_.max_instance_depth;
    const Shape too_big{max_nodes + 1, max_depth + 1};
    std::map<std::string, Shape, std::less<>> measured;
    std::set<std::string, std::less<>> visiting;
    bool recursive = false;
    std::function<Shape(const BtNodeSpec&, int)> node;
    auto tree = [&](const BtNodeSpec& at, const std::string& id, int level) -> Shape {
      if (auto it = measured.find(id); it != measured.end()) return it->second;
      auto t = impl.trees.find(id);
      if (t == impl.trees.end()) return {};
      if (visiting.count(id) != 0) {
        recursive = true;
        error(at.file, at.line, 0,
              "SubTree '" + id + "' includes itself (recursive trees cannot be instantiated)");
        return too_big;
      }
      visiting.insert(id);
      const Shape shape = node(t->second, level);
      visiting.erase(id);
      measured.emplace(id, shape);
      return shape;
    };
    // `level` is the node's depth in the instance (1 for the root).
    node = [&](const BtNodeSpec& s, int level) -> Shape {
      if (level > max_depth) return Shape{1, max_depth + 1};
      Shape out{1, 1};
      auto add = [&](const Shape& below) {
        out.nodes = std::min(out.nodes + below.nodes, max_nodes + 1);
        out.depth = std::min(std::max(out.depth, below.depth + 1), max_depth + 1);
      };
      if (s.kind == BtNodeKind::kSubTree && !s.subtree_id.empty()) add(tree(s, s.subtree_id, level + 1));
      for (const BtNodeSpec& c : s.children) add(node(c, level + 1));
      return out;
    };
    for (const auto& [id, spec] : impl.trees) (void)tree(spec, id, 1);
    if (recursive) return;  // reported where the SubTree names a tree it is part of
    for (const auto& [id, spec] : impl.trees) {
      const Shape shape = measured.at(id);
      if (shape.nodes > max_nodes)
        error(spec.file, spec.line, 0,
              "BehaviorTree '" + id + "' expands to more than " + std::to_string(max_nodes) +
                  " nodes (every SubTree is copied into each instance)");
      else if (shape.depth > max_depth)
        error(
            spec.file, spec.line, 0,
            "BehaviorTree '" + id + "' nests SubTrees deeper than " + std::to_string(max_depth) + " levels");
    }
  }

  struct Read {
    std::string file;
    int line;
    int column;
    std::string node;
    std::string port;
    std::string key;
    BtPortType type;
  };

  const BtRegistry& registry_;
  const BtLoadOptions& options_;
  std::vector<std::string> known_;
  std::vector<std::unique_ptr<XmlElement>> documents_;
  std::map<std::string, RawTree> raw_;
  std::vector<std::string> order_;
  std::set<std::string> included_;
  std::vector<std::string> include_stack_;
  std::vector<FieldError> errors_;
  std::vector<std::string> details_;  // the same errors with "<file>:<line>: " in front
  std::set<std::string> written_;
  std::vector<Read> reads_;
  int version_ = 3;
  std::string file_;
  bool syntax_error_ = false;
};

}  // namespace

struct BtDocument::Impl : DocumentData {};

Result<BtDocument> BtDocument::parse(std::string_view xml, const BtRegistry& registry,
                                     const BtLoadOptions& options) {
  Loader loader(registry, options);
  auto impl = std::make_shared<Impl>();
  loader.read_root(xml, "", options.base_dir, 0, &impl->main);
  if (loader.ok()) loader.build(*impl);
  if (!loader.ok()) return tl::unexpected(loader.failure());
  BtDocument doc;
  doc.impl_ = std::move(impl);
  return doc;
}

Result<BtDocument> BtDocument::from_element(world::XmlElement root, const BtRegistry& registry,
                                            const BtLoadOptions& options) {
  Loader loader(registry, options);
  auto impl = std::make_shared<Impl>();
  loader.read_element(std::move(root), "", options.base_dir, 0, &impl->main);
  if (loader.ok()) loader.build(*impl);
  if (!loader.ok()) return tl::unexpected(loader.failure());
  BtDocument doc;
  doc.impl_ = std::move(impl);
  return doc;
}

Result<BtDocument> BtDocument::load(const std::filesystem::path& file, const BtRegistry& registry,
                                    BtLoadOptions options) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return fail(ErrorCode::kNotFound, "cannot read behaviour tree file " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > options.limits.max_bytes)
    return fail(ErrorCode::kPayloadTooLarge, "behaviour tree file " + file.string() + " is too large");
  const std::filesystem::path dir =
      file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  if (options.base_dir.empty()) options.base_dir = dir;
  Loader loader(registry, options);
  auto impl = std::make_shared<Impl>();
  loader.read_root(text.str(), file.filename().string(), dir, 0, &impl->main);
  if (loader.ok()) loader.build(*impl);
  if (!loader.ok()) return tl::unexpected(loader.failure());
  BtDocument doc;
  doc.impl_ = std::move(impl);
  return doc;
}

const std::string& BtDocument::main_tree() const {
  return impl_->main;
}

std::vector<std::string> BtDocument::tree_ids() const {
  std::vector<std::string> out;
  for (const auto& [id, spec] : impl_->trees) out.push_back(id);
  return out;
}

const BtNodeSpec* BtDocument::tree(std::string_view id) const {
  auto it = impl_->trees.find(id);
  return it == impl_->trees.end() ? nullptr : &it->second;
}

BtTree BtDocument::instantiate(std::string_view id) const {
  BtTree tree;
  tree.document_ = impl_;
  tree.blackboards_.push_back(std::make_unique<BtBlackboard>());
  const Impl& impl = *impl_;
  auto& boards = tree.blackboards_;
  BtTreeContext& ctx = *tree.context_;
  std::function<std::unique_ptr<BtNode>(const BtNodeSpec&, BtBlackboard&)> build =
      [&](const BtNodeSpec& spec, BtBlackboard& bb) -> std::unique_ptr<BtNode> {
    std::unique_ptr<BtNode> node = impl.factories.at(spec.type)(BtNodeInit{spec, ctx, bb});
    if (spec.kind == BtNodeKind::kSubTree) {
      BtBlackboard* sub = &bb;
      if (!spec.shared_blackboard) {
        boards.push_back(std::make_unique<BtBlackboard>(&bb));
        sub = boards.back().get();
        for (const auto& [inner, outer] : spec.remaps) sub->remap(inner, outer);
        for (const auto& [inner, text] : spec.literals) sub->set(inner, BtValue{text});
        sub->set_autoremap(spec.autoremap);
      }
      node->add_child(build(impl.trees.at(spec.subtree_id), *sub));
      return node;
    }
    for (const BtNodeSpec& c : spec.children) node->add_child(build(c, bb));
    return node;
  };
  tree.root_ =
      build(impl.trees.at(std::string(id.empty() ? std::string_view(impl.main) : id)), *boards.front());
  return tree;
}

}  // namespace socsim::crowd
