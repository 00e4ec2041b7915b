// The REST API as a client sees it: real HTTP to a real server on 127.0.0.1 with a real SQLite
// file. Covers the platform issue's acceptance list (errors, limits, auth, pagination, ETags,
// export/import, concurrency).
#include <gtest/gtest.h>

#include <set>

#include "core/cards/card.hpp"
#include "core/common/json_io.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

const char* kCard = R"({"title":"Reception rush","description":"Patients queue at reception.",
  "tags":["queue","hospital"],"prompt":"patients queue at the reception desk","seed":7,
  "generator":{"name":"offline"},"domain":"hospital","world":{"zones":[]},"metrics":{"agents":12}})";

Json body_of(const httplib::Result& r) {
  return Json::parse(r->body);
}

void expect_problem(const httplib::Result& r, int status) {
  ASSERT_TRUE(r) << "no response";
  EXPECT_EQ(r->status, status) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  Json p = body_of(r);
  EXPECT_EQ(p["status"], status);
  EXPECT_TRUE(p["type"].get<std::string>().rfind("https://socsim.dev/problems/", 0) == 0);
  EXPECT_TRUE(p.contains("title") && p.contains("detail") && p["errors"].is_array());
}

TEST(Api, HealthInfoAndOpenApi) {
  TestServer s;
  auto c = s.client();
  auto h = c.Get("/api/v1/health");
  ASSERT_TRUE(h);
  EXPECT_EQ(h->status, 200);
  EXPECT_EQ(body_of(h)["status"], "ok");
  auto i = c.Get("/api/v1/info");
  ASSERT_TRUE(i);
  Json info = body_of(i);
  EXPECT_EQ(info["websocket_url"], "ws://127.0.0.1:8081/ws");
  EXPECT_EQ(info["generators"][0]["name"], "offline");
  EXPECT_FALSE(info["version"].get<std::string>().empty());
  auto o = c.Get("/api/v1/openapi.yaml");
  ASSERT_TRUE(o);
  EXPECT_EQ(o->status, 200);
  EXPECT_NE(o->body.find("openapi: 3.1"), std::string::npos);
  auto web = c.Get("/");
  ASSERT_TRUE(web);
  EXPECT_EQ(web->status, 200);
  EXPECT_NE(web->body.find("socsim"), std::string::npos);
  expect_problem(c.Get("/api/v1/nothing-here"), 404);
}

TEST(Api, CardIsCreatedReadWithETagAndRevalidated) {
  TestServer s;
  auto c = s.client();
  auto r = c.Post("/api/v1/cards", kCard, "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201) << r->body;
  Json card = body_of(r);
  const std::string id = card["id"];
  EXPECT_EQ(r->get_header_value("Location"), "/api/v1/cards/" + id);
  EXPECT_EQ(card["author"], "anonymous");
  const std::string etag = r->get_header_value("ETag");
  EXPECT_EQ(etag, "\"" + card["content_hash"].get<std::string>() + "\"");
  auto g = c.Get(("/api/v1/cards/" + id).c_str());
  ASSERT_TRUE(g);
  EXPECT_EQ(g->status, 200);
  EXPECT_EQ(body_of(g), card);
  auto cached = c.Get(("/api/v1/cards/" + id).c_str(), {{"If-None-Match", etag}});
  ASSERT_TRUE(cached);
  EXPECT_EQ(cached->status, 304);
  EXPECT_TRUE(cached->body.empty());
  auto stale = c.Get(("/api/v1/cards/" + id).c_str(), {{"If-None-Match", "\"0000\""}});
  EXPECT_EQ(stale->status, 200);
  expect_problem(c.Get("/api/v1/cards/crd_00000000000000000000"), 404);
}

TEST(Api, MalformedJsonIs400NamingThePosition) {
  TestServer s;
  auto r = s.client().Post("/api/v1/cards", "{\"title\": \"x\",\n \"tags\": [1,}", "application/json");
  expect_problem(r, 400);
  Json p = body_of(r);
  EXPECT_EQ(p["errors"][0]["line"], 2);
  EXPECT_NE(p["detail"].get<std::string>().find("line 2"), std::string::npos);
}

TEST(Api, SchemaViolationIs422WithAPointerPerBadField) {
  TestServer s;
  auto r =
      s.client().Post("/api/v1/cards", R"({"title": 3, "seed": "x", "tags": ["ok", "BAD TAG"], "colour": 1})",
                      "application/json");
  expect_problem(r, 422);
  std::set<std::string> pointers;
  const Json problem = body_of(r);
  for (const auto& e : problem["errors"]) pointers.insert(e["pointer"].get<std::string>());
  EXPECT_EQ(pointers, (std::set<std::string>{"/title", "/seed", "/tags/1", "/colour"}));
}

TEST(Api, OversizedBodiesAre413AndChangeNothing) {
  TestServer s;
  auto c = s.client();
  std::string big = R"({"title":"big","prompt":")" + std::string(3u << 20, 'a') + "\"}";
  expect_problem(c.Post("/api/v1/cards", big, "application/json"), 413);
  // The same body sent chunked (no Content-Length) is refused too.
  auto chunked = c.Post(
      "/api/v1/cards",
      [&](size_t offset, httplib::DataSink& sink) {
        const std::size_t n = std::min<std::size_t>(64 * 1024, big.size() - offset);
        sink.write(big.data() + offset, n);
        if (offset + n == big.size()) sink.done();
        return true;
      },
      "application/json");
  ASSERT_TRUE(chunked);
  EXPECT_EQ(chunked->status, 413);
  EXPECT_EQ(body_of(c.Get("/api/v1/health"))["database"]["cards"], 0);
}

