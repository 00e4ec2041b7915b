// GET /api/v1/cards/{id}/export?format=hunav|pedsim|csv|mcap|gazebo|arena|isaac: a card with the clinic world
// and the queue program exports as a HuNavSim tar (or JSON bundle), pedsim_ros XML, an Arena-Rosnav scenario
// and the Isaac Sim files (the same bytes as the core exporters with the card's seed); a card with a stored
// trajectory log as CSV, MCAP and Gazebo actors; without format the card's export document as before; bad
// formats 422.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/interop/export_arena.hpp"
#include "core/interop/export_gazebo_actors.hpp"
#include "core/interop/export_isaac.hpp"
#include "core/interop/mcap_export.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "core/world/pedsim_import.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/interop/interop_text.hpp"
#include "tests/server/test_server.hpp"

namespace socsim {
namespace {

using interop::testing::example;

std::string post_card(httplib::Client& c, const Json& body) {
  auto r = c.Post("/api/v1/cards", body.dump(), "application/json");
  EXPECT_TRUE(r);
  if (!r) return {};
  EXPECT_EQ(r->status, 201) << r->body;
  return Json::parse(r->body).value("id", "");
}

Json clinic_card(const Json& extra = Json::object()) {
  const world::World w = world::world_from_yaml(example("world_clinic.yaml")).value();
  Json card = {{"title", "clinic queue"},
               {"prompt", "patients queue at the reception"},
               {"seed", 11},
               {"world", world::world_to_document(w)},
               {"program", Json::parse(example("program_queue.json"))}};
  card["program"].erase("$schema");
  card.update(extra);
  return card;
}

TEST(ScenarioExports, HunavTarAndJsonBundleAndPedsimXml) {
  testing::TestServer s;
  auto c = s.client();
  const std::string id = post_card(c, clinic_card());
  ASSERT_FALSE(id.empty());

  auto tar = c.Get("/api/v1/cards/" + id + "/export?format=hunav");
  ASSERT_TRUE(tar);
  ASSERT_EQ(tar->status, 200) << tar->body;
  EXPECT_EQ(tar->get_header_value("Content-Type"), "application/x-tar");
  EXPECT_EQ(tar->body.size() % 512, 0u);
  EXPECT_EQ(tar->body.substr(257, 5), "ustar");

  auto bundle = c.Get("/api/v1/cards/" + id + "/export?format=hunav&archive=json");
  ASSERT_TRUE(bundle);
  ASSERT_EQ(bundle->status, 200) << bundle->body;
  const Json files = Json::parse(bundle->body)["files"];
  const std::string base = id + "_agents";
  ASSERT_TRUE(files.contains(base + ".yaml"));
  const YAML::Node params =
      YAML::Load(files[base + ".yaml"].get<std::string>())["hunav_loader"]["ros__parameters"];
  ASSERT_EQ(params["agents"].size(), 6u);  // receptionist + 5 patients; the robot is not a HuNavSim agent
  for (std::size_t k = 1; k <= 6; ++k)
    EXPECT_TRUE(files.contains("behavior_trees/" + base + "__agent_" + std::to_string(k) + "_bt.xml")) << k;
  // The tar holds the same first file.
  EXPECT_NE(tar->body.find(files[base + ".yaml"].get<std::string>()), std::string::npos);

  auto pedsim = c.Get("/api/v1/cards/" + id + "/export?format=pedsim");
  ASSERT_TRUE(pedsim);
  ASSERT_EQ(pedsim->status, 200) << pedsim->body;
  EXPECT_EQ(pedsim->get_header_value("Content-Type"), "application/xml");
  auto back = world::import_pedsim(pedsim->body);
  ASSERT_TRUE(back) << back.error().message();
  int agents = 0;
  for (const auto& a : back->agents) agents += a.count;
  EXPECT_EQ(agents, 7);

  auto card_doc = c.Get("/api/v1/cards/" + id + "/export");
  ASSERT_TRUE(card_doc);
  EXPECT_EQ(card_doc->status, 200);
  EXPECT_EQ(card_doc->get_header_value("Content-Type"), "application/json");
  EXPECT_NE(card_doc->body.find(id), std::string::npos);
}

TEST(ScenarioExports, ArenaScenarioAndIsaacFilesAreTheCoreExportsWithTheCardsSeed) {
  testing::TestServer s;
  auto c = s.client();
  const std::string id = post_card(c, clinic_card());
  const world::World w = world::world_from_yaml(example("world_clinic.yaml")).value();
  const crowd::Program p = crowd::program_from_text(example("program_queue.json")).value();

  auto arena = c.Get("/api/v1/cards/" + id + "/export?format=arena");
  ASSERT_TRUE(arena);
  ASSERT_EQ(arena->status, 200) << arena->body;
  EXPECT_EQ(arena->get_header_value("Content-Type"), "application/json");
  interop::ArenaExportOptions ao;
  ao.seed = 11;
  // The card's world went through its JSON document: compare with the same document's world.
  const world::World stored = world::world_from_document(world::world_to_document(w)).value();
  EXPECT_EQ(arena->body, interop::export_arena_scenario(stored, p, ao).value());

  auto isaac = c.Get("/api/v1/cards/" + id + "/export?format=isaac&archive=json");
  ASSERT_TRUE(isaac);
  ASSERT_EQ(isaac->status, 200) << isaac->body;
  const Json files = Json::parse(isaac->body);
  EXPECT_EQ(files["format"], "isaac");
  interop::IsaacExportOptions io;
  io.seed = 11;
  const std::vector<interop::ExportFile> expected = interop::export_isaac(stored, p, io).value();
  ASSERT_EQ(files["files"].size(), expected.size());
  for (const auto& f : expected) EXPECT_EQ(files["files"].value(f.path, ""), f.content) << f.path;
  auto tar = c.Get("/api/v1/cards/" + id + "/export?format=isaac");
  ASSERT_TRUE(tar);
  EXPECT_EQ(tar->get_header_value("Content-Type"), "application/x-tar");
  EXPECT_NE(tar->body.find("isaacsim.replicator.agent:"), std::string::npos);
}

TEST(ScenarioExports, CsvMcapAndGazeboFromTheStoredTrajectoryLog) {
  testing::TestServer s;
  const world::World w = world::world_from_yaml(example("world_clinic.yaml")).value();
  const crowd::Program p = crowd::program_from_text(example("program_queue.json")).value();
  auto runner = crowd::ScenarioRunner::create(&w, p, {});
  ASSERT_TRUE(runner);
  scenario::TrajectoryRecorder recorder(0.1);
  (*runner)->run(
      2.0, [&](double t, std::span<const crowd::PedestrianState> st) { recorder.add(t, st); }, 2);
  const scenario::TrajectoryLog log = std::move(recorder).finish();
  ASSERT_TRUE(scenario::save_trajectory_log(s.store(), log));
  auto c = s.client();
  const std::string id = post_card(c, clinic_card({{"trajectory_log",
                                                    {{"uri", "/api/v1/trajectories/" + log.sha256()},
                                                     {"format", "socsim-traj-v1+zlib"},
                                                     {"frames", log.frame_count()},
                                                     {"sha256", log.sha256()}}}}));
  auto csv = c.Get("/api/v1/cards/" + id + "/export?format=csv");
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
  EXPECT_EQ(csv->body.rfind("t,id,x,y,vx,vy,state,role,group_id\n", 0), 0u);
  std::size_t rows = 0;
  for (std::size_t f = 0; f < log.frame_count(); ++f) rows += log.frame(f).size();
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv->body.begin(), csv->body.end(), '\n')), rows + 1);

  // MCAP: the log, the card's world, its id, seed and the program's roles (tests/e2e reads the file).
  auto mcap = c.Get("/api/v1/cards/" + id + "/export?format=mcap");
  ASSERT_TRUE(mcap);
  ASSERT_EQ(mcap->status, 200) << mcap->body;
  EXPECT_EQ(mcap->get_header_value("Content-Type"), "application/octet-stream");
  EXPECT_EQ(mcap->get_header_value("Content-Disposition"), "attachment; filename=\"" + id + ".mcap\"");
  interop::McapExportOptions options;
  options.card_id = id;
  options.seed = 11;
  options.roles = p.roles;
  EXPECT_EQ(mcap->body, interop::export_mcap(log, w, options).value());
  auto people_only = c.Get("/api/v1/cards/" + id + "/export?format=mcap&scene_people=false");
  ASSERT_TRUE(people_only);
  options.scene_people = false;
  EXPECT_EQ(people_only->body, interop::export_mcap(log, w, options).value());
  EXPECT_LT(people_only->body.size(), mcap->body.size());

  auto gazebo = c.Get("/api/v1/cards/" + id + "/export?format=gazebo");
  ASSERT_TRUE(gazebo);
  ASSERT_EQ(gazebo->status, 200) << gazebo->body;
  EXPECT_EQ(gazebo->get_header_value("Content-Type"), "application/xml");
  EXPECT_EQ(gazebo->body, interop::export_gazebo_actors(log, w));
}

