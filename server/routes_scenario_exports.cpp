// GET /api/v1/cards/{id}/export?format=hunav|pedsim|csv|mcap|gazebo|arena: a scenario card for other
// simulators. hunav: a tar of <base>.yaml + behavior_trees/<base>__agent_<id>_bt.xml (or ?archive=json for
// {"files": {path: text}}); pedsim: pedsim_ros scenario XML; csv: the card's trajectory log;
// mcap: the trajectory log as a ROS 2 / Foxglove recording (core/interop/mcap_export.hpp);
// gazebo: an SDF world whose actors walk the logged trajectories; arena: an Arena-Rosnav scenario;
// isaac: a tar (or ?archive=json) of world.usda, ira_config.yaml and people_commands.txt.
// Without ?format the card's own export document is returned, as before.
//
// The group is named "card_exports" so that it registers before "cards" (groups register in name
// order and the router answers with the first matching route): it owns the /export path.
#include "core/interop/export_hunav.hpp"
#include "core/interop/export_pedsim_scenario.hpp"
#include "core/interop/tar_archive.hpp"
#include "core/interop/trajectory_csv.hpp"
#include "server/card_exports.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kExportPath = R"(/api/v1/cards/(crd_[0-9a-z]{20}|[^/]+)/export)";

Error bad_parameter(const std::string& name, const std::string& message) {
  return Error(ErrorCode::kValidation, message, {FieldError{"", message, name, 0, 0}});
}

void attach(Response& res, const std::string& file, const std::string& body, const char* type) {
  res.set_header("Content-Disposition", "attachment; filename=\"" + file + "\"");
  res.set_content(body, type);
}

void export_routes(Router& http, RouteContext& ctx) {
  http.Get(kExportPath, [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    const auto format = query(req, "format");
    if (!format || *format == "card") {
      auto doc = ctx.catalogue.export_card(id);
      if (!doc) return reply_problem(res, doc.error(), req.path);
      return attach(res, id + ".card.json", *doc, "application/json");
    }
    if (*format != "hunav" && *format != "pedsim" && *format != "csv" && *format != "mcap" &&
        *format != "gazebo" && *format != "arena" && *format != "isaac")
      return reply_problem(
          res,
          bad_parameter("format", "format must be card, hunav, pedsim, csv, mcap, gazebo, arena or isaac"),
          req.path);
    const std::string scene_people = query(req, "scene_people").value_or("auto");
    if (scene_people != "true" && scene_people != "false" && scene_people != "auto")
      return reply_problem(res, bad_parameter("scene_people", "scene_people must be true, false or auto"),
                           req.path);
    const std::string archive = query(req, "archive").value_or("tar");
    if (archive != "tar" && archive != "json")
      return reply_problem(res, bad_parameter("archive", "archive must be tar or json"), req.path);
    auto card = ctx.catalogue.get(id);
    if (!card) return reply_problem(res, card.error(), req.path);

    if (*format == "csv") {
      auto loaded = card_trajectory_log(ctx.store, *card);
      if (!loaded) return reply_problem(res, loaded.error(), req.path);
      return attach(res, id + ".trajectories.csv", interop::trajectories_csv(*loaded), "text/csv");
    }

    if (*format == "mcap") {
      auto mcap =
          card_mcap(ctx.store, *card,
                    scene_people == "auto" ? std::nullopt : std::optional<bool>(scene_people == "true"));
      if (!mcap) return reply_problem(res, mcap.error(), req.path);
      return attach(res, id + ".mcap", *mcap, "application/octet-stream");
    }
    if (*format == "gazebo") {
      auto sdf = card_gazebo_actors(ctx.store, *card);
      if (!sdf) return reply_problem(res, sdf.error(), req.path);
      return attach(res, id + ".world", *sdf, "application/xml");
    }
    if (*format == "arena") {
      auto json = card_arena(*card);
      if (!json) return reply_problem(res, json.error(), req.path);
      return attach(res, id + ".arena.json", *json, "application/json");
    }
    auto s = card_export_scenario(*card);
    if (!s) return reply_problem(res, s.error(), req.path);
    if (*format == "pedsim") {
      interop::PedsimExportOptions options;
      options.seed = card->content.seed;
      auto xml = interop::export_pedsim_scenario(s->world, s->program, options);
      if (!xml) return reply_problem(res, xml.error(), req.path);
      return attach(res, id + ".pedsim.xml", *xml, "application/xml");
    }
    Result<std::vector<interop::ExportFile>> files;
    if (*format == "isaac") {
      files = card_isaac(*card);
    } else {
      interop::HunavOptions options;
      options.seed = card->content.seed;
      options.base_name = interop::file_stem(id, "card") + "_agents";
      files = interop::export_hunav(s->world, s->program, options);
    }
    if (!files) return reply_problem(res, files.error(), req.path);
    if (archive == "json") {
      Json bundle = Json::object();
      for (const auto& f : *files) bundle[f.path] = f.content;
      return reply_json(res, 200, {{"format", *format}, {"files", bundle}});
    }
    auto tar = interop::tar_archive(*files);
    if (!tar) return reply_problem(res, tar.error(), req.path);
    attach(res, id + "." + *format + ".tar", *tar, "application/x-tar");
  });
}

}  // namespace

SOCSIM_ROUTES("card_exports", export_routes);

}  // namespace socsim::server
