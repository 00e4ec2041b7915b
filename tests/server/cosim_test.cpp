// Co-simulation end to end: POST /api/v1/cosim on a real daemon, a client driving the robot over a
// real WebSocket (subprotocol socsim.cosim.v1) in lock-step and in real time; byte-identical reports
// for the same inputs; every kind of bad input ends in a clear error and a close, never a hang.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/server/live_daemon.hpp"

namespace socsim::server {
namespace {

const char* kCorridor = "zones:\n  - {name: corridor, polygon: [[0, 0], [20, 0], [20, 3], [0, 3]]}\n";

Json corridor_document() {
  return world::world_to_document(world::world_from_yaml(kCorridor).value());
}

Json walker_program() {
  return {{"name", "encounter"},
          {"agents",
           {{{"name", "walker"}, {"position", {14, 1.0}}, {"goals", {{1, 1.0}}}, {"cyclic_goals", false}}}}};
}

Json request(Json extra = Json::object()) {
  Json body{{"program", walker_program()},
            {"world", kCorridor},
            {"seed", 4},
            {"robot", {{"start", {{"x", 2}, {"y", 2.0}, {"yaw", 0}}}, {"goal", {{"x", 10}, {"y", 2.0}}}}},
            {"time_limit", 30}};
  body.update(extra);
  return body;
}

std::string step(std::uint64_t k, double v, double omega = 0.0) {
  return Json{{"type", "step"}, {"step", k}, {"robots", {{{"cmd", {{"v", v}, {"omega", omega}}}}}}}.dump();
}

struct CosimClient : Viewer {
  CosimClient(int port, const std::string& path, const std::string& offer = "socsim.cosim.v1")
      : Viewer(port, path, offer) {}
  void send(const std::string& text) {
    ws.text(true);
    ws.write(asio::buffer(text));
  }
};

// Drives the robot of the session at ws_url at 0.8 m/s to the end; the report message's bytes.
std::string drive_session(Daemon& d, const std::string& ws_url) {
  CosimClient c(d.ws_port, ws_url);
  EXPECT_EQ(c.protocol, "socsim.cosim.v1");
  auto hello = c.read();
  EXPECT_TRUE(hello && hello->type() == "hello");
  auto first = c.read();
  EXPECT_TRUE(first && first->type() == "observation");
  for (std::uint64_t k = 1; k < 2000; ++k) {
    c.send(step(k, 0.8));
    auto m = c.read();
    if (!m) return "no observation";
    const Json o = m->json();
    EXPECT_EQ(o["type"], "observation");
    EXPECT_EQ(o["step"], k);
    if (o["status"] == "ended") {
      auto report = c.read();
      return report ? report->bytes : "no report";
    }
  }
  return "did not end";
}

std::string drive_to_the_end(Daemon& d, const Json& body) {
  return drive_session(d, d.post("/api/v1/cosim", body, 201)["ws_url"].get<std::string>());
}

TEST(Cosim, LockStepRunsToAReportThatIsTheSameEveryTime) {
  Daemon d;
  const std::string a = drive_to_the_end(d, request());
  const std::string b = drive_to_the_end(d, request());
  EXPECT_EQ(a, b);
  const Json r = Json::parse(a);
  EXPECT_EQ(r["type"], "report");
  EXPECT_EQ(r["end_reason"], "episode_ended");
  ASSERT_EQ(r["metrics"]["robots"].size(), 1u);
  const Json& robot = r["metrics"]["robots"][0];
  EXPECT_EQ(robot["name"], "robot_0");
  EXPECT_TRUE(robot["outcome"] == "success" || robot["outcome"] == "collision_person") << robot;
  for (const char* k :
       {"path_length", "minimum_distance_to_people", "social_work", "avg_jerk", "path_efficiency"})
    EXPECT_TRUE(robot.contains(k)) << k;
  const std::string waiting = d.post("/api/v1/cosim", request(), 201)["id"];
  EXPECT_EQ(d.get("/api/v1/cosim/" + waiting)["status"], "waiting");
}

TEST(Cosim, ObservationsCarryThePeopleAndTheRobot) {
  Daemon d;
  const Json created = d.post("/api/v1/cosim", request(), 201);
  EXPECT_EQ(created["subprotocol"], "socsim.cosim.v1");
  EXPECT_EQ(created["websocket_url"],
            "ws://127.0.0.1:" + std::to_string(d.ws_port) + created["ws_url"].get<std::string>());
  CosimClient c(d.ws_port, created["ws_url"].get<std::string>());
  const Json hello = c.read()->json();
  EXPECT_EQ(hello["protocol"], "socsim.cosim.v1");
  EXPECT_DOUBLE_EQ(hello["dt"], 0.05);
  EXPECT_EQ(hello["robots"][0]["goal"]["radius"], 0.5);
  const Json o = c.read()->json();
  ASSERT_EQ(o["people"].size(), 1u);
  for (const char* k :
       {"id", "pose", "twist", "state", "role", "intent", "group_id", "proxemics", "metadata"})
    EXPECT_TRUE(o["people"][0].contains(k)) << k;
  EXPECT_EQ(o["robots"][0]["outcome"], "running");
  c.send(step(1, 1.0));
  const Json o1 = c.read()->json();
  EXPECT_NEAR(o1["robots"][0]["pose"]["x"].get<double>(), 2.0025, 1e-12);  // 0.05 m/s after one step
  c.send(R"({"type": "stop"})");
  const Json report = c.read()->json();
  EXPECT_EQ(report["type"], "report");
  EXPECT_EQ(report["end_reason"], "stopped_by_client");
  EXPECT_FALSE(c.read(1000ms)) << "closed after the report";
  EXPECT_EQ(d.get("/api/v1/cosim/" + created["id"].get<std::string>())["report"]["steps"], 1);
}

// A client offering socsim.cosim.v1.binary gets the same observations as binary frames
// (docs/cosim.md, "Binary observations"): float32 copies of the JSON figures.
TEST(Cosim, BinaryObservationsCarryTheJsonObservationsFigures) {
  Daemon d;
  CosimClient j(d.ws_port, d.post("/api/v1/cosim", request(), 201)["ws_url"].get<std::string>());
  CosimClient b(d.ws_port, d.post("/api/v1/cosim", request(), 201)["ws_url"].get<std::string>(),
                "socsim.cosim.v1.binary, socsim.cosim.v1");
  EXPECT_EQ(b.protocol, "socsim.cosim.v1.binary");
  j.read();
  const Json hello = b.read()->json();
  EXPECT_EQ(hello["encoding"], "binary");
  ASSERT_EQ(hello["roles"].size(), 1u);
  j.read();
  b.read();
  for (std::uint64_t k = 1; k <= 3; ++k) {
    j.send(step(k, 0.8, 0.1));
    b.send(step(k, 0.8, 0.1));
  }
  Json o;
  for (int k = 0; k < 3; ++k) o = j.read()->json();
  std::optional<Message> m;
  for (int k = 0; k < 3; ++k) m = b.read();
  ASSERT_TRUE(m && m->binary);
  const std::string& bytes = m->bytes;
  ASSERT_EQ(bytes.size(), 32u + 28u + 32u);  // header, one robot, one person
  EXPECT_EQ(bytes.substr(0, 4), "SCB1");
  const auto at = [&bytes](std::size_t offset, auto v) {
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
  };
  EXPECT_EQ(at(4, std::uint8_t{}), 0);  // running
  EXPECT_EQ(at(5, std::uint8_t{}), 1);  // robots
  EXPECT_EQ(at(8, std::uint64_t{}), 3u);
  EXPECT_DOUBLE_EQ(at(16, double{}), o["t"].get<double>());
  EXPECT_EQ(at(24, std::uint32_t{}), 1u);
  EXPECT_FLOAT_EQ(at(32, float{}), o["robots"][0]["pose"]["x"].get<float>());
  EXPECT_FLOAT_EQ(at(40, float{}), o["robots"][0]["pose"]["yaw"].get<float>());
  EXPECT_FLOAT_EQ(at(52, float{}), o["robots"][0]["twist"]["omega"].get<float>());
  EXPECT_EQ(at(56, std::uint8_t{}), 0);  // outcome running
  const Json& person = o["people"][0];
  EXPECT_EQ(at(60, std::uint32_t{}), person["id"].get<std::uint32_t>());
  EXPECT_FLOAT_EQ(at(64, float{}), person["pose"]["x"].get<float>());
  EXPECT_FLOAT_EQ(at(68, float{}), person["pose"]["y"].get<float>());
  EXPECT_FLOAT_EQ(at(76, float{}), person["twist"]["vx"].get<float>());
  EXPECT_EQ(at(84, std::int32_t{}), person["group_id"].get<std::int32_t>());
  EXPECT_EQ(at(89, std::uint8_t{}), 0);  // the first of hello's roles
  EXPECT_EQ(hello["roles"][0], person["role"]);
  b.send(R"({"type": "stop"})");
  const auto report = b.read();
  ASSERT_TRUE(report && !report->binary);
  EXPECT_EQ(report->json()["type"], "report");
}

// Sends `bad` after the hello; expects an error with `code` and `pointer`, then a close.
void expect_protocol_error(Daemon& d, const std::vector<std::string>& before, const std::string& bad,
                           const std::string& code, const std::string& pointer) {
  const Json created = d.post("/api/v1/cosim", request(), 201);
  CosimClient c(d.ws_port, created["ws_url"].get<std::string>());
  c.read();
  c.read();
  for (const std::string& m : before) {
    c.send(m);
    c.read();
  }
  c.send(bad);
  auto m = c.read();
  ASSERT_TRUE(m) << bad;
  const Json e = m->json();
  EXPECT_EQ(e["type"], "error") << e;
  EXPECT_EQ(e["code"], code) << e;
  if (!pointer.empty()) {
    ASSERT_TRUE(e.contains("errors")) << e;
    EXPECT_EQ(e["errors"][0]["pointer"], pointer) << e;
  }
  EXPECT_FALSE(c.read(2000ms)) << "closed after the error";
  EXPECT_EQ(c.ws.reason().code, websocket::close_code::policy_error);
  EXPECT_EQ(d.get("/api/v1/cosim/" + created["id"].get<std::string>())["status"], "ended");
}

TEST(Cosim, BadInputEndsWithAClearErrorAndAClose) {
  Daemon d;
  expect_protocol_error(d, {}, R"({"type": "step", "step": 1, "robots": [{"cmd": {"v": NaN, "omega": 0}}]})",
                        "protocol_error", "");
  expect_protocol_error(d, {}, step(1, 100.0), "protocol_error", "/robots/0/cmd/v");
  expect_protocol_error(d, {step(1, 0.5)}, step(3, 0.5), "out_of_order", "/step");
  expect_protocol_error(d, {}, step(0, 0.5), "out_of_order", "/step");
  expect_protocol_error(d, {},
                        R"({"type": "step", "step": 1, "robots": [{"cmd": {"v": 0, "omega": 0}},
                                                                  {"cmd": {"v": 0, "omega": 0}}]})",
                        "protocol_error", "/robots");
  expect_protocol_error(d, {},
                        R"({"type": "step", "step": 1, "robots": [{"pose": {"x": 9, "y": 2, "yaw": 0},
                                                                   "twist": {"vx": 0, "vy": 0, "omega": 0}}]})",
                        "protocol_error", "/robots/0/pose");
  expect_protocol_error(d, {}, R"({"type": "teleport"})", "protocol_error", "/type");
  expect_protocol_error(d, {}, R"({"type": "step", "step": 1, "robots": [{"cmd": {"v": 0}}]})",
                        "protocol_error", "/robots/0/cmd/omega");
  expect_protocol_error(d, {}, "not json", "protocol_error", "");
}