TEST(ScenarioExports, ProblemsAreNamed) {
  testing::TestServer s;
  auto c = s.client();
  const std::string id = post_card(c, clinic_card());
  auto bad = c.Get("/api/v1/cards/" + id + "/export?format=unity");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 422);
  EXPECT_EQ(Json::parse(bad->body)["errors"][0]["parameter"], "format");
  for (const char* format : {"csv", "mcap", "gazebo"}) {
    auto no_log = c.Get("/api/v1/cards/" + id + "/export?format=" + format);
    ASSERT_TRUE(no_log);
    EXPECT_EQ(no_log->status, 404) << format;
  }
  auto bad_option = c.Get("/api/v1/cards/" + id + "/export?format=mcap&scene_people=maybe");
  ASSERT_TRUE(bad_option);
  EXPECT_EQ(bad_option->status, 422);
  EXPECT_EQ(Json::parse(bad_option->body)["errors"][0]["parameter"], "scene_people");
  auto missing = c.Get("/api/v1/cards/crd_00000000000000000000/export?format=pedsim");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  // A card whose program names a place the world lacks: 422 with the program pointer.
  Json broken = clinic_card();
  broken["program"]["agents"][1]["spawn"] = "no_such_room";
  const std::string bid = post_card(c, broken);
  auto refused = c.Get("/api/v1/cards/" + bid + "/export?format=hunav");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 422) << refused->body;
  EXPECT_EQ(Json::parse(refused->body)["errors"][0]["pointer"], "/agents/1/spawn");
}

}  // namespace
}  // namespace socsim
