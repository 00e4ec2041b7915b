#include "core/household/persona.hpp"

#include <algorithm>
#include <cctype>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"

namespace socsim::household {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

bool contains_phrase(std::string_view text, std::string_view phrase) {
  if (phrase.empty()) return false;
  for (std::size_t pos = text.find(phrase); pos != std::string_view::npos; pos = text.find(phrase, pos + 1)) {
    const bool left_ok = pos == 0 || !is_word_char(text[pos - 1]);
    const std::size_t end = pos + phrase.size();
    const bool right_ok = end >= text.size() || !is_word_char(text[end]);
    if (left_ok && right_ok) return true;
  }
  return false;
}

bool any_of_phrases(std::string_view text, std::initializer_list<std::string_view> phrases) {
  return std::any_of(phrases.begin(), phrases.end(),
                     [&](std::string_view p) { return contains_phrase(text, p); });
}

int count_phrases(std::string_view text, std::initializer_list<std::string_view> phrases) {
  return static_cast<int>(std::count_if(phrases.begin(), phrases.end(),
                                        [&](std::string_view p) { return contains_phrase(text, p); }));
}

// ---- clock times in free text ("7 am", "12:30 am", "midnight", "noon") ----

struct Token {
  std::string word;
  int minutes = -1;  // ≥ 0 when the token is a time of day
};

std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(text[i]))) {
      int h = 0, m = 0;
      std::size_t j = i;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
        h = h * 10 + (text[j++] - '0');
      bool colon = false;
      if (j + 2 < text.size() && text[j] == ':' && std::isdigit(static_cast<unsigned char>(text[j + 1])) &&
          std::isdigit(static_cast<unsigned char>(text[j + 2]))) {
        m = (text[j + 1] - '0') * 10 + (text[j + 2] - '0');
        j += 3;
        colon = true;
      }
      std::size_t k = j;
      while (k < text.size() && text[k] == ' ') ++k;
      auto starts = [&](std::string_view w) { return text.substr(k, w.size()) == w; };
      int minutes = -1;
      std::size_t next = j;
      if (starts("am") || starts("a.m.")) {
        minutes = (h % 12) * 60 + m;
        next = k + (starts("am") ? 2 : 4);
      } else if (starts("pm") || starts("p.m.")) {
        minutes = (h % 12 + 12) * 60 + m;
        next = k + (starts("pm") ? 2 : 4);
      } else if (colon) {
        minutes = h * 60 + m;
      }
      if (minutes >= 0 && h <= 24 && m < 60)
        out.push_back({"", minutes});
      else
        out.push_back({std::string(text.substr(i, j - i)), -1});
      i = next;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
    std::string word(text.substr(i, j - i));
    while (!word.empty() && !std::isalnum(static_cast<unsigned char>(word.back()))) word.pop_back();
    if (word == "midnight")
      out.push_back({word, 1440});
    else if (word == "noon" || word == "midday")
      out.push_back({word, 720});
    else
      out.push_back({word, -1});
    i = j;
  }
  return out;
}

std::vector<std::string> split_clauses(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) out.push_back(cur);
    cur.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ';' || c == ',' || (c == '.' && (i + 1 >= text.size() || text[i + 1] == ' '))) {
      flush();
      continue;
    }
    if (text.compare(i, 5, " and ") == 0 || text.compare(i, 5, " but ") == 0) {
      flush();
      i += 3;
      continue;
    }
    cur += c;
  }
  flush();
  return out;
}

enum class Label { kNone, kBed, kBedLate, kWake };

struct RoutineTimes {
  int general_bed = -1, general_wake = -1, work_bed = -1, work_wake = -1, free_bed = -1, free_wake = -1;
};