TEST(Cosim, BadRequestsAreRefusedWithPointers) {
  Daemon d;
  Json many = request();
  many.erase("robot");
  many["robots"] = Json::array();
  for (int k = 0; k < 5; ++k) many["robots"].push_back({{"start", {{"x", 2 + k}, {"y", 1}}}});
  const Json e = d.post("/api/v1/cosim", many, 422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/robots");
  const Json e2 = d.post("/api/v1/cosim", request({{"robot", {{"start", {{"x", 1}}}, {"radius", 9}}}}), 422);
  EXPECT_EQ(e2["errors"].size(), 2u);
  EXPECT_EQ(d.post("/api/v1/cosim", request({{"mode", "fast"}}), 422)["errors"][0]["pointer"], "/mode");
  Json no_robot = request();
  no_robot.erase("robot");
  EXPECT_EQ(d.post("/api/v1/cosim", no_robot, 422)["errors"][0]["pointer"], "/robots");
  EXPECT_EQ(d.post("/api/v1/cosim", request({{"card_id", "card_nope"}}), 422)["errors"][0]["pointer"], "");
}

TEST(Cosim, TheSubprotocolIsRequiredAndOneClientOnly) {
  Daemon d;
  const Json created = d.post("/api/v1/cosim", request(), 201);
  const std::string path = created["ws_url"];
  EXPECT_THROW(Viewer(d.ws_port, path), beast::system_error);
  CosimClient first(d.ws_port, path);
  EXPECT_THROW(CosimClient(d.ws_port, path), beast::system_error);
}

TEST(Cosim, AnIdleClientTimesOut) {
  ServerConfig config = quick_config();
  config.sim_idle_s = 1;
  Daemon d(config);
  const Json created = d.post("/api/v1/cosim", request(), 201);
  CosimClient c(d.ws_port, created["ws_url"].get<std::string>());
  c.read();
  c.read();
  auto m = c.read(5000ms);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->json()["code"], "idle_timeout");
  EXPECT_FALSE(c.read(2000ms));
}

