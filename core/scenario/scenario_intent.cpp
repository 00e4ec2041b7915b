#include "core/scenario/scenario_intent.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "core/knowledge/types.hpp"
#include "core/scenario/wordnet.hpp"

namespace socsim::scenario {

namespace {

using Tokens = std::vector<TextToken>;

// --- Closed word classes -------------------------------------------------------------------------

const std::set<std::string, std::less<>> kFunctionWords = {
    "a",
    "an",
    "the",
    "this",
    "that",
    "these",
    "those",
    "their",
    "its",
    "his",
    "her",
    "our",
    "my",
    "your",
    "each",
    "every",
    "all",
    "both",
    "any",
    "no",
    "another",
    "and",
    "or",
    "but",
    "nor",
    "while",
    "whereas",
    "then",
    "as",
    "when",
    "after",
    "before",
    "where",
    "who",
    "whom",
    "which",
    "whose",
    "if",
    "because",
    "so",
    "than",
    "until",
    "once",
    "at",
    "in",
    "on",
    "by",
    "near",
    "next",
    "to",
    "from",
    "into",
    "through",
    "along",
    "behind",
    "outside",
    "inside",
    "between",
    "past",
    "among",
    "across",
    "toward",
    "towards",
    "via",
    "for",
    "with",
    "without",
    "of",
    "over",
    "under",
    "up",
    "down",
    "onto",
    "beside",
    "around",
    "about",
    "during",
    "is",
    "are",
    "was",
    "were",
    "be",
    "been",
    "being",
    "am",
    "have",
    "has",
    "had",
    "do",
    "does",
    "did",
    "will",
    "would",
    "can",
    "could",
    "should",
    "may",
    "might",
    "must",
    "shall",
    "they",
    "them",
    "he",
    "him",
    "she",
    "it",
    "we",
    "us",
    "i",
    "me",
    "you",
    "there",
    "here",
    "everyone",
    "everybody",
    "nobody",
    "someone",
    "somebody",
    "anyone",
    "anybody",
    "noone",
    "not",
    "only",
    "just",
    "also",
    "too",
    "very",
    "else",
    "otherwise",
    "except",
    "plus",
    "per",
    "upon",
    "within",
    "like",
    "exactly",
    "precisely",
    "roughly",
    "approximately",
    "nearly",
    "almost",
    "around",
    "some",
    "several",
    "many",
    "few",
    "lots",
    "lot",
    "dozens",
    "hundreds",
    "thousands",
    "dozen",
    "hundred",
    "thousand",
    "couple",
    "handful",
    "numerous",
    "more",
    "most",
    "less",
    "fewer",
    "least",
    "own",
    "together",
    "yet",
    "still",
    "already",
    "again",
    "always",
    "never",
    "how",
    "what",
    "why",
    "whether",
    "either",
    "neither",
    "one",
    "ones",
    "themselves",
    "himself",
    "herself",
    "itself",
    "everything",
    "something",
    "nothing",
    "else's",
    "out",
    "off",
};

// Verbs after which "for <people>" names people awaited or sought, not present ("waiting for a
// doctor"); matched with their -s, -ed, -ing forms.
constexpr std::array<std::string_view, 9> kAwaitingVerbs = {"wait", "look", "search", "ask", "call",
                                                            "hunt", "queu", "queue",  "long"};
const std::set<std::string, std::less<>> kAwaitedDeterminers = {"a",    "an",  "the", "their", "his",
                                                                "her",  "its", "our", "my",    "your",
                                                                "some", "any", "new", "next",  "other"};
// Words between a counted group and the people that say who they are ("five friends, all
// teenagers", "forty people, mostly tourists", "30 visitors: parents, some with children").
const std::set<std::string, std::less<>> kAppositionMarkers = {
    "all",    "mostly",  "most",    "many", "some",    "including", "among",  "them",   "of",  "whom",
    "mainly", "largely", "chiefly", "half", "several", "both",      "nearly", "almost", "are", "were"};
// Between the further people of an apposition ("parents, some with children").
const std::set<std::string, std::less<>> kAppositionLinks = {",",     "and",  "or",  "with",
                                                             "their", "some", "many"};

bool is_function(const TextToken& t) {
  return t.kind != TextToken::Kind::kWord || kFunctionWords.count(t.text) != 0 ||
         cardinal_at(std::vector<TextToken>{t}, 0).has_value();
}

// --- Venue kinds ---------------------------------------------------------------------------------

struct VenueKind {
  std::string_view type;
  std::string_view building_type;  // nearest of knowledge::building_types()
};
// Nearest today's generator has: halls with seats → school (classrooms, hall), public buildings
// with a desk and rooms off corridors → office, shops → retail, eating places → canteen.
constexpr std::array<VenueKind, 22> kVenueKinds = {{
    {"hospital", "hospital"},       {"office", "office"},
    {"school", "school"},           {"airport", "airport"},
    {"residential", "residential"}, {"warehouse", "warehouse"},
    {"retail", "retail"},           {"canteen", "canteen"},
    {"train_station", "airport"},   {"hotel", "office"},
    {"library", "school"},          {"museum", "retail"},
    {"theatre", "school"},          {"arena", "airport"},
    {"factory", "warehouse"},       {"mall", "retail"},
    {"supermarket", "retail"},      {"restaurant", "canteen"},
    {"university", "school"},       {"gym", "school"},
    {"care_home", "hospital"},      {"community_hall", "school"},
}};

// Venue words, longest first where one contains another; an empty type means "a place inside a
// building, not the building" ("ticket office", "nurses station").
const std::vector<std::pair<std::string_view, std::string_view>> kVenueWords = {
    {"old people home", "care_home"},
    {"movie theater", "theatre"},
    {"train station", "train_station"},
    {"railway station", "train_station"},
    {"rail station", "train_station"},
    {"metro station", "train_station"},
    {"subway station", "train_station"},
    {"underground station", "train_station"},
    {"tube station", "train_station"},
    {"bus station", "train_station"},
    {"polling station", "community_hall"},
    {"polling place", "community_hall"},
    {"nurses station", ""},
    {"nurse station", ""},
    {"police station", "office"},
    {"fire station", ""},
    {"gas station", ""},
    {"petrol station", ""},
    {"charging station", ""},
    {"ticket office", ""},
    {"box office", ""},
    {"post office", "office"},
    {"care home", "care_home"},
    {"nursing home", "care_home"},
    {"retirement home", "care_home"},
    {"care facility", "care_home"},
    {"community hall", "community_hall"},
    {"community centre", "community_hall"},
    {"community center", "community_hall"},
    {"village hall", "community_hall"},
    {"parish hall", "community_hall"},
    {"church hall", "community_hall"},
    {"town hall", "community_hall"},
    {"concert hall", "arena"},
    {"concert venue", "arena"},
    {"sports hall", "gym"},
    {"sports centre", "gym"},
    {"sports center", "gym"},
    {"leisure centre", "gym"},
    {"leisure center", "gym"},
    {"fitness centre", "gym"},
    {"fitness center", "gym"},
    {"shopping centre", "mall"},
    {"shopping center", "mall"},
    {"shopping mall", "mall"},
    {"bank branch", "office"},
    {"aquarium", "museum"},
    {"zoo", "museum"},
    {"town hall", "community_hall"},
    {"church", "community_hall"},
    {"market hall", "mall"},
    {"market", "mall"},
    {"distribution centre", "warehouse"},
    {"distribution center", "warehouse"},
    {"fulfilment centre", "warehouse"},
    {"fulfillment center", "warehouse"},
    {"coffee shop", "restaurant"},
    {"grocery store", "supermarket"},
    {"department store", "retail"},
    {"conference centre", "hotel"},
    {"lecture hall", "university"},
    {"assembly hall", ""},
    {"main hall", ""},
    {"station hall", ""},
    {"arrivals hall", ""},
    {"departures hall", ""},
    {"dining hall", ""},
    {"entrance hall", ""},
    {"hospital", "hospital"},
    {"clinic", "hospital"},
    {"infirmary", "hospital"},
    {"office", "office"},
    {"offices", "office"},
    {"school", "school"},
    {"schoolyard", "school"},
    {"kindergarten", "school"},
    {"airport", "airport"},
    {"terminal", "airport"},
    {"station", "train_station"},
    {"underground", "train_station"},
    {"subway", "train_station"},
    {"metro", "train_station"},
    {"hotel", "hotel"},
    {"motel", "hotel"},
    {"hostel", "hotel"},
    {"library", "library"},
    {"museum", "museum"},
    {"gallery", "museum"},
    {"cinema", "theatre"},
    {"theatre", "theatre"},
    {"theater", "theatre"},
    {"arena", "arena"},
    {"stadium", "arena"},
    {"factory", "factory"},
    {"plant", "factory"},
    {"mall", "mall"},
    {"supermarket", "supermarket"},
    {"grocery", "supermarket"},
    {"cafe", "restaurant"},
    {"café", "restaurant"},
    {"restaurant", "restaurant"},
    {"pizzeria", "restaurant"},
    {"bistro", "restaurant"},

    {"pub", "restaurant"},
    {"university", "university"},
    {"campus", "university"},
    {"college", "university"},
    {"gym", "gym"},
    {"gymnasium", "gym"},
    {"canteen", "canteen"},
    {"cafeteria", "canteen"},
    {"warehouse", "warehouse"},
    {"depot", "warehouse"},
    {"shop", "retail"},
    {"store", "retail"},
    {"bookshop", "retail"},
    {"bakery", "retail"},
    {"pharmacy", "retail"},
    {"boutique", "retail"},
    {"home", "residential"},
    {"house", "residential"},
    {"flat", "residential"},
    {"apartment", "residential"},
};

// WordNet hypernyms that identify a venue kind for words the table lacks ("motel" → hotel).
const std::vector<std::pair<std::string_view, std::string_view>> kVenueHypernyms = {
    {"hospital", "hospital"},
    {"medical building", "hospital"},
    {"hotel", "hotel"},
    {"restaurant", "restaurant"},
    {"cafeteria", "canteen"},
    {"supermarket", "supermarket"},
    {"shop", "retail"},
    {"school", "school"},
    {"library", "library"},
    {"museum", "museum"},
    {"theater", "theatre"},
    {"stadium", "arena"},
    {"factory", "factory"},
    {"warehouse", "warehouse"},
    {"office building", "office"},
    {"airport", "airport"},
    {"railway station", "train_station"},
    {"university", "university"},
    {"college", "university"},
    {"gymnasium", "gym"},
    {"shopping center", "mall"},
    {"nursing home", "care_home"},
    {"dwelling", "residential"},
    {"housing", "residential"},
    // Buildings the generator has no type of its own for: the nearest by use (an assembly hall for
    // worship, desks and counters for public offices).
    {"place of worship", "community_hall"},
    {"government building", "office"},
    {"depository financial institution", "office"},
};

// --- Places, features, people --------------------------------------------------------------------

// Features the world generator builds and counts.
const std::set<std::string, std::less<>> kFeatureHeads = {
    "exit",     "door",      "doorway",  "entrance", "gate",     "turnstile", "counter",
    "checkout", "till",      "desk",     "elevator", "lift",     "escalator", "stair",
    "stairs",   "staircase", "stairway", "table",    "seat",     "chair",     "bench",
    "sofa",     "platform",  "lane",     "scanner",  "carousel", "machine",   "bay",
    "kiosk",    "booth",     "stall",    "stand",    "window",   "hatch",     "screen",
    "stage",    "bar",       "shelf",    "rack",     "bed",      "line",      "belt",
    "conveyor", "podium",    "row",      "barrier",  "gangway",  "ramp",      "checkpoint",
};
// Counted features for which a bare "line" is a queue, not a production line.
bool feature_head(const std::string& head, std::size_t words) {
  if (head == "line") return words > 1;
  return kFeatureHeads.count(head) != 0;
}

const std::set<std::string, std::less<>> kRoomHeads = {
    "room",      "hall",      "lobby",      "foyer",      "corridor", "hallway",    "kitchen",  "lounge",
    "ward",      "concourse", "ballroom",   "auditorium", "studio",   "playground", "yard",     "courtyard",
    "park",      "lab",       "laboratory", "reception",  "pool",     "toilet",     "bathroom", "bedroom",
    "cloakroom", "grotto",    "department", "floor",      "wing",     "area",       "zone",     "section",
    "aisle",     "atrium",    "terrace",    "garden",     "basement", "classroom",  "court",    "pitch",
    "track",     "dock",      "gatehouse",  "underpass",  "tunnel",   "passage",    "centre",   "center",
    "quarter",   "block",     "space",      "office",     "canteen",  "cafeteria",  "cafe",     "café",
    "corner",    "side",      "front",      "back",       "end",      "middle",     "gallery",  "treasury",
};

const std::set<std::string, std::less<>> kCollectives = {
    "queue", "line",    "group",      "crowd", "party", "class", "team", "family", "orchestra", "band",
    "choir", "busload", "delegation", "gang",  "troop", "bunch", "pair", "couple", "squad",     "audience",
};
const std::set<std::string, std::less<>> kTogetherCollectives = {"group", "party", "family",     "team",
                                                                 "class", "squad", "delegation", "gang"};

const std::set<std::string, std::less<>> kGenericPeople = {"people", "person",      "persons", "folks",
                                                           "folk",   "individuals", "humans",  "others"};
const std::set<std::string, std::less<>> kMassPeople = {"staff", "personnel", "crew"};

const std::set<std::string, std::less<>> kPluralModifiers = {"sales", "arrivals", "departures", "sports",
                                                             "goods", "customs",  "accounts",   "nurses"};

// Normalised roles: the program roles with crowd parameters (lexicon.hpp), by WordNet hypernym.
const std::vector<std::pair<std::string_view, std::string_view>> kRoleAnchors = {
    {"nurse", "nurse"},
    {"doctor", "doctor"},
    {"medical practitioner", "doctor"},
    {"health professional", "nurse"},
    {"patient", "patient"},
    {"receptionist", "receptionist"},
    {"clerk", "receptionist"},
    {"security guard", "security"},
    {"guard", "security"},
    {"watchman", "security"},
    {"lawman", "security"},
    {"policeman", "security"},
    {"passenger", "passenger"},
    {"traveler", "passenger"},
    {"student", "student"},
    {"pupil", "student"},
    {"schoolchild", "child"},
    {"child", "child"},
    {"juvenile", "child"},
    {"old person", "elderly"},
    {"oldster", "elderly"},
    {"pensioner", "elderly"},
    {"resident", "resident"},
    {"inhabitant", "resident"},
    {"guest", "guest"},
    {"visitor", "visitor"},
    {"tourist", "visitor"},
    {"customer", "customer"},
    {"shopper", "customer"},
    {"consumer", "customer"},
    {"diner", "customer"},
    {"jogger", "jogger"},
    {"runner", "jogger"},
    {"employee", "worker"},
    {"worker", "worker"},
    {"workman", "worker"},
    {"skilled worker", "worker"},
    {"professional", "worker"},
    {"serviceman", "worker"},
};

const std::vector<std::pair<std::string_view, std::string_view>> kDensityWords = {
    {"busy", "high"},        {"crowded", "high"}, {"packed", "high"}, {"bustling", "high"},
    {"overcrowded", "high"}, {"rush", "high"},    {"quiet", "low"},   {"empty", "low"},
    {"deserted", "low"},     {"calm", "low"},     {"sparse", "low"},  {"almost", ""},
};

const std::set<std::string, std::less<>> kPlacePrepositions = {
    "at",    "in",      "on",   "by",     "near",  "next",   "beside",  "behind",  "outside", "inside",
    "along", "through", "past", "around", "into",  "to",     "towards", "toward",  "from",    "across",
    "among", "up",      "down", "via",    "under", "within", "onto",    "between",
};

// --- Helpers -------------------------------------------------------------------------------------

std::string join_text(const Tokens& t, std::size_t s, std::size_t e) {
  std::string out;
  for (std::size_t k = s; k < e && k < t.size(); ++k) out += (out.empty() ? "" : " ") + t[k].text;
  return out;
}

Span span_of(const Tokens& t, std::size_t s, std::size_t e) {
  if (s >= e || s >= t.size()) return {};
  return Span{t[s].span.begin, t[std::min(e, t.size()) - 1].span.end};
}

std::string strip_accents(std::string w) {
  std::string out;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w.compare(i, 2, "\xC3\xA9") == 0 || w.compare(i, 2, "\xC3\xA8") == 0) {
      out.push_back('e');
      ++i;
    } else {
      out.push_back(w[i]);
    }
  }
  return out;
}

