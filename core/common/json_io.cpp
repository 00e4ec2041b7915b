#include "core/common/json_io.hpp"

#include <algorithm>

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

Result<Json> parse_json_untrusted(std::string_view text, int max_depth) {
  bool too_deep = false;
  // The parser itself is iterative; the callback keeps it from building (and later dumping)
  // values nested past the limit, which are then rejected as a whole.
  const auto cb = [&](int depth, Json::parse_event_t ev, Json&) {
    if ((ev == Json::parse_event_t::object_start || ev == Json::parse_event_t::array_start) &&
        depth + 1 > max_depth)
      too_deep = true;
    return !too_deep;
  };
  try {
    Json j = Json::parse(text.begin(), text.end(), cb, /*allow_exceptions=*/true, /*ignore_comments=*/false);
    if (too_deep) {
      return fail(ErrorCode::kBadRequest, "JSON nesting deeper than " + std::to_string(max_depth) + " levels",
                  {FieldError{"", "nesting too deep", "", 0, 0}});
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
    // 406: a number beyond double's range (1e400). nlohmann throws it without a position; the
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
                {FieldError{"", what, "", at.first, at.second}});
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
