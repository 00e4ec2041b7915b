// Fuzz target: a BehaviorTree.CPP XML document (v3 or v4) as a program carries it inline:
// BtDocument::parse with the full node library and its literal checks against a world, then one
// instance of every tree (what each agent of a run gets). Includes are refused (no base dir).
#include <cstddef>
#include <cstdint>

#include "core/crowd/bt_nodes.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

struct Library {
  socsim::crowd::CrowdSimulation sim;
  socsim::crowd::BtEnvironment env;
  socsim::crowd::BtRegistry registry;
  socsim::crowd::BtLoadOptions load;

  explicit Library(socsim::crowd::CrowdSimulation s)
      : sim(std::move(s)), env(sim, &socsim::fuzz::small_world()), registry(behavior_registry(env)) {
    auto field = socsim::crowd::VelocityField::from_values(socsim::fuzz::small_world().bounds(), 1, 1,
                                                           {socsim::crowd::Vec2{}});
    if (!field) socsim::fuzz::broken(field.error().detail.c_str(), __FILE__, __LINE__);
    env.add_velocity_field("visitors", std::move(*field), {});
    load = behavior_load_options(env);
  }
};

Library& library() {
  static Library lib = [] {
    auto sim = socsim::crowd::CrowdSimulation::create({});
    if (!sim) socsim::fuzz::broken(sim.error().detail.c_str(), __FILE__, __LINE__);
    return Library(std::move(*sim));
  }();
  return lib;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Library& lib = library();
  auto doc = socsim::crowd::BtDocument::parse(socsim::fuzz::text(data, size), lib.registry, lib.load);
  if (!doc) return 0;
  SOCSIM_FUZZ_CHECK(doc->tree(doc->main_tree()) != nullptr);
  for (const std::string& id : doc->tree_ids()) (void)doc->instantiate(id);
  return 0;
}
