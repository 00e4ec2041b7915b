#include "core/floorplan/rooms.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace socsim::floorplan {
namespace {

using C = Circulation;

// Typical areas are what plans of that kind usually give the room (net, m²); the generator
// draws from [area_lo, area_hi] and then raises the result to the code minima it retrieved.
constexpr std::array kRoomTypes = {
    // dwellings
    RoomType{"living_room", "living room", C::kNone, true, "residential", 18, 28},
    RoomType{"kitchen", "kitchen", C::kNone, false, "commercial_kitchen", 8, 13},
    RoomType{"bedroom", "bedroom", C::kNone, true, "residential", 9, 13},
    RoomType{"bathroom", "bathroom", C::kNone, false, "", 4.2, 6.5},
    RoomType{"hallway", "hallway", C::kCorridor, false, "", 0, 0},
    RoomType{"storage", "storage room", C::kNone, false, "stock_storage", 2.6, 3.6},
    RoomType{"dining_room", "dining room", C::kNone, true, "residential", 10, 14},
    RoomType{"study", "study", C::kNone, true, "residential", 7, 10},
    // offices
    RoomType{"open_office", "open-plan office", C::kNone, false, "business", 55, 90},
    RoomType{"private_office", "private office", C::kNone, false, "business", 10, 14},
    RoomType{"meeting_room", "meeting room", C::kNone, false, "business", 13, 20},
    RoomType{"reception", "reception", C::kNone, false, "waiting", 18, 26},
    RoomType{"kitchenette", "kitchenette", C::kNone, false, "", 8, 12},
    RoomType{"toilet", "toilet", C::kNone, false, "", 3.2, 4.5},
    RoomType{"corridor", "corridor", C::kCorridor, false, "", 0, 0},
    // health care
    RoomType{"lobby", "lobby", C::kNone, false, "waiting", 32, 46},
    RoomType{"waiting_room", "waiting room", C::kNone, false, "waiting", 16, 26},
    RoomType{"patient_room", "patient room", C::kNone, false, "sleeping", 16, 21},
    RoomType{"nurse_station", "nurse station", C::kNone, false, "outpatient", 10, 14},
    RoomType{"treatment_room", "treatment room", C::kNone, false, "outpatient", 13, 18},
    RoomType{"icu_room", "ICU room", C::kNone, false, "inpatient_treatment", 26, 32},
    // canteens, shops, warehouses, schools, airports
    RoomType{"dining_hall", "dining hall", C::kHall, false, "dining", 90, 150},
    RoomType{"sales_floor", "sales floor", C::kHall, false, "mercantile", 110, 180},
    RoomType{"stock_room", "stock room", C::kNone, false, "stock_storage", 12, 20},
    RoomType{"warehouse_floor", "warehouse floor", C::kHall, false, "warehouse", 220, 360},
    RoomType{"loading_bay", "loading bay", C::kNone, false, "warehouse", 26, 40},
    RoomType{"break_room", "break room", C::kNone, false, "dining", 12, 18},
    RoomType{"classroom", "classroom", C::kNone, false, "classroom", 50, 64},
    RoomType{"staff_room", "staff room", C::kNone, false, "business", 18, 26},
    RoomType{"concourse", "concourse", C::kHall, false, "concourse", 160, 260},
    RoomType{"gate_area", "gate area", C::kNone, false, "waiting", 40, 60},
    RoomType{"cafe", "cafe", C::kNone, false, "dining", 26, 36},
    RoomType{"security", "security checkpoint", C::kNone, false, "waiting", 30, 40},
    // stations
    RoomType{"ticket_hall", "ticket hall", C::kNone, false, "waiting", 70, 120},
    RoomType{"platform", "platform", C::kNone, false, "waiting", 140, 220},
    // hotels, care homes
    RoomType{"hotel_room", "hotel room", C::kNone, false, "hotel", 16, 24},
    RoomType{"resident_room", "resident's room", C::kNone, false, "sleeping", 14, 18},
    RoomType{"day_room", "day room", C::kNone, false, "dining", 30, 45},
    // libraries, museums
    RoomType{"reading_room", "reading room", C::kHall, false, "reading", 120, 200},
    RoomType{"library_stacks", "stacks", C::kNone, false, "stacks", 40, 70},
    RoomType{"study_room", "study room", C::kNone, false, "reading", 10, 16},
    RoomType{"gallery", "gallery", C::kNone, false, "exhibit", 45, 80},
    // theatres, arenas, universities
    RoomType{"foyer", "foyer", C::kHall, false, "waiting", 90, 150},
    RoomType{"auditorium", "auditorium", C::kNone, false, "concentrated_seating", 140, 260},
    RoomType{"backstage", "backstage", C::kNone, false, "stage", 20, 35},
    RoomType{"arena_floor", "arena floor", C::kNone, false, "standing", 600, 1000},
    RoomType{"concession", "concession stand", C::kNone, false, "mercantile", 10, 16},
    RoomType{"first_aid", "first-aid room", C::kNone, false, "outpatient", 10, 15},
    RoomType{"lecture_hall", "lecture hall", C::kNone, false, "concentrated_seating", 110, 180},
    RoomType{"seminar_room", "seminar room", C::kNone, false, "classroom", 35, 50},
    // factories, malls, restaurants
    RoomType{"production_floor", "production floor", C::kHall, false, "industrial", 300, 500},
    RoomType{"locker_room", "locker room", C::kNone, false, "locker_room", 14, 22},
    RoomType{"mall_concourse", "mall concourse", C::kHall, false, "", 200, 320},
    RoomType{"shop_unit", "shop", C::kNone, false, "mercantile", 40, 70},
    RoomType{"food_court", "food court", C::kNone, false, "dining", 120, 180},
    RoomType{"restaurant", "restaurant", C::kHall, false, "dining", 70, 120},
    // sports halls, community halls
    RoomType{"sports_hall", "sports hall", C::kNone, false, "exercise", 300, 420},
    RoomType{"fitness_room", "fitness room", C::kNone, false, "exercise", 60, 90},
    RoomType{"changing_room", "changing room", C::kNone, false, "locker_room", 16, 24},
    RoomType{"main_hall", "main hall", C::kHall, false, "unconcentrated", 120, 200},
};

constexpr std::array<std::pair<std::string_view, std::string_view>, 52> kSynonyms = {{
    {"guest_room", "hotel_room"},
    {"bedroom_suite", "hotel_room"},
    {"resident_bedroom", "resident_room"},
    {"lounge_area", "day_room"},
    {"common_room", "day_room"},
    {"ticket_office", "ticket_hall"},
    {"booking_hall", "ticket_hall"},
    {"track", "platform"},
    {"exhibition_room", "gallery"},
    {"exhibition_hall", "gallery"},
    {"stacks", "library_stacks"},
    {"book_stacks", "library_stacks"},
    {"lobby_hall", "foyer"},
    {"cinema_hall", "auditorium"},
    {"screen_room", "auditorium"},
    {"theatre_hall", "auditorium"},
    {"concert_hall", "auditorium"},
    {"kiosk", "concession"},
    {"lecture_theatre", "lecture_hall"},
    {"workshop", "production_floor"},
    {"shop", "shop_unit"},
    {"store_unit", "shop_unit"},
    {"gym_hall", "sports_hall"},
    {"gymnasium", "sports_hall"},
    {"fitness_studio", "fitness_room"},
    {"dressing_room", "changing_room"},
    {"assembly_hall", "main_hall"},
    {"polling_hall", "main_hall"},
    {"living", "living_room"},
    {"lounge", "living_room"},
    {"bed_room", "bedroom"},
    {"hallways", "hallway"},
    {"passage", "hallway"},
    {"restroom", "toilet"},
    {"wc", "toilet"},
    {"washroom", "toilet"},
    {"ward", "patient_room"},
    {"patient_bedroom", "patient_room"},
    {"exam_room", "treatment_room"},
    {"examination_room", "treatment_room"},
    {"consultation_room", "treatment_room"},
    {"office", "private_office"},
    {"conference_room", "meeting_room"},
    {"canteen", "dining_hall"},
    {"dining_area", "dining_hall"},
    {"shop_floor", "sales_floor"},
    {"stockroom", "stock_room"},
    {"store_room", "storage"},
    {"waiting_area", "waiting_room"},
    {"icu", "icu_room"},
    {"gate", "gate_area"},
    {"entrance_hall", "lobby"},
}};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (char& c : out)
    if (c == ' ' || c == '-') c = '_';
  return out;
}

}  // namespace

std::span<const RoomType> room_types() {
  return kRoomTypes;
}

const RoomType* find_room_type(std::string_view type) {
  std::string t = lower(type);
  for (const auto& [from, to] : kSynonyms)
    if (t == from) t = std::string(to);
  for (const auto& r : kRoomTypes)
    if (r.type == t) return &r;
  return nullptr;
}

std::string canonical_room_type(std::string_view type) {
  const RoomType* r = find_room_type(type);
  return r ? std::string(r->type) : lower(type);
}

bool is_corridor_type(std::string_view type) {
  const RoomType* r = find_room_type(type);
  return r && r->circulation == Circulation::kCorridor;
}
bool is_hall_type(std::string_view type) {
  const RoomType* r = find_room_type(type);
  return r && r->circulation == Circulation::kHall;
}
bool is_bedroom_type(std::string_view type) {
  return canonical_room_type(type) == "bedroom";
}
bool is_habitable_type(std::string_view type) {
  const RoomType* r = find_room_type(type);
  return r && r->habitable;
}
bool is_toilet_type(std::string_view type) {
  const std::string t = canonical_room_type(type);
  return t == "toilet" || t == "bathroom";
}

}  // namespace socsim::floorplan
