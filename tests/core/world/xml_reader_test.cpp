// Strict XML reader: structure, attributes, entities and text; every malformed input an
// error with its line, including DOCTYPE (entity bombs) and mismatched tags.
#include "core/world/xml_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

TEST(XmlReader, ReadsElementsAttributesAndText) {
  auto doc = parse_xml(R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- a scenario -->
<scenario>
  <obstacle x1="-0.5" y1='2'/>
  <note lang="en">A &amp; B &lt;3 &#65;&#x42;<![CDATA[<raw>]]></note>
</scenario>
)");
  ASSERT_TRUE(doc) << doc.error().message();
  EXPECT_EQ(doc->name, "scenario");
  ASSERT_EQ(doc->children.size(), 2u);
  const XmlElement& obstacle = doc->children[0];
  EXPECT_EQ(*obstacle.attribute("x1"), "-0.5");
  EXPECT_EQ(*obstacle.attribute("y1"), "2");
  EXPECT_EQ(obstacle.attribute("x2"), nullptr);
  EXPECT_EQ(obstacle.line, 4);
  EXPECT_EQ(obstacle.column, 3);
  EXPECT_EQ(doc->children[1].text, "A & B <3 AB<raw>");
  EXPECT_EQ(doc->children_named("obstacle").size(), 1u);
}

struct BadXml {
  const char* text;
  const char* message;
  int line;
};

class XmlErrors : public ::testing::TestWithParam<BadXml> {};

TEST_P(XmlErrors, NameWhatAndWhere) {
  auto doc = parse_xml(GetParam().text);
  ASSERT_FALSE(doc);
  EXPECT_EQ(doc.error().code, ErrorCode::kBadRequest);
  EXPECT_THAT(doc.error().detail, HasSubstr(GetParam().message));
  EXPECT_EQ(doc.error().errors.at(0).line, GetParam().line);
}

INSTANTIATE_TEST_SUITE_P(Malformed, XmlErrors,
                         ::testing::Values(BadXml{"<a>\n<b></a>", "</a> closes <b>", 2},
                                           BadXml{"<!DOCTYPE lolz [<!ENTITY lol \"lol\">]>\n<a/>",
                                                  "DOCTYPE is not allowed", 1},
                                           BadXml{"<a x=\"1\" x=\"2\"/>", "duplicate attribute 'x'", 1},
                                           BadXml{"<a>\n  &nbsp;</a>", "unknown entity '&nbsp;'", 2},
                                           BadXml{"<a x=1/>", "attribute value must be quoted", 1},
                                           BadXml{"<a>\n<b/>\n", "element <a> is not closed", 3},
                                           BadXml{"<a/><b/>", "content after the root element", 1},
                                           BadXml{"<a><!-- x -- y --></a>", "'--' inside a comment", 1},
                                           BadXml{"", "expected the root element", 1},
                                           BadXml{"<a>&#0;</a>", "invalid character reference", 1}));

TEST(XmlReader, DepthAndElementCountAreCapped) {
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<a>";
  for (int i = 0; i < 100; ++i) deep += "</a>";
  auto d = parse_xml(deep);
  ASSERT_FALSE(d);
  EXPECT_THAT(d.error().detail, HasSubstr("nested deeper than 64"));
  std::string wide = "<a>";
  for (int i = 0; i < 50; ++i) wide += "<b/>";
  wide += "</a>";
  auto w = parse_xml(wide, XmlLimits{1 << 20, 64, 10});
  ASSERT_FALSE(w);
  EXPECT_THAT(w.error().detail, HasSubstr("more than 10 elements"));
}

TEST(XmlReader, EscapeRoundTrips) {
  const std::string nasty = "a<b>&\"c'";
  auto doc = parse_xml("<x v=\"" + xml_escape(nasty) + "\">" + xml_escape(nasty) + "</x>");
  ASSERT_TRUE(doc);
  EXPECT_EQ(*doc->attribute("v"), nasty);
  EXPECT_EQ(doc->text, nasty);
}

}  // namespace
}  // namespace socsim::world
