#pragma once
// Prompt templates: readable Markdown files in schemas/prompts/<name>.md, embedded at build time,
// with "## system" and "## user" sections and {{variable}} placeholders.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/llm/llm_client.hpp"

namespace socsim::llm {

using PromptVariables = std::map<std::string, std::string>;

struct PromptTemplate {
  std::string name;
  std::string header;                  // text before the first section: documentation, not sent
  std::string system;                  // may be empty
  std::string user;                    // may be empty (not both)
  std::vector<std::string> variables;  // placeholders used, sorted, unique
};

// Parses a template; kValidation naming the line of a malformed section or placeholder.
Result<PromptTemplate> parse_prompt_template(std::string name, std::string_view text);

// The templates compiled into this build (schemas/prompts/*.md), by name ("floor_plan").
const std::map<std::string, PromptTemplate>& embedded_prompt_templates();
Result<const PromptTemplate*> find_prompt_template(std::string_view name);

// Substitutes every placeholder; values are inserted verbatim (never re-scanned). A missing or an
// unused variable is a programming error: kInternal naming the template and the variable.
// Gives the system message (when the template has one), then the user message.
Result<std::vector<ChatMessage>> render_prompt(const PromptTemplate& tpl, const PromptVariables& variables);

}  // namespace socsim::llm