// The written form of a noun WordNet lemmatised to another word is a plural: "-s", and the
// irregular people words ("children", "women", "firemen").
bool plural_form(std::string_view w) {
  return w.ends_with("s") || w.ends_with("men") || w.ends_with("children") || w.ends_with("folk");
}

bool has_sense(const NounEntry& e, std::string_view lexfile, std::size_t within) {
  for (std::size_t k = 0; k < e.senses.size() && k < within; ++k)
    if (e.senses[k].lexfile == lexfile) return true;
  return false;
}

bool hypernym_of(const NounEntry& e, std::string_view word, std::size_t within) {
  for (std::size_t k = 0; k < e.senses.size() && k < within; ++k)
    for (const std::string& h : e.senses[k].hypernyms)
      if (h == word) return true;
  return false;
}

enum class Cls { kNone, kPerson, kGenericPerson, kCollective, kVenue, kRoom, kFeature, kObject, kRobot };

struct Chunk {
  std::size_t s = 0, e = 0;  // tokens [s, e)
  Cls cls = Cls::kNone;
  std::string head;  // lemma of the last word
  std::string name;  // as written, singular, without determiners, venue words and adjectives
  bool plural = false;
  bool possessive = false;
  std::string why;
  std::optional<std::string> venue_type;  // when a venue
  bool maybe_person = false;              // a person in a rarer sense, or a word WordNet lacks
  bool named = false;                     // one person by name and title ("Dr Okafor")
};

// Titles before a name, and the role of the person they name.
const std::map<std::string, std::string, std::less<>> kTitles = {
    {"dr", "doctor"},           {"doctor", "doctor"},
    {"professor", "professor"}, {"prof", "professor"},
    {"mr", "person"},           {"mrs", "person"},
    {"ms", "person"},           {"miss", "person"},
    {"nurse", "nurse"},         {"officer", "police officer"},
    {"captain", "captain"},     {"coach", "coach"}};

class Reader {
 public:
  Reader(const WordNet& wn, std::string_view prompt) : wn_(wn), t_(tokenize_text(prompt)) {
    out_.prompt = prompt;
    for (const TextToken& tok : t_) {
      const NounEntry* e = tok.kind == TextToken::Kind::kWord ? &noun(tok.text) : nullptr;
      lemma_.push_back(e != nullptr && e->known ? e->lemma : std::string());
      plain_.push_back(strip_accents(tok.text));
    }
  }

  ScenarioIntent run();

 private:
  const WordNet& wn_;
  Tokens t_;
  ScenarioIntent out_;
  std::vector<Chunk> chunks_;
  std::map<std::size_t, QuantityMatch> quantity_ending_;  // token index after the quantity → quantity
  std::vector<bool> used_;                                // tokens a quantity or chunk consumed
  std::vector<std::string> lemma_;                        // noun lemma per token ("" when none)
  std::vector<std::string> plain_;                        // text without accents

