// Live simulations end to end: REST on a real daemon, frames over a real WebSocket (Beast client).
// Sessions from a program and from a card's recording, JSON and binary frames, controls over REST
// and the socket, idle end, limits, problems with pointers, and a viewer that never reads.
#include <gtest/gtest.h>

#include <map>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include <chrono>
#include <optional>
#include <thread>

#include "core/cards/catalogue.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "server/simulation_sessions.hpp"
#include "server/ws_server.hpp"
#include "tests/server/live_daemon.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

// Two walkers crossing a 10 m room, a staff member among them; no world needed.
Json walkers(int pairs = 1) {
  Json agents = Json::array();
  for (int i = 0; i < pairs; ++i) {
    const double y = 1.5 * i;
    agents.push_back(
        {{"name", "east" + std::to_string(i)}, {"position", {0.0, y}}, {"goals", {{10.0, y}, {0.0, y}}}});
    agents.push_back({{"name", "west" + std::to_string(i)},
                      {"role", "staff"},
                      {"position", {10.0, y + 0.5}},
                      {"goals", {{0.0, y + 0.5}, {10.0, y + 0.5}}}});
  }
  return {{"name", "walkers"}, {"dt", 0.05}, {"decision_period", 0.1}, {"agents", agents}};
}

// A crowd spread over a square, walking to the opposite side and back.
Json crowd(int n) {
  const double side = std::ceil(std::sqrt(n)) * 1.5;
  return {{"name", "crowd"},
          {"agents",
           {{{"name", "crowd"},
             {"spawn", {{0.0, 0.0}, {side, 0.0}, {side, side}, {0.0, side}}},
             {"count", n},
             {"goals", {{side / 2, side}, {side / 2, 0.0}}}}}}};
}

std::string ws_path(const std::string& id, const std::string& query = "") {
  return "/ws/simulations/" + id + query;
}

TEST(Simulations, ProgramSessionStreamsHelloAndJsonFrames) {
  Daemon d;
  const Json created = d.post("/api/v1/simulations", {{"program", walkers()}, {"seed", 3}}, 201);
  ASSERT_TRUE(created.contains("id"));
  EXPECT_EQ(created["status"], "running");
  EXPECT_EQ(created["kind"], "program");
  EXPECT_EQ(created["ws_url"], "/ws/simulations/" + created["id"].get<std::string>());
  EXPECT_EQ(created["websocket_url"], "ws://127.0.0.1:" + std::to_string(d.ws_port) + "/ws/simulations/" +
                                          created["id"].get<std::string>());
  EXPECT_DOUBLE_EQ(created["frame_hz"], 20.0);

  Viewer v(d.ws_port, created["ws_url"].get<std::string>());
  auto hello = v.read();
  ASSERT_TRUE(hello);
  const Json h = hello->json();
  EXPECT_EQ(h["type"], "hello");
  EXPECT_EQ(h["session"], created["id"]);
  EXPECT_EQ(h["format"], "json");
  EXPECT_NE(std::find(h["roles"].begin(), h["roles"].end(), "staff"), h["roles"].end());
  EXPECT_EQ(h["states"][0], "walking");

  double previous_t = -1;
  std::uint32_t previous_seq = 0;
  for (int i = 0; i < 10; ++i) {
    auto m = v.next("frame");
    ASSERT_TRUE(m);
    const Json f = m->json();
    ASSERT_EQ(f["agents"].size(), 2u);
    EXPECT_GT(f["t"].get<double>(), previous_t);
    EXPECT_GT(f["seq"].get<std::uint32_t>(), previous_seq);
    previous_t = f["t"];
    previous_seq = f["seq"];
    const Json& a = f["agents"][1];
    for (const char* k : {"id", "x", "y", "yaw", "vx", "vy", "state", "role", "group_id", "target"})
      EXPECT_TRUE(a.contains(k)) << k;
    EXPECT_EQ(a["role"], "staff");
    EXPECT_EQ(a["state"], "walking");
  }
  EXPECT_GT(previous_t, 0.0) << "the simulation advances in time";
  const Json status = d.get("/api/v1/simulations/" + created["id"].get<std::string>());
  EXPECT_EQ(status["viewers"], 1);
  EXPECT_GE(status["frames_sent"].get<int>(), 10);
}