TEST(Api, PromptLongerThanTheLimitIs422) {
  ServerConfig cfg;
  cfg.max_prompt_bytes = 100;
  TestServer s(cfg);
  Json card = Json::parse(kCard);
  card["prompt"] = std::string(101, 'p');
  auto r = s.client().Post("/api/v1/cards", card.dump(), "application/json");
  expect_problem(r, 422);
  EXPECT_EQ(body_of(r)["errors"][0]["pointer"], "/prompt");
}

TEST(Api, WrongMediaTypeIs415) {
  TestServer s;
  expect_problem(s.client().Post("/api/v1/cards", "title=x", "application/x-www-form-urlencoded"), 415);
}

TEST(Api, WritesNeedAKeyWhenKeysAreSetAndOnlyTheAuthorDeletes) {
  ServerConfig cfg;
  cfg.api_keys = parse_api_keys("alice:alice-secret-0123456789,bob:bob-secret-0123456789").value();
  TestServer s(cfg);
  auto c = s.client();
  auto none = c.Post("/api/v1/cards", kCard, "application/json");
  expect_problem(none, 401);
  EXPECT_EQ(none->get_header_value("WWW-Authenticate"), "Bearer realm=\"socsim\"");
  expect_problem(c.Post("/api/v1/cards", {{"Authorization", "Bearer wrong-secret-0123456789"}}, kCard,
                        "application/json"),
                 401);
  auto ok = c.Post("/api/v1/cards", {{"Authorization", "Bearer alice-secret-0123456789"}}, kCard,
                   "application/json");
  ASSERT_TRUE(ok);
  ASSERT_EQ(ok->status, 201);
  const std::string id = body_of(ok)["id"];
  EXPECT_EQ(body_of(ok)["author"], "alice");
  auto read = c.Get(("/api/v1/cards/" + id).c_str());
  EXPECT_EQ(read->status, 200) << "reads of cards need no key";
  expect_problem(
      c.Delete(("/api/v1/cards/" + id).c_str(), {{"Authorization", "Bearer bob-secret-0123456789"}}), 403);
  auto del = c.Delete(("/api/v1/cards/" + id).c_str(), {{"Authorization", "Bearer alice-secret-0123456789"}});
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 204);
  expect_problem(c.Get(("/api/v1/cards/" + id).c_str()), 404);
}