  const NounEntry& noun(const std::string& w) const { return wn_.noun(strip_accents(w)); }
  bool noun_known(const std::string& w) const { return noun(w).known; }
  bool content(std::size_t i) const;
  // The word starts with a capital letter as written.
  [[nodiscard]] bool capitalised(std::size_t i) const {
    const unsigned char first = static_cast<unsigned char>(out_.prompt[t_[i].span.begin]);
    return first >= 'A' && first <= 'Z';
  }
  bool significant(const std::string& word) const;
  void find_quantities();
  void find_chunks();
  void classify(Chunk& c);
  void resolve_maybe_persons();
  [[nodiscard]] bool coordinated_with_person(std::size_t chunk) const;
  bool person_word(const std::string& word, const Chunk& c, std::string& why) const;
  std::string normalise_role(const std::string& role, const std::string& head, std::string& why) const;
  void find_venue();
  // Token i belongs to a chunk that names people (the venue word before it describes them).
  [[nodiscard]] bool modifies_people(std::size_t i) const;
  void read_people();
  void apply_products();
  void attach_places_and_activities();
  void read_exclusivity_and_density();
  void read_categories();
  std::optional<std::string> venue_at(std::size_t i, std::size_t& length) const;
  [[nodiscard]] std::optional<Count> determiner_count(std::size_t chunk_start, bool plural) const;
  [[nodiscard]] std::optional<QuantityMatch> quantity_before(std::size_t chunk_start) const;
};

bool Reader::content(std::size_t i) const {
  if (i >= t_.size()) return false;
  const TextToken& tok = t_[i];
  if (is_function(tok)) return false;
  const NounEntry& e = noun(tok.text);
  if (e.known) return true;
  if (wn_.is_adjective(strip_accents(tok.text))) return true;
  // Unknown to WordNet: a name or a new word; "-ing" and "-ly" words are verbs and adverbs.
  if (wn_.is_verb(tok.text) || wn_.is_adverb(tok.text)) return false;
  return !tok.text.ends_with("ly");
}

bool Reader::significant(const std::string& w) const {
  const NounEntry& e = noun(w);
  const std::string lemma = e.known ? e.lemma : w;
  if (kFeatureHeads.count(lemma) || kRoomHeads.count(lemma) || kCollectives.count(lemma)) return true;
  if (kGenericPeople.count(w) || kMassPeople.count(lemma)) return true;
  for (const auto& [phrase, type] : kVenueWords)
    if (phrase == lemma) return true;
  return has_sense(e, "noun.person", 3) || lemma == "robot";
}

void Reader::find_quantities() {
  used_.assign(t_.size(), false);
  for (std::size_t i = 0; i < t_.size();) {
    auto q = quantity_at(t_, i);
    if (!q || q->length == 0) {
      ++i;
      continue;
    }
    // "sit around one table", "gather around two tables": a preposition, not an approximation.
    if ((t_[i].is("around") || t_[i].is("about") || t_[i].is("over")) && q->length >= 2) {
      static const std::set<std::string, std::less<>> kBeforeCount = {"with", "of",  "for", "are",  "is",
                                                                      "were", "was", "has", "have", "had",
                                                                      "and",  ",",   ":",   "by",   "than"};
      const bool one = q->count.kind == CountKind::kApprox && q->count.value == 1;
      const bool after_verb = i > 0 && kBeforeCount.count(t_[i - 1].text) == 0 &&
                              t_[i - 1].kind == TextToken::Kind::kWord && wn_.is_verb(t_[i - 1].text);
      if (one || after_verb) {
        ++i;
        continue;
      }
    }
    // "9 am", "platform 4": a number glued to a time or a name is not a count.
    const std::size_t after = i + q->length;
    if (after < t_.size() && (t_[after].is("am") || t_[after].is("pm") || t_[after].is("o'clock"))) {
      i = after + 1;
      continue;
    }
    if (i > 0 && t_[i].kind == TextToken::Kind::kNumber && q->length == 1 &&
        (t_[i - 1].is("platform") || t_[i - 1].is("gate") || t_[i - 1].is("room") || t_[i - 1].is("floor") ||
         t_[i - 1].is("at") || t_[i - 1].is("lane") || t_[i - 1].is("track"))) {
      i = after;
      continue;
    }
    quantity_ending_[after] = *q;
    for (std::size_t k = i; k < after; ++k) used_[k] = true;
    i = after;
  }
}

void Reader::find_chunks() {
  for (std::size_t i = 0; i < t_.size();) {
    if (used_[i] || !content(i)) {
      ++i;
      continue;
    }
    std::size_t e = i + 1;
    // A title and the capitalised words after it: one named person ("Mrs Patel waits").
    if (kTitles.count(t_[i].text))
      while (e < t_.size() && t_[e].kind == TextToken::Kind::kWord && t_[e].sentence == t_[i].sentence &&
             capitalised(e))
        ++e;
    const bool titled = e > i + 1;
    while (!titled && e < t_.size() && !used_[e] && content(e) && t_[e].sentence == t_[i].sentence) {
      const TextToken& prev = t_[e - 1];
      if (prev.possessive) break;
      const NounEntry& pe = noun(prev.text);
      const bool prev_plural = pe.known && pe.lemma != prev.text && plural_form(prev.text);
      if (prev_plural && kPluralModifiers.count(prev.text) == 0 && prev.text != "people") break;
      if (prev.text == "people" || kGenericPeople.count(prev.text)) break;
      // "nurse calls", "guide wait", "robot drives": a noun that can be a verb after a
      // significant noun is the verb of the clause.
      const std::string& next = t_[e].text;
      const NounEntry& ne = noun(next);
      if (significant(prev.text) && wn_.is_verb(next) && !significant(next)) break;
      // "a security guard stands", "a gate agent checks": a verb agreeing with a singular person.
      if (!prev_plural && has_sense(pe, "noun.person", 3) && next.ends_with("s") && !next.ends_with("ss") &&
          !has_sense(ne, "noun.person", 1) && wn_.is_verb(next.substr(0, next.size() - 1)))
        break;
      if (!ne.known && wn_.is_verb(next)) break;
      // "baristas work", "stallholders set up": a plural WordNet lacks, then a verb.
      if (!pe.known && prev.text.size() > 3 && prev.text.ends_with("s") && !prev.text.ends_with("ss") &&
          wn_.is_verb(next) && !significant(next))
        break;
      ++e;
    }
    Chunk c;
    c.s = i;
    c.e = e;
    classify(c);
    chunks_.push_back(std::move(c));
    i = e;
  }
}

bool Reader::person_word(const std::string& w, const Chunk& c, std::string& why) const {
  const NounEntry& e = noun(w);
  if (e.known) {
    if (has_sense(e, "noun.person", 1)) {
      why = "WordNet: '" + e.lemma + "' is a person (noun.person)";
      return true;
    }
    (void)c;
    return false;
  }
  // Not in WordNet: agent nouns ("carer", "concertgoer").
  std::string s = w;
  if (s.ends_with("s") && !s.ends_with("ss")) s.pop_back();
  // Compounds ending in a person ("stallholder" = stall + holder, "shopworker", "ticketholder").
  for (std::size_t cut = 3; cut + 4 <= s.size(); ++cut) {
    const NounEntry& head = noun(s.substr(cut));
    if (head.known && has_sense(head, "noun.person", 2) && noun_known(s.substr(0, cut))) {
      why = "'" + s + "': a " + s.substr(cut) + " (WordNet: a person) of " + s.substr(0, cut);
      return true;
    }
  }
  if (s.ends_with("goer")) {
    why = "'" + s + "': one who goes to something";
    return true;
  }
  for (std::string_view suffix : {"er", "or", "ist"}) {
    if (s.size() > suffix.size() + 2 && s.ends_with(suffix)) {
      const std::string base = s.substr(0, s.size() - suffix.size());
      if (wn_.is_verb(base) || wn_.is_verb(base + "e")) {
        why = "'" + s + "': one who does what the verb '" + base + "' says";
        return true;
      }
    }
  }
  return false;
}

std::optional<std::string> Reader::venue_at(std::size_t i, std::size_t& length) const {
  length = 0;
  for (const auto& [phrase, type] : kVenueWords) {
    // Phrases match lemmas word by word ("train stations", "the nurses' station").
    std::size_t n = 0, p = 0;
    bool ok = true;
    while (p < phrase.size()) {
      const std::size_t q = std::min(phrase.find(' ', p), phrase.size());
      const std::string_view want = phrase.substr(p, q - p);
      if (i + n >= t_.size() || t_[i + n].kind != TextToken::Kind::kWord) {
        ok = false;
        break;
      }
      if (t_[i + n].text != want && plain_[i + n] != want && lemma_[i + n] != want) {
        ok = false;
        break;
      }
      ++n;
      p = q + 1;
    }
    if (ok && n > 0) {
      length = n;
      return std::string(type);
    }
  }
  return std::nullopt;
}

