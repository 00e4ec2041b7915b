#include "core/scenario/lexicon.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace socsim::scenario {

namespace {

using C = Category;

constexpr std::array<Category, 7> kCategories = {C::kEmergency,      C::kQueuing,   C::kSocialParty,
                                                 C::kCoffeeBreak,    C::kReception, C::kBottleneck,
                                                 C::kNormalOperation};

// Weights: 1.0 for the category's own word, more for unambiguous phrases, less for words that
// also occur in other settings ("break", "counter", "work").
const std::vector<CategoryPhrase> kCategoryPhrases = {
    // emergency
    {"emergency", C::kEmergency, 1.0},
    {"evacuation", C::kEmergency, 1.1},
    {"evacuate", C::kEmergency, 1.1},
    {"evacuates", C::kEmergency, 1.1},
    {"evacuating", C::kEmergency, 1.1},
    {"fire alarm", C::kEmergency, 1.3},
    {"fire drill", C::kEmergency, 1.3},
    {"alarm", C::kEmergency, 0.9},
    {"alarms", C::kEmergency, 0.9},
    {"fire", C::kEmergency, 0.8},
    {"drill", C::kEmergency, 0.6},
    {"smoke", C::kEmergency, 0.7},
    {"panic", C::kEmergency, 0.8},
    {"escape", C::kEmergency, 0.7},
    {"flee", C::kEmergency, 0.8},
    {"fleeing", C::kEmergency, 0.8},
    {"leave the building", C::kEmergency, 0.9},
    {"get out", C::kEmergency, 0.6},
    {"rush out", C::kEmergency, 0.8},
    {"run for the exits", C::kEmergency, 1.0},
    {"exits", C::kEmergency, 0.3},
    // queuing
    {"queue", C::kQueuing, 1.0},
    {"queues", C::kQueuing, 1.0},
    {"queuing", C::kQueuing, 1.0},
    {"queueing", C::kQueuing, 1.0},
    {"queued", C::kQueuing, 1.0},
    {"line up", C::kQueuing, 1.0},
    {"lines up", C::kQueuing, 1.0},
    {"lining up", C::kQueuing, 1.0},
    {"in line", C::kQueuing, 0.9},
    {"in a line", C::kQueuing, 0.9},
    {"waiting in line", C::kQueuing, 1.2},
    {"stand in line", C::kQueuing, 1.2},
    {"form a line", C::kQueuing, 1.1},
    {"wait their turn", C::kQueuing, 0.9},
    {"take turns", C::kQueuing, 0.7},
    {"water dispenser", C::kQueuing, 0.3},
    {"elevator", C::kQueuing, 0.3},
    // social / home party
    {"party", C::kSocialParty, 1.1},
    {"parties", C::kSocialParty, 1.1},
    {"house party", C::kSocialParty, 1.3},
    {"home party", C::kSocialParty, 1.3},
    {"gathering", C::kSocialParty, 0.9},
    {"get together", C::kSocialParty, 1.0},
    {"celebration", C::kSocialParty, 1.0},
    {"celebrate", C::kSocialParty, 1.0},
    {"celebrating", C::kSocialParty, 1.0},
    {"birthday", C::kSocialParty, 0.9},
    {"mingle", C::kSocialParty, 1.0},
    {"mingling", C::kSocialParty, 1.0},
    {"socialize", C::kSocialParty, 0.8},
    {"socialise", C::kSocialParty, 0.8},
    {"dancing", C::kSocialParty, 0.7},
    {"dance", C::kSocialParty, 0.6},
    {"guests", C::kSocialParty, 0.5},
    {"friends", C::kSocialParty, 0.3},
    {"at home", C::kSocialParty, 0.4},
    // coffee break
    {"coffee break", C::kCoffeeBreak, 1.4},
    {"coffee", C::kCoffeeBreak, 0.9},
    {"coffee machine", C::kCoffeeBreak, 1.1},
    {"break room", C::kCoffeeBreak, 1.0},
    {"breakroom", C::kCoffeeBreak, 1.0},
    {"break", C::kCoffeeBreak, 0.5},
    {"lunch break", C::kCoffeeBreak, 0.9},
    {"tea", C::kCoffeeBreak, 0.5},
    {"water cooler", C::kCoffeeBreak, 0.9},
    {"kitchenette", C::kCoffeeBreak, 0.6},
    {"chat", C::kCoffeeBreak, 0.8},
    {"chats", C::kCoffeeBreak, 0.8},
    {"chatting", C::kCoffeeBreak, 0.8},
    {"small talk", C::kCoffeeBreak, 0.9},
    {"stop and chat", C::kCoffeeBreak, 1.1},
    {"brief exchange", C::kCoffeeBreak, 0.8},
    {"talk", C::kCoffeeBreak, 0.4},
    {"talking", C::kCoffeeBreak, 0.4},
    {"loiter", C::kCoffeeBreak, 0.5},
    // reception / check-in
    {"reception", C::kReception, 1.0},
    {"check in", C::kReception, 1.1},
    {"checks in", C::kReception, 1.1},
    {"checking in", C::kReception, 1.1},
    {"checkin", C::kReception, 1.1},
    {"front desk", C::kReception, 1.1},
    {"help desk", C::kReception, 0.9},
    {"information desk", C::kReception, 0.9},
    {"registration", C::kReception, 1.0},
    {"register", C::kReception, 0.9},
    {"registering", C::kReception, 0.9},
    {"sign in", C::kReception, 0.8},
    {"admission", C::kReception, 0.8},
    {"admissions", C::kReception, 0.8},
    {"receptionist", C::kReception, 0.6},
    {"counter", C::kReception, 0.4},
    {"arrive", C::kReception, 0.3},
    {"arriving", C::kReception, 0.3},
    {"arrivals", C::kReception, 0.3},
    // bottleneck
    {"bottleneck", C::kBottleneck, 1.3},
    {"narrow door", C::kBottleneck, 1.2},
    {"narrow doorway", C::kBottleneck, 1.2},
    {"narrow", C::kBottleneck, 0.7},
    {"doorway", C::kBottleneck, 0.8},
    {"squeeze", C::kBottleneck, 1.0},
    {"squeezing", C::kBottleneck, 1.0},
    {"squeezes", C::kBottleneck, 1.0},
    {"rush through", C::kBottleneck, 1.1},
    {"push through", C::kBottleneck, 1.1},
    {"pushing", C::kBottleneck, 0.7},
    {"congestion", C::kBottleneck, 1.0},
    {"congested", C::kBottleneck, 1.0},
    {"crowding", C::kBottleneck, 0.8},
    {"jam", C::kBottleneck, 0.8},
    {"door block", C::kBottleneck, 1.1},
    {"block the door", C::kBottleneck, 1.1},
    {"blocking the door", C::kBottleneck, 1.1},
    {"choke point", C::kBottleneck, 1.1},
    {"chokepoint", C::kBottleneck, 1.1},
    {"through the door", C::kBottleneck, 0.8},
    {"through one door", C::kBottleneck, 1.0},
    {"single door", C::kBottleneck, 0.9},
    {"funnel", C::kBottleneck, 0.7},
    // normal operation
    {"normal operation", C::kNormalOperation, 1.3},
    {"normal", C::kNormalOperation, 0.6},
    {"routine", C::kNormalOperation, 1.0},
    {"everyday", C::kNormalOperation, 0.9},
    {"everyday traffic", C::kNormalOperation, 1.3},
    {"business as usual", C::kNormalOperation, 1.3},
    {"typical day", C::kNormalOperation, 1.0},
    {"daily", C::kNormalOperation, 0.6},
    {"ordinary", C::kNormalOperation, 0.7},
    {"regular", C::kNormalOperation, 0.5},
    {"traffic", C::kNormalOperation, 0.5},
    {"work", C::kNormalOperation, 0.5},
    {"working", C::kNormalOperation, 0.5},
    {"walk around", C::kNormalOperation, 0.5},
    {"walking around", C::kNormalOperation, 0.5},
    {"go about", C::kNormalOperation, 0.7},
    {"commute", C::kNormalOperation, 0.5},
    {"dinner", C::kNormalOperation, 0.5},
    {"shift", C::kNormalOperation, 0.4},
    // everyday words for waiting, gathering, registering, pushing and walking
    {"wait", C::kQueuing, 0.6},
    {"waits", C::kQueuing, 0.6},
    {"waiting", C::kQueuing, 0.6},
    {"waiting room", C::kQueuing, 0.9},
    {"a line of", C::kQueuing, 0.9},
    {"gather", C::kSocialParty, 0.9},
    {"gathers", C::kSocialParty, 0.9},
    {"gathered", C::kSocialParty, 0.8},
    {"dances", C::kSocialParty, 0.8},
    {"signs in", C::kReception, 0.9},
    {"registers", C::kReception, 0.9},
    {"greets", C::kReception, 0.8},
    {"crowd the", C::kBottleneck, 0.6},
    {"pour out", C::kBottleneck, 1.0},
    {"walk", C::kNormalOperation, 0.4},
    {"walks", C::kNormalOperation, 0.4},
    {"reading", C::kNormalOperation, 0.4},
};

const std::vector<RoleWord> kRoleWords = {
    {"nurse", "nurse"},
    {"nurses", "nurse"},
    {"doctor", "doctor"},
    {"doctors", "doctor"},
    {"physician", "doctor"},
    {"physicians", "doctor"},
    {"surgeon", "doctor"},
    {"surgeons", "doctor"},
    {"visitor", "visitor"},
    {"visitors", "visitor"},
    {"patient", "patient"},
    {"patients", "patient"},
    {"staff member", "staff"},
    {"staff members", "staff"},
    {"staff", "staff"},
    {"employee", "worker"},
    {"employees", "worker"},
    {"worker", "worker"},
    {"workers", "worker"},
    {"office worker", "worker"},
    {"office workers", "worker"},
    {"colleague", "worker"},
    {"colleagues", "worker"},
    {"coworker", "worker"},
    {"coworkers", "worker"},
    {"receptionist", "receptionist"},
    {"receptionists", "receptionist"},
    {"clerk", "receptionist"},
    {"clerks", "receptionist"},
    {"guest", "guest"},
    {"guests", "guest"},
    {"customer", "customer"},
    {"customers", "customer"},
    {"shopper", "customer"},
    {"shoppers", "customer"},
    {"client", "customer"},
    {"clients", "customer"},
    {"child", "child"},
    {"children", "child"},
    {"kid", "child"},
    {"kids", "child"},
    {"elderly", "elderly"},
    {"elderly people", "elderly"},
    {"senior", "elderly"},
    {"seniors", "elderly"},
    {"pensioner", "elderly"},
    {"pensioners", "elderly"},
    {"jogger", "jogger"},
    {"joggers", "jogger"},
    {"runner", "jogger"},
    {"runners", "jogger"},
    {"student", "student"},
    {"students", "student"},
    {"resident", "resident"},
    {"residents", "resident"},
    {"family members", "resident"},
    {"security guard", "security"},
    {"security guards", "security"},
    {"guard", "security"},
    {"guards", "security"},
    {"passenger", "passenger"},
    {"passengers", "passenger"},
    {"person", "adult"},
    {"persons", "adult"},
    {"people", "adult"},
    {"pedestrian", "adult"},
    {"pedestrians", "adult"},
    {"adult", "adult"},
    {"adults", "adult"},
    {"individuals", "adult"},
    {"occupants", "adult"},
    {"agent", "adult"},
    {"agents", "adult"},
};

// Desired speeds from the pedestrian literature's ranges (healthy adults ~1.3 m/s, patients and
// children slower, staff on duty brisker); radii of an adult shoulder half-width, smaller for children.
// Minima: the slow end of walking speeds observed for each group (patients and residents with
// reduced mobility walk at 0.4–0.6 m/s; the engine takes any speed ≥ 0.3 m/s through a 0.9 m door).
const std::vector<RoleProfile> kRoleProfiles = {
    {"nurse", 1.40, 0.18, 0.8, 2.0, 0.28},     {"doctor", 1.35, 0.18, 0.8, 2.0, 0.28},
    {"visitor", 1.20, 0.22, 0.6, 1.8, 0.30},   {"patient", 0.95, 0.20, 0.4, 1.5, 0.30},
    {"worker", 1.30, 0.20, 0.7, 2.0, 0.30},    {"receptionist", 1.20, 0.15, 0.7, 1.8, 0.28},
    {"guest", 1.10, 0.22, 0.5, 1.8, 0.30},     {"customer", 1.20, 0.22, 0.6, 1.8, 0.30},
    {"child", 1.05, 0.25, 0.5, 1.9, 0.22},     {"student", 1.35, 0.22, 0.7, 2.1, 0.28},
    {"resident", 1.15, 0.22, 0.5, 1.8, 0.30},  {"security", 1.35, 0.15, 0.8, 2.2, 0.32},
    {"passenger", 1.25, 0.25, 0.6, 2.0, 0.32},
};

const std::vector<CountWord> kCountWords = {
    {"one", 1, false, false},
    {"single", 1, false, false},
    {"two", 2, false, false},
    {"three", 3, false, false},
    {"four", 4, false, false},
    {"five", 5, false, false},
    {"six", 6, false, false},
    {"seven", 7, false, false},
    {"eight", 8, false, false},
    {"nine", 9, false, false},
    {"ten", 10, false, false},
    {"eleven", 11, false, false},
    {"twelve", 12, false, false},
    {"thirteen", 13, false, false},
    {"fourteen", 14, false, false},
    {"fifteen", 15, false, false},
    {"sixteen", 16, false, false},
    {"seventeen", 17, false, false},
    {"eighteen", 18, false, false},
    {"nineteen", 19, false, false},
    {"twenty", 20, false, false},
    {"thirty", 30, false, false},
    {"forty", 40, false, false},
    {"fifty", 50, false, false},
    {"sixty", 60, false, false},
    {"seventy", 70, false, false},
    {"eighty", 80, false, false},
    {"ninety", 90, false, false},
    {"hundred", 100, false, true},
    {"dozen", 12, false, true},
    {"a hundred", 100, false, false},
    {"a dozen", 12, false, false},
    {"dozens of", 24, true, false},
    {"hundreds of", 200, true, false},
    {"a couple of", 2, false, false},
    {"a couple", 2, false, false},
    {"couple of", 2, false, false},
    {"a pair of", 2, false, false},
    {"pair of", 2, false, false},
    {"a few", 3, true, false},
    {"few", 3, true, false},
    {"a handful of", 4, true, false},
    {"several", 5, true, false},
    {"some", 4, true, false},
    {"many", 15, true, false},
    {"lots of", 20, true, false},
    {"a lot of", 20, true, false},
    {"numerous", 15, true, false},
    {"a group of", 4, true, false},
    {"a small group of", 3, true, false},
    {"a large group of", 10, true, false},
    {"a crowd of", 40, true, false},
    {"a large crowd of", 80, true, false},
    {"a big crowd of", 80, true, false},
    {"crowd of", 40, true, false},
    {"a crowd", 40, true, false},
    {"a large crowd", 80, true, false},
    {"a", 1, false, false},
    {"an", 1, false, false},
    {"a lone", 1, false, false},
};

const std::vector<std::string_view> kApproximation = {
    "more than", "up to",  "at least", "no more than", "about", "around", "roughly", "approximately",
    "approx",    "nearly", "almost",   "some",         "circa", "maybe",  "perhaps", "over"};

const std::vector<PlacePhrase> kPlacePhrases = {
    {"elevator",
     {"elevator", "lift"},
     {},
     {"elevator_lobby", "elevator"},
     false,
     false,
     {"elevator", "lift"}},
    {"elevators",
     {"elevator", "lift"},
     {},
     {"elevator_lobby", "elevator"},
     false,
     false,
     {"elevator", "lift"}},
    {"lift", {"elevator", "lift"}, {}, {"elevator_lobby", "elevator"}, false, false, {"elevator", "lift"}},
    {"reception desk",
     {"counter"},
     {"queue_lane", "counter_area"},
     {"reception", "lobby"},
     false,
     false,
     {"reception"}},
    {"reception counter",
     {"counter"},
     {"queue_lane", "counter_area"},
     {"reception", "lobby"},
     false,
     false,
     {"reception"}},
    {"front desk",
     {"counter"},
     {"queue_lane", "counter_area"},
     {"reception", "lobby"},
     false,
     false,
     {"reception"}},
    {"check in",
     {"counter"},
     {"queue_lane", "counter_area"},
     {"reception", "lobby"},
     false,
     false,
     {"reception"}},
    {"registration desk", {"counter"}, {"queue_lane"}, {"reception", "lobby"}, false, false, {"reception"}},
    {"reception",
     {"counter"},
     {"queue_lane", "counter_area"},
     {"reception", "lobby"},
     false,
     false,
     {"reception"}},
    {"information desk",
     {"counter"},
     {"queue_lane"},
     {"concourse", "lobby", "reception"},
     false,
     false,
     {"info", "reception"}},
    {"counter", {"counter"}, {"queue_lane", "counter_area"}, {}, false, false, {"counter"}},
    {"checkout", {"counter"}, {"queue_lane"}, {"sales_floor"}, false, false, {"checkout"}},
    {"nurse station", {"counter"}, {}, {"nurse_station"}, false, false, {"nurse"}},
    {"nurses station", {"counter"}, {}, {"nurse_station"}, false, false, {"nurse"}},
    {"water dispenser", {"water_dispenser"}, {}, {}, false, false, {"water"}},
    {"water cooler", {"water_dispenser"}, {}, {}, false, false, {"water"}},
    {"water fountain", {"water_dispenser"}, {}, {}, false, false, {"water"}},
    {"drinking fountain", {"water_dispenser"}, {}, {}, false, false, {"water"}},
    {"water", {"water_dispenser"}, {}, {}, false, false, {"water"}},
    {"vending machine", {"vending_machine"}, {}, {}, false, false, {"vending"}},
    {"vending machines", {"vending_machine"}, {}, {}, false, false, {"vending"}},
    {"snack machine", {"vending_machine"}, {}, {}, false, false, {"vending", "snack"}},
    {"coffee machine",
     {"coffee_machine"},
     {},
     {"kitchenette", "break_room", "staff_room"},
     false,
     false,
     {"coffee"}},
    {"coffee", {"coffee_machine"}, {}, {"kitchenette", "break_room", "staff_room"}, false, false, {"coffee"}},
    {"break room", {}, {}, {"break_room", "staff_room", "kitchenette"}, false, false, {"break"}},
    {"staff room", {}, {}, {"staff_room", "break_room"}, false, false, {"staff"}},
    {"kitchenette", {}, {}, {"kitchenette", "break_room"}, false, false, {"kitchenette"}},
    {"kitchen", {}, {}, {"kitchen", "kitchenette"}, false, false, {"kitchen"}},
    {"canteen", {}, {"seating_area"}, {"dining_hall", "canteen"}, false, false, {"canteen", "dining"}},
    {"cafeteria", {}, {"seating_area"}, {"dining_hall", "canteen", "cafe"}, false, false, {"dining", "cafe"}},
    {"dining room", {"dining_table"}, {}, {"dining_room"}, false, false, {"dining"}},
    {"corridor intersection", {}, {"corridor"}, {"corridor", "hallway"}, false, false, {"corridor"}},
    {"corridor", {}, {"corridor"}, {"corridor", "hallway"}, false, false, {"corridor"}},
    {"corridors", {}, {"corridor"}, {"corridor", "hallway"}, false, false, {"corridor"}},
    {"hallway", {}, {"corridor"}, {"hallway", "corridor"}, false, false, {"hallway", "corridor"}},
    {"hall", {}, {"corridor"}, {"hallway", "corridor", "concourse"}, false, false, {"hall"}},
    {"living room", {"sofa"}, {"seating_area"}, {"living_room"}, false, false, {"living"}},
    {"lounge", {"sofa"}, {"seating_area"}, {"living_room", "lounge"}, false, false, {"lounge", "living"}},
    {"sofa", {"sofa"}, {}, {}, false, false, {"sofa"}},
    {"couch", {"sofa"}, {}, {}, false, false, {"sofa"}},
    {"table", {"table", "dining_table", "meeting_table", "coffee_table"}, {}, {}, false, false, {"table"}},
    {"bedroom", {"bed"}, {}, {"bedroom"}, false, false, {"bedroom"}},
    {"waiting room",
     {"chair"},
     {"waiting_zone", "seating_area"},
     {"waiting_room"},
     false,
     false,
     {"waiting"}},
    {"waiting area",
     {"chair"},
     {"waiting_zone", "seating_area"},
     {"waiting_room", "lobby"},
     false,
     false,
     {"waiting"}},
    {"lobby", {}, {"waiting_zone", "entrance"}, {"lobby", "reception"}, false, false, {"lobby"}},
    {"main entrance", {}, {"entrance"}, {}, true, true, {"entrance"}},
    {"entrance", {}, {"entrance"}, {}, true, true, {"entrance"}},
    {"front door", {}, {"entrance"}, {}, true, true, {"entrance"}},
    {"exit", {}, {"exit", "entrance"}, {}, true, true, {"exit", "entrance"}},
    {"exits", {}, {"exit", "entrance"}, {}, true, true, {"exit", "entrance"}},
    {"emergency exit", {}, {"exit"}, {}, true, true, {"exit"}},
    {"assembly point", {}, {"assembly_zone"}, {}, false, false, {"assembly"}},
    {"doorway", {}, {}, {}, true, false, {"door"}},
    {"door", {}, {}, {}, true, false, {"door"}},
    {"narrow door", {}, {}, {}, true, false, {"door"}},
    {"office",
     {"desk"},
     {"work_area"},
     {"open_office", "private_office", "office"},
     false,
     false,
     {"office"}},
    {"open office", {"desk"}, {"work_area"}, {"open_office"}, false, false, {"office"}},
    {"desks", {"desk"}, {"work_area"}, {"open_office"}, false, false, {"desk"}},
    {"desk", {"desk"}, {"work_area"}, {}, false, false, {"desk"}},
    {"meeting room", {"meeting_table"}, {}, {"meeting_room"}, false, false, {"meeting"}},
    {"patient room", {"bed"}, {}, {"patient_room"}, false, false, {"patient"}},
    {"patient rooms", {"bed"}, {}, {"patient_room"}, false, false, {"patient"}},
    {"ward", {"bed"}, {}, {"patient_room"}, false, false, {"patient"}},
    {"treatment room", {"exam_table"}, {}, {"treatment_room"}, false, false, {"treatment"}},
    {"toilet", {"toilet"}, {}, {"toilet", "bathroom"}, false, false, {"toilet"}},
    {"toilets", {"toilet"}, {}, {"toilet", "bathroom"}, false, false, {"toilet"}},
    {"bathroom", {"toilet"}, {}, {"bathroom", "toilet"}, false, false, {"bathroom"}},
    {"restroom", {"toilet"}, {}, {"toilet", "bathroom"}, false, false, {"toilet"}},
    {"aisle", {}, {"walkway"}, {"warehouse_floor", "sales_floor"}, false, false, {"aisle"}},
    {"aisles", {}, {"walkway"}, {"warehouse_floor", "sales_floor"}, false, false, {"aisle"}},
    {"loading bay", {"pallet"}, {"work_area"}, {"loading_bay"}, false, false, {"loading", "dock"}},
    {"warehouse floor", {"rack"}, {"walkway"}, {"warehouse_floor"}, false, false, {"warehouse"}},
    {"classroom", {"desk"}, {}, {"classroom"}, false, false, {"classroom"}},
    {"gate", {"counter"}, {"queue_lane"}, {"gate_area"}, false, false, {"gate"}},
};

const std::vector<std::string_view> kPrepositions = {
    "in front of", "next to", "close to", "on the way to", "at",     "near",    "in",     "inside",
    "by",          "around",  "to",       "into",          "from",   "towards", "toward", "beside",
    "outside",     "through", "along",    "past",          "behind", "across"};

const std::vector<std::string_view> kEmergencyNodes = {"ReactiveFallback", "Sequence", "TimeExpired",
                                                       "Evacuate", "Wander"};
const std::vector<std::string_view> kQueuingNodes = {"Sequence", "Fallback", "JoinQueue",   "ServeAtCounter",
                                                     "SitAt",    "WaitAt",   "LookAtPoint", "StopAndWait"};
const std::vector<std::string_view> kPartyNodes = {"Sequence", "Repeat", "Gather", "Wander"};
const std::vector<std::string_view> kCoffeeNodes = {"Sequence", "Gather", "Wander"};
const std::vector<std::string_view> kReceptionNodes = {"Sequence", "JoinQueue",   "ServeAtCounter", "GoTo",
                                                       "Evacuate", "LookAtPoint", "StopAndWait"};
const std::vector<std::string_view> kBottleneckNodes = {"FollowVelocityField", "Sequence", "GoTo",
                                                        "Evacuate"};
const std::vector<std::string_view> kNormalNodes = {"Sequence", "Fallback", "GoTo",
                                                    "SitAt",    "WaitAt",   "Wander"};

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '\'';
}

}  // namespace