TEST(Simulations, ProgramInAStoredOrInlineWorld) {
  Daemon d;
  const Json world =
      d.post("/api/v1/worlds", {{"prompt", "a clinic with six patient rooms"}, {"seed", 4}}, 201);
  ASSERT_TRUE(world.contains("id"));
  const std::string world_id = world["id"];
  const Json document = d.get("/api/v1/worlds/" + world_id)["world"];
  ASSERT_GE(document["zones"].size(), 2u);
  const std::string from = document["zones"][0]["name"], to = document["zones"][1]["name"];
  const Json program = {{"agents", {{{"name", "visitor"}, {"spawn", from}, {"count", 3}, {"goals", {to}}}}}};

  const Json stored =
      d.post("/api/v1/simulations", {{"program", program}, {"world_id", world_id}, {"seed", 1}}, 201);
  EXPECT_EQ(stored["world_id"], world_id);
  Viewer v(d.ws_port, stored["ws_url"].get<std::string>());
  EXPECT_EQ(v.read()->json()["world_id"], world_id);
  auto frame = v.next("frame");
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->json()["agents"].size(), 3u);

  const Json inline_world =
      d.post("/api/v1/simulations", {{"program", program}, {"world", document}, {"seed", 1}}, 201);
  EXPECT_EQ(inline_world["agents"], 3);
  const Json missing =
      d.post("/api/v1/simulations", {{"program", program}, {"world_id", "wld_aaaaaaaaaaaaaaaaaaaa"}}, 404);
  EXPECT_EQ(missing["errors"][0]["pointer"], "/world_id") << missing.dump();
  Json unknown_place = program;
  unknown_place["agents"][0]["goals"][0] = "no_such_room";
  const Json p = d.post("/api/v1/simulations", {{"program", unknown_place}, {"world_id", world_id}}, 422);
  EXPECT_EQ(p["errors"][0]["pointer"], "/program/agents/0/goals/0") << p.dump();
  Json broken_world = document;
  broken_world["zones"][0]["polygon"] = "square";
  const Json w = d.post("/api/v1/simulations", {{"program", program}, {"world", broken_world}}, 422);
  EXPECT_EQ(w["errors"][0]["pointer"].get<std::string>().rfind("/world/zones/0", 0), 0u) << w.dump();
}