void Reader::classify(Chunk& c) {
  // "Dr Okafor", "Mrs Patel", "Professor Lee": a title and capitalised words name one person.
  if (auto title = kTitles.find(t_[c.s].text); title != kTitles.end() && c.e - c.s >= 2) {
    bool name = true;
    for (std::size_t k = c.s + 1; k < c.e && name; ++k) name = capitalised(k);
    if (name) {
      c.cls = Cls::kPerson;
      c.named = true;
      c.head = c.name = title->second;
      c.why = "'" + join_text(t_, c.s, c.e) + "': one person named with the title '" + t_[c.s].text + "'";
      return;
    }
  }
  const std::size_t last = c.e - 1;
  const std::string& word = t_[last].text;
  const NounEntry& e = noun(word);
  c.head = e.known ? e.lemma : strip_accents(word);
  c.plural = e.known && e.lemma != word && plural_form(word);
  if (!e.known && c.head.size() > 3 && c.head.ends_with("s") && !c.head.ends_with("ss")) {
    c.head.pop_back();  // a plural WordNet lacks ("carers", "baristas")
    c.plural = true;
  }
  if (word == "people" || word == "staff" || word == "personnel" || word == "others") c.plural = true;
  c.possessive = t_[last].possessive;
  // The name as written: the last two words that are nouns (not venue words, not adjectives).
  std::vector<std::string> words;
  for (std::size_t k = c.s; k < c.e; ++k) {
    const std::string& w = t_[k].text;
    const NounEntry& we = noun(w);
    if (k + 1 < c.e) {
      if (!we.known) {
        if (!wn_.is_adjective(w) && !wn_.is_verb(w) && k + 1 == last) words.push_back(w);
        continue;
      }
      std::size_t vl = 0;
      if (auto v = venue_at(k, vl); v && !v->empty() && k + vl <= last) continue;  // "mall security guards"
      if (wn_.is_adjective(w) && (we.senses.empty() || we.senses[0].lexfile != "noun.artifact")) {
        // Adjectives go ("elderly", "new"), except noun-first words ("security", "tour").
        const bool noun_first =
            !we.senses.empty() && we.senses[0].lexfile != "noun.attribute" && w != "other" && w != "single" &&
            w != "only" && w != "lone" && w != "main" && w != "narrow" && w != "busy" && w != "quiet" &&
            w != "long" && w != "small" && w != "big" && w != "large" && w != "new" && w != "elderly" &&
            w != "young" && w != "open" && w != "empty" && w != "junior" && w != "senior" && w != "personal";
        if (!noun_first) continue;
      }
      words.push_back(we.lemma);
    } else {
      words.push_back(c.head);
    }
  }
  if (words.size() > 2) words.erase(words.begin(), words.end() - 2);
  for (const std::string& w : words) c.name += (c.name.empty() ? "" : " ") + w;
  // A two-word collocation WordNet knows ("security guard", "tour guide", "water cooler").
  const std::string compound = words.size() == 2 ? words[0] + " " + words[1] : std::string();
  static const NounEntry kNone;
  const NounEntry& ce = compound.empty() ? kNone : noun(compound);

  std::size_t vl = 0;
  std::optional<std::string> venue;
  for (std::size_t k = c.s; k < c.e && !venue; ++k) {
    auto v = venue_at(k, vl);
    if (v && k + vl == c.e) venue = v;  // the head is a venue word (modifiers are handled in find_venue)
  }
  if (c.head == "robot" || hypernym_of(e, "automaton", 1)) {
    c.cls = Cls::kRobot;
    c.why = "robot";
    return;
  }
  if (kGenericPeople.count(word) != 0) {
    c.cls = Cls::kGenericPerson;
    c.why = "'" + word + "' means people";
    return;
  }
  if (kMassPeople.count(c.head) != 0) {
    c.cls = Cls::kPerson;
    c.why = "'" + c.head + "' is a body of people";
    return;
  }
  if (kCollectives.count(c.head) != 0 && c.e < t_.size() && t_[c.e].is("of")) {
    c.cls = Cls::kCollective;
    c.why = "collective '" + c.head + " of'";
    return;
  }
  if (venue && !venue->empty()) {
    c.cls = Cls::kVenue;
    c.venue_type = venue;
    c.why = "venue word";
    return;
  }
  if (feature_head(c.head, words.size())) {
    c.cls = Cls::kFeature;
    c.why = "feature '" + c.head + "'";
    return;
  }
  if (kRoomHeads.count(c.head) != 0 || (venue && venue->empty())) {
    c.cls = Cls::kRoom;
    c.why = "room or area '" + c.head + "'";
    return;
  }
  std::string why;
  // "30 residents, some with walkers": what part of a group has with it is a thing when the word
  // can be one (a walking frame), not more people ("parents, some with children" stays people).
  if (e.known && c.s >= 2 && t_[c.s - 1].is("with") && has_sense(e, "noun.artifact", 3) &&
      (t_[c.s - 2].is("some") || t_[c.s - 2].is("many") || t_[c.s - 2].is("most") ||
       t_[c.s - 2].is("several") || t_[c.s - 2].is("few") || t_[c.s - 2].is("half") ||
       t_[c.s - 2].is("others"))) {
    c.cls = Cls::kObject;
    c.why = "WordNet: '" + e.lemma + "' can be a thing (noun.artifact), said of part of a group ('" +
            t_[c.s - 2].text + " with')";
    return;
  }
  if (ce.known && has_sense(ce, "noun.person", 1)) {
    c.cls = Cls::kPerson;
    c.why = "WordNet: '" + ce.lemma + "' is a person (noun.person)";
    return;
  }
  if (person_word(word, c, why)) {
    c.cls = Cls::kPerson;
    c.why = why;
    return;
  }
  // A person only in a rarer sense ("fans", "commuters", "cleaner") or a word WordNet lacks
  // ("barista"): decided once every chunk is classified (resolve_maybe_persons).
  c.maybe_person = (e.known && has_sense(e, "noun.person", 3)) || (!e.known && !wn_.is_adjective(word));
  if (e.known && (hypernym_of(e, "room", 2) || hypernym_of(e, "area", 1) || hypernym_of(e, "passage", 1))) {
    c.cls = Cls::kRoom;
    c.why = "WordNet: '" + e.lemma + "' is a room or area";
    return;
  }
  if (e.known && has_sense(e, "noun.artifact", 2)) {
    c.cls = Cls::kObject;
    c.why = "WordNet: '" + e.lemma + "' is an object (noun.artifact)";
    return;
  }
  if (ce.known && !ce.senses.empty() && ce.senses[0].lexfile == "noun.artifact") {
    c.cls = Cls::kObject;
    c.why = "WordNet: '" + ce.lemma + "' is an object (noun.artifact)";
    return;
  }
}

bool Reader::coordinated_with_person(std::size_t ci) const {
  // Chunks next to this one in its sentence with only "and", "or", commas, articles and counts between.
  auto link = [&](std::size_t a_end, std::size_t b_start) {
    bool joined = false;
    for (std::size_t k = a_end; k < b_start; ++k) {
      joined = joined || t_[k].text == "," || t_[k].is("and") || t_[k].is("or");
      const TextToken& x = t_[k];
      if (x.text == "," || x.is("and") || x.is("or") || x.is("a") || x.is("an") || x.is("the") ||
          x.is("their") || used_[k])
        continue;
      return false;
    }
    return joined;
  };
  const Chunk& c = chunks_[ci];
  auto person = [](const Chunk& o) { return o.cls == Cls::kPerson || o.cls == Cls::kGenericPerson; };
  if (ci > 0 && person(chunks_[ci - 1]) && t_[chunks_[ci - 1].s].sentence == t_[c.s].sentence &&
      link(chunks_[ci - 1].e, c.s))
    return true;
  if (ci + 1 < chunks_.size() && person(chunks_[ci + 1]) &&
      t_[chunks_[ci + 1].s].sentence == t_[c.s].sentence && link(c.e, chunks_[ci + 1].s))
    return true;
  return false;
}

void Reader::resolve_maybe_persons() {
  // Twice, so that "a cleaner, a dishwasher and two cooks" spreads along the list.
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t ci = 0; ci < chunks_.size(); ++ci) {
      Chunk& c = chunks_[ci];
      if (!c.maybe_person || (c.cls != Cls::kNone && c.cls != Cls::kObject)) continue;
      const bool counted = quantity_before(c.s).has_value();
      const NounEntry& e = noun(t_[c.e - 1].text);
      const bool coordinated = coordinated_with_person(ci);
      // "a gate agent checks tickets": an article and a verb that agrees.
      const bool subject = c.s > 0 &&
                           (t_[c.s - 1].is("a") || t_[c.s - 1].is("an") || t_[c.s - 1].is("the")) &&
                           c.e < t_.size() && t_[c.e].text.ends_with("s") &&
                           wn_.is_verb(t_[c.e].text.substr(0, t_[c.e].text.size() - 1));
      // "a cleaner vacuuming the floor", "a cleaner who vacuums", "fans stream out": the subject of a
      // verb; "nobody except a cleaner": whom an exception names.
      bool acting = false, excepted = false;
      if (c.e < t_.size() && t_[c.e].kind == TextToken::Kind::kWord) {
        const std::string& next = t_[c.e].text;
        acting = next == "who" || (next.ends_with("ing") && wn_.is_verb(next)) ||
                 (c.plural && !next.ends_with("s") && wn_.is_verb(next) && !significant(next));
      }
      {
        std::size_t k = c.s;
        while (k > 0 &&
               (t_[k - 1].is("a") || t_[k - 1].is("an") || t_[k - 1].is("the") || t_[k - 1].is("one") ||
                t_[k - 1].is("for") || t_[k - 1].is("single") || used_[k - 1]))
          --k;
        // "a robot weaves through commuters", "among fans": moving between them, they are people.
        if (c.plural && k > 0 &&
            (t_[k - 1].is("through") || t_[k - 1].is("among") || t_[k - 1].is("amid") ||
             t_[k - 1].is("amidst") || t_[k - 1].is("between") || t_[k - 1].is("past")))
          acting = true;
        excepted =
            k > 0 && (t_[k - 1].is("except") || t_[k - 1].is("but") || t_[k - 1].is("apart") ||
                      t_[k - 1].is("besides") || (t_[k - 1].is("than") && k > 1 && t_[k - 2].is("other")));
      }
      // A word WordNet lacks, counted and named in a prompt about people ("one barista behind the counter").
      const bool among_people = std::any_of(chunks_.begin(), chunks_.end(), [](const Chunk& o) {
        return o.cls == Cls::kPerson || o.cls == Cls::kGenericPerson || o.cls == Cls::kCollective;
      });
      if ((e.known && (counted || coordinated || subject || acting || excepted)) ||
          (!e.known && (coordinated || subject || (counted && among_people)))) {
        c.cls = Cls::kPerson;
        c.why = e.known ? "WordNet: '" + e.lemma + "' can be a person (noun.person), and is " +
                              (counted ? "counted" : "named with people")
                        : "'" + c.head + "' is not in WordNet; taken as a person: named with people";
      }
    }
}

std::optional<QuantityMatch> Reader::quantity_before(std::size_t s) const {
  if (auto it = quantity_ending_.find(s); it != quantity_ending_.end()) return it->second;
  // "ten more people", "two other nurses", "five extra staff"
  if (s > 0 && (t_[s - 1].is("more") || t_[s - 1].is("other") || t_[s - 1].is("extra")))
    if (auto it = quantity_ending_.find(s - 1); it != quantity_ending_.end()) return it->second;
  return std::nullopt;
}

std::optional<Count> Reader::determiner_count(std::size_t s, bool plural) const {
  if (plural || s == 0) return std::nullopt;
  const std::string& d = t_[s - 1].text;
  if (d == "a" || d == "an" || d == "the" || d == "their" || d == "his" || d == "her" || d == "its" ||
      d == "our" || d == "my" || d == "your" || d == "this" || d == "that" || d == "single" || d == "lone" ||
      d == "sole" ||
      (d == "only" && s >= 2 && (t_[s - 2].is("the") || t_[s - 2].is("an") || t_[s - 2].is("one")))) {
    Count c = Count::exact(1);
    c.phrase = d;
    c.span = t_[s - 1].span;
    return c;
  }
  return std::nullopt;
}

