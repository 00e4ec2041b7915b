#pragma once
// What a prompt's ScenarioIntent asks of the world, in the world generator's terms: the counted
// features, named rooms and objects as world::WorldRequirements (core/world/requirements.hpp),
// and how many people the prompt puts in the building (its occupants).
#include <cstddef>

#include "core/scenario/scenario_intent.hpp"
#include "core/world/requirements.hpp"

namespace socsim::scenario {

// The people the prompt counts: the sum of its groups with a count (each as the generator will
// simulate it, Count::people()); groups without a count add nothing.
std::size_t people_named(const ScenarioIntent& intent);

// Features the world generator knows (world::feature_from_word) with their counts — exact as said
// ("two exits", "the only checkout"), "at least" the lower bound of a range or approximation, at
// least one when only named ("the exits", "a counter") — clamped to what a request may ask for;
// rooms and objects as named (other counted things are rooms when the prompt names them as rooms,
// else objects: "three galleries", "the coffee machine"); occupants = people_named() when the
// prompt counts anyone. Features said twice keep the larger count.
world::WorldRequirements world_requirements(const ScenarioIntent& intent);

}  // namespace socsim::scenario
