// schemas/openapi.yaml is kept true: it parses, is OpenAPI 3.1, and every operation it documents
// exists on the server (a route miss would answer "no resource at …").
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <regex>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

TEST(OpenApi, EveryDocumentedOperationIsServed) {
  testing::TestServer s;
  auto c = s.client();
  auto r = c.Get("/api/v1/openapi.yaml");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  YAML::Node doc = YAML::Load(r->body);
  EXPECT_EQ(doc["openapi"].as<std::string>().substr(0, 3), "3.1");
  int operations = 0;
  for (const auto& path : doc["paths"]) {
    // Fill path parameters with plausible but unknown values: a documented route answers with
    // its own 404 ("no card with id …"), a missing one with the router's "no resource at".
    const std::string url = std::regex_replace(path.first.as<std::string>(), std::regex(R"(\{[^}]+\})"), "x");
    for (const auto& op : path.second) {
      const std::string method = op.first.as<std::string>();
      if (method != "get" && method != "post" && method != "delete") continue;
      httplib::Result res = method == "get"    ? c.Get(url.c_str())
                            : method == "post" ? c.Post(url.c_str(), "{}", "application/json")
                                               : c.Delete(url.c_str());
      ++operations;
      ASSERT_TRUE(res) << method << " " << url;
      EXPECT_EQ(res->body.find("no resource at"), std::string::npos)
          << method << " " << url << " is documented but not served";
    }
  }
  EXPECT_GE(operations, 15);
}

}  // namespace
}  // namespace socsim::server
