#include "core/scenario/intent_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace socsim::scenario {
namespace {

std::string snake(const std::string& s) {
  std::string out;
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      out.push_back(static_cast<char>(std::tolower(u)));
    else if (!out.empty() && out.back() != '_')
      out.push_back('_');
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

std::string last_word(const std::string& snake_name) {
  const auto k = snake_name.rfind('_');
  return k == std::string::npos ? snake_name : snake_name.substr(k + 1);
}

bool generic(const PeopleGroup& g) {
  return g.program_role == "adult" || g.normalized_role == "adult";
}

// One entry of the program with people in it.
struct Entry {
  std::string role;
  std::size_t count = 0;
  std::string pointer;  // /agents/<i> or /ambient_groups/<i>/size
  std::string words;    // an ambient group without a role: its name and description
};

bool mentions(const std::string& words, const PeopleGroup& g) {
  const std::string w = " " + snake(words) + "_";
  for (const std::string& r : {snake(g.role), snake(g.program_role)}) {
    if (r.empty()) continue;
    for (const std::string& form : {r, r + "s", r + "es"})
      if (w.find("_" + form + "_") != std::string::npos || w.find(" " + form + "_") != std::string::npos)
        return true;
  }
  return false;
}

std::vector<Entry> entries(const Json& program) {
  std::vector<Entry> out;
  const Json agents = program.value("agents", Json::array());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const Json& a = agents[i];
    const std::size_t n =
        a.contains("count") && a["count"].is_number_unsigned() ? a["count"].get<std::size_t>()
        : a.contains("count") && a["count"].is_number_integer()
            ? static_cast<std::size_t>(std::max<std::int64_t>(0, a["count"].get<std::int64_t>()))
            : 1;
    out.push_back(Entry{a.value("role", std::string("adult")), n, "/agents/" + std::to_string(i), ""});
  }
  const Json groups = program.value("ambient_groups", Json::array());
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const Json& g = groups[i];
    const std::size_t n =
        g.contains("size") && g["size"].is_number_integer()
            ? static_cast<std::size_t>(std::max<std::int64_t>(0, g["size"].get<std::int64_t>()))
            : 0;
    const bool has_role = g.contains("role") && g["role"].is_string();
    out.push_back(Entry{has_role ? g["role"].get<std::string>() : std::string("adult"), n,
                        "/ambient_groups/" + std::to_string(i) + "/size",
                        has_role
                            ? std::string()
                            : g.value("name", std::string()) + " " + g.value("description", std::string())});
  }
  return out;
}

// Which named group each entry belongs to (index into intent.groups), nullopt for people nobody
// asked for. Specific groups first; a generic group ("people") takes what no other claims.
std::vector<std::optional<std::size_t>> assign(const std::vector<Entry>& es, const ScenarioIntent& intent) {
  std::vector<std::optional<std::size_t>> out(es.size());
  std::optional<std::size_t> any;
  for (std::size_t g = 0; g < intent.groups.size(); ++g)
    if (generic(intent.groups[g]) && !any) any = g;
  for (std::size_t e = 0; e < es.size(); ++e) {
    for (std::size_t g = 0; g < intent.groups.size() && !out[e]; ++g)
      if (!generic(intent.groups[g]) && (role_is(intent.groups[g], es[e].role) ||
                                         (!es[e].words.empty() && mentions(es[e].words, intent.groups[g]))))
        out[e] = g;
    if (!out[e] && any) out[e] = any;
  }
  return out;
}

// The prompt's own words for a group ("two nurses").
std::string said(const ScenarioIntent& intent, const PeopleGroup& g) {
  if (g.span.end > g.span.begin && g.span.end <= intent.prompt.size())
    return "'" + intent.prompt.substr(g.span.begin, g.span.end - g.span.begin) + "'";
  return "'" + (g.count.phrase.empty() ? g.role : g.count.phrase + " " + g.role) + "'";
}

