// /api/v1/worlds over HTTP: offline generation (201, stored, compliance and knowledge provenance),
// world.yaml and exports, pagination, validation of posted world.yaml (twelve kinds of broken
// files → 422 naming line and field), and an LLM endpoint that is down: the job fails naming it
// within the configured timeout while the offline generator still answers.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/world/world_yaml.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

using ::testing::HasSubstr;
using testing::TestServer;

Json json_of(const httplib::Result& r) {
  EXPECT_TRUE(r);
  return Json::parse(r->body);
}

using socsim::testing::post;

TEST(Worlds, OfflineGenerationIsStoredWithComplianceAndProvenance) {
  TestServer s;
  auto c = s.client();
  auto r = post(c, "/api/v1/worlds", {{"prompt", "a clinic with six patient rooms"}, {"seed", 4}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201) << r->body;
  const Json created = Json::parse(r->body);
  const std::string id = created["id"];
  EXPECT_EQ(r->get_header_value("Location"), "/api/v1/worlds/" + id);
  EXPECT_EQ(created["domain"], "hospital");
  EXPECT_EQ(created["compliance"]["passed"], true);

  const Json w = json_of(c.Get(("/api/v1/worlds/" + id).c_str()));
  EXPECT_EQ(w["generator"], "offline");
  EXPECT_EQ(w["seed"], 4);
  int patient_rooms = 0;
  for (const auto& z : w["world"]["zones"]) patient_rooms += z["type"] == "patient_room";
  EXPECT_EQ(patient_rooms, 6);
  EXPECT_FALSE(w["compliance"]["checks"].empty());
  for (const auto& check : w["compliance"]["checks"]) {
    EXPECT_FALSE(check["ref_id"].get<std::string>().empty());
    EXPECT_TRUE(check.contains("section") && check.contains("required") && check.contains("status"));
  }
  bool ibc_corridor = false;
  for (const auto& k : w["provenance"]["knowledge"])
    ibc_corridor = ibc_corridor || k["ref_id"] == "ibc2018_1020_corridor_i2";
  EXPECT_TRUE(ibc_corridor);
  EXPECT_EQ(w["provenance"]["classification"]["type"], "hospital");

  // world.yaml is the stored source; it reads back to the same world the JSON shows.
  auto yaml = c.Get(("/api/v1/worlds/" + id + "/world.yaml").c_str());
  ASSERT_TRUE(yaml);
  EXPECT_EQ(yaml->status, 200);
  EXPECT_THAT(yaml->get_header_value("Content-Type"), HasSubstr("application/yaml"));
  auto world = world::world_from_yaml(yaml->body);
  ASSERT_TRUE(world) << world.error().message();
  EXPECT_EQ(world->zones().size(), w["world"]["zones"].size());

  // The same request and seed give the same bytes.
  auto again = post(c, "/api/v1/worlds", {{"prompt", "a clinic with six patient rooms"}, {"seed", 4}});
  const std::string id2 = Json::parse(again->body)["id"];
  EXPECT_EQ(c.Get(("/api/v1/worlds/" + id2 + "/world.yaml").c_str())->body, yaml->body);
}

TEST(Worlds, RequirementsAreBuiltOrNamed) {
  TestServer s;
  auto c = s.client();
  auto r = post(c, "/api/v1/worlds",
                {{"prompt", "a canteen"},
                 {"seed", 2},
                 {"requirements",
                  {{"features", {{{"feature", "exit"}, {"count", 3}}, {{"feature", "tables"}, {"count", 8}}}},
                   {"objects", {{{"name", "music system"}}}},
                   {"occupants", 90}}}});
  ASSERT_EQ(r->status, 201) << r->body;
  const std::string id = Json::parse(r->body)["id"];
  const Json w = json_of(c.Get(("/api/v1/worlds/" + id).c_str()));
  int exits = 0, tables = 0, music = 0;
  for (const auto& d : w["world"]["doors"]) exits += d["connects"].size() == 1;
  for (const auto& e : w["world"]["entities"]) {
    tables += e["type"] == "table";
    music += e["type"] == "music_system";
  }
  EXPECT_EQ(exits, 3);
  EXPECT_EQ(tables, 8);
  EXPECT_EQ(music, 1);
  EXPECT_EQ(w["compliance"]["scenario_occupants"], 90);
  EXPECT_EQ(w["provenance"]["requirements_met"][0]["built"], 3);

  auto bad =
      post(c, "/api/v1/worlds",
           {{"prompt", "a flat"}, {"requirements", {{"features", {{{"feature", "moat"}, {"count", 1}}}}}}});
  ASSERT_EQ(bad->status, 422);
  EXPECT_THAT(bad->body, HasSubstr("/requirements/features/0/feature"));
}

TEST(Worlds, ExportsInEveryFormat) {
  TestServer s;
  auto c = s.client();
  Json graph = {
      {"domain", "office"},
      {"rooms", Json::array({{{"name", "hall"}, {"type", "corridor"}},
                             {{"name", "desk_area"}, {"type", "open_office"}},
                             {{"name", "meet"}, {"type", "meeting_room"}}})},
      {"adjacency", Json::array({Json::array({"hall", "desk_area"}), Json::array({"hall", "meet"})})}};
  auto r = post(c, "/api/v1/worlds", {{"scene_graph", graph}, {"seed", 2}, {"generator", "offline"}});
  ASSERT_EQ(r->status, 201) << r->body;
  const std::string base =
      "/api/v1/worlds/" + Json::parse(r->body)["id"].get<std::string>() + "/export?format=";
  auto sdf = c.Get((base + "sdf").c_str());
  EXPECT_EQ(sdf->status, 200);
  EXPECT_THAT(sdf->body, HasSubstr("<sdf version=\"1.7\">"));
  auto pedsim = c.Get((base + "pedsim").c_str());
  EXPECT_THAT(pedsim->body, HasSubstr("<obstacle "));
  auto svg = c.Get((base + "svg").c_str());
  EXPECT_THAT(svg->get_header_value("Content-Type"), HasSubstr("image/svg+xml"));
  const Json map = json_of(c.Get((base + "map").c_str()));
  EXPECT_THAT(map["yaml"].get<std::string>(), HasSubstr("resolution: 0.05"));
  EXPECT_EQ(map["pgm_base64"].get<std::string>().substr(0, 3), "UDU");  // "P5" base64-encoded
  auto pgm = c.Get((base + "map-pgm").c_str());
  EXPECT_EQ(pgm->body.substr(0, 2), "P5");
  auto my = c.Get((base + "map-yaml").c_str());
  EXPECT_THAT(my->body, HasSubstr("image: "));
  auto bad = c.Get((base + "dwg").c_str());
  EXPECT_EQ(bad->status, 422);
  EXPECT_EQ(Json::parse(bad->body)["errors"][0]["parameter"], "format");
  EXPECT_EQ(c.Get("/api/v1/worlds/wld_doesnotexist/export?format=sdf")->status, 404);
}

TEST(Worlds, BadRequestsNameTheirFields) {
  TestServer s;
  auto c = s.client();
  auto neither = post(c, "/api/v1/worlds", {{"seed", 1}});
  EXPECT_EQ(neither->status, 422);
  auto both = post(c, "/api/v1/worlds",
                   {{"prompt", "a house"}, {"scene_graph", {{"rooms", Json::array()}}}, {"seed", -1}});
  EXPECT_EQ(both->status, 422);
  std::vector<std::string> pointers;
  const Json problem = Json::parse(both->body);
  for (const auto& e : problem["errors"]) pointers.push_back(e["pointer"]);
  EXPECT_THAT(pointers, ::testing::IsSupersetOf({"/prompt", "/seed"}));
  auto graph = post(
      c, "/api/v1/worlds",
      {{"scene_graph",
        {{"rooms", Json::array({{{"name", "a"}, {"type", "kitchen"}}, {{"name", "b"}, {"type", "bedroom"}}})},
         {"adjacency", Json::array({Json::array({"a", "zz"})})}}}});
  EXPECT_EQ(graph->status, 422);
  EXPECT_EQ(Json::parse(graph->body)["errors"][0]["pointer"], "/scene_graph/adjacency/0/1");
  auto llm = post(c, "/api/v1/worlds", {{"prompt", "an office"}, {"generator", "llm"}});
  EXPECT_EQ(llm->status, 422);  // no endpoint configured on this server
  EXPECT_EQ(Json::parse(llm->body)["errors"][0]["pointer"], "/generator");
}

// Issue 14 #1: an explicit null was read as "absent" by the field reader but as "given" by the
// presence check, so the prompt of an empty optional was read (a crash, or a bogus "prompt too long").
TEST(Worlds, NullPromptOrSceneGraphIsRefusedNotCrashed) {
  TestServer s;
  auto c = s.client();
  for (const Json& body : {Json{{"prompt", nullptr}}, Json{{"scene_graph", nullptr}},
                           Json{{"prompt", nullptr}, {"scene_graph", nullptr}, {"seed", 3}}}) {
    auto r = post(c, "/api/v1/worlds", body);
    ASSERT_TRUE(r) << "server died on " << body.dump();
    EXPECT_EQ(r->status, 422) << body.dump() << " → " << r->body;
    EXPECT_THAT(r->body, HasSubstr("give scene_graph (rooms and adjacency) or prompt"));
    EXPECT_THAT(r->body, ::testing::Not(HasSubstr("too long")));
  }
  EXPECT_EQ(c.Get("/api/v1/health")->status, 200);
}

// Issue 14 #11: coordinates of 1e200 passed every check and made GEOS fail inside the validation
// (500); every coordinate is now bounded to ±100 km (world::kMaxCoordinate) and refused with 422.
TEST(Worlds, CoordinatesBeyondTheDocumentedRangeAre422WithThePointer) {
  TestServer s;
  auto c = s.client();
  for (const std::string e : {"1e200", "1e308", "-1e300", "100001"}) {
    const std::string yaml =
        "name: \"far\"\nzones:\n  - {name: \"lobby\", type: \"lobby\", polygon: [[0, 0], [" + e + ", 0], [" +
        e + ", " + e + "], [0, " + e + "]]}\n";
    auto r = c.Post("/api/v1/worlds/validate", yaml, "application/yaml");
    ASSERT_TRUE(r) << e;
    EXPECT_EQ(r->status, 422) << e << ": " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], "/zones/0/polygon/1") << r->body;
    EXPECT_THAT(r->body, HasSubstr("within ±100000 m"));
  }
  const std::string door_far = R"(name: "door"
