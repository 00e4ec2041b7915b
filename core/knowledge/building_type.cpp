#include "core/knowledge/building_type.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "core/knowledge/types.hpp"

namespace socsim::knowledge {
namespace {

struct LexiconEntry {
  std::string_view phrase;  // singular, lower case, words separated by one space
  std::string_view type;
  double weight;
};

// Weights: 3 = names the building type outright; 2 = a room or role almost only found there;
// 1 = a typical but shared indicator; below 1 = weak hints that only break ties.
constexpr LexiconEntry kLexicon[] = {
    // hospital
    {"hospital", "hospital", 3},
    {"clinic", "hospital", 3},
    {"infirmary", "hospital", 3},
    {"icu", "hospital", 3},
    {"intensive care", "hospital", 3},
    {"er", "hospital", 3},
    {"emergency room", "hospital", 3},
    {"emergency department", "hospital", 3},
    {"a&e", "hospital", 3},
    {"ward", "hospital", 2},
    {"patient", "hospital", 2},
    {"patient room", "hospital", 3},
    {"nurse", "hospital", 2},
    {"nurse station", "hospital", 3},
    {"nursing station", "hospital", 3},
    {"doctor", "hospital", 1.5},
    {"physician", "hospital", 1.5},
    {"surgeon", "hospital", 2},
    {"operating theatre", "hospital", 3},
    {"operating room", "hospital", 3},
    {"triage", "hospital", 2},
    {"stretcher", "hospital", 2},
    {"gurney", "hospital", 2},
    {"wheelchair", "hospital", 0.5},
    {"radiology", "hospital", 2},
    {"pharmacy", "hospital", 1},
    {"outpatient", "hospital", 2},
    {"inpatient", "hospital", 2},
    {"medical", "hospital", 1.5},
    {"exam room", "hospital", 2},
    {"examination room", "hospital", 2},
    {"consultation room", "hospital", 1.5},
    {"waiting room", "hospital", 1},
    {"visitor", "hospital", 0.5},
    {"ambulance", "hospital", 2},
    {"hospital bed", "hospital", 3},
    // office
    {"office", "office", 3},
    {"open plan", "office", 2},
    {"open-plan", "office", 2},
    {"cubicle", "office", 2},
    {"meeting room", "office", 2},
    {"conference room", "office", 2},
    {"conference", "office", 1},
    {"boardroom", "office", 2},
    {"workstation", "office", 1.5},
    {"desk", "office", 1},
    {"coworking", "office", 3},
    {"co-working", "office", 3},
    {"colleague", "office", 1},
    {"employee", "office", 1},
    {"coworker", "office", 1},
    {"businessperson", "office", 1.5},
    {"manager", "office", 1},
    {"printer", "office", 1},
    {"copy room", "office", 2},
    {"break room", "office", 1},
    {"reception", "office", 0.5},
    {"lobby", "office", 0.5},
    {"headquarters", "office", 2},
    {"call center", "office", 2},
    {"call centre", "office", 2},
    {"staff", "office", 0.3},
    // residential
    {"house", "residential", 2},
    {"home", "residential", 2},
    {"flat", "residential", 2},
    {"apartment", "residential", 3},
    {"dwelling", "residential", 3},
    {"bungalow", "residential", 3},
    {"cottage", "residential", 3},
    {"villa", "residential", 2},
    {"condo", "residential", 3},
    {"bedroom", "residential", 2},
    {"living room", "residential", 2},
    {"lounge", "residential", 1},
    {"kitchen", "residential", 0.8},
    {"bathroom", "residential", 0.8},
    {"family", "residential", 1},
    {"household", "residential", 2},
    {"resident", "residential", 1.5},
    {"roommate", "residential", 2},
    {"housemate", "residential", 2},
    {"sofa", "residential", 1},
    {"couch", "residential", 1},
    {"garage", "residential", 1},
    {"garden", "residential", 0.5},
    {"studio apartment", "residential", 3},
    {"dining room", "residential", 1},
    {"laundry room", "residential", 1},
    {"hallway", "residential", 0.3},
    // canteen
    {"canteen", "canteen", 3},
    {"cafeteria", "canteen", 3},
    {"refectory", "canteen", 3},
    {"mess hall", "canteen", 3},
    {"dining hall", "canteen", 3},
    {"food court", "mall", 2},
    {"restaurant", "restaurant", 3},
    {"cafe", "restaurant", 3},
    {"café", "restaurant", 3},
    {"coffee shop", "restaurant", 3},
    {"diner", "restaurant", 3},
    {"bistro", "restaurant", 3},
    {"lunch", "canteen", 1.5},
    {"breakfast", "canteen", 1},
    {"dinner", "canteen", 1},
    {"meal", "canteen", 1.5},
    {"tray", "canteen", 2},
    {"buffet", "canteen", 2},
    {"serving counter", "canteen", 3},
    {"food counter", "canteen", 3},
    {"waiter", "restaurant", 2},
    {"waitress", "restaurant", 2},
    {"chef", "canteen", 1},
    {"eat", "canteen", 1},
    {"eating", "canteen", 1},
    {"dining", "canteen", 1},
    {"table", "canteen", 0.5},
    {"order food", "canteen", 3},
    // retail
    {"shop", "retail", 2},
    {"store", "retail", 1.5},
    {"supermarket", "supermarket", 3},
    {"grocery", "supermarket", 3},
    {"mall", "mall", 3},
    {"shopping", "retail", 2},
    {"boutique", "retail", 3},
    {"checkout", "retail", 2},
    {"check-out", "retail", 2},
    {"till", "retail", 1.5},
    {"cashier", "retail", 2},
    {"customer", "retail", 1},
    {"shopper", "retail", 2},
    {"shelf", "retail", 1},
    {"shelve", "retail", 1},
    {"aisle", "retail", 0.5},
    {"sales floor", "retail", 3},
    {"fitting room", "retail", 3},
    {"display", "retail", 0.5},
    {"retail", "retail", 3},
    {"department store", "retail", 3},
    {"market", "retail", 1.5},
    {"counter", "retail", 0.5},
    {"counter", "canteen", 0.5},
    // warehouse
    {"warehouse", "warehouse", 3},
    {"distribution center", "warehouse", 3},
    {"distribution centre", "warehouse", 3},
    {"fulfillment", "warehouse", 3},
    {"fulfilment", "warehouse", 3},
    {"logistics", "warehouse", 2},
    {"forklift", "warehouse", 3},
    {"pallet", "warehouse", 2},
    {"rack", "warehouse", 1.5},
    {"racking", "warehouse", 2},
    {"picking", "warehouse", 2},
    {"picker", "warehouse", 2},
    {"loading dock", "warehouse", 3},
    {"dock", "warehouse", 1},
    {"inventory", "warehouse", 1.5},
    {"storage", "warehouse", 0.5},
    {"aisle", "warehouse", 1},
    {"shipping", "warehouse", 1.5},
    {"parcel", "warehouse", 1.5},
    {"conveyor", "warehouse", 2},
    {"stockroom", "warehouse", 1},
    {"depot", "warehouse", 2},
    // school
    {"school", "school", 3},
    {"classroom", "school", 3},
    {"class room", "school", 3},
    {"pupil", "school", 2},
    {"student", "school", 1.5},
    {"teacher", "school", 2},
    {"lecture", "university", 2},
    {"lecture hall", "university", 3},
    {"university", "university", 3},
    {"campus", "university", 2},
    {"college", "university", 2},
    {"kindergarten", "school", 3},
    {"playground", "school", 1},
    {"recess", "school", 2},
    {"library", "library", 3},
    {"auditorium", "theatre", 2},
    // airport
    {"airport", "airport", 3},
    {"terminal", "airport", 2},
    {"departure", "airport", 1.5},
    {"arrival", "airport", 1},
    {"boarding", "airport", 2},
    {"gate", "airport", 1},
    {"departure gate", "airport", 3},
    {"boarding gate", "airport", 3},
    {"check-in", "airport", 1.5},
    {"check in", "airport", 1.5},
    {"security check", "airport", 2},
    {"baggage", "airport", 2},
    {"luggage", "airport", 1.5},
    {"passenger", "airport", 1.5},
    {"flight", "airport", 3},
    {"concourse", "airport", 2},
    {"runway", "airport", 3},
    {"duty free", "airport", 3},
    {"passport control", "airport", 3},
    // train or metro station
    {"train station", "train_station", 3},
    {"railway station", "train_station", 3},
    {"rail station", "train_station", 3},
    {"metro station", "train_station", 3},
    {"subway station", "train_station", 3},
    {"underground station", "train_station", 3},
    {"tube station", "train_station", 3},
    {"bus station", "train_station", 3},
    {"station", "train_station", 2},
    {"metro", "train_station", 3},
    {"subway", "train_station", 3},
    {"railway", "train_station", 2},
    {"train", "train_station", 2},
    {"tram", "train_station", 2},
    {"commuter", "train_station", 2},
    {"platform", "train_station", 2},
    {"ticket barrier", "train_station", 3},
    {"ticket gate", "train_station", 3},
    {"turnstile", "train_station", 1.5},
    {"ticket machine", "train_station", 2},
    {"concourse", "train_station", 1.5},
    // hotel
    {"hotel", "hotel", 3},
    {"motel", "hotel", 3},
    {"hostel", "hotel", 3},
    {"inn", "hotel", 2},
    {"guest room", "hotel", 3},
    {"front desk", "hotel", 2},
    {"concierge", "hotel", 3},
    {"room service", "hotel", 3},
    {"bellboy", "hotel", 3},
    {"housekeeping", "hotel", 2},
    {"guest", "hotel", 1},
    {"suite", "hotel", 1.5},
    {"lobby", "hotel", 0.5},
    // library
    {"librarian", "library", 3},
    {"reading room", "library", 3},
    {"bookshelf", "library", 2},
    {"bookcase", "library", 2},
    {"book", "library", 1},
    {"borrow", "library", 1.5},
    {"study room", "library", 1.5},
    // museum or gallery
    {"museum", "museum", 3},
    {"gallery", "museum", 3},
    {"art gallery", "museum", 3},
    {"exhibition", "museum", 3},
    {"exhibit", "museum", 2},
    {"curator", "museum", 3},
    {"painting", "museum", 1.5},
    {"sculpture", "museum", 2},
    {"artwork", "museum", 2},
    {"visitor", "museum", 0.5},
    // cinema or theatre
    {"theatre", "theatre", 3},
    {"theater", "theatre", 3},
    {"cinema", "theatre", 3},
    {"movie theater", "theatre", 3},
    {"movie", "theatre", 2},
    {"film", "theatre", 1.5},
    {"screening", "theatre", 2},
    {"usher", "theatre", 3},
    {"box office", "theatre", 3},
    {"popcorn", "theatre", 2},
    {"audience", "theatre", 1.5},
    {"stage", "theatre", 1},
    {"play", "theatre", 0.5},
    // arena or concert hall
    {"arena", "arena", 3},
    {"stadium", "arena", 3},
    {"concert hall", "arena", 3},
    {"concert", "arena", 2},
    {"gig", "arena", 2},
    {"spectator", "arena", 2},
    {"bleacher", "arena", 2},
    {"fan", "arena", 1},
    {"match", "arena", 1},
    // factory
    {"factory", "factory", 3},
    {"production line", "factory", 3},
    {"assembly line", "factory", 3},
    {"manufacturing", "factory", 3},
    {"production", "factory", 2},
    {"workshop", "factory", 2},
    {"machine", "factory", 1.5},
    {"foreman", "factory", 2},
    {"worker", "factory", 1},
    {"shift", "factory", 1},
    {"plant", "factory", 1},
    // shopping mall
    {"shopping mall", "mall", 3},
    {"shopping centre", "mall", 3},
    {"shopping center", "mall", 3},
    {"shopping arcade", "mall", 3},
    // supermarket
    {"trolley", "supermarket", 1.5},
    {"cart", "supermarket", 1},
    {"deli", "supermarket", 2},
    {"checkout", "supermarket", 1.5},
    {"till", "supermarket", 1},
    // café or restaurant
    {"pub", "restaurant", 3},
    {"bar", "restaurant", 1.5},
    {"bartender", "restaurant", 3},
    {"menu", "restaurant", 1.5},
    {"dinner", "restaurant", 1},
    // university
    {"seminar", "university", 2},
    {"seminar room", "university", 3},
    {"undergraduate", "university", 3},
    {"professor", "university", 3},
    {"student", "university", 1},
    // gym or sports hall
    {"gym", "gym", 3},
    {"gymnasium", "gym", 3},
    {"sports hall", "gym", 3},
    {"sports centre", "gym", 3},
    {"sports center", "gym", 3},
    {"fitness", "gym", 3},
    {"workout", "gym", 3},
    {"treadmill", "gym", 3},
    {"changing room", "gym", 2},
    {"locker room", "gym", 2},
    {"basketball", "gym", 2},
    {"badminton", "gym", 2},
    {"swimming pool", "gym", 2},
    // care home
    {"care home", "care_home", 3},
    {"nursing home", "care_home", 3},
    {"retirement home", "care_home", 3},
    {"old people", "care_home", 2},
    {"elderly", "care_home", 2},
    {"carer", "care_home", 3},
    {"caregiver", "care_home", 3},
    {"dementia", "care_home", 3},
    // community hall (polling station)
    {"community hall", "community_hall", 3},
    {"community centre", "community_hall", 3},
    {"community center", "community_hall", 3},
    {"village hall", "community_hall", 3},
    {"church hall", "community_hall", 3},
    {"town hall", "community_hall", 2},
    {"polling station", "community_hall", 3},
    {"polling place", "community_hall", 3},
    {"voting", "community_hall", 3},
    {"vote", "community_hall", 2},
    {"voter", "community_hall", 3},
    {"ballot", "community_hall", 3},
    {"election", "community_hall", 3},
    {"bingo", "community_hall", 2},
};

constexpr std::string_view kNegations[] = {"no", "not", "non", "without", "never"};
constexpr double kDefaultConfidence = 0.3;
constexpr std::size_t kMaxPhraseWords = 3;

std::string singular(std::string w) {
  if (w.size() > 4 && w.ends_with("ies")) return w.substr(0, w.size() - 3) + "y";
  if (w.size() > 3 && w.ends_with("s") && !w.ends_with("ss") && !w.ends_with("us") && !w.ends_with("is"))
    w.pop_back();
  return w;
}

// Lower-case words; letters, digits, '&' and inner '-' stay in a word; "'s" is dropped.
std::vector<std::string> tokenize(std::string_view text) {
  std::vector<std::string> out;
  std::string w;
  auto flush = [&] {
    while (!w.empty() && w.back() == '-') w.pop_back();
    if (w.size() > 2 && w.ends_with("'s")) w.resize(w.size() - 2);
    if (!w.empty()) out.push_back(singular(w));
    w.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (std::isalnum(u) || u >= 0x80 || u == '&' || (u == '\'' && !w.empty()) || (u == '-' && !w.empty())) {
      w.push_back(static_cast<char>(std::tolower(u)));
    } else {
      flush();
    }
  }
  flush();
  return out;
}

std::string lexicon_key(std::string_view phrase) {
  std::string key;
  for (const auto& w : tokenize(phrase)) key += (key.empty() ? "" : " ") + w;
  return key;
}

// Lexicon phrases in the same normal form as the text's words, built once.
const std::multimap<std::string, const LexiconEntry*>& lexicon_index() {
  static const std::multimap<std::string, const LexiconEntry*> index = [] {
    std::multimap<std::string, const LexiconEntry*> m;
    for (const auto& e : kLexicon) m.emplace(lexicon_key(e.phrase), &e);
    return m;
  }();
  return index;
}

std::string format_weight(double w) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.1f", w);
  return buf;
}

}  // namespace

