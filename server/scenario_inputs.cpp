#include "server/scenario_inputs.hpp"

#include "core/cards/world_store.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"

namespace socsim::server {

// The world of a program session: a stored world by id, a world document, or world.yaml text.
Result<std::shared_ptr<const world::World>> session_world(RouteContext& ctx, const Json& body) {
  if (body.contains("world_id")) {
    const std::string id = body["world_id"].get<std::string>();
    auto stored = cards::WorldStore(ctx.store).get(id);
    if (!stored && stored.error().code == ErrorCode::kNotFound)
      return fail(ErrorCode::kNotFound, "no world with id '" + id + "'",
                  {FieldError{"/world_id", "names no stored world (see GET /api/v1/worlds)"}});
    if (!stored) return tl::unexpected(stored.error());
    auto w = world::world_from_yaml(stored->world_yaml);
    if (!w)
      return fail(ErrorCode::kInternal,
                  "stored world '" + id + "' no longer validates: " + w.error().message());
    return std::make_shared<const world::World>(std::move(*w));
  }
  if (!body.contains("world")) return std::shared_ptr<const world::World>();
  const Json& doc = body["world"];
  auto w = doc.is_string() ? world::world_from_yaml(doc.get<std::string>()) : world::world_from_document(doc);
  if (!w) return tl::unexpected(Error(w.error()).under("/world"));
  return std::make_shared<const world::World>(std::move(*w));
}

Status no_tree_files(const crowd::Program& p) {
  std::vector<FieldError> errors;
  auto check = [&](const std::optional<crowd::ProgramTree>& t) {
    if (t && !t->file.empty())
      errors.push_back({"/program" + t->pointer + "/file",
                        "the server reads no files; give the behaviour tree inline as 'xml'"});
  };
  for (const auto& [name, tree] : p.behavior_trees) check(tree);
  for (const auto& a : p.agents) check(a.behavior);
  for (const auto& g : p.ambient_groups) check(g.behavior);
  if (errors.empty()) return {};
  return fail(ErrorCode::kValidation, "behaviour trees given as files", std::move(errors));
}

Result<CardScenario> card_scenario(RouteContext& ctx, const std::string& card_id) {
  auto c = ctx.catalogue.get(card_id);
  if (!c) {
    if (c.error().code == ErrorCode::kNotFound)
      return fail(ErrorCode::kNotFound, "no card with id '" + card_id + "'",
                  {FieldError{"/card_id", "names no card in the catalogue"}});
    return tl::unexpected(c.error());
  }
  if (!c->content.program.is_object())
    return fail(ErrorCode::kValidation, "the card has no scenario program",
                {FieldError{"/card_id", "card '" + card_id + "' records no program"}});
  CardScenario out;
  if (c->content.world.is_object()) {
    auto w = world::world_from_document(c->content.world);
    if (!w)
      return fail(ErrorCode::kInternal,
                  "the world of card '" + card_id + "' no longer validates: " + w.error().message());
    out.world = std::make_shared<const world::World>(std::move(*w));
  }
  auto program = crowd::program_from_json(c->content.program);
  if (!program)
    return fail(ErrorCode::kInternal,
                "the program of card '" + card_id + "' no longer parses: " + program.error().message());
  out.program = std::move(*program);
  return out;
}

}  // namespace socsim::server
