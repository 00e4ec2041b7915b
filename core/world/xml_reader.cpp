#include "core/world/xml_reader.hpp"

#include <cstdint>

#include "core/common/json_io.hpp"

namespace socsim::world {

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::children_named(std::string_view child) const {
  std::vector<const XmlElement*> out;
  for (const auto& c : children) {
    if (c.name == child) out.push_back(&c);
  }
  return out;
}

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

struct XmlReject {
  std::string message;
  std::size_t pos;
};

class XmlParser {
 public:
  XmlParser(std::string_view text, const XmlLimits& limits) : s_(text), limits_(limits) {}

  XmlElement document() {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // UTF-8 byte order mark
    misc(true);
    if (pos_ >= s_.size() || s_[pos_] != '<') fail("expected the root element");
    XmlElement root = element(1);
    misc(false);
    if (pos_ < s_.size()) fail("content after the root element");
    return root;
  }

  [[nodiscard]] std::size_t pos() const { return pos_; }

 private:
  [[noreturn]] void fail(const std::string& msg) const { throw XmlReject{msg, pos_}; }

  bool starts(std::string_view t) const { return s_.substr(pos_, t.size()) == t; }

  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r'))
      ++pos_;
  }

  void skip_past(std::string_view end, const char* what) {
    const auto at = s_.find(end, pos_);
    if (at == std::string_view::npos) fail(std::string("unterminated ") + what);
    pos_ = at + end.size();
  }

  // Whitespace, comments and (before the root) the XML declaration.
  void misc(bool prolog) {
    while (true) {
      skip_space();
      if (starts("<!--")) {
        comment();
      } else if (starts("<?xml") && prolog && pos_ <= 3) {
        skip_past("?>", "XML declaration");
      } else if (starts("<?")) {
        fail("processing instructions are not supported");
      } else if (starts("<!DOCTYPE") || starts("<!doctype")) {
        fail("DOCTYPE is not allowed (no entity definitions)");
      } else {
        return;
      }
    }
  }

  void comment() {
    pos_ += 4;
    const auto at = s_.find("--", pos_);
    if (at == std::string_view::npos) fail("unterminated comment");
    pos_ = at;
    if (!starts("-->")) fail("'--' inside a comment");
    pos_ += 3;
  }

  static bool name_char(char c, bool first) {
    const auto u = static_cast<unsigned char>(c);
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' || u >= 0x80) return true;
    return !first && ((c >= '0' && c <= '9') || c == '-' || c == '.');
  }

  std::string name() {
    const std::size_t start = pos_;
    if (pos_ >= s_.size() || !name_char(s_[pos_], true)) fail("expected a name");
    while (pos_ < s_.size() && name_char(s_[pos_], false)) ++pos_;
    return std::string(s_.substr(start, pos_ - start));
  }

