// Prompt templates: every embedded template parses, declares the variables it uses and names the
// JSON it answers with; rendering substitutes verbatim and refuses missing or unused variables.
#include "core/llm/prompt_template.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

namespace socsim::llm {
namespace {

using ::testing::HasSubstr;

TEST(PromptTemplates, EveryArtifactOfThePapersHasATemplate) {
  for (const char* name : {"floor_plan", "scenario_program", "persona", "day_plan", "activity_schedule",
                           "activity_database", "hint", "hint_interpretation", "repair", "json_only"}) {
    auto tpl = find_prompt_template(name);
    ASSERT_TRUE(tpl.has_value()) << name;
    EXPECT_THAT((*tpl)->header, HasSubstr("Answers with:")) << name;
  }
}

TEST(PromptTemplates, DeclaredVariablesAreExactlyThePlaceholders) {
  const std::regex declared_line("(^|\\n)Variables: ([a-z_, ]+)");
  for (const auto& [name, tpl] : embedded_prompt_templates()) {
    std::smatch m;
    ASSERT_TRUE(std::regex_search(tpl.header, m, declared_line)) << name << " has no Variables: line";
    std::vector<std::string> declared;
    std::string list = m[2];
    for (std::size_t start = 0; start < list.size();) {
      std::size_t end = list.find(',', start);
      if (end == std::string::npos) end = list.size();
      std::string v = list.substr(start, end - start);
      v.erase(0, v.find_first_not_of(' '));
      v.erase(v.find_last_not_of(' ') + 1);
      if (!v.empty()) declared.push_back(v);
      start = end + 1;
    }
    std::sort(declared.begin(), declared.end());
    EXPECT_EQ(declared, tpl.variables) << name;
  }
}

TEST(PromptTemplates, ArtifactTemplatesAskForOneJsonObject) {
  for (const char* name : {"floor_plan", "scenario_program", "persona", "day_plan", "activity_schedule",
                           "activity_database", "hint", "hint_interpretation"}) {
    const PromptTemplate& tpl = **find_prompt_template(name);
    EXPECT_FALSE(tpl.system.empty()) << name;
    EXPECT_THAT(tpl.user, HasSubstr("Answer with one JSON object")) << name;
  }
}

TEST(PromptTemplates, PaperRequirementsAreInThePrompts) {
  const auto text = [](const char* name) {
    const PromptTemplate& t = **find_prompt_template(name);
    return t.system + "\n" + t.user;
  };
  EXPECT_THAT(text("floor_plan"), HasSubstr("{{constraints}}"));
  EXPECT_THAT(text("scenario_program"), HasSubstr("BehaviorTree.CPP v4"));
  EXPECT_THAT(text("scenario_program"), HasSubstr("Ambient groups"));
  EXPECT_THAT(text("activity_schedule"), HasSubstr("\"leave home\""));
  EXPECT_THAT(text("activity_schedule"), HasSubstr("granularity"));
  EXPECT_THAT(text("activity_database"), HasSubstr("p(l|a)"));
  EXPECT_THAT(text("activity_database"), HasSubstr("p(r|o,a,l)"));
  EXPECT_THAT(text("activity_database"), HasSubstr("sum to 1"));
  EXPECT_THAT(text("persona"), HasSubstr("eight fields"));
}

TEST(PromptTemplates, RenderingSubstitutesVerbatim) {
  auto tpl = parse_prompt_template("t",
                                   "# t\nAnswers with: x\n\n## system\nBe {{ mood }}.\n\n## user\nSay "
                                   "{{what}} {{what}}; keep {\"a\": {\"b\": 1}} and {{ 3 }}.\n");
  ASSERT_TRUE(tpl.has_value()) << tpl.error().message();
  EXPECT_EQ(tpl->variables, (std::vector<std::string>{"mood", "what"}));
  auto messages = render_prompt(*tpl, {{"mood", "brief"}, {"what", "{{mood}}"}});
  ASSERT_TRUE(messages.has_value()) << messages.error().message();
  ASSERT_EQ(messages->size(), 2u);
  EXPECT_EQ((*messages)[0].role, "system");
  EXPECT_EQ((*messages)[0].content, "Be brief.");
  EXPECT_EQ((*messages)[1].content, "Say {{mood}} {{mood}}; keep {\"a\": {\"b\": 1}} and {{ 3 }}.");
}

TEST(PromptTemplates, MissingAndUnusedVariablesAreErrors) {
  auto tpl = parse_prompt_template("t", "## user\nHello {{name}}\n");
  ASSERT_TRUE(tpl.has_value());
  auto missing = render_prompt(*tpl, {});
  ASSERT_FALSE(missing.has_value());
  EXPECT_THAT(missing.error().detail, HasSubstr("needs {{name}}"));
  auto unused = render_prompt(*tpl, {{"name", "x"}, {"nmae", "y"}});
  ASSERT_FALSE(unused.has_value());
  EXPECT_THAT(unused.error().detail, HasSubstr("has no {{nmae}}"));
}

TEST(PromptTemplates, MalformedTemplatesAreRefusedWithALine) {
  auto none = parse_prompt_template("t", "just text\n");
  ASSERT_FALSE(none.has_value());
  EXPECT_THAT(none.error().detail, HasSubstr("neither"));
  auto twice = parse_prompt_template("t", "## user\na\n## user\nb\n");
  ASSERT_FALSE(twice.has_value());
  EXPECT_EQ(twice.error().errors.at(0).line, 3);
  auto order = parse_prompt_template("t", "## user\na\n## system\nb\n");
  ASSERT_FALSE(order.has_value());
  auto open = parse_prompt_template("t", "## user\nline one\nHello {{name\n");
  ASSERT_FALSE(open.has_value());
  EXPECT_THAT(open.error().detail, HasSubstr("not closed"));
  EXPECT_EQ(open.error().errors.at(0).line, 3);
}

}  // namespace
}  // namespace socsim::llm
