// Configuration precedence (flags over environment over defaults), API keys and rate limits.
#include "server/config.hpp"

#include <gtest/gtest.h>

#include "server/auth.hpp"
#include "server/rate_limit.hpp"

namespace socsim::server {
namespace {

TEST(Config, DefaultsMatchTheReadme) {
  auto c = load_config({}, {});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->port, 8080);
  EXPECT_EQ(c->ws_port, 8081);
  EXPECT_EQ(c->db, "./var/socsim.db");
  EXPECT_EQ(c->max_body_bytes, 2u << 20);
  EXPECT_TRUE(c->api_keys.empty());
}

TEST(Config, FlagsOverrideEnvironment) {
  auto c = load_config({"--port", "9000", "--db=/tmp/x.db"},
                       {{"SOCSIM_PORT", "7000"}, {"SOCSIM_WS_PORT", "7001"}});
  ASSERT_TRUE(c) << c.error().message();
  EXPECT_EQ(c->port, 9000);
  EXPECT_EQ(c->ws_port, 7001);
  EXPECT_EQ(c->db, "/tmp/x.db");
}

TEST(Config, BadValuesNameTheOption) {
  auto c = load_config({"--port", "80000"}, {});
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().detail.find("--port"), std::string::npos);
  auto e = load_config({}, {{"SOCSIM_MAX_BODY", "lots"}});
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().detail.find("SOCSIM_MAX_BODY"), std::string::npos);
  EXPECT_FALSE(load_config({"--no-such-flag", "1"}, {}));
  EXPECT_FALSE(load_config({"--port"}, {}));
}

TEST(ApiKeys, ParseAndAuthenticate) {
  auto keys = parse_api_keys("alice:0123456789abcdef,bob:fedcba9876543210");
  ASSERT_TRUE(keys);
  KeyRing ring(*keys);
  EXPECT_TRUE(ring.enabled());
  EXPECT_EQ(ring.authenticate("Bearer 0123456789abcdef").value(), "alice");
  EXPECT_EQ(ring.authenticate("Bearer fedcba9876543210").value(), "bob");
  EXPECT_FALSE(ring.authenticate("Bearer 0123456789abcdeX"));
  EXPECT_FALSE(ring.authenticate("0123456789abcdef"));
  EXPECT_FALSE(ring.authenticate(""));
  EXPECT_FALSE(parse_api_keys("alice:short"));
  EXPECT_FALSE(parse_api_keys("nocolon"));
  EXPECT_FALSE(parse_api_keys("a:0123456789abcdef,a:0123456789abcdeg"));
}

TEST(RateLimiter, AllowsTheBurstThenAsksToWait) {
  RateLimiter limiter(1.0, 3.0);
  EXPECT_EQ(limiter.admit("10.0.0.1"), 0);
  EXPECT_EQ(limiter.admit("10.0.0.1"), 0);
  EXPECT_EQ(limiter.admit("10.0.0.1"), 0);
  EXPECT_GE(limiter.admit("10.0.0.1"), 1);
  EXPECT_EQ(limiter.admit("10.0.0.2"), 0) << "clients have separate buckets";
}

}  // namespace
}  // namespace socsim::server