zones:
  - {name: "lobby", type: "lobby", polygon: [[0, 0], [6, 0], [6, 6], [0, 6]]}
doors:
  - {name: "entrance", pose: [3, 1e250], width: 1.8, connects: ["lobby"]}
)";
  auto r = c.Post("/api/v1/worlds/validate", door_far, "application/yaml");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422) << r->body;
  EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], "/doors/0/pose") << r->body;
  // 100 km is accepted.
  const std::string edge = R"(name: "edge"
zones:
  - {name: "lobby", type: "lobby", polygon: [[99990, 0], [100000, 0], [100000, 10], [99990, 10]]}
)";
  EXPECT_EQ(c.Post("/api/v1/worlds/validate", edge, "application/yaml")->status, 200);
}

TEST(Worlds, ListIsPaginatedNewestFirst) {
  TestServer s;
  auto c = s.client();
  std::vector<std::string> ids;
  for (int seed = 1; seed <= 3; ++seed) {
    auto r = post(c, "/api/v1/worlds", {{"prompt", "a small flat"}, {"seed", seed}});
    ASSERT_EQ(r->status, 201) << r->body;
    ids.push_back(Json::parse(r->body)["id"]);
  }
  const Json first = json_of(c.Get("/api/v1/worlds?page_size=2"));
  ASSERT_EQ(first["items"].size(), 2u);
  EXPECT_EQ(first["items"][0]["id"], ids[2]);
  ASSERT_TRUE(first["next_cursor"].is_string());
  const Json second = json_of(
      c.Get(("/api/v1/worlds?page_size=2&cursor=" + first["next_cursor"].get<std::string>()).c_str()));
  ASSERT_EQ(second["items"].size(), 1u);
  EXPECT_EQ(second["items"][0]["id"], ids[0]);
  EXPECT_TRUE(second["next_cursor"].is_null());
  EXPECT_EQ(json_of(c.Get("/api/v1/worlds?domain=hospital"))["items"].size(), 0u);
  EXPECT_EQ(c.Get("/api/v1/worlds?cursor=nonsense")->status, 400);
}

