#include "server/card_exports.hpp"

#include "core/interop/export_arena.hpp"
#include "core/interop/export_gazebo_actors.hpp"
#include "core/interop/export_isaac.hpp"
#include "core/interop/mcap_export.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "core/world/world_document.hpp"

namespace socsim::server {

Result<CardExport> card_export_scenario(const cards::Card& card) {
  const cards::CardContent& c = card.content;
  if (!c.world.is_object() || !c.program.is_object())
    return fail(ErrorCode::kValidation, "card " + card.id + " has no world and program to export",
                {FieldError{c.world.is_object() ? "/program" : "/world", "missing"}});
  auto w = world::world_from_document(c.world);
  if (!w) return tl::unexpected(Error(w.error()).under("/world"));
  auto p = crowd::program_from_json(c.program);
  if (!p) return tl::unexpected(Error(p.error()).under("/program"));
  return CardExport{std::move(*w), std::move(*p)};
}

Result<scenario::TrajectoryLog> card_trajectory_log(store::Store& store, const cards::Card& card) {
  const Json& log = card.content.trajectory_log;
  if (!log.is_object() || !log.contains("sha256") || !log["sha256"].is_string())
    return tl::unexpected(Error(ErrorCode::kNotFound, "card " + card.id + " has no trajectory log",
                                {FieldError{"/trajectory_log", "missing"}}));
  return scenario::load_trajectory_log(store, log["sha256"].get<std::string>());
}

Result<std::string> card_mcap(store::Store& store, const cards::Card& card,
                              std::optional<bool> scene_people) {
  auto s = card_export_scenario(card);
  if (!s) return tl::unexpected(s.error());
  auto log = card_trajectory_log(store, card);
  if (!log) return tl::unexpected(log.error());
  interop::McapExportOptions options;
  options.card_id = card.id;
  options.seed = card.content.seed;
  options.roles = s->program.roles;
  options.scene_people = scene_people;
  auto mcap = interop::export_mcap(*log, s->world, options);
  if (!mcap) return tl::unexpected(Error(mcap.error()).under("/program"));
  return mcap;
}

Result<std::string> card_gazebo_actors(store::Store& store, const cards::Card& card) {
  auto s = card_export_scenario(card);
  if (!s) return tl::unexpected(s.error());
  auto log = card_trajectory_log(store, card);
  if (!log) return tl::unexpected(log.error());
  return interop::export_gazebo_actors(*log, s->world);
}

Result<std::string> card_arena(const cards::Card& card) {
  auto s = card_export_scenario(card);
  if (!s) return tl::unexpected(s.error());
  interop::ArenaExportOptions options;
  options.seed = card.content.seed;
  auto json = interop::export_arena_scenario(s->world, s->program, options);
  if (!json) return tl::unexpected(Error(json.error()).under("/program"));
  return json;
}

Result<std::vector<interop::ExportFile>> card_isaac(const cards::Card& card) {
  auto s = card_export_scenario(card);
  if (!s) return tl::unexpected(s.error());
  interop::IsaacExportOptions options;
  options.seed = card.content.seed;
  const Json& log = card.content.trajectory_log;
  if (log.is_object() && log.contains("duration_s") && log["duration_s"].is_number())
    options.duration_s = log["duration_s"].get<double>();
  auto files = interop::export_isaac(s->world, s->program, options);
  if (!files) return tl::unexpected(Error(files.error()).under("/program"));
  return files;
}

}  // namespace socsim::server
