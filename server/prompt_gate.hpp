#pragma once
// The one gate every text-to-scenario entry passes (POST /api/v1/scenarios, /interpret and
// `socsim scenario generate`): the prompt's form, language and content (core/scenario/prompt_check)
// checked with WordNet's words, and its interpretation. A refusal is kValidation at /prompt.
#include <cstddef>
#include <string>

#include "core/scenario/scenario_intent.hpp"

namespace socsim::server {

Result<scenario::ScenarioIntent> checked_prompt(const std::string& prompt, std::size_t max_prompt_bytes);

}  // namespace socsim::server