std::string Reader::normalise_role(const std::string& role, const std::string& head, std::string& why) const {
  for (const RoleWord& r : role_words())
    if (r.phrase == role || r.phrase == head) {
      why += "; known role '" + std::string(r.role) + "'";
      return std::string(r.role);
    }
  for (const std::string& w : {role, head}) {
    const NounEntry& e = noun(w);
    if (!e.known) continue;
    // Nearest anchor up the chain of the first person sense.
    for (const NounSense& s : e.senses) {
      if (s.lexfile != "noun.person") continue;
      for (const std::string& h : s.hypernyms)
        for (const auto& [anchor, mapped] : kRoleAnchors)
          if (h == anchor) {
            why += "; nearest known role '" + std::string(mapped) + "' (WordNet hypernym '" + h + "')";
            return std::string(mapped);
          }
      break;
    }
  }
  return "adult";
}

// Places and things that belong to one kind of venue, for prompts that name no venue ("passengers
// board a train at platform 2").
const std::vector<std::pair<std::string_view, std::string_view>> kVenueOfPart = {
    {"platform", "train_station"},
    {"train", "train_station"},
    {"carriage", "train_station"},
    {"ward", "hospital"},
    {"operating theatre", "hospital"},
    {"classroom", "school"},
    {"playground", "school"},
    {"checkout", "supermarket"},
    {"aisle", "supermarket"},
    {"trolley", "supermarket"},
    {"gallery", "museum"},
    {"exhibit", "museum"},
    {"boarding gate", "airport"},
    {"runway", "airport"},
    {"baggage claim", "airport"},
    {"lecture hall", "university"},
    {"treadmill", "gym"},
    {"changing room", "gym"},
    {"reading room", "library"},
    {"bookshelf", "library"},
    {"assembly line", "factory"},
    {"conveyor belt", "factory"},
    {"loading dock", "warehouse"},
    {"forklift", "warehouse"},
    {"reception desk", "hotel"},
    {"guest room", "hotel"},
    {"stage", "theatre"},
    {"auditorium", "theatre"},
    {"menu", "restaurant"},
    {"living room", "residential"},
    {"bedroom", "residential"},
    {"kitchen", "residential"}};

bool Reader::modifies_people(std::size_t i) const {
  for (const Chunk& c : chunks_)
    if (c.s <= i && i < c.e) return c.cls == Cls::kPerson || c.cls == Cls::kGenericPerson;
  return false;
}

void Reader::find_venue() {
  for (std::size_t i = 0; i < t_.size(); ++i) {
    if (t_[i].kind != TextToken::Kind::kWord) continue;
    std::size_t n = 0;
    auto v = venue_at(i, n);
    if (v) {
      if (v->empty()) {
        i += n - 1;
        continue;
      }
      // "office" after a possessive or as a room of another venue ("the head teacher's office").
      if (*v == "office" && i > 0 && t_[i - 1].possessive) continue;
      // "school children visit the aquarium", "hospital staff at the station": a venue word before
      // people describes them; a later venue word names the place.
      if (modifies_people(i + n)) {
        std::size_t later = i + n, n3 = 0;
        while (later < t_.size() &&
               !(venue_at(later, n3) && !venue_at(later, n3)->empty() && !modifies_people(later + n3)))
          ++later;
        if (later < t_.size()) {
          i = later - 1;
          continue;
        }
      }
      if (*v == "residential" && t_[i].is("home") && i > 0 && !t_[i - 1].is("at") && !t_[i - 1].is("the")) {
        // "care home" is in the table; a bare "home" needs "at home" or "the home".
        if (!(i + 1 < t_.size() && t_[i + 1].kind == TextToken::Kind::kPunct)) continue;
      }
      // Two venue words in a row: the head names the building ("university library"), unless it is
      // a place to eat or shop inside the first ("museum café", "factory canteen").
      std::size_t n2 = 0;
      const std::size_t next = i + n;
      if (next < t_.size() && !t_[next - 1].possessive) {
        auto v2 = venue_at(next, n2);
        if (v2 && !v2->empty() && *v2 != "canteen" && *v2 != "restaurant" && *v2 != "retail" && *v2 != *v) {
          v = v2;
          i = next;
          n = n2;
        }
      }
      VenueIntent venue;
      venue.type = *v;
      venue.building_type = std::string(nearest_building_type(*v));
      venue.words = join_text(t_, i, i + n);
      venue.span = span_of(t_, i, i + n);
      venue.why = "venue word '" + venue.words + "'";
      out_.venue = venue;
      return;
    }
  }
  // WordNet: a noun whose hypernyms include a venue kind ("motel" → hotel, "hostel").
  for (const Chunk& c : chunks_) {
    for (std::size_t k = c.s; k < c.e; ++k) {
      const NounEntry& e = noun(t_[k].text);
      if (!e.known || e.senses.empty() || e.senses[0].lexfile != "noun.artifact") continue;
      for (const std::string& h : e.senses[0].hypernyms)
        for (const auto& [anchor, type] : kVenueHypernyms)
          if (h == anchor) {
            VenueIntent venue;
            venue.type = std::string(type);
            venue.building_type = std::string(nearest_building_type(type));
            venue.words = t_[k].text;
            venue.span = t_[k].span;
            venue.why = "WordNet: '" + e.lemma + "' is a kind of " + h;
            out_.venue = venue;
            return;
          }
    }
  }
  // No venue word: the places and things named say where ("at platform 2" → a station).
  for (const Chunk& c : chunks_) {
    for (const auto& [part, type] : kVenueOfPart) {
      const bool two = part.find(' ') != std::string_view::npos;
      if (c.head != part && c.name != part && !(two && c.name.ends_with(part))) continue;
      VenueIntent venue;
      venue.type = std::string(type);
      venue.building_type = std::string(nearest_building_type(type));
      venue.words = join_text(t_, c.s, c.e);
      venue.span = span_of(t_, c.s, c.e);
      venue.why = "no venue word; '" + std::string(part) + "' belongs to a " + std::string(type);
      out_.venue = venue;
      return;
    }
  }
}