// Whether n people satisfy the count the prompt gave; the expectation in words otherwise.
std::optional<std::string> count_problem(const Count& c, std::size_t n) {
  const double v = static_cast<double>(n);
  switch (c.kind) {
    case CountKind::kExact:
      if (std::llround(c.value) == static_cast<long long>(n)) return std::nullopt;
      return "exactly " + std::to_string(std::llround(c.value));
    case CountKind::kApprox:
      if (std::abs(v - c.value) <= 0.1 * c.value + 0.5) return std::nullopt;
      return "about " + std::to_string(std::llround(c.value)) + " (within 10 %)";
    case CountKind::kRange:
      if (v >= std::floor(c.min) && v <= std::ceil(c.max)) return std::nullopt;
      return "between " + std::to_string(std::llround(c.min)) + " and " + std::to_string(std::llround(c.max));
    case CountKind::kUnspecified:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

bool role_is(const PeopleGroup& g, const std::string& program_role) {
  std::string r = snake(program_role);
  auto same = [&](const std::string& x) {
    if (x.empty()) return false;
    return r == x || r == x + "s" || r == x + "es" ||
           (x.ends_with("y") && r == x.substr(0, x.size() - 1) + "ies");
  };
  const std::string pr = snake(g.program_role), written = snake(g.role), norm = snake(g.normalized_role);
  if (same(pr) || same(written) || (!generic(g) && same(norm))) return true;
  // "triage_nurse" for a group of nurses, "nurse" for a group of triage nurses.
  if (same(last_word(written)) && written.find('_') != std::string::npos) return true;
  return r.ends_with("_" + written) || r.ends_with("_" + pr);
}

bool names_who_is_there(const ScenarioIntent& intent) {
  return !intent.groups.empty() && !intent.background;
}

Json added_groups(const Json& program, const ScenarioIntent& intent,
                  const std::vector<std::string>& categories, const std::string& domain) {
  const auto es = entries(program);
  const auto owner = assign(es, intent);
  std::map<std::string, std::size_t> extra;
  std::vector<std::string> order;
  for (std::size_t e = 0; e < es.size(); ++e) {
    if (owner[e] || es[e].count == 0) continue;
    if (!extra.count(es[e].role)) order.push_back(es[e].role);
    extra[es[e].role] += es[e].count;
  }
  std::string what;
  for (const auto& c : categories) what += (what.empty() ? "" : ", ") + c;
  std::string why;
  if (intent.groups.empty()) {
    why = "the prompt names nobody: the usual people " +
          (domain.empty() ? std::string() : "of a " + domain + " ") + "for " +
          (what.empty() ? std::string("normal operation") : what);
  } else if (intent.background) {
    std::string words;
    for (const auto& w : intent.background_words) words += (words.empty() ? "'" : ", '") + w + "'";
    why = "the prompt asks for people beyond those it names" + (words.empty() ? "" : " (" + words + ")");
  } else {
    why = "not asked for by the prompt";
  }
  Json out = Json::array();
  for (const auto& role : order) out.push_back(Json{{"role", role}, {"count", extra[role]}, {"why", why}});
  return out;
}

std::vector<FieldError> intent_contradictions(const Json& program, const ScenarioIntent& intent,
                                              std::size_t bound) {
  std::vector<FieldError> out;
  const auto es = entries(program);
  const auto owner = assign(es, intent);
  std::vector<std::size_t> people(intent.groups.size(), 0);
  std::vector<std::string> where(intent.groups.size());
  for (std::size_t e = 0; e < es.size(); ++e) {
    if (!owner[e]) continue;
    people[*owner[e]] += es[e].count;
    if (where[*owner[e]].empty()) where[*owner[e]] = es[e].pointer;
  }
  std::size_t counted = 0;
  for (const PeopleGroup& g : intent.groups) counted += g.count.people();
  const bool check_counts = counted <= bound;
  // Groups said twice ("a nurse … the nurse") are one role: compare the role's total once.
  std::map<std::string, std::pair<Count, std::size_t>> by_role;  // role → (summed count, first group)
  std::vector<std::string> role_order;
  for (std::size_t g = 0; g < intent.groups.size(); ++g) {
    const PeopleGroup& grp = intent.groups[g];
    auto [it, fresh] = by_role.emplace(grp.program_role, std::pair{grp.count, g});
    if (fresh)
      role_order.push_back(grp.program_role);
    else if (grp.count.specified() && it->second.first.specified())
      it->second.first.plus(grp.count);
  }
  for (const std::string& role : role_order) {
    const auto& [count, first] = by_role[role];
    const PeopleGroup& g = intent.groups[first];
    std::size_t n = 0;
    std::string ptr;
    for (std::size_t k = 0; k < intent.groups.size(); ++k)
      if (intent.groups[k].program_role == role) {
        n += people[k];
        if (ptr.empty()) ptr = where[k];
      }
    if (n == 0) {
      out.push_back(
          FieldError{"", "the prompt names " + said(intent, g) + " but the program has nobody of that role"});
      continue;
    }
    if (!check_counts) continue;
    if (auto want = count_problem(count, n))
      out.push_back(FieldError{ptr, "the prompt says " + said(intent, g) + " (" + *want +
                                        "), the program has " + std::to_string(n) + " " + g.program_role});
  }
  if (names_who_is_there(intent)) {
    std::string named;
    for (const std::string& role : role_order) named += (named.empty() ? "" : ", ") + role;
    for (std::size_t e = 0; e < es.size(); ++e)
      if (!owner[e] && es[e].count > 0)
        out.push_back(FieldError{
            es[e].pointer, std::to_string(es[e].count) + " " + es[e].role +
                               ": nobody asked for them; the prompt names who is there (" + named + ")"});
  }
  return out;
}

}  // namespace socsim::scenario