TEST(Worlds, ValidateReportsComplianceForAPostedWorldYaml) {
  TestServer s;
  auto c = s.client();
  const std::string yaml = R"(name: "two rooms"
zones:
  - {name: "lobby", type: "lobby", polygon: [[0, 0], [6, 0], [6, 6], [0, 6]]}
  - {name: "patient_room_1", type: "patient_room", polygon: [[6, 0], [9, 0], [9, 4], [6, 4]]}
doors:
  - {name: "entrance", pose: [3, 0], width: 1.8, connects: ["lobby"]}
  - {name: "d", pose: [6, 2], width: 1.2, connects: ["lobby", "patient_room_1"]}
)";
  for (const char* type : {"application/yaml", "text/yaml"}) {
    auto r = c.Post("/api/v1/worlds/validate?domain=hospital", yaml, type);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const Json j = Json::parse(r->body);
    EXPECT_EQ(j["valid"], true);
    EXPECT_EQ(j["compliance"]["passed"], false);  // a 12 m² patient room: below HBN 03-01's 15 m²
    bool found = false;
    for (const auto& check : j["compliance"]["checks"])
      if (check["name"] == "patient_bedroom_area") {
        found = true;
        EXPECT_EQ(check["status"], "fail");
        EXPECT_EQ(check["value"], 12.0);
        EXPECT_EQ(check["element"], "patient_room_1");
      }
    EXPECT_TRUE(found);
  }
  // Without ?domain= the building type comes from the zone names and types.
  const Json guessed = Json::parse(c.Post("/api/v1/worlds/validate", yaml, "application/yaml")->body);
  EXPECT_EQ(guessed["compliance"]["building_type"], "hospital");
  EXPECT_EQ(c.Post("/api/v1/worlds/validate", yaml, "text/plain")->status, 415);
}