TEST(Simulations, BinaryFramesCarryTheSameStatesAsJson) {
  Daemon d;
  const std::string id = d.start({{"program", walkers(3)}, {"seed", 11}});
  Viewer json_viewer(d.ws_port, ws_path(id), "socsim.json.v1");
  Viewer binary_viewer(d.ws_port, ws_path(id), "socsim.binary.v1");
  Viewer query_viewer(d.ws_port, ws_path(id, "?format=binary"));
  EXPECT_EQ(json_viewer.protocol, "socsim.json.v1");
  EXPECT_EQ(binary_viewer.protocol, "socsim.binary.v1");
  EXPECT_EQ(binary_viewer.read()->json()["format"], "binary");
  EXPECT_EQ(query_viewer.read()->json()["format"], "binary");

  // Frames from seq 5 on reach both (earlier ones may predate a viewer).
  std::map<std::uint32_t, Json> json_frames;
  while (json_frames.size() < 5) {
    auto m = json_viewer.next("frame");
    ASSERT_TRUE(m);
    Json f = m->json();
    if (f["seq"].get<std::uint32_t>() >= 5) json_frames[f["seq"]] = f;
  }
  int compared = 0;
  while (compared < 5) {
    auto m = binary_viewer.next("binary");
    ASSERT_TRUE(m);
    auto frame = decode_frame_binary(m->bytes);
    ASSERT_TRUE(frame) << frame.error().detail;
    auto it = json_frames.find(frame->seq);
    if (it == json_frames.end()) continue;
    const Json& j = it->second;
    EXPECT_EQ(frame->t, j["t"].get<double>());
    ASSERT_EQ(frame->agents.size(), j["agents"].size());
    for (std::size_t i = 0; i < frame->agents.size(); ++i) {
      const FrameAgent& b = frame->agents[i];
      const Json& a = j["agents"][i];
      EXPECT_EQ(b.id, a["id"].get<std::uint32_t>());
      // JSON writes the same 32-bit floats (shortest text that reads back exactly).
      EXPECT_EQ(b.x, a["x"].get<float>());
      EXPECT_EQ(b.y, a["y"].get<float>());
      EXPECT_EQ(b.yaw, a["yaw"].get<float>());
      EXPECT_EQ(b.vx, a["vx"].get<float>());
      EXPECT_EQ(b.vy, a["vy"].get<float>());
      EXPECT_EQ(crowd::activity_names().at(b.state), a["state"].get<std::string>());
      EXPECT_EQ(b.group_id, a["group_id"].get<std::int32_t>());
    }
    ++compared;
  }
  // Role indices point into the hello's role table.
  Viewer late(d.ws_port, ws_path(id), "socsim.binary.v1");
  const Json hello = late.read()->json();
  auto frame = decode_frame_binary(late.next("binary")->bytes);
  ASSERT_TRUE(frame);
  EXPECT_EQ(hello["roles"][frame->agents[1].role], "staff");
  EXPECT_EQ(hello["binary_layout"]["agent_bytes"], kBinaryAgentBytes);
}

TEST(Simulations, PauseStopsFramesAndResumeContinues) {
  Daemon d;
  const std::string id = d.start({{"program", walkers()}});
  Viewer v(d.ws_port, ws_path(id));
  ASSERT_TRUE(v.next("frame"));
  v.command({{"action", "pause"}});
  auto paused = v.next("status");
  ASSERT_TRUE(paused);
  EXPECT_EQ(paused->json()["paused"], true);
  std::this_thread::sleep_for(200ms);  // a step under way when the pause came has finished
  const double t0 = d.get("/api/v1/simulations/" + id)["t"];
  std::this_thread::sleep_for(600ms);
  const Json during = d.get("/api/v1/simulations/" + id);
  EXPECT_EQ(during["status"], "paused");
  EXPECT_EQ(during["t"].get<double>(), t0) << "simulated time stands still while paused";
  d.post("/api/v1/simulations/" + id + "/control", {{"action", "resume"}}, 200);
  // While paused at most the frame of the step under way was streamed, then the resume's status.
  int frames_while_paused = 0;
  for (;;) {
    auto next = v.read();
    ASSERT_TRUE(next);
    if (next->type() == "status") {
      EXPECT_EQ(next->json()["paused"], false);
      break;
    }
    ASSERT_EQ(next->type(), "frame");
    EXPECT_EQ(next->json()["t"].get<double>(), t0);
    ++frames_while_paused;
  }
  EXPECT_LE(frames_while_paused, 1);
  auto frame = v.next("frame");
  ASSERT_TRUE(frame);
  EXPECT_GT(frame->json()["t"].get<double>(), t0);
}

