#include "server/prompt_gate.hpp"

#include "core/scenario/prompt_check.hpp"
#include "core/scenario/wordnet.hpp"

namespace socsim::server {

Result<scenario::ScenarioIntent> checked_prompt(const std::string& prompt, std::size_t max_prompt_bytes) {
  const scenario::PromptRules rules{.max_bytes = max_prompt_bytes};
  if (auto s = scenario::check_prompt_form(prompt, rules); !s) return tl::unexpected(s.error());
  auto wordnet = scenario::WordNet::open();
  if (!wordnet) return tl::unexpected(wordnet.error());
  if (auto s = scenario::check_prompt_language(prompt, scenario::english_words(**wordnet), rules); !s)
    return tl::unexpected(s.error());
  auto intent = scenario::interpret_prompt(prompt);
  if (!intent) return tl::unexpected(intent.error());
  if (auto s = scenario::check_prompt_content(*intent); !s) return tl::unexpected(s.error());
  return intent;
}

}  // namespace socsim::server
