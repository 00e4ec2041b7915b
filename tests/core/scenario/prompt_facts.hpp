#pragma once
// Scores prompt understanding against tests/fixtures/prompts/everyday.jsonl (format in its README):
// for every prompt, each fact a reader expects — venue, category, total, people per role, nobody
// extra, feature counts, named objects, robots, moving together — holds or not. Shared by
// `socsim-bench prompts` and the fixture test.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scenario/scenario_intent.hpp"

namespace socsim::scenario::facts {

struct Expected {
  enum class Kind { kExact, kApprox, kRange, kPresent };
  Kind kind = Kind::kPresent;
  double value = 0, min = 0, max = 0;
};

inline Expected expected(const nlohmann::json& j) {
  Expected e;
  if (j.is_number()) {
    e.kind = Expected::Kind::kExact;
    e.value = e.min = e.max = j.get<double>();
    return e;
  }
  const std::string s = j.get<std::string>();
  if (s == "?") return e;
  if (s[0] == '~') {
    e.kind = Expected::Kind::kApprox;
    e.value = std::stod(s.substr(1));
    e.min = e.value * 0.9;
    e.max = e.value * 1.1;
    return e;
  }
  const auto dash = s.find('-');
  e.kind = Expected::Kind::kRange;
  e.min = std::stod(s.substr(0, dash));
  e.max = std::stod(s.substr(dash + 1));
  e.value = (e.min + e.max) / 2;
  return e;
}

// Does an understood count satisfy the expectation?
inline bool holds(const Expected& e, const Count& c) {
  switch (e.kind) {
    case Expected::Kind::kPresent:
      return true;
    case Expected::Kind::kExact:
      return c.kind == CountKind::kExact && c.value == e.value;
    case Expected::Kind::kApprox:
      return c.specified() && std::abs(c.value - e.value) <= 0.1 * e.value + 1e-9;
    case Expected::Kind::kRange:
      return c.specified() && c.min >= e.min - 1e-9 && c.max <= e.max + 1e-9;
  }
  return false;
}

// A number of simulated people (a scenario's agents) against the expectation.
inline bool holds(const Expected& e, double n) {
  switch (e.kind) {
    case Expected::Kind::kPresent:
      return n > 0;
    case Expected::Kind::kExact:
      return n == e.value;
    case Expected::Kind::kApprox:
      return std::abs(n - e.value) <= 0.1 * e.value + 1e-9;
    case Expected::Kind::kRange:
      return n >= e.min - 1e-9 && n <= e.max + 1e-9;
  }
  return false;
}

inline bool role_matches(const std::string& key, const std::string& role) {
  if (role == key) return true;
  return role.size() > key.size() && role.ends_with(" " + key);
}

struct Prompt {
  std::string id;
  std::string prompt;
  nlohmann::json facts;
};

inline std::vector<Prompt> load(const std::string& path) {
  std::vector<Prompt> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    auto j = nlohmann::json::parse(line);
    out.push_back(Prompt{j.at("id").get<std::string>(), j.at("prompt").get<std::string>(), j});
  }
  return out;
}

struct Tally {
  std::map<std::string, std::pair<int, int>> kinds;  // kind → (held, checked)
  std::vector<std::string> failures;                 // "id: kind: detail"
  void add(const std::string& id, const std::string& kind, bool ok, const std::string& detail) {
    auto& k = kinds[kind];
    k.second += 1;
    k.first += ok ? 1 : 0;
    if (!ok) failures.push_back(id + ": " + kind + ": " + detail);
  }
  [[nodiscard]] std::pair<int, int> all() const {
    std::pair<int, int> s{0, 0};
    for (const auto& [k, v] : kinds) {
      s.first += v.first;
      s.second += v.second;
    }
    return s;
  }
};

inline std::string describe(const Count& c) {
  return nlohmann::json(to_json(c)).dump();
}