TEST(Simulations, SpeedChangesTheRateOfSimulatedTime) {
  Daemon d;
  const std::string id = d.start({{"program", walkers()}});
  Viewer v(d.ws_port, ws_path(id));
  auto rate = [&](std::chrono::milliseconds span) {
    const double t0 = v.next("frame")->json()["t"];
    const auto w0 = std::chrono::steady_clock::now();
    double t1 = t0;
    while (std::chrono::steady_clock::now() - w0 < span) t1 = v.next("frame")->json()["t"];
    return (t1 - t0) / std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  };
  const double normal = rate(1000ms);
  EXPECT_NEAR(normal, 1.0, 0.35) << "real time at speed 1";
  const Json st = d.post("/api/v1/simulations/" + id + "/control", {{"action", "speed"}, {"value", 4}}, 200);
  EXPECT_EQ(st["speed"], 4.0);
  EXPECT_DOUBLE_EQ(st["frame_hz"], 20.0) << "frames stay at the stream rate; each covers more simulated time";
  ASSERT_TRUE(v.next("status"));
  const double fast = rate(1000ms);
  EXPECT_GT(fast, 2.5 * normal) << "normal " << normal << " fast " << fast;
}

TEST(Simulations, StopEndsWithAnEndMessageAndCloses) {
  Daemon d;
  const std::string id = d.start({{"program", walkers()}});
  Viewer v(d.ws_port, ws_path(id));
  ASSERT_TRUE(v.next("frame"));
  v.command({{"action", "stop"}});
  auto end = v.next("end");
  ASSERT_TRUE(end);
  EXPECT_EQ(end->json()["reason"], "stopped");
  EXPECT_FALSE(v.read(2000ms)) << "the server closes the socket after 'end'";
  const Json st = d.get("/api/v1/simulations/" + id);
  EXPECT_EQ(st["status"], "ended");
  EXPECT_EQ(st["end_reason"], "stopped");
  d.post("/api/v1/simulations/" + id + "/control", {{"action", "resume"}}, 409);
}

TEST(Simulations, DurationEndsTheSession) {
  Daemon d;
  const std::string id = d.start({{"program", walkers()}, {"duration_s", 1.0}, {"speed", 4}});
  Viewer v(d.ws_port, ws_path(id));
  auto end = v.next("end", 5000ms);
  ASSERT_TRUE(end);
  EXPECT_EQ(end->json()["reason"], "completed");
  EXPECT_NEAR(end->json()["t"].get<double>(), 1.0, 1e-6);
}

TEST(Simulations, EndsWhenNobodyWatches) {
  auto config = quick_config();
  config.sim_idle_s = 0.4;
  Daemon d(config);
  const std::string never_watched = d.start({{"program", walkers()}});
  const std::string left = d.start({{"program", walkers()}});
  {
    Viewer v(d.ws_port, ws_path(left));
    ASSERT_TRUE(v.next("frame"));
    std::this_thread::sleep_for(700ms);  // longer than the idle time, but watched
    EXPECT_EQ(d.get("/api/v1/simulations/" + left)["status"], "running");
  }
  std::this_thread::sleep_for(1200ms);
  for (const std::string& id : {never_watched, left}) {
    const Json st = d.get("/api/v1/simulations/" + id);
    EXPECT_EQ(st["status"], "ended") << id;
    EXPECT_EQ(st["end_reason"], "idle") << id;
  }
  EXPECT_EQ(d.get("/api/v1/simulations")["running"], 0);
}

TEST(Simulations, LimitsOnSessionsViewersAndAgents) {
  auto config = quick_config();
  config.max_simulations = 2;
  config.max_viewers = 1;
  config.max_sim_agents = 6;
  Daemon d(config);
  const std::string a = d.start({{"program", walkers()}});
  d.start({{"program", walkers()}});
  auto r =
      d.http.client().Post("/api/v1/simulations", Json{{"program", walkers()}}.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 429);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  EXPECT_FALSE(r->get_header_value("Retry-After").empty());

  Viewer first(d.ws_port, ws_path(a));
  try {
    Viewer second(d.ws_port, ws_path(a));
    ADD_FAILURE() << "a second viewer was accepted";
  } catch (const beast::system_error&) {
  }
  EXPECT_EQ(d.get("/api/v1/simulations/" + a)["viewers"], 1);

  // Stopping one frees a place.
  d.post("/api/v1/simulations/" + a + "/control", {{"action", "stop"}}, 200);
  const Json big = d.post("/api/v1/simulations", {{"program", walkers(4)}}, 422);
  EXPECT_EQ(big["errors"][0]["pointer"], "/program");
  d.start({{"program", walkers(3)}});
}