TEST(Cosim, RealTimeHoldsTheLastCommandAndCountsLateness) {
  Daemon d;
  const Json created = d.post("/api/v1/cosim", request({{"mode", "realtime"}, {"rate_hz", 20}}), 201);
  CosimClient c(d.ws_port, created["ws_url"].get<std::string>());
  c.read();
  c.read();
  c.send(step(1, 1.0));
  // Without further messages the server keeps stepping with the held command.
  std::uint64_t last_step = 0;
  double last_x = 0.0;
  for (int k = 0; k < 10; ++k) {
    auto m = c.next("observation");
    ASSERT_TRUE(m);
    last_step = m->json()["step"];
    last_x = m->json()["robots"][0]["pose"]["x"];
  }
  EXPECT_GE(last_step, 10u);
  EXPECT_GT(last_x, 2.05) << "the held 1 m/s command moves the robot";
  c.send(R"({"type": "stop"})");
  auto report = c.next("report");
  ASSERT_TRUE(report);
  EXPECT_GE(report->json()["late_ticks"].get<int>(), 8);
}

// The view a browser polls: the robot's path from a frame on (each frame once over successive
// polls), everyone now, the world on request; bad parameters are 422 naming them.
TEST(Cosim, TheViewGivesThePathSinceAFrameAndTheWorldOnRequest) {
  Daemon d;
  const Json created = d.post("/api/v1/cosim", request(), 201);
  const std::string id = created["id"];
  CosimClient c(d.ws_port, created["ws_url"].get<std::string>());
  c.read();
  c.read();
  for (std::uint64_t k = 1; k <= 10; ++k) {
    c.send(step(k, 0.8));
    ASSERT_TRUE(c.read());
  }
  const Json first = d.get("/api/v1/cosim/" + id + "/view?world=true");
  EXPECT_EQ(first["status"], "running");
  EXPECT_EQ(first["frames"], 11);
  ASSERT_EQ(first["robots"].size(), 1u);
  EXPECT_EQ(first["robots"][0]["path"].size(), 11u);
  EXPECT_EQ(first["robots"][0]["path"][0], Json::parse("[2.0, 2.0]"));
  EXPECT_EQ(first["people"].size(), 1u);
  EXPECT_TRUE(first.contains("world"));
  for (std::uint64_t k = 11; k <= 13; ++k) {
    c.send(step(k, 0.8));
    ASSERT_TRUE(c.read());
  }
  const Json next = d.get("/api/v1/cosim/" + id + "/view?since=11");
  EXPECT_EQ(next["robots"][0]["path"].size(), 3u);
  EXPECT_FALSE(next.contains("world"));
  EXPECT_EQ(next["robots"][0]["path"][2][0], next["robots"][0]["pose"]["x"]);
  const Json listed = d.get("/api/v1/cosim");
  ASSERT_FALSE(listed["items"].empty());
  EXPECT_EQ(listed["items"][0]["id"], id);
  auto client = d.http.client();
  for (const char* bad : {"?since=-1", "?since=x", "?world=yes"}) {
    auto r = client.Get(("/api/v1/cosim/" + id + "/view" + bad).c_str());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << bad;
    EXPECT_FALSE(Json::parse(r->body)["errors"][0]["parameter"].get<std::string>().empty()) << r->body;
  }
  auto missing = client.Get("/api/v1/cosim/cosim_nope/view");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
}