// Checks the understood intent against the fixture's facts.
inline void score_intent(const Prompt& p, const ScenarioIntent& in, Tally& t) {
  const auto& f = p.facts;
  if (f.contains("venue")) {
    const std::string got = in.venue ? in.venue->type : "(none)";
    t.add(p.id, "venue", got == f["venue"].get<std::string>(),
          "expected " + f["venue"].get<std::string>() + ", got " + got);
  }
  if (f.contains("category")) {
    std::vector<std::string> want;
    if (f["category"].is_string())
      want.push_back(f["category"].get<std::string>());
    else
      want = f["category"].get<std::vector<std::string>>();
    std::string got;
    for (const auto& c : in.categories) got += std::string(to_string(c.category)) + " ";
    for (const auto& w : want)
      t.add(p.id, "category", got.find(w + " ") != std::string::npos, "expected " + w + ", got " + got);
  }
  std::map<std::string, Expected> people;
  if (f.contains("people"))
    for (const auto& [k, v] : f["people"].items()) people[k] = expected(v);
  for (const auto& [key, e] : people) {
    Count sum;
    bool found = false;
    for (const PeopleGroup& g : in.groups) {
      if (!role_matches(key, g.role)) continue;
      sum = found ? sum.plus(g.count) : g.count;
      found = true;
    }
    t.add(p.id, "role", found && holds(e, sum),
          key + " " + f["people"][key].dump() + ": got " + (found ? describe(sum) : "no group"));
  }
  if (!f.value("others", false)) {
    std::string extra;
    for (const PeopleGroup& g : in.groups) {
      bool known = false;
      for (const auto& [key, e] : people) known = known || role_matches(key, g.role);
      if (!known) extra += "'" + g.role + "' ";
    }
    t.add(p.id, "no_extra", extra.empty(), "groups nobody asked for: " + extra);
  }
  if (f.contains("total")) {
    const Count total = in.total();
    t.add(p.id, "total", holds(expected(f["total"]), total),
          "expected " + f["total"].dump() + ", got " + describe(total));
  }
  if (f.contains("features"))
    for (const auto& [key, v] : f["features"].items()) {
      const Feature* hit = nullptr;
      for (const Feature& x : in.world.features)
        if (x.head == key || x.name == key || role_matches(key, x.name)) hit = &x;
      t.add(p.id, "feature", hit != nullptr && holds(expected(v), hit->count),
            key + " " + v.dump() + ": got " + (hit ? describe(hit->count) : "none"));
    }
  if (f.contains("objects"))
    for (const auto& o : f["objects"]) {
      const std::string key = o.get<std::string>();
      bool hit = false;
      for (const Feature& x : in.world.features) hit = hit || x.name == key || role_matches(x.head, key);
      for (const NamedThing& x : in.world.objects) hit = hit || x.name == key;
      for (const NamedThing& x : in.world.rooms) hit = hit || x.name == key;
      t.add(p.id, "object", hit, key + " not among the world requirements");
    }
  if (f.contains("robots") || !in.robots.empty()) {
    double n = 0;
    for (const RobotMention& r : in.robots) n += r.count.specified() ? r.count.value : 1;
    const double want = f.value("robots", 0.0);
    t.add(p.id, "robots", n == want, "expected " + std::to_string(want) + ", got " + std::to_string(n));
  }
  if (f.contains("together"))
    for (const auto& r : f["together"]) {
      bool ok = false;
      for (const PeopleGroup& g : in.groups)
        ok = ok || (role_matches(r.get<std::string>(), g.role) && g.together);
      t.add(p.id, "together", ok, r.get<std::string>() + " not moving together");
    }
}

}  // namespace socsim::scenario::facts

namespace socsim::scenario::facts {

// People per program role in a scenario program: spotlight entries (count, 1 when positioned) and
// ambient groups.
inline std::map<std::string, double> program_people(const nlohmann::json& program) {
  std::map<std::string, double> out;
  for (const auto& a : program.value("agents", nlohmann::json::array()))
    out[a.value("role", std::string("adult"))] += a.value("count", 1.0);
  for (const auto& g : program.value("ambient_groups", nlohmann::json::array()))
    out[g.value("role", std::string("adult"))] += g.value("size", 0.0);
  return out;
}

inline std::string program_role_of(const std::string& key) {
  if (key == "person") return "adult";
  std::string r = key;
  for (char& c : r)
    if (c == ' ' || c == '-') c = '_';
  return r;
}

inline bool program_role_matches(const std::string& key, const std::string& role) {
  const std::string k = program_role_of(key);
  return role == k || (role.size() > k.size() && role.ends_with("_" + k));
}

// Checks the people of a generated program against the fixture: each role's count, nobody extra,
// the total. `produced` is false when no scenario came out (counted as one failed fact).
inline void score_program(const Prompt& p, bool produced, const nlohmann::json& program, Tally& t,
                          const std::string& error = "") {
  t.add(p.id, "produced", produced, error);
  if (!produced) return;
  const auto& f = p.facts;
  const auto people = program_people(program);
  std::map<std::string, Expected> want;
  if (f.contains("people"))
    for (const auto& [k, v] : f["people"].items()) want[k] = expected(v);
  for (const auto& [key, e] : want) {
    double n = 0;
    for (const auto& [role, count] : people)
      if (program_role_matches(key, role)) n += count;
    t.add(p.id, "role", holds(e, n),
          key + " " + f["people"][key].dump() + ": scenario has " + std::to_string(n));
  }
  if (!f.value("others", false)) {
    std::string extra;
    for (const auto& [role, count] : people) {
      bool known = false;
      for (const auto& [key, e] : want) known = known || program_role_matches(key, role);
      if (!known) extra += role + "=" + std::to_string(static_cast<int>(count)) + " ";
    }
    t.add(p.id, "no_extra", extra.empty(), "people nobody asked for: " + extra);
  }
  if (f.contains("total")) {
    double n = 0;
    for (const auto& [role, count] : people) n += count;
    t.add(p.id, "total", holds(expected(f["total"]), n),
          "expected " + f["total"].dump() + ", scenario has " + std::to_string(n));
  }
}

}  // namespace socsim::scenario::facts