// Issue 14 #10: the author is not part of the content hash, so a key holder could write any name
// into an export file and import it; the importer's key is the author, whatever the file says.
TEST(Api, ImportRecordsTheImportingKeyAsAuthor) {
  ServerConfig cfg;
  cfg.api_keys = parse_api_keys("alice:alice-secret-0123456789,bob:bob-secret-0123456789").value();
  TestServer s(cfg);
  auto c = s.client();
  cards::Card forged;
  forged.id = cards::new_card_id();
  forged.content = cards::parse_card_content(Json::parse(kCard), {}).value();
  forged.author = "alice";
  forged.created_at = "2026-01-02T03:04:05.000Z";
  forged.content_hash = cards::content_hash(forged.content, forged.version, forged.parent_id);
  const std::string doc = cards::export_document(forged);
  auto r = c.Post("/api/v1/cards/import", {{"Authorization", "Bearer bob-secret-0123456789"}}, doc,
                  "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201) << r->body;
  EXPECT_EQ(body_of(r)["author"], "bob");
  EXPECT_EQ(body_of(r)["content_hash"], forged.content_hash) << "the content and its hash are kept";
  EXPECT_EQ(body_of(c.Get(("/api/v1/cards/" + forged.id).c_str()))["author"], "bob");
  // So alice's key, not bob's, is the one that cannot delete it.
  expect_problem(
      c.Delete(("/api/v1/cards/" + forged.id).c_str(), {{"Authorization", "Bearer alice-secret-0123456789"}}),
      403);
}

TEST(Api, PageWalkVisitsEveryCardExactlyOnce) {
  TestServer s;
  auto c = s.client();
  std::set<std::string> created;
  for (int i = 0; i < 17; ++i) {
    Json card = Json::parse(kCard);
    card["title"] = "card " + std::to_string(i);
    created.insert(
        body_of(c.Post("/api/v1/cards", card.dump(), "application/json"))["id"].get<std::string>());
  }
  std::set<std::string> seen;
  std::string url = "/api/v1/cards?page_size=5";
  for (int guard = 0; guard < 10; ++guard) {
    auto r = c.Get(url.c_str());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    Json page = body_of(r);
    EXPECT_LE(page["items"].size(), 5u);
    for (const auto& item : page["items"]) {
      EXPECT_TRUE(seen.insert(item["id"].get<std::string>()).second);
      EXPECT_FALSE(item.contains("world")) << "lists carry summaries";
    }
    if (page["next_cursor"].is_null()) break;
    url = "/api/v1/cards?page_size=5&cursor=" + page["next_cursor"].get<std::string>();
  }
  EXPECT_EQ(seen, created);
  auto bad = c.Get("/api/v1/cards?page_size=0");
  expect_problem(bad, 422);
  EXPECT_EQ(body_of(bad)["errors"][0]["parameter"], "page_size");
  expect_problem(c.Get("/api/v1/cards?page_size=1000"), 422);
  expect_problem(c.Get("/api/v1/cards?cursor=forged"), 400);
}

// Issue 14 #12: households?cursor=garbage answered 200 with an empty page, personas 422, the
// others 400; simulations ignored page_size=abc. One parser (server/pagination.hpp) now reads
// them for every list: page_size out of range → 422, a cursor the list did not issue → 400, both
// naming the parameter.
TEST(Api, EveryListReadsPageParametersTheSameWay) {
  TestServer s;
  auto c = s.client();
  for (const char* list : {"/api/v1/cards", "/api/v1/jobs", "/api/v1/worlds", "/api/v1/personas",
                           "/api/v1/households", "/api/v1/simulations"}) {
    for (const char* size : {"abc", "0", "-1", "101", "1e2", "", "99999999999999999999"}) {
      auto r = c.Get((std::string(list) + "?page_size=" + size).c_str());
      expect_problem(r, 422);
      EXPECT_EQ(body_of(r)["errors"][0]["parameter"], "page_size") << list << " page_size=" << size;
    }
    for (const char* cursor : {"garbage", "w1.x", "j1.-5", "s1.", "hh_0000", "%20"}) {
      auto r = c.Get((std::string(list) + "?cursor=" + cursor).c_str());
      expect_problem(r, 400);
      EXPECT_EQ(body_of(r)["errors"][0]["parameter"], "cursor") << list << " cursor=" << cursor;
    }
    // A NUL in the query is refused by the transport before any list reads it.
    expect_problem(c.Get((std::string(list) + "?cursor=%00").c_str()), 400);
    auto ok = c.Get((std::string(list) + "?page_size=1").c_str());
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->status, 200) << list << ": " << ok->body;
  }
}

// Issue 14 #12: a key named twice in one object was accepted (nlohmann keeps the last).
TEST(Api, DuplicateKeysInABodyAre400WithThePointer) {
  TestServer s;
  auto c = s.client();
  auto r = c.Post("/api/v1/cards", R"({"title": "a", "title": "b", "generator": {"name": "offline"}})",
                  "application/json");
  expect_problem(r, 400);
  EXPECT_EQ(body_of(r)["errors"][0]["pointer"], "/title");
  auto nested =
      c.Post("/api/v1/worlds", R"({"scene_graph": {"rooms": [], "rooms": []}})", "application/json");
  expect_problem(nested, 400);
  EXPECT_EQ(body_of(nested)["errors"][0]["pointer"], "/scene_graph/rooms");
}