void Reader::read_people() {
  std::set<std::size_t> consumed;  // chunk indices already read as part of another
  auto group_from = [&](const Chunk& c, Count count, const std::string& why) {
    PeopleGroup g;
    if (c.cls == Cls::kGenericPerson) {
      g.role = "person";
      g.normalized_role = "adult";
      g.program_role = "adult";
      g.why = c.why;
    } else {
      g.role = c.name.empty() ? c.head : c.name;
      g.why = c.why;
      g.normalized_role = normalise_role(g.role, c.head, g.why);
      g.program_role = g.role;
      std::replace(g.program_role.begin(), g.program_role.end(), ' ', '_');
      std::replace(g.program_role.begin(), g.program_role.end(), '-', '_');
    }
    if (!why.empty()) g.why += "; " + why;
    g.count = std::move(count);
    g.span = span_of(t_, c.s, c.e);
    if (g.count.specified() && g.count.span.end > 0)
      g.span.begin = std::min(g.span.begin, g.count.span.begin);
    g.sentence = t_[c.s].sentence;
    return g;
  };
  auto negated = [&](std::size_t s) {
    for (std::size_t k = s; k > 0 && s - k < 3; --k) {
      const TextToken& p = t_[k - 1];
      if (p.is("no") || p.is("without") || p.is("not")) return true;
      if (!(p.is("any") || p.is("more") || p.is("other"))) return false;
    }
    return false;
  };
  auto role_of = [&](const Chunk& c) {
    return c.cls == Cls::kGenericPerson ? std::string("person") : c.name;
  };
  // "waiting for a doctor", "looking for their parents", "queuing for two cashiers": the people
  // awaited or sought are not there (yet); they are said, not added.
  auto awaited = [&](std::size_t s) {
    std::size_t k = s;
    while (k > 0 && (used_[k - 1] || kAwaitedDeterminers.count(t_[k - 1].text))) --k;
    if (k < 2 || !t_[k - 1].is("for") || t_[k - 2].kind != TextToken::Kind::kWord) return false;
    const std::string& v = t_[k - 2].text;
    for (const std::string_view stem : kAwaitingVerbs) {
      if (!v.starts_with(stem)) continue;
      const std::string_view rest = std::string_view(v).substr(stem.size());
      if (rest.empty() || rest == "s" || rest == "es" || rest == "ed" || rest == "ing" || rest == "eing" ||
          rest == "d")
        return true;
    }
    return false;
  };
  // Who the last group is, for appositions: "five friends, all teenagers", "30 visitors: parents,
  // some with children", "forty people, mostly tourists" describe the people already counted.
  std::optional<std::size_t> last_group;  // index in out_.groups
  std::size_t last_group_end = 0;         // token after its words
  bool in_apposition = false;
  auto apposition = [&](const Chunk& c) {
    if (!last_group || c.s < last_group_end) return false;
    const PeopleGroup& g = out_.groups[*last_group];
    if (!g.count.specified() || g.count.kind == CountKind::kRange) return false;
    bool separator = false, marker = false;
    for (std::size_t k = last_group_end; k < c.s; ++k) {
      const TextToken& x = t_[k];
      if (k == last_group_end &&
          (x.text == ":" || x.text == "(" || x.text == "-" || x.text == "—" || x.text == "–"))
        separator = marker = true;
      else if (k == last_group_end && x.text == ",")
        separator = true;
      else if (kAppositionMarkers.count(x.text) || used_[k])
        marker = marker || kAppositionMarkers.count(x.text) != 0;
      else if (!(in_apposition && kAppositionLinks.count(x.text)))
        return false;
    }
    if (in_apposition) return true;
    return separator && (marker || g.role == "person");
  };

  for (std::size_t ci = 0; ci < chunks_.size(); ++ci) {
    if (consumed.count(ci)) continue;
    Chunk& c = chunks_[ci];
    if (c.cls == Cls::kRobot) {
      RobotMention r;
      r.words = c.name.empty() ? c.head : c.name;
      if (auto q = quantity_before(c.s))
        r.count = q->count;
      else
        r.count = determiner_count(c.s, c.plural).value_or(Count{});
      r.span = span_of(t_, c.s, c.e);
      out_.robots.push_back(std::move(r));
      continue;
    }
    if (c.cls == Cls::kCollective) {
      // "a queue of 8 patients", "two classes of 25 pupils each", "a family of four".
      const std::size_t of = c.e;
      std::optional<QuantityMatch> inner;
      std::size_t k = of + 1;
      if (auto q = quantity_at(t_, k)) {
        inner = q;
        k += q->length;
      }
      while (k < t_.size() && (t_[k].is("the") || t_[k].is("their"))) ++k;
      std::optional<std::size_t> person;
      for (std::size_t cj = ci + 1; cj < chunks_.size(); ++cj)
        if (chunks_[cj].s == k) {
          if (chunks_[cj].cls == Cls::kPerson || chunks_[cj].cls == Cls::kGenericPerson) person = cj;
          break;
        }
      const bool together = kTogetherCollectives.count(c.head) != 0;
      const auto outer = quantity_before(c.s);
      std::string why = "collective '" + join_text(t_, c.s, c.e) + " of'";
      Count count = inner ? inner->count : Count{};
      if (inner && outer && outer->count.kind == CountKind::kExact && outer->count.value > 1) {
        count.times(outer->count.value);  // "two classes of 25 pupils (each)"
        count.phrase = outer->count.phrase + " × " + inner->count.phrase;
        count.span = Span{outer->count.span.begin, inner->count.span.end};
        why += "; product of " + outer->count.phrase + " and " + inner->count.phrase;
      }
      if (person) {
        Chunk& p = chunks_[*person];
        consumed.insert(*person);
        if (negated(c.s)) continue;
        PeopleGroup g = group_from(p, count, why);
        g.together = together;
        g.span.begin = std::min(g.span.begin, span_of(t_, c.s, c.e).begin);
        out_.groups.push_back(std::move(g));
        last_group = out_.groups.size() - 1;
        last_group_end = p.e;
        in_apposition = false;
      } else if (inner && !negated(c.s)) {
        Chunk self = c;
        self.cls = Cls::kPerson;
        self.name = c.head;
        PeopleGroup g = group_from(self, count, why);
        g.normalized_role = "adult";
        g.together = together;
        g.span = span_of(t_, c.s, of + 1 + inner->length);
        out_.groups.push_back(std::move(g));
        last_group = out_.groups.size() - 1;
        last_group_end = of + 1 + inner->length;
        in_apposition = false;
      }
      continue;
    }
    if (c.cls != Cls::kPerson && c.cls != Cls::kGenericPerson) continue;
    if (c.possessive) continue;  // "the head teacher's office", "children's library"
    // "per child", "each of": a reference, read by apply_products.
    if (c.s > 0 && (t_[c.s - 1].is("per") || t_[c.s - 1].is("each"))) continue;
    if (negated(c.s)) {
      out_.exclusivity.excluded_roles.push_back(role_of(c));
      out_.exclusivity.phrases.push_back(
          join_text(t_, c.s >= 2 && t_[c.s - 2].is("without") ? c.s - 2 : c.s - 1, c.e));
      out_.exclusivity.spans.push_back(span_of(t_, c.s - 1, c.e));
      continue;
    }
    // "farmers market", "fishermen's wharf": people naming the venue, not people there.
    if (c.plural && !quantity_before(c.s) && c.e < t_.size()) {
      std::size_t n = 0;
      if (auto v = venue_at(c.e, n); v && !v->empty()) continue;
    }
    if (awaited(c.s)) {
      out_.warnings.push_back(
          IntentWarning{"'" + join_text(t_, c.s, c.e) + "' is waited for or sought, not there: not added",
                        span_of(t_, c.s, c.e)});
      continue;
    }
    auto q = quantity_before(c.s);
    if ((!q || !q->count.specified() || q->count.kind == CountKind::kRange) && !c.named &&
        !determiner_count(c.s, c.plural) && apposition(c)) {
      PeopleGroup& g = out_.groups[*last_group];
      g.why += "; '" + join_text(t_, c.s, c.e) + "' says who they are";
      in_apposition = true;
      last_group_end = c.e;
      continue;
    }
    const bool other = std::any_of(t_.begin() + static_cast<std::ptrdiff_t>(c.s),
                                   t_.begin() + static_cast<std::ptrdiff_t>(c.e),
                                   [](const TextToken& x) { return x.is("other"); });
    if (c.cls == Cls::kGenericPerson && (!q || q->count.kind == CountKind::kRange) &&
        (other || t_[c.e - 1].is("others"))) {
      out_.background = true;
      out_.background_words.push_back(join_text(t_, c.s, c.e));
      continue;
    }
    Count count;
    if (q) {
      count = q->count;
    } else if (c.named) {
      count = Count::exact(1);
      count.phrase = join_text(t_, c.s, c.e);
      count.span = span_of(t_, c.s, c.e);
    } else if (auto d = determiner_count(c.s, c.plural)) {
      count = *d;
    }
    // A mention without a count of a role already named is the same people ("the ushers guide …").
    const std::string role = role_of(c);
    auto same = std::find_if(out_.groups.begin(), out_.groups.end(), [&](const PeopleGroup& g) {
      return g.role == role || (!role.empty() && g.role.ends_with(" " + role));
    });
    std::size_t before = c.s;
    while (before > 0 && (t_[before - 1].is("only") || t_[before - 1].is("same"))) --before;
    const bool definite = before > 0 && (t_[before - 1].is("the") || t_[before - 1].is("their"));
    if (same != out_.groups.end() && (!count.specified() || (definite && !q && same->count.specified())))
      continue;
    if (same != out_.groups.end() && !same->count.specified() && count.specified()) {
      // "guests check in …; 90 guests are expected": the count of the people already named.
      same->count = count;
      same->why += "; count from '" + count.phrase + " " + join_text(t_, c.s, c.e) + "'";
      continue;
    }
    // A singular count noun with neither article nor number is a verb or a title ("the ushers guide
    // everyone"), not somebody present.
    if (!count.specified() && !c.plural && c.cls == Cls::kPerson && kMassPeople.count(c.head) == 0) continue;
    if (c.cls == Cls::kGenericPerson && !count.specified() && definite) continue;  // "the only people"
    std::string why;
    if (c.s > 0 && t_[c.s - 1].is("another") && q) why = "'another': a further group";
    PeopleGroup g = group_from(c, count, why);
    g.together = q && (q->count.phrase.find("group of") != std::string::npos);
    out_.groups.push_back(std::move(g));
    last_group = out_.groups.size() - 1;
    last_group_end = c.e;
    in_apposition = false;
  }
  // "eight customers wait in line and three more sit by the window": more of the people named
  // just before ("ten more people" with its noun was read above).
  for (const auto& ending : quantity_ending_) {
    const std::size_t after = ending.first;  // (not a structured binding: lambdas capture it below)
    const QuantityMatch& q = ending.second;
    if (after >= t_.size() || !t_[after].is("more") || !q.count.specified()) continue;
    const bool noun_follows = std::any_of(chunks_.begin(), chunks_.end(), [&](const Chunk& c) {
      return (c.s == after + 1 || c.s == after) && c.cls != Cls::kNone && c.cls != Cls::kObject;
    });
    if (noun_follows) continue;
    const std::size_t at = t_[after - q.length].span.begin;
    PeopleGroup* nearest = nullptr;
    for (PeopleGroup& g : out_.groups)
      if (g.span.end <= at && (nearest == nullptr || g.span.end > nearest->span.end)) nearest = &g;
    if (nearest == nullptr || !nearest->count.specified()) continue;
    nearest->count.plus(q.count);
    nearest->why += "; '" + q.count.phrase + " more'";
  }
}

void Reader::apply_products() {
  // Counted features and groups by head lemma, for "per line", "each with".
  auto feature_count = [&](std::size_t before, std::size_t sentence) -> std::optional<double> {
    std::optional<double> best;
    for (const Chunk& c : chunks_) {
      if (c.e > before) break;
      if (t_[c.s].sentence != sentence) continue;
      if (c.cls != Cls::kFeature && c.cls != Cls::kRoom && c.cls != Cls::kObject && c.cls != Cls::kVenue)
        continue;
      if (auto q = quantity_before(c.s); q && q->count.kind == CountKind::kExact && q->count.value > 1)
        best = q->count.value;
    }
    return best;
  };
  for (std::size_t i = 0; i < t_.size(); ++i) {
    // "each with / each has / each having a queue of six customers"
    if (t_[i].is("each") && i + 1 < t_.size() &&
        (t_[i + 1].is("with") || t_[i + 1].is("has") || t_[i + 1].is("having") || t_[i + 1].is("holding"))) {
      auto factor = feature_count(i, t_[i].sentence);
      if (!factor) continue;
      for (PeopleGroup& g : out_.groups) {
        if (g.sentence != t_[i].sentence || g.span.begin < t_[i].span.end) continue;
        if (g.count.kind == CountKind::kUnspecified) break;
        g.count.times(*factor);
        g.count.phrase += " × " + std::to_string(static_cast<int>(*factor));
        g.why += "; 'each': times " + std::to_string(static_cast<int>(*factor));
        break;
      }
    }
    // "four operators per line", "one parent per child"
    if (t_[i].is("per") && i + 1 < t_.size()) {
      const NounEntry& e = noun(t_[i + 1].text);
      const std::string head = e.known ? e.lemma : t_[i + 1].text;
      std::optional<double> factor;
      for (const PeopleGroup& g : out_.groups)
        if ((g.role == head || g.role.ends_with(" " + head)) && g.count.kind == CountKind::kExact)
          factor = g.count.value;
      if (!factor)
        for (const Chunk& c : chunks_)
          if (c.head == head && c.s < i)
            if (auto q = quantity_before(c.s); q && q->count.kind == CountKind::kExact)
              factor = q->count.value;
      if (!factor) continue;
      // The group right before "per".
      for (auto it = out_.groups.rbegin(); it != out_.groups.rend(); ++it) {
        if (it->span.end > t_[i].span.begin) continue;
        if (it->count.kind == CountKind::kUnspecified) break;
        it->count.times(*factor);
        it->count.phrase += " per " + head;
        it->why += "; 'per " + head + "': times " + std::to_string(static_cast<int>(*factor));
        break;
      }
    }
    // "a guard at each of its 4 doors"
    if (t_[i].is("each") && i + 1 < t_.size() && t_[i + 1].is("of")) {
      std::size_t k = i + 2;
      while (k < t_.size() && (t_[k].is("the") || t_[k].is("its") || t_[k].is("their"))) ++k;
      auto q = quantity_at(t_, k);
      if (!q || q->count.kind != CountKind::kExact) continue;
      for (auto it = out_.groups.rbegin(); it != out_.groups.rend(); ++it) {
        if (it->span.end > t_[i].span.begin) continue;
        if (it->count.kind == CountKind::kUnspecified) break;
        it->count.times(q->count.value);
        it->why += "; 'each of " + q->count.phrase + "'";
        break;
      }
    }
    // "fourteen of them", "around 35 of them", "there are nine of them"
    if (t_[i].is("of") && i + 1 < t_.size() && t_[i + 1].is("them")) {
      auto q = quantity_before(i);
      if (!q) continue;
      PeopleGroup* target = nullptr;
      for (PeopleGroup& g : out_.groups)
        if (g.span.end <= t_[i].span.begin && !g.count.specified()) target = &g;
      if (target == nullptr) continue;
      target->count = q->count;
      target->why += "; count from '" + q->count.phrase + " of them'";
    }
  }
}

