// Property (issue 14 acceptance): whatever one field of a valid request body is replaced with,
// the API answers 4xx with a problem document, never 5xx, and keeps answering. Every POST
// endpoint of schemas/openapi.yaml gets a valid example body; each of its fields (top level, and
// nested ones down to kMaxDepth through objects and the first element of arrays) is replaced in
// turn by each bad value below, and one unknown key is added at each level.
//
// A "bad" value can be a valid one for some fields (0 for a seed, "" for a description, {} for
// optional metrics): those answers are 2xx, which is fine; created jobs are cancelled and live
// simulations deleted at once, so they cost nothing. What must never happen is a 5xx, a reply
// that is not application/problem+json for a 4xx, or a server that stops answering.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

constexpr int kMaxDepth = 3;  // /zones/0/polygon is depth 3
constexpr const char* kPlaceholder = "\x01__bad_value__\x01";

// The replacements, as raw JSON text (some, like a 400-digit number, have no nlohmann value).
const std::vector<std::pair<std::string, std::string>>& bad_values() {
  static const std::vector<std::pair<std::string, std::string>> values = [] {
    std::string deep;
    for (int i = 0; i < 60; ++i) deep += "[";
    for (int i = 0; i < 60; ++i) deep += "]";
    return std::vector<std::pair<std::string, std::string>>{
        {"null", "null"},
        {"true", "true"},
        {"false", "false"},
        {"zero", "0"},
        {"minus one", "-1"},
        {"fraction", "0.5"},
        {"1e308", "1e308"},
        {"-1e308", "-1e308"},
        {"1e400 (overflows a double)", "1e400"},
        {"2^64", "18446744073709551616"},
        {"400-digit integer", std::string(400, '9')},
        {"\"NaN\"", "\"NaN\""},
        {"\"-Infinity\"", "\"-Infinity\""},
        {"empty string", "\"\""},
        {"100 kB string", "\"" + std::string(100'000, 'x') + "\""},
        {"NUL character", "\"a\\u0000b\""},
        {"lone surrogate", "\"\\ud800\""},
        {"empty array", "[]"},
        {"empty object", "{}"},
        {"object for a string", "{\"name\": \"x\"}"},
        {"array of numbers", "[1, 2, 3]"},
        {"60-deep array", deep},
    };
  }();
  return values;
}

struct Endpoint {
  std::string path;
  Json body;
  std::string content_type = "application/json";
};

// Paths (JSON pointers, as token lists) to every member of an object reachable from the body
// through objects and the first element of arrays.
void member_paths(const Json& v, std::vector<std::string>& prefix, int depth,
                  std::vector<std::vector<std::string>>& out) {
  if (depth >= kMaxDepth) return;
  if (v.is_object()) {
    for (const auto& [k, child] : v.items()) {
      prefix.push_back(k);
      out.push_back(prefix);
      member_paths(child, prefix, depth + 1, out);
      prefix.pop_back();
    }
  } else if (v.is_array() && !v.empty()) {
    prefix.push_back("0");
    out.push_back(prefix);
    member_paths(v[0], prefix, depth + 1, out);
    prefix.pop_back();
  }
}

Json& at(Json& root, const std::vector<std::string>& path) {
  Json* v = &root;
  for (const auto& t : path) v = v->is_array() ? &(*v)[std::stoul(t)] : &(*v)[t];
  return *v;
}

std::string pointer_of(const std::vector<std::string>& path) {
  std::string p;
  for (const auto& t : path) p += "/" + t;
  return p.empty() ? "/" : p;
}

class BadInput : public ::testing::Test {
 protected:
  static ServerConfig config() {
    ServerConfig c;
    c.rate_limit_rps = 0;            // thousands of requests from one client, on purpose
    c.max_jobs_per_client = 100000;  // accepted jobs are cancelled at once
    c.job_workers = 1;
    c.sim_idle_s = 3600;  // the controlled simulation must outlive the test
    return c;
  }
  TestServer server_{config()};
  httplib::Client client_ = server_.client();

  Json post_ok(const std::string& path, const Json& body, int status) {
    auto r = client_.Post(path.c_str(), body.dump(), "application/json");
    EXPECT_TRUE(r) << path;
    if (!r) return Json();
    EXPECT_EQ(r->status, status) << path << ": " << r->body;
    return Json::parse(r->body);
  }

  // Undoes what an accepted request started, so that the next ones are judged alone.
  void clean_up(const std::string& path, const httplib::Response& r) {
    if (r.status != 201 && r.status != 202) return;
    const Json j = Json::parse(r.body, nullptr, false);
    if (!j.is_object() || !j.contains("id") || !j["id"].is_string()) return;
    const std::string id = j["id"];
    if (r.status == 202 && id.rfind("job_", 0) == 0) client_.Delete(("/api/v1/jobs/" + id).c_str());
    if (path == "/api/v1/simulations") client_.Delete(("/api/v1/simulations/" + id).c_str());
  }
};

Json world_document() {
  return {
      {"name", "two_rooms"},
      {"zones",
       {{{"name", "lobby"}, {"type", "lobby"}, {"polygon", {{0, 0}, {6, 0}, {6, 6}, {0, 6}}}},
        {{"name", "office_1"}, {"type", "office"}, {"polygon", {{6, 0}, {10, 0}, {10, 6}, {6, 6}}}}}},
      {"doors",
       {{{"name", "entrance"}, {"pose", {3, 0}}, {"width", 1.8}, {"connects", {"lobby"}}},
        {{"name", "d1"}, {"pose", {6, 3}}, {"width", 1.2}, {"connects", {"lobby", "office_1"}}}}},
      {"segmentation",
       {{{"name", "queue"}, {"kind", "queue_lane"}, {"polygon", {{1, 1}, {2, 1}, {2, 3}, {1, 3}}}}}},
      {"entities", {{{"type", "desk"}, {"name", "desk_1"}, {"pose", {8, 3}}, {"affordances", {"work"}}}}}};
}

Json program() {
  return {
      {"name", "walkers"},
      {"dt", 0.05},
      {"agents",
       {{{"name", "east"}, {"position", {1.0, 2.0}}, {"speed", 1.2}, {"goals", {{8.0, 2.0}, {1.0, 2.0}}}}}}};
}

TEST_F(BadInput, EveryPostFieldReplacedByEveryBadValueIsA4xxProblem) {
  const auto started = std::chrono::steady_clock::now();
  // Resources the sub-resource endpoints need.
  const Json card_body = {{"title", "Reception rush"},
                          {"description", "Patients queue at reception."},
                          {"tags", {"queue", "hospital"}},
                          {"prompt", "patients queue at the reception desk"},
                          {"seed", 7},
                          {"generator", {{"name", "offline"}, {"model", "none"}}},
                          {"domain", "hospital"},
                          {"world", world_document()},
                          {"metrics", {{"agents", 12}}},
                          {"provenance", {{"source", "test"}}}};
  const std::string card_id = post_ok("/api/v1/cards", card_body, 201)["id"];
  const Json exported = Json::parse(client_.Get(("/api/v1/cards/" + card_id + "/export").c_str())->body);
  const Json sim =
      post_ok("/api/v1/simulations",
              {{"program", program()}, {"world", world_document()}, {"seed", 1}, {"speed", 1}}, 201);
  const std::string sim_id = sim["id"];

  const std::vector<Endpoint> endpoints = {
      {"/api/v1/cards", card_body},
      {"/api/v1/cards/" + card_id + "/versions",
       {{"title", "Evening rush"}, {"seed", 8}, {"tags", {"evening"}}}},
      {"/api/v1/cards/import", exported},
      {"/api/v1/cards/" + card_id + "/replay", {{"note", "the body is not read"}}},
      {"/api/v1/personas",
       {{"name", "Ilse Brandt"},
        {"age", 51},
        {"gender", "female"},
        {"routine", "She goes to bed at 11 pm and gets up at 7 am."},
        {"personality", {"curious"}},
        {"occupation", "She is a potter with a studio in the garden."},
        {"thoughts", "She is preparing a market stall."},
        {"lifestyle", "She lives alone and grows tomatoes."}}},
      {"/api/v1/personas/generate",
       {{"count", 1},
        {"seed", 3},
        {"generator", "offline"},
        {"store", false},
        {"constraints",
         {{"min_age", 30}, {"max_age", 60}, {"household_role", "single"}, {"gender", "male"}}}}},
      {"/api/v1/households",
       {{"rooms", 4},
        {"residents", 1},
        {"days", 1},
        {"start_weekday", "Monday"},
        {"seed", 1},
        {"generator", "offline"}}},
      {"/api/v1/navbench",
       {{"split", "normal"},
        {"scenes", 1},
        {"seed", 1},
        {"tasks_per_scene", 1},
        {"max_steps", 10},
        {"training_houses", 10},
        {"alpha", 0.5}}},
      {"/api/v1/worlds",
       {{"prompt", "a small office with two rooms"},
        {"seed", 1},
        {"domain", "office"},
        {"generator", "offline"},
        {"jurisdiction", "US"}}},
      {"/api/v1/worlds",
       {{"scene_graph",
         {{"rooms",
           {{{"name", "a"}, {"type", "office"}, {"area", 12}}, {{"name", "b"}, {"type", "corridor"}}}},
          {"adjacency", {{"a", "b"}}},
          {"entrance", "b"},
          {"domain", "office"}}},
        {"seed", 2}}},
      {"/api/v1/worlds/validate", world_document(), "application/yaml"},
      {"/api/v1/scenarios",
       {{"prompt", "people queue at the reception desk"},
        {"duration_s", 2},
        {"seed", 1},
        {"generator", "offline"},
        {"agents", 5},
        {"title", "queue"},
        {"tags", {"queue"}},
        {"world", world_document()}}},
      {"/api/v1/simulations",
       {{"program", program()}, {"world", world_document()}, {"seed", 1}, {"speed", 1}, {"duration_s", 5}}},
      {"/api/v1/simulations/" + sim_id + "/control", {{"action", "speed"}, {"value", 2}}},
  };

  std::size_t requests = 0, accepted = 0;
  std::map<std::string, int> failures;  // "path pointer value → status"
  auto send = [&](const Endpoint& e, const std::string& text, const std::string& what) {
    auto r = client_.Post(e.path.c_str(), text, e.content_type.c_str());
    ++requests;
    if (!r) {
      failures[e.path + " " + what + " → no answer"] = 0;
      return;
    }
    if (r->status >= 200 && r->status < 300) {
      ++accepted;
      if (std::getenv("SOCSIM_PROPERTY_VERBOSE")) std::cout << "accepted: " << e.path << " " << what << "\n";
      clean_up(e.path, *r);
      return;
    }
    const bool problem = r->get_header_value("Content-Type") == "application/problem+json";
    if (r->status < 400 || r->status >= 500 || !problem)
      failures[e.path + " " + what + " → " + std::to_string(r->status) + " " + r->body.substr(0, 200)] =
          r->status;
  };

  for (const Endpoint& e : endpoints) {
    std::vector<std::vector<std::string>> paths;
    std::vector<std::string> prefix;
    member_paths(e.body, prefix, 0, paths);
    for (const auto& path : paths) {
      Json body = e.body;
      at(body, path) = kPlaceholder;
      const std::string text = body.dump();
      const std::string quoted = Json(kPlaceholder).dump();
      const std::size_t pos = text.find(quoted);
      ASSERT_NE(pos, std::string::npos);
      for (const auto& [name, raw] : bad_values()) {
        std::string bad = text;
        bad.replace(pos, quoted.size(), raw);
        send(e, bad, pointer_of(path) + " = " + name);
      }
      // An unknown key beside the field.
      std::vector<std::string> parent(path.begin(), path.end() - 1);
      Json& container = at(body, parent);
      if (container.is_object()) {
        Json extra = e.body;
        at(extra, parent)["zz_unknown_field"] = 1;
        send(e, extra.dump(), pointer_of(parent) + " + unknown key");
      }
    }
    // The body as a whole replaced.
    for (const auto& [name, raw] : bad_values()) send(e, raw, "whole body = " + name);
    auto health = client_.Get("/api/v1/health");
    ASSERT_TRUE(health) << "the server stopped answering after " << e.path;
    ASSERT_EQ(health->status, 200);
  }

  std::string report;
  for (const auto& [what, status] : failures) report += "\n  " + what;
  EXPECT_TRUE(failures.empty()) << failures.size() << " of " << requests
                                << " answers were not 4xx problems:" << report;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << "bad_input_property: " << endpoints.size() << " endpoints, " << requests << " requests, "
            << accepted << " accepted (the value was valid there), " << failures.size() << " failures, "
            << seconds << " s\n";
  auto health = client_.Get("/api/v1/health");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

}  // namespace
}  // namespace socsim::server