std::span<const Category> all_categories() {
  return kCategories;
}

std::string_view to_string(Category c) {
  switch (c) {
    case C::kEmergency:
      return "emergency";
    case C::kQueuing:
      return "queuing";
    case C::kSocialParty:
      return "social_party";
    case C::kCoffeeBreak:
      return "coffee_break";
    case C::kReception:
      return "reception";
    case C::kBottleneck:
      return "bottleneck";
    case C::kNormalOperation:
      return "normal_operation";
  }
  return "normal_operation";
}

std::optional<Category> category_from_string(std::string_view s) {
  for (Category c : kCategories)
    if (to_string(c) == s) return c;
  return std::nullopt;
}

std::vector<Token> tokenize(std::string_view prompt) {
  std::vector<Token> out;
  std::size_t clause = 0;
  std::size_t i = 0;
  bool clause_has_words = false;
  auto end_clause = [&] {
    if (clause_has_words) ++clause;
    clause_has_words = false;
  };
  while (i < prompt.size()) {
    const char c = prompt[i];
    if (c == ',' || c == ';' || c == ':' || c == '!' || c == '?' || c == '(' || c == ')') {
      end_clause();
      ++i;
      continue;
    }
    if (!is_word_char(c) || c == '.' || c == '\'') {
      // A full stop ends a clause unless it is a decimal point (handled inside numbers).
      if (c == '.') end_clause();
      ++i;
      continue;
    }
    std::size_t j = i;
    bool digits = std::isdigit(static_cast<unsigned char>(c)) != 0;
    while (j < prompt.size()) {
      const char d = prompt[j];
      if (std::isalnum(static_cast<unsigned char>(d)) != 0) {
        if (std::isdigit(static_cast<unsigned char>(d)) == 0) digits = false;
        ++j;
      } else if (d == '.' && digits && j + 1 < prompt.size() &&
                 std::isdigit(static_cast<unsigned char>(prompt[j + 1])) != 0) {
        ++j;  // decimal point
      } else if (d == '\'' && j + 1 < prompt.size() &&
                 std::isalpha(static_cast<unsigned char>(prompt[j + 1])) != 0) {
        ++j;  // apostrophe inside a word (don't, nurse's)
      } else {
        break;
      }
    }
    std::string word;
    for (std::size_t k = i; k < j; ++k)
      word.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(prompt[k]))));
    if (word.size() > 2 && word.ends_with("'s")) word.resize(word.size() - 2);
    if (word == "while" || word == "whereas" || word == "meanwhile" || word == "then" || word == "whilst") {
      end_clause();
    } else {
      out.push_back(Token{word, i, clause, digits});
      clause_has_words = true;
    }
    i = j;
  }
  return out;
}

