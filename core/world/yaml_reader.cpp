#include "core/world/yaml_reader.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <charconv>
#include <cmath>
#include <regex>
#include <sstream>
#include <vector>

namespace socsim::world {

namespace {

struct YamlReject {
  std::string message;
  int line;
  int column;
};

bool is_int(const std::string& s) {
  static const std::regex re("[-+]?[0-9]+");
  return std::regex_match(s, re);
}
bool is_float(const std::string& s) {
  static const std::regex re(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
  return std::regex_match(s, re);
}

Json resolve_plain(const std::string& s, const YAML::Mark& mark) {
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return nullptr;
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  if (is_int(s)) {
    std::int64_t v = 0;
    const char* first = s.data() + (s[0] == '+' ? 1 : 0);
    auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), v);
    if (ec == std::errc() && ptr == s.data() + s.size()) return v;
    // Too large for int64: keep it as a float so range checks can report it.
  }
  if (is_int(s) || is_float(s)) {
    double d = 0;
    const char* first = s.data() + (s[0] == '+' ? 1 : 0);
    auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), d);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(d)) {
      throw YamlReject{"number '" + s + "' is out of range", mark.line + 1, mark.column + 1};
    }
    return d;
  }
  const std::string lower = [&] {
    std::string l = s;
    for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return l;
  }();
  if (lower == ".inf" || lower == "+.inf" || lower == "-.inf" || lower == ".nan") {
    throw YamlReject{"'" + s + "' is not a finite number", mark.line + 1, mark.column + 1};
  }
  return s;
}

class JsonBuilder : public YAML::EventHandler {
 public:
  JsonBuilder(SourcePositions* positions, std::size_t max_nodes)
      : positions_(positions), max_nodes_(max_nodes) {}

  Json take() { return std::move(root_); }
  [[nodiscard]] bool empty() const { return !has_root_; }

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    check(mark, anchor, "?");
    value(mark, nullptr);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { reject_anchor(mark); }
  void OnAnchor(const YAML::Mark& mark, const std::string&) override { reject_anchor(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& v) override {
    check(mark, anchor, tag);
    if (expecting_key()) {
      Frame& f = stack_.back();
      if (f.value.contains(v)) {
        throw YamlReject{"duplicate key '" + v + "'", mark.line + 1, mark.column + 1};
      }
      f.key = v;
      f.have_key = true;
      return;
    }
    value(mark, tag == "!" ? Json(v) : resolve_plain(v, mark));
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    check(mark, anchor, tag);
    open(mark, Json::array());
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    check(mark, anchor, tag);
    open(mark, Json::object());
  }
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    Json value;
    std::string pointer;
    std::string key;
    bool have_key = false;
  };

  [[nodiscard]] bool expecting_key() const {
    return !stack_.empty() && stack_.back().value.is_object() && !stack_.back().have_key;
  }

  static void reject_anchor(const YAML::Mark& mark) {
    throw YamlReject{"YAML anchors and aliases are not allowed", mark.line + 1, mark.column + 1};
  }

  void check(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string& tag) {
    if (++nodes_ > max_nodes_) {
      throw YamlReject{"document has more than " + std::to_string(max_nodes_) + " nodes", mark.line + 1,
                       mark.column + 1};
    }
    if (anchor != YAML::NullAnchor) reject_anchor(mark);
    if (tag != "?" && tag != "!" && !tag.empty()) {
      throw YamlReject{"YAML tags are not supported ('" + tag + "')", mark.line + 1, mark.column + 1};
    }
  }

  // Pointer of the next value in the innermost container.
  std::string next_pointer(const YAML::Mark& mark) {
    if (stack_.empty()) return "";
    Frame& f = stack_.back();
    if (f.value.is_array()) return f.pointer + "/" + std::to_string(f.value.size());
    if (!f.have_key) throw YamlReject{"only plain text keys are supported", mark.line + 1, mark.column + 1};
    return f.pointer + "/" + json_pointer_token(f.key);
  }

  void place(Json v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      has_root_ = true;
      return;
    }
    Frame& f = stack_.back();
    if (f.value.is_array()) {
      f.value.push_back(std::move(v));
    } else {
      f.value[f.key] = std::move(v);
      f.have_key = false;
    }
  }

  void value(const YAML::Mark& mark, Json v) {
    const std::string ptr = next_pointer(mark);
    if (positions_) positions_->set(ptr, mark.line + 1, mark.column + 1);
    place(std::move(v));
  }

  void open(const YAML::Mark& mark, Json container) {
    const std::string ptr = next_pointer(mark);
    if (positions_) positions_->set(ptr, mark.line + 1, mark.column + 1);
    stack_.push_back(Frame{std::move(container), ptr, {}, false});
  }

  void close() {
    Frame f = std::move(stack_.back());
    stack_.pop_back();
    place(std::move(f.value));
  }

  SourcePositions* positions_;
  std::size_t max_nodes_;
  std::size_t nodes_ = 0;
  std::vector<Frame> stack_;
  Json root_;
  bool has_root_ = false;
};

}  // namespace

std::pair<int, int> SourcePositions::find(std::string_view pointer) const {
  std::string p(pointer);
  while (true) {
    auto it = at_.find(p);
    if (it != at_.end()) return it->second;
    if (p.empty()) return {0, 0};
    p.erase(p.find_last_of('/'));
  }
}

void SourcePositions::annotate(Error& error) const {
  for (auto& fe : error.errors) {
    if (fe.line != 0) continue;
    auto [line, column] = find(fe.pointer);
    fe.line = line;
    fe.column = column;
  }
}

Result<Json> parse_yaml_untrusted(std::string_view text, SourcePositions* positions,
                                  const YamlLimits& limits) {
  if (text.size() > limits.max_bytes) {
    return fail(ErrorCode::kPayloadTooLarge, "YAML document is " + std::to_string(text.size()) +
                                                 " bytes; at most " + std::to_string(limits.max_bytes) +
                                                 " allowed");
  }
  auto reject = [](const std::string& msg, int line, int column) {
    return fail(
        ErrorCode::kBadRequest,
        "YAML: " + msg + " (line " + std::to_string(line) + ", column " + std::to_string(column) + ")",
        {FieldError{"", msg, {}, line, column}});
  };
  try {
    std::istringstream in{std::string(text)};
    YAML::Parser parser(in);
    JsonBuilder builder(positions, limits.max_nodes);
    if (!parser.HandleNextDocument(builder) || builder.empty()) return Json(nullptr);
    JsonBuilder extra(nullptr, limits.max_nodes);
    if (parser.HandleNextDocument(extra)) return reject("only one YAML document is allowed", 0, 0);
    return builder.take();
  } catch (const YamlReject& r) {
    return reject(r.message, r.line, r.column);
  } catch (const YAML::Exception& e) {
    return reject(e.msg, e.mark.line + 1, e.mark.column + 1);
  }
}

}  // namespace socsim::world