TEST(Simulations, BadRequestsAreProblemsWithPointers) {
  Daemon d;
  auto first_pointer = [](const Json& p) {
    return p["errors"].empty() ? std::string("?") : p["errors"][0]["pointer"].get<std::string>();
  };
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", Json::object(), 422)), "");
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", {{"card_id", "crd_00000000000000000000"}}, 404)),
            "/card_id");
  EXPECT_EQ(
      first_pointer(d.post("/api/v1/simulations", {{"program", walkers()}, {"world_id", "wld_nope"}}, 404)),
      "/world_id");
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", {{"program", walkers()}, {"speed", 100}}, 422)),
            "/speed");
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", {{"program", walkers()}, {"colour", "red"}}, 422)),
            "/colour");
  Json bad = walkers();
  bad["agents"][1]["goals"][0] = "reception_desk";  // a place, but there is no world
  const Json p = d.post("/api/v1/simulations", {{"program", bad}}, 422);
  EXPECT_EQ(first_pointer(p).rfind("/program/agents/1", 0), 0u) << p.dump();
  Json typo = walkers();
  typo["agents"][0]["speeed"] = 1;
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", {{"program", typo}}, 422)),
            "/program/agents/0/speeed");
  Json file_tree = walkers();
  file_tree["agents"][0]["behavior"] = {{"file", "/etc/passwd"}};
  EXPECT_EQ(first_pointer(d.post("/api/v1/simulations", {{"program", file_tree}}, 422)),
            "/program/agents/0/behavior/file");

  const std::string id = d.start({{"program", walkers()}});
  const std::string control = "/api/v1/simulations/" + id + "/control";
  EXPECT_EQ(first_pointer(d.post(control, {{"action", "seek"}, {"value", 1}}, 422)), "/action");
  EXPECT_EQ(first_pointer(d.post(control, {{"action", "fly"}}, 422)), "/action");
  EXPECT_EQ(first_pointer(d.post(control, {{"action", "speed"}, {"value", 0.01}}, 422)), "/value");
  EXPECT_EQ(first_pointer(d.post(control, {{"action", "speed"}}, 422)), "/value");
  d.post("/api/v1/simulations/sim_unknown/control", {{"action", "pause"}}, 404);
  EXPECT_EQ(d.http.client().Get("/api/v1/simulations/sim_unknown")->status, 404);

  // Over the socket the same command is answered with an error message to that viewer only.
  Viewer v(d.ws_port, ws_path(id));
  v.command({{"action", "seek"}, {"value", 1}});
  auto err = v.next("error");
  ASSERT_TRUE(err);
  EXPECT_EQ(err->json()["status"], 422);
  EXPECT_EQ(err->json()["errors"][0]["pointer"], "/action");
  // A number beyond double (found by tests/fuzz): nlohmann's out_of_range escaped the socket's read
  // handler and aborted the daemon; over REST it was a 500.
  v.ws.text(true);
  v.ws.write(asio::buffer(std::string(R"({"action":"speed","value":1e400})")));
  auto overflow = v.next("error");
  ASSERT_TRUE(overflow);
  EXPECT_EQ(overflow->json()["status"], 400);
  EXPECT_EQ(d.http.client().Post(control, R"({"action":"speed","value":-1e400})", "application/json")->status,
            400);
  d.post(control, {{"action", "pause"}}, 200);
  try {
    Viewer nobody(d.ws_port, ws_path("sim_unknown"));
    ADD_FAILURE() << "an unknown session was accepted";
  } catch (const beast::system_error&) {
  }
}