std::span<const CategoryPhrase> category_phrases() {
  return kCategoryPhrases;
}
std::span<const RoleWord> role_words() {
  return kRoleWords;
}

std::optional<RoleProfile> role_profile(std::string_view role) {
  for (const RoleProfile& p : kRoleProfiles)
    if (p.role == role) return p;
  return std::nullopt;
}

bool is_builtin_role(std::string_view role) {
  return role == "adult" || role == "elderly" || role == "staff" || role == "jogger" ||
         role == "stroller_pusher";
}

std::span<const CountWord> count_words() {
  return kCountWords;
}

std::span<const std::string_view> approximation_phrases() {
  return kApproximation;
}

std::span<const PlacePhrase> place_phrases() {
  return kPlacePhrases;
}
std::span<const std::string_view> place_prepositions() {
  return kPrepositions;
}

std::string_view node_query(Category c) {
  switch (c) {
    case C::kEmergency:
      return "evacuate to the nearest exit when the fire alarm sounds, emergency leave building";
    case C::kQueuing:
      return "join a queue lane, wait in line, advance, be served at the counter";
    case C::kSocialParty:
      return "gather in a group and talk, cluster, wander around the room, party";
    case C::kCoffeeBreak:
      return "gather near a point with colleagues, chat, then continue walking";
    case C::kReception:
      return "walk to the reception counter, queue, be served, register, then leave";
    case C::kBottleneck:
      return "follow a velocity field crowd flow through a door, go to a place";
    case C::kNormalOperation:
      return "walk to a place, sit at a desk or seat, wait, wander around a region";
  }
  return "";
}

std::span<const std::string_view> category_nodes(Category c) {
  switch (c) {
    case C::kEmergency:
      return kEmergencyNodes;
    case C::kQueuing:
      return kQueuingNodes;
    case C::kSocialParty:
      return kPartyNodes;
    case C::kCoffeeBreak:
      return kCoffeeNodes;
    case C::kReception:
      return kReceptionNodes;
    case C::kBottleneck:
      return kBottleneckNodes;
    case C::kNormalOperation:
      return kNormalNodes;
  }
  return {};
}

}  // namespace socsim::scenario