TEST(Api, SearchAndFilters) {
  TestServer s;
  auto c = s.client();
  Json a = Json::parse(kCard);
  Json b = Json::parse(kCard);
  b["title"] = "Fire drill";
  b["prompt"] = "everyone evacuates the office";
  b["description"] = "An alarm sounds on the third floor.";
  b["tags"] = {"emergency"};
  b["domain"] = "office";
  c.Post("/api/v1/cards", a.dump(), "application/json");
  c.Post("/api/v1/cards", b.dump(), "application/json");
  auto count = [&](const char* url) { return body_of(c.Get(url))["items"].size(); };
  EXPECT_EQ(count("/api/v1/cards?q=evacuate"), 1u);
  EXPECT_EQ(count("/api/v1/cards?q=reception%20patients"), 1u);
  EXPECT_EQ(count("/api/v1/cards?tag=emergency"), 1u);
  EXPECT_EQ(count("/api/v1/cards?domain=hospital"), 1u);
  EXPECT_EQ(count("/api/v1/cards?author=anonymous"), 2u);
  EXPECT_EQ(count("/api/v1/cards?q=submarine"), 0u);
}

TEST(Api, VersionsExportAndImportKeepTheHash) {
  TestServer a;
  TestServer b;
  auto ca = a.client();
  Json v1 = body_of(ca.Post("/api/v1/cards", kCard, "application/json"));
  auto v2r = ca.Post(("/api/v1/cards/" + v1["id"].get<std::string>() + "/versions").c_str(),
                     R"({"title": "Reception rush, evening"})", "application/json");
  ASSERT_EQ(v2r->status, 201);
  Json v2 = body_of(v2r);
  EXPECT_EQ(v2["parent_id"], v1["id"]);
  EXPECT_EQ(v2["version"], 2);
  EXPECT_EQ(v2["prompt"], v1["prompt"]);
  auto exported = ca.Get(("/api/v1/cards/" + v2["id"].get<std::string>() + "/export").c_str());
  ASSERT_EQ(exported->status, 200);
  auto imported = b.client().Post("/api/v1/cards/import", exported->body, "application/json");
  ASSERT_EQ(imported->status, 201) << imported->body;
  EXPECT_EQ(body_of(imported)["content_hash"], v2["content_hash"]);
  auto again = b.client().Get(("/api/v1/cards/" + v2["id"].get<std::string>() + "/export").c_str());
  EXPECT_EQ(again->body, exported->body) << "export → import → export must be byte-stable";
  auto twice = b.client().Post("/api/v1/cards/import", exported->body, "application/json");
  EXPECT_EQ(twice->status, 200);
  std::string tampered = exported->body;
  tampered.replace(tampered.find("evening"), 7, "morning");
  auto bad = b.client().Post("/api/v1/cards/import", tampered, "application/json");
  expect_problem(bad, 422);
  EXPECT_EQ(body_of(bad)["errors"][0]["pointer"], "/card/content_hash");
}

TEST(Api, RateLimitAnswers429WithRetryAfter) {
  ServerConfig cfg;
  cfg.rate_limit_rps = 0.5;
  cfg.rate_limit_burst = 3;
  TestServer s(cfg);  // its readiness probe spends one token
  auto c = s.client();
  c.Get("/api/v1/health");
  c.Get("/api/v1/health");
  auto limited = c.Get("/api/v1/health");
  expect_problem(limited, 429);
  EXPECT_GE(std::stoi(limited->get_header_value("Retry-After")), 1);
}

TEST(Api, HundredConcurrentPostsLoseNone) {
  ServerConfig cfg;
  cfg.rate_limit_rps = 0;
  TestServer s(cfg);
  std::vector<std::thread> threads;
  std::atomic<int> created{0};
  for (int t = 0; t < 10; ++t) {
    threads.emplace_back([&, t] {
      auto c = s.client();
      for (int i = 0; i < 10; ++i) {
        Json card = Json::parse(kCard);
        card["title"] = "concurrent " + std::to_string(t) + "/" + std::to_string(i);
        auto r = c.Post("/api/v1/cards", card.dump(), "application/json");
        if (r && r->status == 201) ++created;
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(created.load(), 100);
  EXPECT_EQ(body_of(s.client().Get("/api/v1/health"))["database"]["cards"], 100);
}

}  // namespace
}  // namespace socsim::server
