#include "core/common/json_io.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

namespace socsim {

std::pair<int, int> line_column(std::string_view text, std::size_t byte_offset) {
  byte_offset = std::min(byte_offset, text.size());
  int line = 1, col = 1;
  for (std::size_t i = 0; i < byte_offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

namespace {

// Where the parser is, for naming a duplicate key by its JSON pointer.
class KeyTracker {
 public:
  void open(bool object) {
    std::string token;
    if (!frames_.empty())
      token = frames_.back().object ? json_pointer_token(frames_.back().key)
                                    : std::to_string(frames_.back().index);
    frames_.push_back({object, std::move(token), {}, {}, 0});
  }
  void close() {
    if (!frames_.empty()) frames_.pop_back();
    element_done();
  }
  void element_done() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
  }
  // False when the current object already has this key.
  bool key(const std::string& k) {
    if (frames_.empty() || !frames_.back().object) return true;
    frames_.back().key = k;
    return frames_.back().keys.insert(k).second;
  }
  // Where the value being read goes (a member's key or an element's index).
  [[nodiscard]] std::string value_pointer() const {
    if (frames_.empty()) return "";
    if (frames_.back().object) return pointer();
    std::string p;
    for (std::size_t i = 1; i < frames_.size(); ++i) p += "/" + frames_[i].token;
    return p + "/" + std::to_string(frames_.back().index);
  }
  [[nodiscard]] std::string pointer() const {
    std::string p;
    for (std::size_t i = 1; i < frames_.size(); ++i) p += "/" + frames_[i].token;
    if (!frames_.empty() && frames_.back().object) p += "/" + json_pointer_token(frames_.back().key);
    return p;
  }

 private:
  struct Frame {
    bool object;
    std::string token;  // how the parent reaches it
    std::set<std::string> keys;
    std::string key;    // the current key (objects)
    std::size_t index;  // the current element (arrays)
  };
  std::vector<Frame> frames_;
};

}  // namespace

Result<Json> parse_json_untrusted(std::string_view text, int max_depth) {
  bool too_deep = false;
  std::optional<std::string> duplicate;  // pointer of the first repeated key
  KeyTracker where;
  // The parser itself is iterative; the callback keeps it from building (and later dumping)
  // values nested past the limit, which are then rejected as a whole. It also refuses an object
  // that names a key twice: nlohmann keeps the last, so a checker and a later reader could
  // disagree about which value was sent.
  const auto cb = [&](int depth, Json::parse_event_t ev, Json& parsed) {
    if ((ev == Json::parse_event_t::object_start || ev == Json::parse_event_t::array_start) &&
        depth + 1 > max_depth)
      too_deep = true;
    if (too_deep) return false;
    switch (ev) {
      case Json::parse_event_t::object_start:
        where.open(true);
        break;
      case Json::parse_event_t::array_start:
        where.open(false);
        break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        where.close();
        break;
      case Json::parse_event_t::key:
        if (!where.key(parsed.get<std::string>()) && !duplicate) duplicate = where.pointer();
        break;
      case Json::parse_event_t::value:
        where.element_done();
        break;
    }
    return true;
  };
  try {
    Json j = Json::parse(text.begin(), text.end(), cb, /*allow_exceptions=*/true, /*ignore_comments=*/false);
    if (too_deep) {
      return fail(ErrorCode::kBadRequest, "JSON nesting deeper than " + std::to_string(max_depth) + " levels",
                  {FieldError{"", "nesting too deep"}});
    }
    if (duplicate) {
      return fail(ErrorCode::kBadRequest, "the JSON names a key twice in one object, at " + *duplicate,
                  {FieldError{*duplicate, "duplicate key"}});
    }
    return j;
  } catch (const Json::parse_error& e) {
    const std::size_t pos = e.byte > 0 ? e.byte - 1 : 0;
    auto [line, col] = line_column(text, pos);
    std::string what = e.what();
    // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 1, column 2: "
    if (auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
    return fail(ErrorCode::kBadRequest,
                "JSON syntax error at line " + std::to_string(line) + ", column " + std::to_string(col) +
                    " (byte " + std::to_string(pos) + ")",
                {FieldError{"", what, "", line, col}});
  } catch (const Json::out_of_range& e) {
    // 406: a number beyond double's range (1e400), named by its pointer (where the parser was)
    // and its line and column. nlohmann throws it without a position; the
    // message quotes the literal, which is found in the text for the line and column.
    std::string what = e.what();
    std::pair<int, int> at{0, 0};
    if (auto open = what.find('\''), close = what.rfind('\'');
        open != std::string::npos && close > open + 1) {
      if (auto pos = text.find(std::string_view(what).substr(open + 1, close - open - 1));
          pos != std::string_view::npos)
        at = line_column(text, pos);
    }
    if (auto p = what.find("number overflow"); p != std::string::npos) what = what.substr(p);
    return fail(ErrorCode::kBadRequest,
                "JSON number out of range at line " + std::to_string(at.first) + ", column " +
                    std::to_string(at.second),
                {FieldError{where.value_pointer(), what, "", at.first, at.second}});
  }
}

std::string canonical_json(const Json& value) {
  return value.dump(-1, ' ', /*ensure_ascii=*/false, Json::error_handler_t::strict);
}

std::string json_pointer_token(std::string_view token) {
  std::string out;
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out.push_back(c);
  }
  return out;
}

}  // namespace socsim
