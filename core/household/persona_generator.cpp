#include "core/household/persona_generator.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>
#include <tuple>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"
#include "core/common/text.hpp"

namespace socsim::household {
namespace {

const HouseholdRolePart& role_text(const PersonaParts& parts, HouseholdRole role) {
  for (const auto& r : parts.roles)
    if (r.role == role) return r;
  return parts.roles.front();
}

bool is_child_occupation(const OccupationPart& o) {
  return o.pattern == WorkPattern::kPreschool || o.pattern == WorkPattern::kSchool;
}

std::string clock_text(int minutes) {
  const int m = ((minutes % 1440) + 1440) % 1440;
  if (m == 0) return "midnight";
  const int h = m / 60, mm = m % 60;
  const int h12 = h % 12 == 0 ? 12 : h % 12;
  std::string s = std::to_string(h12);
  if (mm != 0) s += ":" + std::string(mm < 10 ? "0" : "") + std::to_string(mm);
  return s + (h < 12 ? " am" : " pm");
}

std::string replace_all(std::string s, std::string_view from, std::string_view to) {
  for (std::size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
  return s;
}

struct Voice {
  std::string first, p, pp, po;
};

std::string capitalised(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  return s;
}

std::string fill(std::string text, const Voice& v, std::string_view variant = {}) {
  text = replace_all(std::move(text), "{X}", variant);
  text = replace_all(std::move(text), "{F}", v.first);
  text = replace_all(std::move(text), "{P}", capitalised(v.p));
  text = replace_all(std::move(text), "{PP}", capitalised(v.pp));
  text = replace_all(std::move(text), "{pp}", v.pp);
  text = replace_all(std::move(text), "{po}", v.po);
  return replace_all(std::move(text), "{p}", v.p);
}

bool contains_word(const std::string& text, const std::string& phrase) {
  for (std::size_t pos = text.find(phrase); pos != std::string::npos; pos = text.find(phrase, pos + 1)) {
    const bool left = pos == 0 || !std::isalnum(static_cast<unsigned char>(text[pos - 1]));
    const std::size_t end = pos + phrase.size();
    const bool right = end >= text.size() || !std::isalnum(static_cast<unsigned char>(text[end]));
    if (left && right) return true;
  }
  return false;
}

std::set<std::string> content_words(const Persona& p) {
  static const std::set<std::string> stop = {
      "with",  "from",  "that",   "their", "them",     "they", "this",  "when",  "what",  "most",
      "every", "after", "before", "about", "into",     "over", "also",  "works", "goes",  "gets",
      "lives", "still", "often",  "week",  "weekdays", "days", "other", "home",  "where", "whole",
      "long",  "very",  "some",   "than",  "then",     "more", "each"};
  std::set<std::string> names;
  std::string w;
  for (char c : ascii_lower(p.name) + " ") {
    if (std::isalpha(static_cast<unsigned char>(c)))
      w += c;
    else if (!w.empty())
      names.insert(std::exchange(w, {}));
  }
  std::string text = p.occupation + " " + p.routine + " " + p.lifestyle;
  for (const auto& t : p.personality) text += " " + t;
  std::set<std::string> out;
  for (char c : ascii_lower(text) + " ") {
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '-') {
      w += c;
    } else if (!w.empty()) {
      if (w.size() >= 4 && !stop.count(w) && !names.count(w) && w != "she" && w != "her" && w != "his")
        out.insert(w);
      w.clear();
    }
  }
  return out;
}

struct Candidate {
  Persona persona;
  const OccupationPart* occupation = nullptr;
  int bed = 0, wake = 0;
};

bool reads_back(const Candidate& c) {
  const PersonaTraits t = infer_traits(c.persona);
  WorkPattern expected = c.occupation->pattern;
  if (expected != t.work) return false;
  if (c.occupation->day_sleeper)
    return t.work_night.bed == 8 * 60 && t.work_night.wake == 15 * 60 &&
           t.free_night.bed % 1440 == c.bed % 1440;
  return t.work_night.bed % 1440 == c.bed % 1440 && t.work_night.wake == c.wake;
}

int pick_quarter(Rng& rng, int lo, int hi) {
  const int n = (hi - lo) / 15;
  return lo + 15 * static_cast<int>(rng.between(0, std::max(0, n)));
}

const std::string& pick(Rng& rng, const std::vector<std::string>& v) {
  return v[rng.below(static_cast<std::uint32_t>(v.size()))];
}

std::string routine_text(Rng& rng, const Voice& v, const OccupationPart& o, int bed, int wake, bool child) {
  if (o.day_sleeper)
    return fill(
        "On work days {F} sleeps from 8 am to 3 pm after {pp} night shift; on free days {p} goes to bed at " +
            clock_text(bed) + " and gets up at " + clock_text(wake) + ".",
        v);
  const std::string b = clock_text(bed), w = clock_text(wake);
  std::vector<std::string> forms = {"{F} goes to bed at " + b + " and gets up at " + w + ".",
                                    "{F} is in bed by " + b + " and up at " + w + ".",
                                    "{F} goes to bed around " + b + " and wakes at " + w + "."};
  if (child)
    forms = {"{F} has to be in bed at " + b + " and gets up at " + w + ".",
             "{F} goes to bed at " + b + " and wakes at " + w + "."};
  return fill(forms[rng.below(static_cast<std::uint32_t>(forms.size()))], v);
}

std::vector<const OccupationPart*> matching_occupations(const PersonaParts& parts,
                                                        const PersonaConstraints& c, HouseholdRole role,
                                                        int lo, int hi) {
  std::vector<const OccupationPart*> out;
  const std::string wanted = c.occupation ? ascii_lower(*c.occupation) : "";
  for (const auto& o : parts.occupations) {
    if ((role == HouseholdRole::kChild) != is_child_occupation(o)) continue;
    if (o.pattern == WorkPattern::kHomemaker && role != HouseholdRole::kParent) continue;
    if (std::max(lo, o.min_age) > std::min(hi, o.max_age)) continue;
    if (!wanted.empty()) {
      bool match = contains_word(wanted, o.key) || contains_word(o.key, wanted);
      for (const std::string& k : o.keywords)
        match = match || contains_word(wanted, k) || contains_word(k, wanted);
      if (!match) continue;
    }
    out.push_back(&o);
  }
  return out;
}

std::string article_for(const std::string& word) {
  return !word.empty() && std::string("aeiou").find(static_cast<char>(
                              std::tolower(static_cast<unsigned char>(word[0])))) != std::string::npos
             ? "an"
             : "a";
}

}  // namespace

std::string_view household_role_name(HouseholdRole role) {
  switch (role) {
    case HouseholdRole::kSingle:
      return "single";
    case HouseholdRole::kPartner:
      return "partner";
    case HouseholdRole::kParent:
      return "parent";
    case HouseholdRole::kChild:
      return "child";
    case HouseholdRole::kGrandparent:
      return "grandparent";
    case HouseholdRole::kFlatmate:
      return "flatmate";
  }
  return "single";
}

std::optional<HouseholdRole> parse_household_role(std::string_view name) {
  for (auto r : {HouseholdRole::kSingle, HouseholdRole::kPartner, HouseholdRole::kParent,
                 HouseholdRole::kChild, HouseholdRole::kGrandparent, HouseholdRole::kFlatmate})
    if (household_role_name(r) == name) return r;
  return std::nullopt;
}

Result<PersonaRequest> persona_request_from_json(const Json& json, const std::string& pointer) {
  JsonChecker check;
  PersonaRequest r;
  if (!json.is_object()) {
    check.add(pointer, "must be an object");
    return tl::unexpected(check.error("invalid persona request"));
  }
  if (auto v = check.integer(json, pointer, "count", false, 1, 200)) r.count = static_cast<int>(*v);
  if (auto v = check.integer(json, pointer, "seed", false, 0, INT64_MAX))
    r.seed = static_cast<std::uint64_t>(*v);
  const std::string cp = JsonChecker::child(pointer, "constraints");
  if (const Json* c = check.object(json, pointer, "constraints", false)) {
    check.only_keys(*c, cp, {"min_age", "max_age", "occupation", "household_role", "gender"});
    if (auto v = check.integer(*c, cp, "min_age", false, 0, 120))
      r.constraints.min_age = static_cast<int>(*v);
    if (auto v = check.integer(*c, cp, "max_age", false, 0, 120))
      r.constraints.max_age = static_cast<int>(*v);
    if (r.constraints.min_age && r.constraints.max_age && *r.constraints.min_age > *r.constraints.max_age)
      check.add(JsonChecker::child(cp, "max_age"), "must be at least min_age");
    if (auto v = check.string(*c, cp, "occupation", false, 2, 60)) {
      const bool ok = std::all_of(v->begin(), v->end(), [](char ch) {
        return std::isalpha(static_cast<unsigned char>(ch)) || ch == ' ' || ch == '-' || ch == '\'';
      });
      if (!ok)
        check.add(JsonChecker::child(cp, "occupation"),
                  "may contain only letters, spaces, hyphens and apostrophes");
      else
        r.constraints.occupation = *v;
    }
    if (auto v = check.string(*c, cp, "household_role", false, 1, 20)) {
      if (auto role = parse_household_role(*v))
        r.constraints.household_role = role;
      else
        check.add(JsonChecker::child(cp, "household_role"),
                  "must be one of single, partner, parent, child, grandparent, flatmate");
    }
    if (auto v = check.string(*c, cp, "gender", false, 1, 20)) {
      if (*v == "female" || *v == "male")
        r.constraints.gender = *v;
      else
        check.add(JsonChecker::child(cp, "gender"), "must be female or male");
    }
  }
  if (!check.ok()) return tl::unexpected(check.error("invalid persona request"));
  return r;
}

Result<PersonaGenerateRequest> persona_generate_request_from_json(const Json& json) {
  PersonaGenerateRequest r;
  JsonChecker check;
  if (json.is_object()) {
    check.only_keys(json, "", {"count", "seed", "constraints", "generator", "store", "model"});
    if (auto v = check.string(json, "", "generator", false, 1, 20)) {
      if (*v != "offline" && *v != "llm")
        check.add("/generator", "must be offline or llm");
      else
        r.generator = *v;
    }
    r.store = check.boolean(json, "", "store", false).value_or(false);
    r.model = check.string(json, "", "model", false, 1, 200);
    if (r.model && r.generator != "llm") check.add("/model", "a model is chosen only with generator llm");
  }
  auto personas = persona_request_from_json(json);
  std::vector<FieldError> errors = personas ? std::vector<FieldError>{} : personas.error().errors;
  errors.insert(errors.end(), check.errors().begin(), check.errors().end());
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "invalid persona generation request", std::move(errors));
  r.personas = *personas;
  return r;
}