RoutineTimes parse_routine(const std::string& routine_lower) {
  RoutineTimes r;
  for (const std::string& clause : split_clauses(routine_lower)) {
    const bool free =
        any_of_phrases(clause, {"weekend", "weekends", "free day", "free days", "nights off", "days off",
                                "night off", "day off", "saturday", "sunday", "saturdays", "sundays"});
    const bool work =
        !free && any_of_phrases(clause, {"work day", "work days", "workday", "workdays", "school", "shift",
                                         "work", "school days", "class", "classes"});
    const auto tokens = tokenize(clause);
    Label last = Label::kNone;
    Label prev_time_label = Label::kNone;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const auto& t = tokens[i];
      if (t.minutes < 0) {
        const std::string& w = t.word;
        if (w == "bed" || w == "asleep" || w == "sleep" || w == "sleeps" || w == "sleeping")
          last = Label::kBed;
        else if ((w == "stay" || w == "stays") && i + 1 < tokens.size() && tokens[i + 1].word == "up") {
          last = Label::kBedLate;
          ++i;
        } else if (w == "wake" || w == "wakes" || w == "waking" || w == "up" || w == "alarm" || w == "rise" ||
                   w == "rises")
          last = Label::kWake;
        continue;
      }
      Label label = last;
      const std::string& before = i > 0 ? tokens[i - 1].word : std::string();
      const bool connector = before == "until" || before == "till" || before == "to";
      // "sleeps from 8 am to 3 pm", "sleeps until 10 am": the time after the connector is the waking time.
      if (connector && last == Label::kBed)
        label = (prev_time_label == Label::kBed || before != "to") ? Label::kWake : Label::kBed;
      if (label == Label::kNone) continue;
      prev_time_label = label;
      int* bed = free ? &r.free_bed : work ? &r.work_bed : &r.general_bed;
      int* wake = free ? &r.free_wake : work ? &r.work_wake : &r.general_wake;
      if (label == Label::kWake)
        *wake = t.minutes % 1440;
      else
        *bed = t.minutes;
    }
  }
  return r;
}

// "from 7 pm to 7 am" ranges in a text, in order.
std::vector<std::pair<int, int>> parse_ranges(const std::string& text_lower) {
  std::vector<std::pair<int, int>> out;
  const auto tokens = tokenize(text_lower);
  for (std::size_t i = 0; i + 2 < tokens.size(); ++i) {
    if (tokens[i].minutes >= 0 && tokens[i + 1].word == "to" && tokens[i + 2].minutes >= 0) {
      int a = tokens[i].minutes % 1440, b = tokens[i + 2].minutes % 1440;
      if (b <= a) b += 1440;
      out.emplace_back(a, b);
      i += 2;
    }
  }
  return out;
}

int parse_until(const std::string& text_lower) {
  const auto tokens = tokenize(text_lower);
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i)
    if (tokens[i].word == "until" && tokens[i + 1].minutes >= 0) return tokens[i + 1].minutes;
  return -1;
}

// Weekday names and "Monday to Friday" style ranges in the occupation.
std::array<bool, 7> parse_days(const std::string& text_lower, bool& found) {
  std::array<bool, 7> days{};
  found = false;
  std::vector<std::pair<std::size_t, Weekday>> mentioned;
  const auto tokens = tokenize(text_lower);
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    std::string w = tokens[i].word;
    if (!w.empty() && w.back() == 's') w.pop_back();
    if (w.size() < 6) continue;
    if (auto d = parse_weekday(w)) mentioned.emplace_back(i, *d);
  }
  for (std::size_t k = 0; k + 1 < mentioned.size(); ++k) {
    const auto [i, a] = mentioned[k];
    const auto [j, b] = mentioned[k + 1];
    if (j == i + 2 && tokens[i + 1].word == "to") {
      found = true;
      for (int d = static_cast<int>(a);; d = (d + 1) % 7) {
        days[static_cast<std::size_t>(d)] = true;
        if (d == static_cast<int>(b)) break;
      }
      ++k;
    }
  }
  return days;
}

std::array<bool, 7> days_after(std::string_view text, std::string_view marker) {
  std::array<bool, 7> days{};
  const auto pos = text.find(marker);
  if (pos == std::string_view::npos) return days;
  const auto tokens = tokenize(text.substr(pos + marker.size(), 48));
  for (const auto& t : tokens) {
    std::string w = t.word;
    if (!w.empty() && w.back() == 's') w.pop_back();
    if (w.size() >= 6)
      if (auto d = parse_weekday(w)) days[static_cast<std::size_t>(*d)] = true;
  }
  return days;
}

}  // namespace