void Reader::attach_places_and_activities() {
  struct Place {
    std::size_t begin_token, end_token;
    std::string text;
    Span span;
    std::size_t sentence;
  };
  std::vector<Place> places;
  for (const Chunk& c : chunks_) {
    if (c.cls != Cls::kRoom && c.cls != Cls::kFeature && c.cls != Cls::kObject && c.cls != Cls::kVenue)
      continue;
    std::size_t s = c.s;
    while (s > 0 && (t_[s - 1].is("the") || t_[s - 1].is("a") || t_[s - 1].is("an") || t_[s - 1].is("its") ||
                     t_[s - 1].is("their") || t_[s - 1].is("her") || t_[s - 1].is("his") ||
                     t_[s - 1].kind == TextToken::Kind::kNumber || quantity_before(s).has_value()))
      --s;
    if (s == 0) continue;
    std::size_t p = s - 1;
    if (t_[p].is("to") && p > 0 && (t_[p - 1].is("next") || t_[p - 1].is("close"))) --p;
    if (t_[p].is("of") && p > 0 && t_[p - 1].is("front") && p > 1 && t_[p - 2].is("in")) p -= 2;
    if (kPlacePrepositions.count(t_[p].text) == 0) continue;
    places.push_back(Place{p, c.e, join_text(t_, p, c.e), span_of(t_, p, c.e), t_[c.s].sentence});
  }
  for (PeopleGroup& g : out_.groups) {
    const Place* best = nullptr;
    for (const Place& pl : places)
      if (pl.sentence == g.sentence && pl.span.begin >= g.span.end) {
        best = &pl;
        break;
      }
    if (best == nullptr)
      for (const Place& pl : places)
        if (pl.sentence == g.sentence && pl.span.end <= g.span.begin) best = &pl;
    if (best != nullptr) {
      g.place = best->text;
      g.place_span = best->span;
    }
    // Activity: the first verb after the group in its sentence.
    for (std::size_t k = 0; k < t_.size(); ++k) {
      if (t_[k].span.begin < g.span.end || t_[k].sentence != g.sentence) continue;
      if (t_[k].kind != TextToken::Kind::kWord) continue;
      static const std::set<std::string, std::less<>> kSkip = {
          "who", "are",  "is",   "was",      "were", "be",    "and",  "then",
          "all", "both", "each", "together", "also", "still", "have", "has"};
      if (kSkip.count(t_[k].text)) continue;
      if (wn_.is_verb(t_[k].text) && !t_[k].is("a")) g.activity = t_[k].text;
      break;
    }
  }
  // World requirements: counted features, named rooms, objects where people are.
  for (const Chunk& c : chunks_) {
    const std::string name = c.name.empty() ? c.head : c.name;
    if (c.cls == Cls::kFeature) {
      Feature f;
      f.name = name;
      f.head = c.head;
      if (auto q = quantity_before(c.s))
        f.count = q->count;
      else if (auto d = determiner_count(c.s, c.plural))
        f.count = *d;
      f.span = span_of(t_, c.s, c.e);
      // The same feature said again: the largest count; "the front door and the back door": two.
      auto same = std::find_if(out_.world.features.begin(), out_.world.features.end(),
                               [&](const Feature& o) { return o.head == f.head; });
      if (same == out_.world.features.end()) {
        out_.world.features.push_back(std::move(f));
      } else if (f.count.specified()) {
        const bool both_single = same->count.kind == CountKind::kExact && f.count.kind == CountKind::kExact &&
                                 f.count.value == 1 && same->name != f.name && !quantity_before(c.s);
        if (both_single)
          same->count = Count::exact(same->count.value + 1);
        else if (!same->count.specified() || f.count.value > same->count.value)
          same->count = f.count;
      }
    } else if (c.cls == Cls::kRoom || c.cls == Cls::kVenue) {
      if (c.cls == Cls::kRoom) out_.world.rooms.push_back(NamedThing{name, span_of(t_, c.s, c.e)});
      // Counted rooms are requirements too ("three galleries", "two classrooms").
      if (auto q = quantity_before(c.s); q && q->count.specified())
        out_.world.features.push_back(Feature{name, c.head, q->count, span_of(t_, c.s, c.e)});
    } else if (c.cls == Cls::kObject) {
      const bool placed = c.s > 0 && std::any_of(places.begin(), places.end(),
                                                 [&](const auto& p) { return p.end_token == c.e; });
      if (placed) out_.world.objects.push_back(NamedThing{name, span_of(t_, c.s, c.e)});
    }
  }
  // "together", "as a group": everyone in that sentence.
  for (std::size_t i = 0; i < t_.size(); ++i)
    if (t_[i].is("together") || (t_[i].is("as") && i + 2 < t_.size() && t_[i + 2].is("group")))
      for (PeopleGroup& g : out_.groups)
        if (g.sentence == t_[i].sentence) g.together = true;
}

void Reader::read_exclusivity_and_density() {
  auto add = [&](std::size_t s, std::size_t e) {
    out_.exclusivity.exclusive = true;
    out_.exclusivity.phrases.push_back(join_text(t_, s, e));
    out_.exclusivity.spans.push_back(span_of(t_, s, e));
  };
  for (std::size_t i = 0; i < t_.size(); ++i) {
    const TextToken& w = t_[i];
    if (w.kind != TextToken::Kind::kWord) continue;
    if (w.is("except")) {
      add(i, i + (i + 1 < t_.size() && t_[i + 1].is("for") ? 2 : 1));
    } else if ((w.is("nobody") || w.is("noone")) ||
               (w.is("no") && i + 1 < t_.size() && t_[i + 1].is("one"))) {
      const std::size_t n = w.is("no") ? 2 : 1;
      add(i, i + n + (i + n < t_.size() && t_[i + n].is("else") ? 1 : 0));
    } else if (w.is("only") || w.is("alone") || w.is("otherwise") || w.is("solely")) {
      add(i, i + 1);
    } else if (w.is("empty") || w.is("deserted") || w.is("closed")) {
      add(i, i + 1);
    } else if (w.is("just") && (quantity_at(t_, i + 1) ||
                                (i + 1 < t_.size() && (t_[i + 1].is("a") || t_[i + 1].is("the"))))) {
      add(i, i + 1);
    }
    for (const auto& [word, level] : kDensityWords) {
      if (level.empty() || w.text != word) continue;
      if (word == "rush" && !(i + 1 < t_.size() && t_[i + 1].is("hour"))) continue;
      out_.density.push_back(
          DensityWord{word == "rush" ? "rush hour" : std::string(word), std::string(level), w.span});
    }
    if (w.is("passers-by") || w.is("passersby") || w.is("bystanders") ||
        (w.is("rest") && i + 1 < t_.size() && t_[i + 1].is("of"))) {
      out_.background = true;
      out_.background_words.push_back(w.text);
    }
  }
  if (!out_.exclusivity.excluded_roles.empty()) out_.exclusivity.exclusive = true;
  // A density word asks for more people only when no group says how many there are.
  const bool counted = std::any_of(out_.groups.begin(), out_.groups.end(),
                                   [](const PeopleGroup& g) { return g.count.specified(); });
  if (!counted && !out_.exclusivity.exclusive)
    for (const DensityWord& d : out_.density)
      if (d.level == "high") {
        out_.background = true;
        out_.background_words.push_back(d.word);
      }
  if (out_.exclusivity.exclusive) {
    out_.background = false;
    out_.background_words.clear();
  }
}