BuildingTypeGuess classify_building_type(std::string_view text) {
  const std::vector<std::string> words = tokenize(text);
  BuildingTypeGuess guess;
  std::size_t i = 0;
  while (i < words.size()) {
    // Longest phrase first, so "coffee shop" is not also read as "shop".
    std::size_t matched_len = 0;
    std::vector<const LexiconEntry*> matched;
    for (std::size_t len = std::min(kMaxPhraseWords, words.size() - i); len >= 1 && matched_len == 0; --len) {
      std::string candidate;
      for (std::size_t j = i; j < i + len; ++j) candidate += (j == i ? "" : " ") + words[j];
      const auto [first, last] = lexicon_index().equal_range(candidate);
      for (auto it = first; it != last; ++it) matched.push_back(it->second);
      if (!matched.empty()) matched_len = len;
    }
    if (matched_len == 0) {
      ++i;
      continue;
    }
    bool negated = false;
    for (std::size_t back = 1; back <= 2 && back <= i; ++back) {
      for (auto n : kNegations) negated = negated || words[i - back] == n;
    }
    if (!negated) {
      for (const LexiconEntry* e : matched) {
        guess.evidence.push_back({std::string(e->phrase), std::string(e->type), e->weight});
        guess.scores[std::string(e->type)] += e->weight;
      }
    }
    i += matched_len;
  }

  if (guess.scores.empty()) {
    guess.type = "residential";
    guess.confidence = kDefaultConfidence;
    guess.explanation = "no building-type indicator found; residential is the default";
    return guess;
  }
  // Highest score wins; ties go to the type listed first in building_types().
  double total = 0.0;
  for (const auto& [type, score] : guess.scores) total += score;
  double best = -1.0;
  for (std::string_view t : building_types()) {
    auto it = guess.scores.find(std::string(t));
    if (it != guess.scores.end() && it->second > best) {
      best = it->second;
      guess.type = it->first;
    }
  }
  guess.confidence = best / (total + 1.0);
  std::string words_for;
  for (const auto& e : guess.evidence) {
    if (e.type != guess.type) continue;
    words_for += (words_for.empty() ? "'" : ", '") + e.term + "' (+" + format_weight(e.weight) + ")";
  }
  guess.explanation = guess.type + " because of " + words_for;
  std::string against;
  for (const auto& [type, score] : guess.scores) {
    if (type != guess.type) against += (against.empty() ? "" : ", ") + type + " " + format_weight(score);
  }
  if (!against.empty()) guess.explanation += "; other indications: " + against;
  return guess;
}

BuildingTypeGuess classify_building_type(const std::vector<std::string>& room_names) {
  std::string text;
  for (const auto& name : room_names) {
    std::string words;
    for (std::size_t i = 0; i < name.size(); ++i) {
      const char c = name[i];
      const bool upper = std::isupper(static_cast<unsigned char>(c)) != 0;
      if (i > 0 && upper && std::islower(static_cast<unsigned char>(name[i - 1]))) words.push_back(' ');
      if (c == '_' || std::isdigit(static_cast<unsigned char>(c)))
        words.push_back(' ');
      else
        words.push_back(c);
    }
    text += words + ". ";
  }
  return classify_building_type(text);
}

Json to_json(const BuildingTypeGuess& g) {
  Json evidence = Json::array();
  for (const auto& e : g.evidence)
    evidence.push_back(Json{{"term", e.term}, {"type", e.type}, {"weight", e.weight}});
  Json scores = Json::object();
  for (const auto& [t, s] : g.scores) scores[t] = s;
  return Json{{"type", g.type},
              {"confidence", g.confidence},
              {"evidence", std::move(evidence)},
              {"scores", std::move(scores)},
              {"explanation", g.explanation}};
}

}  // namespace socsim::knowledge