struct Broken {
  const char* what;
  std::string yaml;
  std::string pointer;
  int line;
};

TEST(Worlds, BrokenWorldYamlGives422NamingLineAndField) {
  TestServer s;
  auto c = s.client();
  const std::string two = "zones:\n  - {name: a, polygon: [[0, 0], [5, 0], [5, 5], [0, 5]]}\n";
  const std::vector<Broken> cases = {
      {"zone without polygon", "zones:\n  - name: office\n    type: office\n", "/zones/0/polygon", 2},
      {"self-crossing polygon", "zones:\n  - name: x\n    polygon: [[0, 0], [5, 5], [5, 0], [0, 5]]\n",
       "/zones/0/polygon", 3},
      {"door on no wall", two + "doors:\n  - {name: d, pose: [2.5, 2.5], width: 1}\n", "/doors/0/pose", 4},
      {"ROI outside every zone",
       two + "segmentation:\n  - {name: q, kind: queue_lane, polygon: [[20, 20], [21, 20], [21, 24]]}\n",
       "/segmentation/0/polygon", 4},
      {"duplicate name", two + "entities:\n  - {type: chair, name: a, pose: [1, 1]}\n", "/entities/0/name",
       4},
      {"unknown field",
       "zones:\n  - name: a\n    colour: blue\n    polygon: [[0, 0], [5, 0], [5, 5], [0, 5]]\n",
       "/zones/0/colour", 3},
      {"text where a number belongs", two + "doors:\n  - {name: d, pose: [5, 2], width: broad}\n",
       "/doors/0/width", 4},
      {"overlapping zones", two + "  - {name: b, polygon: [[4, 0], [9, 0], [9, 5], [4, 5]]}\n",
       "/zones/1/polygon", 3},
      {"unreachable zone", two + "  - {name: b, polygon: [[5, 0], [9, 0], [9, 5], [5, 5]]}\n", "/zones/1", 3},
      {"door to an unknown zone",
       two + "doors:\n  - {name: d, pose: [5, 2], width: 1, connects: [a, garage]}\n", "/doors/0/connects/1",
       4},
      {"entity outside every zone", two + "entities:\n  - {type: bed, name: bed_1, pose: [30, 30]}\n",
       "/entities/0/pose", 4},
      {"unknown ROI kind",
       two + "segmentation:\n  - {name: r, kind: dancefloor, polygon: [[1, 1], [2, 1], [2, 2]]}\n",
       "/segmentation/0/kind", 4},
      {"unknown unit", "units: {length: furlong}\n" + two, "/units/length", 1},
  };
  for (const auto& k : cases) {
    auto r = c.Post("/api/v1/worlds/validate", k.yaml, "application/yaml");
    ASSERT_TRUE(r) << k.what;
    EXPECT_EQ(r->status, 422) << k.what << ": " << r->body;
    const Json p = Json::parse(r->body);
    bool named = false;
    for (const auto& e : p["errors"])
      named = named || (e["pointer"] == k.pointer && e.value("line", 0) == k.line);
    EXPECT_TRUE(named) << k.what << ": " << r->body;
  }
  // Broken YAML syntax is a finding too: 422 with its line.
  auto syntax =
      c.Post("/api/v1/worlds/validate", "zones:\n  - {name: a, polygon: [[0, 0], [1, 0]\n", "text/yaml");
  EXPECT_EQ(syntax->status, 422);
  EXPECT_GT(Json::parse(syntax->body)["errors"][0].value("line", 0), 0);
  // The server is still up.
  EXPECT_EQ(c.Get("/api/v1/health")->status, 200);
}