Result<Persona> persona_from_json(const Json& json, const std::string& pointer) {
  JsonChecker check;
  if (!json.is_object()) {
    check.add(
        pointer,
        "must be an object with name, age, gender, routine, personality, occupation, thoughts, lifestyle");
    return tl::unexpected(check.error("invalid persona"));
  }
  check.only_keys(json, pointer,
                  {"name", "age", "gender", "routine", "personality", "occupation", "thoughts", "lifestyle"});
  Persona p;
  if (auto v = check.string(json, pointer, "name", true, 1, 80)) p.name = *v;
  if (auto v = check.integer(json, pointer, "age", true, 0, 120)) p.age = static_cast<int>(*v);
  if (auto v = check.string(json, pointer, "gender", true, 1, 40)) p.gender = *v;
  if (auto v = check.string(json, pointer, "routine", true, 1, 2000)) p.routine = *v;
  if (auto v = check.string(json, pointer, "occupation", true, 1, 2000)) p.occupation = *v;
  if (auto v = check.string(json, pointer, "thoughts", true, 1, 2000)) p.thoughts = *v;
  if (auto v = check.string(json, pointer, "lifestyle", true, 1, 2000)) p.lifestyle = *v;
  if (const Json* arr = check.array(json, pointer, "personality", true, 12)) {
    const std::string ptr = JsonChecker::child(pointer, "personality");
    if (arr->empty()) check.add(ptr, "must list at least one trait");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const Json& item = (*arr)[i];
      if (!item.is_string() || item.get_ref<const std::string&>().empty() ||
          item.get_ref<const std::string&>().size() > 60)
        check.add(JsonChecker::child(ptr, i), "must be a non-empty string of at most 60 bytes");
      else
        p.personality.push_back(item.get<std::string>());
    }
  }
  if (!p.name.empty()) {
    const bool has_letter = std::any_of(p.name.begin(), p.name.end(),
                                        [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
    if (!has_letter) check.add(JsonChecker::child(pointer, "name"), "must contain a letter");
  }
  if (!check.ok()) return tl::unexpected(check.error("invalid persona"));
  return p;
}

Json to_json(const Persona& p) {
  return Json{{"name", p.name},
              {"age", p.age},
              {"gender", p.gender},
              {"routine", p.routine},
              {"personality", p.personality},
              {"occupation", p.occupation},
              {"thoughts", p.thoughts},
              {"lifestyle", p.lifestyle}};
}

std::string persona_id(const Persona& persona) {
  std::string id;
  for (char c : persona.name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      id += static_cast<char>(std::tolower(u));
    else if (!id.empty() && id.back() != '-')
      id += '-';
  }
  while (!id.empty() && id.back() == '-') id.pop_back();
  if (id.empty()) id = "persona";
  return id.substr(0, 80);
}

std::string_view work_pattern_name(WorkPattern pattern) {
  switch (pattern) {
    case WorkPattern::kCommute:
      return "commute";
    case WorkPattern::kRemote:
      return "remote";
    case WorkPattern::kHybrid:
      return "hybrid";
    case WorkPattern::kNightShift:
      return "night_shift";
    case WorkPattern::kEveningShift:
      return "evening_shift";
    case WorkPattern::kSplitShift:
      return "split_shift";
    case WorkPattern::kCollege:
      return "college";
    case WorkPattern::kSchool:
      return "school";
    case WorkPattern::kPreschool:
      return "preschool";
    case WorkPattern::kRetired:
      return "retired";
    case WorkPattern::kHomemaker:
      return "homemaker";
    case WorkPattern::kFreelance:
      return "freelance";
    case WorkPattern::kJobSeeker:
      return "job_seeker";
  }
  return "commute";
}

std::optional<WorkPattern> parse_work_pattern(std::string_view name) {
  for (int i = 0; i <= static_cast<int>(WorkPattern::kJobSeeker); ++i)
    if (work_pattern_name(static_cast<WorkPattern>(i)) == name) return static_cast<WorkPattern>(i);
  return std::nullopt;
}

bool mentions(const PersonaTraits& traits, std::string_view phrase) {
  return contains_phrase(traits.text, lower(phrase));
}

PersonaTraits infer_traits(const Persona& p) {
  PersonaTraits t;
  std::string personality;
  for (const auto& s : p.personality) personality += s + ", ";
  t.text = lower(p.gender + " | " + p.routine + " | " + p.occupation + " | " + p.thoughts + " | " +
                 p.lifestyle + " | " + personality);
  const std::string occ = lower(p.occupation);
  const std::string life = lower(p.lifestyle);
  t.child = p.age < 13;

  // Work pattern, from the occupation first.
  if (p.age < 6)
    t.work = WorkPattern::kPreschool;
  else if (p.age < 18 && any_of_phrases(occ, {"school", "grader", "grade", "student", "kindergarten"}))
    t.work = WorkPattern::kSchool;
  else if (any_of_phrases(occ, {"night shift", "overnight", "nights"}))
    t.work = WorkPattern::kNightShift;
  else if (any_of_phrases(occ, {"evening shift", "late shift"}))
    t.work = WorkPattern::kEveningShift;
  else if (any_of_phrases(occ, {"split shift"}))
    t.work = WorkPattern::kSplitShift;
  else if (any_of_phrases(occ, {"hybrid"}))
    t.work = WorkPattern::kHybrid;
  else if (any_of_phrases(occ, {"stay-at-home", "homemaker", "housewife", "househusband"}))
    t.work = WorkPattern::kHomemaker;
  else if (any_of_phrases(occ, {"retired", "retiree", "pensioner"}))
    t.work = WorkPattern::kRetired;
  else if (any_of_phrases(occ, {"between jobs", "looking for work", "unemployed", "job seeker"}))
    t.work = WorkPattern::kJobSeeker;
  else if (any_of_phrases(occ, {"freelance", "freelancer", "self-employed"}))
    t.work = WorkPattern::kFreelance;
  else if (any_of_phrases(occ, {"works from home", "remotely", "remote", "from home", "home office"}))
    t.work = WorkPattern::kRemote;
  else if (any_of_phrases(occ, {"student", "phd", "university", "academy", "college"}))
    t.work = WorkPattern::kCollege;
  else if (p.age >= 67 && !any_of_phrases(occ, {"works", "driver", "owns"}))
    t.work = WorkPattern::kRetired;

  // Sleep times from the routine; defaults by age and pattern.
  const RoutineTimes rt = parse_routine(lower(p.routine));
  const bool day_sleeper = t.work == WorkPattern::kNightShift;
  int def_bed = p.age < 7 ? 19 * 60 + 45 : p.age < 13 ? 20 * 60 + 45 : p.age >= 65 ? 22 * 60 : 23 * 60;
  int def_wake = p.age < 13 ? 7 * 60 : p.age >= 65 ? 6 * 60 + 30 : 7 * 60;
  auto pick = [](int a, int b, int c) { return a >= 0 ? a : b >= 0 ? b : c; };
  auto norm_bed = [](int bed) { return bed < 12 * 60 ? bed + 1440 : bed; };
  if (day_sleeper) {
    t.work_night.bed = pick(rt.work_bed, -1, 8 * 60) % 1440;
    t.work_night.wake = pick(rt.work_wake, -1, 15 * 60);
    if (t.work_night.wake <= t.work_night.bed) t.work_night.wake = t.work_night.bed + 7 * 60;
    t.free_night.bed = norm_bed(pick(rt.free_bed, -1, 24 * 60));
    t.free_night.wake = pick(rt.free_wake, -1, (t.free_night.bed + 8 * 60) % 1440);
  } else {
    t.work_night.bed = norm_bed(pick(rt.work_bed, rt.general_bed, def_bed));
    t.work_night.wake = pick(rt.work_wake, rt.general_wake, def_wake);
    t.free_night.bed = norm_bed(pick(rt.free_bed, rt.general_bed, t.work_night.bed));
    const bool sleeps_in = p.age < 65 && t.work != WorkPattern::kRetired &&
                           t.work != WorkPattern::kPreschool && t.work != WorkPattern::kHomemaker;
    t.free_night.wake = pick(rt.free_wake, -1, t.work_night.wake + (sleeps_in ? 75 : 0));
    if (t.free_night.wake >= 14 * 60) t.free_night.wake = 13 * 60;
  }
  t.naps = any_of_phrases(t.text, {"nap", "naps", "napping", "dozes", "doze", "siesta"}) || p.age < 5 ||
           p.age >= 80;

  // Work hours and days.
  bool days_found = false;
  t.work_days = parse_days(occ, days_found);
  const auto ranges = parse_ranges(occ);
  const int wake = t.work_night.wake;
  switch (t.work) {
    case WorkPattern::kSchool:
      t.work_start = std::max(wake + 50, 7 * 60 + 30);
      t.work_end = 15 * 60 + 30;
      break;
    case WorkPattern::kPreschool:
      t.work_start = 8 * 60 + 30;
      t.work_end = 12 * 60 + 30;
      break;
    case WorkPattern::kCollege:
      t.work_start = std::max(9 * 60, wake + 60);
      t.work_end = t.work_start + 6 * 60;
      break;
    case WorkPattern::kNightShift:
      t.work_start = 22 * 60;
      t.work_end = 30 * 60;
      break;
    case WorkPattern::kEveningShift:
      t.work_start = 15 * 60;
      t.work_end = 23 * 60 + 30;
      break;
    case WorkPattern::kSplitShift:
      t.work_start = 6 * 60;
      t.work_end = 10 * 60;
      t.second_start = 17 * 60;
      t.second_end = 20 * 60;
      break;
    default:
      t.work_start = wake < 5 * 60 + 30 ? wake + 45 : std::min(wake + 120, 9 * 60);
      t.work_end = t.work_start + 9 * 60;
  }
  if (!ranges.empty()) {
    t.work_start = ranges[0].first;
    t.work_end = ranges[0].second;
    if (t.work == WorkPattern::kSplitShift && ranges.size() > 1) {
      t.second_start = ranges[1].first;
      t.second_end = ranges[1].second;
    }
  } else if (int until = parse_until(occ); until >= 0) {
    t.work_end = until % 1440 <= t.work_start ? until + 1440 : until;
  } else if (any_of_phrases(occ, {"working late", "long hours", "crunch"})) {
    t.work_end = t.work_start + 11 * 60;
  }
  if (!days_found) {
    t.work_days = {true, true, true, true, true, false, false};
    if (any_of_phrases(occ, {"six days a week"})) t.work_days[5] = true;
    int n = 0;
    if (any_of_phrases(occ, {"four nights a week", "four days a week"})) n = 4;
    if (any_of_phrases(occ, {"three nights a week", "three days a week"})) n = 3;
    if (n > 0) {
      t.work_days = {};
      const auto first = static_cast<int>(fnv1a64(persona_id(p)) % 7);
      for (int k = 0; k < n; ++k) t.work_days[static_cast<std::size_t>((first + k * 7 / n) % 7)] = true;
    }
  }
  if (t.work == WorkPattern::kRetired || t.work == WorkPattern::kHomemaker ||
      t.work == WorkPattern::kJobSeeker)
    t.work_days = {};
  if (t.work == WorkPattern::kHybrid) t.home_work_days = days_after(occ, "from home on");
  if (t.work == WorkPattern::kRemote || t.work == WorkPattern::kFreelance) t.home_work_days = t.work_days;

  // Character.
  const int tidy =
      count_phrases(t.text, {"meticulous", "organized", "organised", "tidy", "neat", "orderly", "disciplined",
                             "precise", "methodical", "perfectionist", "spotless", "minimalist", "efficient",
                             "punctual", "diligent", "conscientious", "tidies"});
  const int messy = count_phrases(
      t.text, {"messy", "disorganized", "scatterbrained", "forgetful", "laid-back", "carefree", "spontaneous",
               "impulsive", "chaotic", "pile up", "leaves", "restless", "clumsy"});
  t.tidiness = std::clamp(0.5 + 0.15 * (tidy - messy), 0.05, 0.95);
  const int social =
      count_phrases(t.text, {"sociable", "outgoing", "talkative", "chatty", "hospitable", "friends",
                             "charismatic", "bubbly", "cheerful", "friendly", "hosts"});
  const int solitary =
      count_phrases(t.text, {"introverted", "reserved", "shy", "solitary", "quiet", "quietly"});
  t.sociability = std::clamp(0.5 + 0.15 * (social - solitary), 0.05, 0.95);
  if (any_of_phrases(t.text, {"five times a day"}))
    t.prayers_per_day = 5;
  else if (any_of_phrases(t.text, {"prays", "morning prayer", "devout"}))
    t.prayers_per_day = 1;
  (void)life;
  return t;
}

}  // namespace socsim::household