// An evaluation with "client": "external": each card × seed is a lock-step session that the test,
// as the lab's client, finds in the evaluation's "current" and drives; the table then has them.
TEST(Cosim, AnExternalEvaluationIsDrivenSessionBySessionIntoItsTable) {
  Daemon d;
  Json program = walker_program();
  program["robot"] = {{"position", {2.0, 2.0}}, {"speed", 1.0}, {"goals", {{10.0, 2.0}}}};
  const std::string card = d.post(
      "/api/v1/cards",
      {{"title", "encounter"}, {"world", corridor_document()}, {"program", program}, {"seed", 1}}, 201)["id"];
  const std::string id =
      d.post("/api/v1/evaluations",
             {{"cards", {card}}, {"seeds", {1, 2}}, {"client", "external"}, {"time_limit_s", 30}}, 202)["id"];
  std::vector<std::string> driven, reports;
  for (int polls = 0; polls < 400 && driven.size() < 2; ++polls) {
    const Json e = d.get("/api/v1/evaluations/" + id);
    if (e.contains("current") && (driven.empty() || e["current"]["cosim"] != driven.back())) {
      EXPECT_EQ(e["current"]["episodes"], 2);
      EXPECT_EQ(e["current"]["card"], card);
      driven.push_back(e["current"]["cosim"]);
      reports.push_back(drive_session(d, e["current"]["ws_url"]));
    } else {
      std::this_thread::sleep_for(25ms);
    }
  }
  ASSERT_EQ(driven.size(), 2u);
  Json done;
  for (int polls = 0; polls < 200; ++polls) {
    done = d.get("/api/v1/evaluations/" + id);
    if (done["status"] == "succeeded" || done["status"] == "failed") break;
    std::this_thread::sleep_for(25ms);
  }
  ASSERT_EQ(done["status"], "succeeded") << done.dump();
  EXPECT_FALSE(done.contains("current"));
  EXPECT_EQ(done["request"]["client"], "external");
  const Json& rows = done["result"]["episodes"];
  ASSERT_EQ(rows.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(rows[k]["planner"], "external");
    EXPECT_EQ(rows[k]["cosim"], driven[k]);
    EXPECT_EQ(rows[k]["end_reason"], "episode_ended");
    EXPECT_EQ(rows[k]["outcome"], Json::parse(reports[k])["metrics"]["robots"][0]["outcome"]);
  }
  EXPECT_EQ(done["result"]["table"]["planners"][0]["planner"], "external");
}