int closed_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(fd);  // nobody listens there now
  return ntohs(a.sin_port);
}

TEST(Worlds, LlmEndpointDownFailsTheJobNamingItWhileOfflineStillWorks) {
  const int port = closed_port();
  ServerConfig config;
  config.llm.base_url = "http://127.0.0.1:" + std::to_string(port);
  config.llm.model = "any";
  config.llm.connect_timeout_ms = 500;
  config.llm.attempt_timeout_ms = 1500;
  config.llm.deadline_ms = 3000;
  config.llm.max_retries = 1;
  TestServer s(config);
  auto c = s.client();
  const auto start = std::chrono::steady_clock::now();
  auto r = post(c, "/api/v1/worlds",
                {{"prompt", "an office with 2 meeting rooms"}, {"generator", "llm"}, {"seed", 1}});
  ASSERT_EQ(r->status, 202) << r->body;
  const std::string location = r->get_header_value("Location");
  const std::string job = Json::parse(r->body)["id"];
  EXPECT_EQ(location, "/api/v1/jobs/" + job);
  ASSERT_TRUE(s.services().jobs->wait(job, std::chrono::seconds(10)));
  const auto elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed, std::chrono::milliseconds(config.llm.deadline_ms + 1000));
  const Json j = json_of(c.Get(location.c_str()));
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["error"]["status"], 502);
  EXPECT_THAT(j["error"]["detail"].get<std::string>(), HasSubstr("127.0.0.1:" + std::to_string(port)));

  auto offline = post(c, "/api/v1/worlds",
                      {{"prompt", "an office with 2 meeting rooms"}, {"generator", "offline"}, {"seed", 1}});
  EXPECT_EQ(offline->status, 201) << offline->body;
}

}  // namespace
}  // namespace socsim::server