  void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp == 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) fail("invalid character reference");
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  void entity(std::string& out) {
    const auto end = s_.find(';', pos_);
    if (end == std::string_view::npos || end - pos_ > 12) fail("unterminated entity reference");
    const std::string_view ent = s_.substr(pos_ + 1, end - pos_ - 1);
    if (ent == "lt")
      out += '<';
    else if (ent == "gt")
      out += '>';
    else if (ent == "amp")
      out += '&';
    else if (ent == "quot")
      out += '"';
    else if (ent == "apos")
      out += '\'';
    else if (ent.size() > 1 && ent[0] == '#') {
      const bool hex = ent[1] == 'x';
      const std::string_view digits = ent.substr(hex ? 2 : 1);
      if (digits.empty()) fail("empty character reference");
      std::uint32_t cp = 0;
      for (const char c : digits) {
        int d = -1;
        if (c >= '0' && c <= '9')
          d = c - '0';
        else if (hex && c >= 'a' && c <= 'f')
          d = c - 'a' + 10;
        else if (hex && c >= 'A' && c <= 'F')
          d = c - 'A' + 10;
        if (d < 0) fail("bad character reference");
        cp = cp * (hex ? 16 : 10) + static_cast<std::uint32_t>(d);
        if (cp > 0x10FFFF) fail("invalid character reference");
      }
      append_utf8(out, cp);
    } else {
      fail("unknown entity '&" + std::string(ent) + ";'");
    }
    pos_ = end + 1;
  }

  XmlElement element(int depth) {
    if (depth > limits_.max_depth) fail("elements nested deeper than " + std::to_string(limits_.max_depth));
    if (++elements_ > limits_.max_elements)
      fail("more than " + std::to_string(limits_.max_elements) + " elements");
    XmlElement e;
    e.line = 0;
    const std::size_t open = pos_;
    ++pos_;  // '<'
    e.name = name();
    position(e, open);
    while (true) {
      const std::size_t before = pos_;
      skip_space();
      if (starts("/>")) {
        pos_ += 2;
        return e;
      }
      if (starts(">")) {
        ++pos_;
        break;
      }
      if (pos_ == before) fail("expected whitespace, '>' or '/>' in <" + e.name + ">");
      std::string key = name();
      skip_space();
      if (!starts("=")) fail("attribute '" + key + "' has no value");
      ++pos_;
      skip_space();
      if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\'')) fail("attribute value must be quoted");
      const char quote = s_[pos_++];
      std::string value;
      while (true) {
        if (pos_ >= s_.size()) fail("unterminated attribute value");
        const char c = s_[pos_];
        if (c == quote) break;
        if (c == '<') fail("'<' in attribute value");
        if (c == '&')
          entity(value);
        else
          value += c, ++pos_;
      }
      ++pos_;
      if (e.attribute(key)) fail("duplicate attribute '" + key + "'");
      e.attributes.emplace_back(std::move(key), std::move(value));
    }
    // Content.
    while (true) {
      if (pos_ >= s_.size()) fail("element <" + e.name + "> is not closed");
      if (starts("</")) {
        pos_ += 2;
        const std::string closing = name();
        if (closing != e.name) fail("</" + closing + "> closes <" + e.name + ">");
        skip_space();
        if (!starts(">")) fail("expected '>'");
        ++pos_;
        return e;
      }
      if (starts("<!--")) {
        comment();
      } else if (starts("<![CDATA[")) {
        pos_ += 9;
        const auto at = s_.find("]]>", pos_);
        if (at == std::string_view::npos) fail("unterminated CDATA");
        e.text += s_.substr(pos_, at - pos_);
        pos_ = at + 3;
      } else if (starts("<!") || starts("<?")) {
        fail("unsupported markup");
      } else if (starts("<")) {
        e.children.push_back(element(depth + 1));
      } else if (s_[pos_] == '&') {
        entity(e.text);
      } else {
        e.text += s_[pos_++];
      }
    }
  }

  void position(XmlElement& e, std::size_t at) {
    // Line/column computed incrementally (documents are read front to back).
    while (line_pos_ < at) {
      if (s_[line_pos_] == '\n')
        ++line_, col_ = 1;
      else
        ++col_;
      ++line_pos_;
    }
    e.line = line_;
    e.column = col_;
  }

  std::string_view s_;
  XmlLimits limits_;
  std::size_t pos_ = 0;
  std::size_t elements_ = 0;
  std::size_t line_pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace

Result<XmlElement> parse_xml(std::string_view text, const XmlLimits& limits) {
  if (text.size() > limits.max_bytes) {
    return fail(ErrorCode::kPayloadTooLarge, "XML document is " + std::to_string(text.size()) +
                                                 " bytes; at most " + std::to_string(limits.max_bytes) +
                                                 " allowed");
  }
  XmlParser parser(text, limits);
  try {
    return parser.document();
  } catch (const XmlReject& r) {
    auto [line, column] = line_column(text, std::min(r.pos, text.size()));
    return fail(
        ErrorCode::kBadRequest,
        "XML: " + r.message + " (line " + std::to_string(line) + ", column " + std::to_string(column) + ")",
        {FieldError{"", r.message, {}, line, column}});
  }
}

}  // namespace socsim::world