Json to_json(const PersonaConstraints& c) {
  Json j = Json::object();
  if (c.min_age) j["min_age"] = *c.min_age;
  if (c.max_age) j["max_age"] = *c.max_age;
  if (c.occupation) j["occupation"] = *c.occupation;
  if (c.household_role) j["household_role"] = household_role_name(*c.household_role);
  if (c.gender) j["gender"] = *c.gender;
  return j;
}

double persona_similarity(const Persona& a, const Persona& b) {
  const auto wa = content_words(a), wb = content_words(b);
  if (wa.empty() && wb.empty()) return 1.0;
  std::size_t common = 0;
  for (const auto& w : wa) common += wb.count(w);
  return static_cast<double>(common) / static_cast<double>(wa.size() + wb.size() - common);
}

bool near_duplicate(const Persona& a, const Persona& b) {
  if (persona_id(a) == persona_id(b)) return true;
  if (ascii_lower(a.gender) != ascii_lower(b.gender) || std::abs(a.age - b.age) > 5) return false;
  return persona_similarity(a, b) >= 0.5;
}

namespace {

std::vector<std::string> strings_of(const Json& j) {
  std::vector<std::string> out;
  for (const auto& s : j) out.push_back(s.get<std::string>());
  if (out.empty()) throw std::invalid_argument("an empty list");
  return out;
}

std::pair<int, int> range_of(const Json& j) {
  const auto r = std::pair{j.at(0).get<int>(), j.at(1).get<int>()};
  if (j.size() != 2 || r.first > r.second) throw std::invalid_argument("a range must be [low, high]");
  return r;
}

OccupationPart occupation_of(const std::string& key, const Json& b) {
  OccupationPart o;
  o.key = key;
  for (const auto& k : b.at("keywords")) o.keywords.push_back(k.get<std::string>());
  const auto pattern = parse_work_pattern(b.at("pattern").get<std::string>());
  if (!pattern) throw std::invalid_argument("unknown work pattern " + b.at("pattern").dump());
  o.pattern = *pattern;
  std::tie(o.min_age, o.max_age) = range_of(b.at("ages"));
  for (const auto& v : b.at("variants")) o.variants.push_back(v.get<std::string>());
  o.text = b.at("text").get<std::string>();
  std::tie(o.bed_lo, o.bed_hi) = range_of(b.at("bed"));
  std::tie(o.wake_lo, o.wake_hi) = range_of(b.at("wake"));
  o.day_sleeper = b.at("day_sleeper").get<bool>();
  o.thoughts = strings_of(b.at("thoughts"));
  o.habit = b.at("habit").get<std::string>();
  return o;
}

}  // namespace