void Reader::read_categories() {
  std::vector<CategoryPhrase> phrases(category_phrases().begin(), category_phrases().end());
  std::map<std::size_t, std::map<Category, CategoryMention>> per_sentence;
  for (std::size_t i = 0; i < t_.size(); ++i) {
    std::size_t best_n = 0;
    const CategoryPhrase* best = nullptr;
    for (const CategoryPhrase& p : phrases) {
      std::size_t n = 0, pos = 0;
      bool ok = true;
      while (pos < p.phrase.size()) {
        const std::size_t q = std::min(p.phrase.find(' ', pos), p.phrase.size());
        if (i + n >= t_.size() || !t_[i + n].is(p.phrase.substr(pos, q - pos))) {
          ok = false;
          break;
        }
        ++n;
        pos = q + 1;
      }
      if (ok && n > best_n) {
        best_n = n;
        best = &p;
      }
    }
    if (best == nullptr) continue;
    CategoryMention& m = per_sentence[t_[i].sentence][best->category];
    m.category = best->category;
    m.score += best->weight;
    m.phrases.emplace_back(best->phrase);
    i += best_n - 1;
  }
  std::map<Category, CategoryMention> activities;
  std::map<std::size_t, Category> sentence_category;
  for (auto& [sentence, scores] : per_sentence) {
    const CategoryMention* top = nullptr;
    for (auto& [cat, m] : scores)
      if (top == nullptr || m.score > top->score) top = &m;
    // An emergency said alongside another activity is the alarm of it: both are understood.
    for (auto& [cat, m] : scores) {
      if (m.score < 0.4) continue;  // weak words alone ("exits", "counter") say where, not what
      CategoryMention& a = activities[cat];
      a.category = cat;
      a.score += m.score;
      a.phrases.insert(a.phrases.end(), m.phrases.begin(), m.phrases.end());
    }
    if (top != nullptr) sentence_category[sentence] = top->category;
  }
  for (auto& [cat, m] : activities) out_.categories.push_back(m);
  std::stable_sort(out_.categories.begin(), out_.categories.end(),
                   [](const CategoryMention& a, const CategoryMention& b) { return a.score > b.score; });
  if (out_.categories.empty())
    out_.categories.push_back(CategoryMention{Category::kNormalOperation, 0.0, {}});
  for (PeopleGroup& g : out_.groups) {
    auto it = sentence_category.find(g.sentence);
    g.category = it != sentence_category.end() ? it->second : out_.categories.front().category;
  }
}

ScenarioIntent Reader::run() {
  find_quantities();
  find_chunks();
  resolve_maybe_persons();
  find_venue();
  read_people();
  apply_products();
  attach_places_and_activities();
  read_exclusivity_and_density();
  read_categories();
  // Warnings: words no dictionary knows (not a name), and counted things that are no person,
  // place or object.
  for (const Chunk& c : chunks_) {
    if (c.cls == Cls::kNone) {
      std::string unknown;
      for (std::size_t k = c.s; k < c.e; ++k) {
        if (t_[k].kind != TextToken::Kind::kWord || !lemma_[k].empty() || wn_.is_verb(plain_[k]) ||
            wn_.is_adjective(plain_[k]) || wn_.is_adverb(plain_[k]))
          continue;
        // A capitalised word inside a sentence is a name ("Platform Nine", "Dr Okafor").
        const bool sentence_start = k == 0 || t_[k - 1].sentence != t_[k].sentence;
        if (!sentence_start && capitalised(k)) continue;
        if (std::any_of(t_[k].text.begin(), t_[k].text.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
          continue;  // "8am", "b12": times and codes
        unknown += (unknown.empty() ? "" : " ") + t_[k].text;
      }
      if (!unknown.empty()) {
        out_.warnings.push_back(IntentWarning{
            "'" + unknown + "' is not a person, place or object I know: ignored", span_of(t_, c.s, c.e)});
        continue;
      }
    }
    const auto q = quantity_before(c.s);
    if ((c.cls != Cls::kNone && c.cls != Cls::kObject) || !q) continue;
    // "a family of four waits": the number belongs to the collective, not to the next word.
    if (auto it = quantity_ending_.find(c.s);
        it != quantity_ending_.end() && c.s > it->second.length && t_[c.s - it->second.length - 1].is("of"))
      continue;
    const std::string name = c.name.empty() ? c.head : c.name;
    if (c.cls == Cls::kObject) {
      const bool used = std::any_of(out_.world.objects.begin(), out_.world.objects.end(),
                                    [&](const NamedThing& o) { return o.name == name; });
      if (!used)
        out_.warnings.push_back(
            IntentWarning{"'" + join_text(t_, c.s, c.e) +
                              "' is an object, not a person or a place where people are: ignored",
                          span_of(t_, c.s, c.e)});
      continue;
    }
    out_.warnings.push_back(
        IntentWarning{"'" + join_text(t_, c.s, c.e) + "' is not a person, place or object I know: ignored",
                      span_of(t_, c.s, c.e)});
  }
  // "0 people", "zero visitors": nobody of that role.
  for (auto it = out_.groups.begin(); it != out_.groups.end();) {
    if (it->count.kind == CountKind::kExact && it->count.value == 0) {
      out_.exclusivity.exclusive = true;
      out_.exclusivity.excluded_roles.push_back(it->role);
      out_.exclusivity.phrases.push_back(it->count.phrase + " " + it->role);
      out_.exclusivity.spans.push_back(it->span);
      it = out_.groups.erase(it);
    } else {
      ++it;
    }
  }
  // Mostly words no English dictionary part of WordNet knows: probably another language.
  std::size_t words = 0, unknown = 0;
  for (std::size_t i = 0; i < t_.size(); ++i) {
    if (t_[i].kind != TextToken::Kind::kWord || kFunctionWords.count(t_[i].text) || used_[i]) continue;
    ++words;
    if (lemma_[i].empty() && !wn_.is_verb(plain_[i]) && !wn_.is_adjective(plain_[i]) &&
        !wn_.is_adverb(plain_[i]))
      ++unknown;
  }
  if (words >= 3 && unknown * 2 >= words)
    out_.warnings.push_back(IntentWarning{"most words are not English words I know (" +
                                              std::to_string(unknown) + " of " + std::to_string(words) +
                                              "): prompts are read in English",
                                          {}});
  if (out_.groups.empty())
    out_.warnings.push_back(IntentWarning{"no people named: the generator chooses who is there", {}});
  if (!out_.venue) out_.warnings.push_back(IntentWarning{"no venue named", {}});
  return std::move(out_);
}

}  // namespace

Count ScenarioIntent::total() const {
  if (groups.empty()) return Count{};
  Count sum = Count::exact(0);
  for (const PeopleGroup& g : groups) sum.plus(g.count);
  return sum;
}

std::vector<std::string_view> venue_types() {
  std::vector<std::string_view> out;
  for (const VenueKind& v : kVenueKinds) out.push_back(v.type);
  return out;
}

std::string_view nearest_building_type(std::string_view venue_type) {
  if (knowledge::is_building_type(venue_type)) return venue_type;
  for (const VenueKind& v : kVenueKinds)
    if (v.type == venue_type) return v.building_type;
  return "office";
}

Result<ScenarioIntent> interpret_prompt(std::string_view prompt) {
  auto wn = WordNet::open();
  if (!wn) return tl::unexpected(wn.error());
  return Reader(**wn, prompt).run();
}

Json to_json(const Count& c) {
  Json j{{"kind", std::string(to_string(c.kind))}};
  if (c.kind == CountKind::kExact || c.kind == CountKind::kApprox) j["value"] = c.value;
  if (c.kind == CountKind::kApprox || c.kind == CountKind::kRange) {
    j["min"] = c.min;
    j["max"] = c.max;
  }
  if (!c.phrase.empty()) {
    j["phrase"] = c.phrase;
    j["span"] = Json::array({c.span.begin, c.span.end});
  }
  return j;
}

namespace {
Json span_json(const Span& s) {
  return Json::array({s.begin, s.end});
}
}  // namespace

Json to_json(const ScenarioIntent& in) {
  Json groups = Json::array();
  for (const PeopleGroup& g : in.groups) {
    Json j{{"role", g.role},
           {"normalized_role", g.normalized_role},
           {"program_role", g.program_role},
           {"count", to_json(g.count)},
           {"together", g.together},
           {"why", g.why},
           {"span", span_json(g.span)}};
    if (g.category) j["category"] = std::string(to_string(*g.category));
    if (!g.activity.empty()) j["activity"] = g.activity;
    if (!g.place.empty()) j["place"] = Json{{"phrase", g.place}, {"span", span_json(g.place_span)}};
    groups.push_back(std::move(j));
  }
  Json features = Json::array();
  for (const Feature& f : in.world.features)
    features.push_back(
        Json{{"name", f.name}, {"head", f.head}, {"count", to_json(f.count)}, {"span", span_json(f.span)}});
  auto things = [](const std::vector<NamedThing>& v) {
    Json a = Json::array();
    for (const NamedThing& n : v) a.push_back(Json{{"name", n.name}, {"span", span_json(n.span)}});
    return a;
  };
  Json spans = Json::array();
  for (const Span& s : in.exclusivity.spans) spans.push_back(span_json(s));
  Json density = Json::array();
  for (const DensityWord& d : in.density)
    density.push_back(Json{{"word", d.word}, {"level", d.level}, {"span", span_json(d.span)}});
  Json robots = Json::array();
  for (const RobotMention& r : in.robots)
    robots.push_back(Json{{"words", r.words}, {"count", to_json(r.count)}, {"span", span_json(r.span)}});
  Json categories = Json::array();
  for (const CategoryMention& c : in.categories)
    categories.push_back(
        Json{{"category", std::string(to_string(c.category))}, {"score", c.score}, {"phrases", c.phrases}});
  Json warnings = Json::array();
  for (const IntentWarning& w : in.warnings) {
    Json j{{"message", w.message}};
    if (w.span.end > 0) j["span"] = span_json(w.span);
    warnings.push_back(std::move(j));
  }
  Json out{
      {"version", 1},
      {"prompt", in.prompt},
      {"groups", groups},
      {"total", to_json(in.total())},
      {"world",
       {{"features", features}, {"rooms", things(in.world.rooms)}, {"objects", things(in.world.objects)}}},
      {"exclusivity",
       {{"exclusive", in.exclusivity.exclusive},
        {"phrases", in.exclusivity.phrases},
        {"spans", spans},
        {"excluded_roles", in.exclusivity.excluded_roles}}},
      {"background", {{"requested", in.background}, {"words", in.background_words}}},
      {"density", density},
      {"robots", robots},
      {"categories", categories},
      {"warnings", warnings}};
  if (in.venue)
    out["venue"] = Json{{"type", in.venue->type},
                        {"building_type", in.venue->building_type},
                        {"words", in.venue->words},
                        {"why", in.venue->why},
                        {"span", span_json(in.venue->span)}};
  else
    out["venue"] = nullptr;
  return out;
}

}  // namespace socsim::scenario