// Nobody connects: the evaluation fails naming the session, and does not hold its worker forever.
TEST(Cosim, AnExternalEvaluationWithoutItsClientFailsNamingTheSession) {
  ServerConfig config = quick_config();
  config.sim_idle_s = 1;
  Daemon d(config);
  const std::string card = d.post(
      "/api/v1/cards",
      {{"title", "encounter"}, {"world", corridor_document()}, {"program", walker_program()}, {"seed", 1}},
      201)["id"];
  const Json body{{"cards", {card}},
                  {"seeds", {1}},
                  {"client", "external"},
                  {"robot", {{"start", {{"x", 2}, {"y", 2}, {"yaw", 0}}}, {"goal", {{"x", 10}, {"y", 2}}}}}};
  const std::string id = d.post("/api/v1/evaluations", body, 202)["id"];
  Json done;
  for (int polls = 0; polls < 200; ++polls) {
    done = d.get("/api/v1/evaluations/" + id);
    if (done["status"] == "failed" || done["status"] == "succeeded") break;
    std::this_thread::sleep_for(25ms);
  }
  ASSERT_EQ(done["status"], "failed") << done.dump();
  EXPECT_NE(done["error"]["detail"].get<std::string>().find("no client connected to /ws/cosim/"),
            std::string::npos)
      << done.dump();
}

}  // namespace
}  // namespace socsim::server