Status add_persona_part(PersonaParts& parts, std::string_view kind, const std::string& name,
                        const Json& body) {
  const std::string where = "persona part " + std::string(kind) + " '" + name + "'";
  try {
    if (kind == "culture") {
      parts.cultures.push_back(
          {strings_of(body.at("female")), strings_of(body.at("male")), strings_of(body.at("surnames"))});
    } else if (kind == "occupation") {
      parts.occupations.push_back(occupation_of(name, body));
      if (parts.occupations.back().text.empty()) throw std::invalid_argument("an empty text");
    } else if (kind == "occupation_fallback") {
      parts.fallback = occupation_of(name, body);
      parts.has_fallback = true;
    } else if (kind == "hobby") {
      HobbyPart h{body.at("text").get<std::string>(), 0, 0};
      std::tie(h.min_age, h.max_age) = range_of(body.at("ages"));
      parts.hobbies.push_back(std::move(h));
    } else if (kind == "traits" || kind == "habits") {
      std::vector<std::string>* list = nullptr;
      if (kind == "traits")
        list = name == "tidy"       ? &parts.tidy_traits
               : name == "messy"    ? &parts.messy_traits
               : name == "social"   ? &parts.social_traits
               : name == "solitary" ? &parts.solitary_traits
               : name == "other"    ? &parts.other_traits
                                    : nullptr;
      else
        list = name == "tidy" ? &parts.tidy_habits : name == "messy" ? &parts.messy_habits : nullptr;
      if (list == nullptr) return fail(ErrorCode::kStore, where + ": unknown group");
      *list = strings_of(body);
    } else if (kind == "household_role") {
      const auto role = parse_household_role(name);
      if (!role) return fail(ErrorCode::kStore, where + ": unknown household role");
      HouseholdRolePart r{*role, 0, 0, strings_of(body.at("lines")), {}};
      std::tie(r.min_age, r.max_age) = range_of(body.at("ages"));
      for (const auto& t : body.at("thoughts")) r.thoughts.push_back(t.get<std::string>());
      parts.roles.push_back(std::move(r));
    } else {
      return fail(ErrorCode::kStore, where + ": unknown kind");
    }
  } catch (const std::exception& e) {
    return fail(ErrorCode::kStore, where + " is malformed: " + e.what());
  }
  return {};
}