TEST(Simulations, ASlowViewerDoesNotSlowAnother) {
  Daemon d;
  const std::string id = d.start({{"program", crowd(400)}, {"seed", 5}});
  // Never reads after the hello, with a tiny receive buffer so its queue on the server fills fast.
  Viewer slow(d.ws_port, ws_path(id), "", 4096);
  ASSERT_TRUE(slow.read());
  Viewer fast(d.ws_port, ws_path(id), "socsim.binary.v1");
  ASSERT_TRUE(fast.next("binary"));
  const double t_start = d.get("/api/v1/simulations/" + id)["t"];
  const auto w0 = std::chrono::steady_clock::now();
  int frames = 0;
  std::uint32_t first_seq = 0, last_seq = 0;
  while (std::chrono::steady_clock::now() - w0 < 4s) {
    auto m = fast.next("binary");
    ASSERT_TRUE(m);
    auto f = decode_frame_binary(m->bytes);
    ASSERT_TRUE(f);
    if (frames++ == 0) first_seq = f->seq;
    last_seq = f->seq;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const Json st = d.get("/api/v1/simulations/" + id);
  EXPECT_GT(st["frames_dropped"].get<int>(), 0) << "the slow viewer lost frames";
  EXPECT_LE(last_seq - first_seq + 1 - static_cast<std::uint32_t>(frames), 2u)
      << "the reading viewer received every frame the session sent";
  // 400 agents in a Debug (or sanitizer) build on a shared machine: the step may cost more than
  // real time allows, but never waits for a viewer.
  EXPECT_GE((st["t"].get<double>() - t_start) / seconds, 0.5) << "the simulation kept (near) real time";
  EXPECT_LE(d.ws->stats().frames_queued, 2 * 8u + 4u) << "queues stay bounded";
}

TEST(Simulations, CommandsFromAViewerThatNeverReadsCannotGrowItsQueue) {
  Daemon d;
  const std::string id = d.start({{"program", walkers()}});
  Viewer spammer(d.ws_port, ws_path(id), "", 4096);
  ASSERT_TRUE(spammer.read());
  // Each bad command is answered with an error, each pause/resume with a status to every viewer;
  // the spammer reads none of them.
  for (int i = 0; i < 20000; ++i) {
    spammer.command({{"action", "fly"}});
    spammer.command({{"action", i % 2 ? "resume" : "pause"}});
  }
  spammer.command({{"action", "speed"}, {"value", 3}});  // the last command, to know when all were handled
  for (int i = 0; i < 1000 && d.get("/api/v1/simulations/" + id)["speed"] != 3.0; ++i)
    std::this_thread::sleep_for(20ms);
  const Json st = d.get("/api/v1/simulations/" + id);
  ASSERT_EQ(st["speed"], 3.0);
  EXPECT_EQ(st["status"], "running");
  EXPECT_LE(d.ws->stats().frames_queued, 8u + 2u) << "errors and statuses are dropped like frames";
}

// A card with a recorded log, built as the scenario pipeline would (runner → recorder → store).
std::string recorded_card(testing::TestServer& s, double seconds, std::string* sha) {
  auto program = crowd::program_from_json(walkers(2)).value();
  crowd::RunnerOptions o;
  o.seed = 9;
  auto runner = crowd::ScenarioRunner::create(nullptr, program, o).value();
  scenario::TrajectoryRecorder recorder(0.1);
  runner->run(
      seconds, [&](double t, std::span<const crowd::PedestrianState> st) { recorder.add(t, st); }, 2);
  scenario::TrajectoryLog log = std::move(recorder).finish();
  EXPECT_TRUE(scenario::save_trajectory_log(s.store(), log));
  *sha = log.sha256();
  cards::CardContent c;
  c.title = "Walkers";
  c.description = "Two pairs cross a room.";
  c.prompt = "people cross a room";
  c.seed = 9;
  c.generator.name = "offline";
  c.program = walkers(2);
  c.trajectory_log = {{"uri", "/api/v1/trajectories/" + log.sha256()},
                      {"format", scenario::kTrajectoryFormat},
                      {"frames", log.frame_count()},
                      {"sha256", log.sha256()}};
  cards::CardCatalogue catalogue(s.store());
  return catalogue.create(c, "anonymous").value().id;
}

TEST(Simulations, CardPlaybackFollowsTheRecordingAndSeeks) {
  Daemon d;
  std::string sha;
  const std::string card = recorded_card(d.http, 6.0, &sha);
  const auto log = scenario::load_trajectory_log(d.http.store(), sha).value();
  const Json created = d.post("/api/v1/simulations", {{"card_id", card}, {"speed", 2}}, 201);
  ASSERT_TRUE(created.contains("id"));
  EXPECT_EQ(created["kind"], "card");
  EXPECT_EQ(created["card_id"], card);
  EXPECT_EQ(created["seekable"], true);
  EXPECT_DOUBLE_EQ(created["frame_hz"], 20.0);  // 10 Hz recording × 2
  EXPECT_NEAR(created["duration_s"].get<double>(), 6.0, 1e-9);
  const std::string id = created["id"];

  Viewer v(d.ws_port, ws_path(id));
  const Json hello = v.read()->json();
  EXPECT_EQ(hello["kind"], "card");
  EXPECT_EQ(hello["roles"], Json(log.roles()));
  // Consecutive recorded frames, unchanged.
  for (int k = 0; k < 5; ++k) {
    const Json f = v.next("frame")->json();
    const double t = f["t"];
    const auto i = static_cast<std::size_t>(std::lround(t / 0.1));
    ASSERT_NEAR(log.frame_time(i), t, 1e-6);
    const auto agents = log.frame(i);
    ASSERT_EQ(f["agents"].size(), agents.size());
    EXPECT_EQ(f["agents"][0]["x"].get<float>(), agents[0].x);
    EXPECT_EQ(f["agents"][0]["vy"].get<float>(), agents[0].vy);
  }
  v.command({{"action", "seek"}, {"value", 4.0}});
  ASSERT_TRUE(v.next("status"));
  const Json sought = v.next("frame")->json();
  EXPECT_NEAR(sought["t"].get<double>(), 4.0, 1e-6);
  EXPECT_EQ(sought["agents"][2]["y"].get<float>(), log.frame(40)[2].y);
  const Json bad = d.post("/api/v1/simulations/" + id + "/control", {{"action", "seek"}, {"value", 60}}, 422);
  EXPECT_EQ(bad["errors"][0]["pointer"], "/value");
  auto end = v.next("end", 5000ms);
  ASSERT_TRUE(end);
  EXPECT_EQ(end->json()["reason"], "completed");
  EXPECT_NEAR(end->json()["t"].get<double>(), log.frame_time(log.frame_count() - 1), 1e-6);

  cards::CardContent no_log;
  no_log.title = "No recording";
  no_log.prompt = "nothing";
  no_log.generator.name = "offline";
  const std::string empty = cards::CardCatalogue(d.http.store()).create(no_log, "anonymous").value().id;
  EXPECT_EQ(d.post("/api/v1/simulations", {{"card_id", empty}}, 422)["errors"][0]["pointer"], "/card_id");
}

TEST(Simulations, SameSeedSameFrames) {
  Daemon d;
  const std::string a = d.start({{"program", crowd(30)}, {"seed", 42}});
  const std::string b = d.start({{"program", crowd(30)}, {"seed", 42}});
  // Both viewers join at once; frames of one seq are compared wherever the two streams overlap (a
  // loaded machine may join after a fixed seq has gone by, so none is named in advance).
  Viewer va(d.ws_port, ws_path(a));
  Viewer vb(d.ws_port, ws_path(b));
  std::map<std::uint32_t, std::string> seen;
  for (int i = 0; i < 40; ++i) {
    auto m = va.next("frame");
    ASSERT_TRUE(m);
    seen[m->json()["seq"].get<std::uint32_t>()] = m->bytes;
  }
  int compared = 0;
  for (int i = 0; i < 200 && compared < 3; ++i) {
    auto m = vb.next("frame");
    ASSERT_TRUE(m);
    const auto seq = m->json()["seq"].get<std::uint32_t>();
    if (auto it = seen.find(seq); it != seen.end()) {
      EXPECT_EQ(it->second, m->bytes) << "seq " << seq;
      ++compared;
    } else if (seq > seen.rbegin()->first) {
      break;
    }
  }
  EXPECT_GT(compared, 0) << "the two streams never showed the same seq";
}

TEST(Simulations, ListAndDelete) {
  Daemon d;
  const std::string a = d.start({{"program", walkers()}});
  const std::string b = d.start({{"program", walkers()}});
  const Json list = d.get("/api/v1/simulations");
  ASSERT_EQ(list["items"].size(), 2u);
  EXPECT_EQ(list["items"][0]["id"], b) << "newest first";
  EXPECT_EQ(list["running"], 2);
  auto r = d.http.client().Delete(("/api/v1/simulations/" + a).c_str());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(Json::parse(r->body)["end_reason"], "deleted");
  EXPECT_EQ(d.http.client().Get(("/api/v1/simulations/" + a).c_str())->status, 404);
  EXPECT_EQ(d.get("/api/v1/simulations")["items"].size(), 1u);
}

TEST(SimulationFrames, BinaryDecoderRefusesBadBytes) {
  std::vector<FrameAgent> agents(2);
  agents[1].id = 7;
  agents[1].x = 1.25f;
  agents[1].group_id = -1;
  const std::string bytes = encode_frame_binary(3, 0.5, agents);
  EXPECT_EQ(bytes.size(), kBinaryHeaderBytes + 2 * kBinaryAgentBytes);
  auto ok = decode_frame_binary(bytes);
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->agents, agents);
  EXPECT_FALSE(decode_frame_binary(bytes.substr(0, bytes.size() - 1)));
  EXPECT_FALSE(decode_frame_binary("SSF2" + bytes.substr(4)));
  EXPECT_FALSE(decode_frame_binary(""));
}

