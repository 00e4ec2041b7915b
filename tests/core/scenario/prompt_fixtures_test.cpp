// The acceptance bar of prompt understanding: at least 95 % of the facts of the fixture prompts
// (tests/fixtures/prompts, README there) hold in their interpretation. `socsim-bench prompts
// --failures` lists the ones that do not.
#include <gtest/gtest.h>

#include "tests/core/scenario/prompt_facts.hpp"

namespace socsim::scenario {
namespace {

TEST(PromptFixtures, AtLeastNinetyFivePercentOfFactsHold) {
  for (const std::string file : {"everyday", "unseen", "probes"}) {
    const auto prompts =
        facts::load(std::string(SOCSIM_SOURCE_DIR) + "/tests/fixtures/prompts/" + file + ".jsonl");
    ASSERT_FALSE(prompts.empty()) << file;
    facts::Tally tally;
    for (const auto& p : prompts) {
      auto intent = interpret_prompt(p.prompt);
      ASSERT_TRUE(intent.has_value()) << intent.error().message();
      facts::score_intent(p, *intent, tally);
    }
    const auto [held, checked] = tally.all();
    const double adherence = static_cast<double>(held) / checked;
    std::string failures;
    for (const auto& f : tally.failures) failures += "\n  " + f;
    EXPECT_GE(adherence, 0.95) << file << ": " << held << " of " << checked << " facts hold" << failures;
    if (file == std::string("everyday")) {
      EXPECT_GE(prompts.size(), 150u);
    }
  }
}

}  // namespace
}  // namespace socsim::scenario