Status check_persona_parts(const PersonaParts& p) {
  std::string missing;
  auto need = [&missing](bool ok, const char* what) {
    if (!ok) missing += (missing.empty() ? "" : ", ") + std::string(what);
  };
  need(!p.cultures.empty(), "cultures");
  need(!p.occupations.empty(), "occupations");
  need(p.has_fallback, "the fallback occupation");
  need(!p.hobbies.empty(), "hobbies");
  need(!p.tidy_traits.empty() && !p.messy_traits.empty() && !p.social_traits.empty() &&
           !p.solitary_traits.empty() && !p.other_traits.empty(),
       "the five trait groups");
  need(!p.tidy_habits.empty() && !p.messy_habits.empty(), "tidy and messy habits");
  need(!p.roles.empty(), "household roles");
  if (missing.empty()) return {};
  return fail(ErrorCode::kStore, "the persona parts lack " + missing +
                                     ": the store is missing migration 0026 (household_persona_parts)");
}

std::vector<std::string> known_occupations(const PersonaParts& parts) {
  std::vector<std::string> out;
  for (const auto& o : parts.occupations) out.push_back(o.key);
  return out;
}

Result<std::vector<Persona>> generate_personas_offline(const PersonaRequest& request,
                                                       std::span<const Persona> existing,
                                                       const PersonaParts& parts) {
  if (request.count < 1 || request.count > 200)
    return fail(ErrorCode::kValidation, "count must be between 1 and 200",
                {FieldError{"/count", "must be between 1 and 200"}});
  const PersonaConstraints& c = request.constraints;
  if (auto s = check_persona_parts(parts); !s) return tl::unexpected(s.error());
  const int lo = c.min_age.value_or(0), hi = c.max_age.value_or(120);
  if (lo > hi)
    return fail(ErrorCode::kValidation, "empty age range",
                {FieldError{"/constraints/max_age", "must be at least min_age"}});

  // Roles that fit the age range, and the occupations that fit role and constraints.
  std::vector<HouseholdRole> roles;
  for (const auto& r : parts.roles) {
    if (c.household_role && r.role != *c.household_role) continue;
    if (std::max(lo, r.min_age) > std::min(hi, r.max_age)) continue;
    roles.push_back(r.role);
  }
  std::vector<std::pair<HouseholdRole, std::vector<const OccupationPart*>>> options;
  for (auto role : roles) {
    const auto& rt = role_text(parts, role);
    auto occ = matching_occupations(parts, c, role, std::max(lo, rt.min_age), std::min(hi, rt.max_age));
    if (!occ.empty()) options.emplace_back(role, std::move(occ));
  }
  // An occupation the list does not know becomes a day job of that name (adults only).
  OccupationPart custom = parts.fallback;
  if (options.empty() && c.occupation && (!c.household_role || *c.household_role != HouseholdRole::kChild) &&
      hi >= parts.fallback.min_age) {
    custom.text = "{F} works as " + article_for(*c.occupation) + " " + ascii_lower(*c.occupation) +
                  " from 9 am to 5 pm.";
    custom.min_age = std::max(parts.fallback.min_age, lo);
    custom.max_age = std::min(parts.fallback.max_age, hi);
    for (auto role : roles)
      if (role != HouseholdRole::kChild) {
        const auto& rt = role_text(parts, role);
        if (std::max(custom.min_age, rt.min_age) <= std::min(custom.max_age, rt.max_age))
          options.push_back({role, {&custom}});
      }
  }
  if (options.empty()) {
    std::string known;
    for (const auto& k : known_occupations(parts)) known += (known.empty() ? "" : ", ") + k;
    return fail(ErrorCode::kValidation, "no persona fits these constraints",
                {FieldError{c.occupation ? "/constraints/occupation" : "/constraints",
                            "no occupation fits the age range and household role (known: " + known + ")"}});
  }

  Rng rng(request.seed, fnv1a64("personas"));
  std::vector<Persona> out;
  std::vector<Persona> taken(existing.begin(), existing.end());
  const int max_attempts = 60 * request.count + 200;
  for (int attempt = 0; attempt < max_attempts && static_cast<int>(out.size()) < request.count; ++attempt) {
    const auto& [role, occs] = options[rng.below(static_cast<std::uint32_t>(options.size()))];
    const OccupationPart& o = *occs[rng.below(static_cast<std::uint32_t>(occs.size()))];
    const HouseholdRolePart& rt = role_text(parts, role);
    const int age_lo = std::max({lo, rt.min_age, o.min_age}), age_hi = std::min({hi, rt.max_age, o.max_age});
    if (age_lo > age_hi) continue;
    Candidate cand;
    cand.occupation = &o;
    Persona& p = cand.persona;
    p.age = static_cast<int>(rng.between(age_lo, age_hi));
    const bool female = c.gender ? *c.gender == "female" : rng.chance(0.5);
    p.gender = female ? "female" : "male";
    const CulturePart& culture = parts.cultures[rng.below(static_cast<std::uint32_t>(parts.cultures.size()))];
    const std::string first = pick(rng, female ? culture.female : culture.male);
    p.name = first + " " + pick(rng, culture.surnames);
    const Voice v{first, female ? "she" : "he", female ? "her" : "his", female ? "her" : "him"};

    cand.bed = pick_quarter(rng, o.bed_lo, o.bed_hi);
    cand.wake = pick_quarter(rng, o.wake_lo, o.wake_hi);
    const bool child = role == HouseholdRole::kChild;
    p.routine = routine_text(rng, v, o, cand.bed, cand.wake, child);
    std::string variant = o.variants.empty() ? "" : pick(rng, o.variants);
    variant = fill(variant, v);
    p.occupation = fill(o.text, v, variant);

    // Personality: a tidiness lean, a sociability lean, and one or two other traits.
    std::vector<std::string> traits;
    const double t_roll = rng.uniform(), s_roll = rng.uniform();
    if (t_roll < 0.4)
      traits.emplace_back(pick(rng, parts.tidy_traits));
    else if (t_roll < 0.75)
      traits.emplace_back(pick(rng, parts.messy_traits));
    if (s_roll < 0.4)
      traits.emplace_back(pick(rng, parts.social_traits));
    else if (s_roll < 0.75)
      traits.emplace_back(pick(rng, parts.solitary_traits));
    while (traits.size() < 3 || (traits.size() < 4 && rng.chance(0.3))) {
      std::string t = pick(rng, parts.other_traits);
      if (std::find(traits.begin(), traits.end(), t) == traits.end()) traits.push_back(std::move(t));
    }
    p.personality = traits;

    // Lifestyle: household, two or three hobbies, a work habit, a tidiness habit.
    std::vector<const HobbyPart*> fit;
    for (const auto& h : parts.hobbies)
      if (p.age >= h.min_age && p.age <= h.max_age) fit.push_back(&h);
    rng.shuffle(fit);
    const std::size_t n_hobbies = std::min<std::size_t>(fit.size(), rng.chance(0.5) ? 2 : 3);
    std::string life = fill(pick(rng, rt.lines), v) + ". " + capitalised(v.p) + " ";
    for (std::size_t i = 0; i < n_hobbies; ++i)
      life += fill(fit[i]->text, v) + (i + 2 < n_hobbies ? ", " : i + 2 == n_hobbies ? " and " : ".");
    if (!o.habit.empty()) life += " " + fill(o.habit, v) + ".";
    auto leans = [&traits](const std::vector<std::string>& words) {
      return std::any_of(traits.begin(), traits.end(), [&words](const std::string& t) {
        return std::find(words.begin(), words.end(), t) != words.end();
      });
    };
    const bool tidy = leans(parts.tidy_traits), messy = leans(parts.messy_traits);
    if (tidy && !child) life += " " + capitalised(v.p) + " " + fill(pick(rng, parts.tidy_habits), v) + ".";
    if (messy && !child) life += " " + capitalised(v.p) + " " + fill(pick(rng, parts.messy_habits), v) + ".";
    p.lifestyle = life;

    std::vector<std::string> thoughts = o.thoughts;
    thoughts.insert(thoughts.end(), rt.thoughts.begin(), rt.thoughts.end());
    p.thoughts = fill(pick(rng, thoughts), v);

    if (!persona_from_json(to_json(p))) continue;
    if (!reads_back(cand)) continue;
    const bool dup =
        std::any_of(taken.begin(), taken.end(), [&](const Persona& q) { return near_duplicate(p, q); });
    if (dup) continue;
    taken.push_back(p);
    out.push_back(std::move(p));
  }
  if (static_cast<int>(out.size()) < request.count)
    return fail(ErrorCode::kValidation,
                "only " + std::to_string(out.size()) +
                    " distinct personas fit these constraints; ask for fewer or widen them",
                {FieldError{"/count", "at most " + std::to_string(out.size()) + " with these constraints"}});
  return out;
}

}  // namespace socsim::household