// Issue 14 #6: one authorisation rule for REST and WebSocket control. On a server with keys, a
// viewer that presented no key (or another author's) may watch but not stop the simulation.
TEST(Simulations, OnlyTheAuthorControlsOverTheSocketToo) {
  server::ServerConfig config = quick_config();
  config.api_keys = {{"alice", "alice-secret-0123456789"}, {"bob", "bob-secret-0123456789"}};
  Daemon d(config);
  auto c = d.http.client();
  c.set_bearer_token_auth("alice-secret-0123456789");
  auto r = c.Post("/api/v1/simulations", Json{{"program", walkers()}}.dump(), "application/json");
  ASSERT_TRUE(r && r->status == 201) << (r ? r->body : "no reply");
  const std::string id = Json::parse(r->body)["id"];

  for (const std::string& offer :
       {std::string(), std::string("socsim.json.v1, bearer.bob-secret-0123456789")}) {
    Viewer stranger(d.ws_port, ws_path(id), offer);
    stranger.command({{"action", "stop"}});
    auto refusal = stranger.next("error");
    ASSERT_TRUE(refusal) << "offer '" << offer << "': the stop is answered with an error";
    EXPECT_EQ(refusal->json()["status"], 403);
    EXPECT_EQ(d.get("/api/v1/simulations/" + id)["status"], "running") << offer;
  }
  Viewer owner(d.ws_port, ws_path(id), "socsim.json.v1, bearer.alice-secret-0123456789");
  EXPECT_EQ(owner.protocol, "socsim.json.v1") << "the key is never echoed as the subprotocol";
  owner.command({{"action", "stop"}});
  EXPECT_TRUE(owner.next("end")) << "the author's stop ends the simulation";
}

}  // namespace
}  // namespace socsim::server
