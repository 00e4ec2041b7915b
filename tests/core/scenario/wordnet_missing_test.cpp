// Without WordNet's data the reader fails with a message naming the directory and the package,
// and does not crash. Its own executable: the data is looked up once per process.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/scenario/scenario_intent.hpp"
#include "core/scenario/wordnet.hpp"

namespace socsim::scenario {
namespace {

TEST(WordNetMissing, ClearErrorNotACrash) {
  ::setenv("WNSEARCHDIR", "/nonexistent/wordnet", 1);
  auto intent = interpret_prompt("Two nurses chat by the coffee machine.");
  ASSERT_FALSE(intent.has_value());
  EXPECT_EQ(intent.error().code, ErrorCode::kInternal);
  EXPECT_NE(intent.error().detail.find("/nonexistent/wordnet"), std::string::npos) << intent.error().detail;
  EXPECT_NE(intent.error().detail.find("wordnet-base"), std::string::npos) << intent.error().detail;
  EXPECT_FALSE(WordNet::open().has_value());  // and stays so
}

}  // namespace
}  // namespace socsim::scenario
