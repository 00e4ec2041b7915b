#pragma once
// A scenario program read against what the prompt says (ScenarioIntent): which of its people are
// the groups the prompt names, which were added and why, and which explicit facts it contradicts
// (a named group missing, a count not held, people nobody asked for). The offline generator and
// the card use it to say what was added; the LLM path quotes the contradictions back to the model.
#include <cstddef>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/scenario/scenario_intent.hpp"

namespace socsim::scenario {

// Whether a program role ("security_guard", "nurses", "guard") is the people of a named group:
// its program role, its role as written, its normalised role or its head noun.
bool role_is(const PeopleGroup& group, const std::string& program_role);

// The prompt asks for nobody beyond the groups it names (it names some and no background words).
bool names_who_is_there(const ScenarioIntent& intent);

// People of the program the prompt did not name: [{role, count, why}], one per program role. A
// generic group ("people", "everyone") takes every role no other group claims.
Json added_groups(const Json& program, const ScenarioIntent& intent,
                  const std::vector<std::string>& categories, const std::string& domain);

// The prompt's explicit facts the program contradicts, one FieldError each, pointing into the
// program (/agents/<i>, /ambient_groups/<i>/size, "" for a group that is missing) and quoting the
// prompt's words: a named group with nobody in it; an exact count not held exactly, an
// approximate one off by more than 10 %, a range not met; and, when the prompt names who is there,
// every group nobody asked for. Counts are not checked when the prompt counts more people than
// `bound` (the agents cap applies: the generator scales them).
std::vector<FieldError> intent_contradictions(const Json& program, const ScenarioIntent& intent,
                                              std::size_t bound);

}  // namespace socsim::scenario
