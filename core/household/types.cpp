#include "core/household/types.hpp"

#include <cctype>
#include <cstdio>

namespace socsim::household {
namespace {
constexpr std::array<std::string_view, kRoomTypeCount> kRoomNames = {"Bedroom", "Bathroom", "LivingRoom",
                                                                     "Kitchen"};
constexpr std::array<std::string_view, 7> kDayNames = {"Monday", "Tuesday",  "Wednesday", "Thursday",
                                                       "Friday", "Saturday", "Sunday"};

bool iequal_prefix(std::string_view text, std::string_view full) {
  if (text.size() < 3 || text.size() > full.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(full[i])))
      return false;
  return true;
}
}  // namespace

std::string_view room_type_name(RoomType type) {
  return kRoomNames[index_of(type)];
}

std::optional<RoomType> parse_room_type(std::string_view name) {
  for (RoomType t : kRoomTypes)
    if (room_type_name(t) == name) return t;
  return std::nullopt;
}

std::string_view weekday_name(Weekday day) {
  return kDayNames[static_cast<std::size_t>(day)];
}

std::optional<Weekday> parse_weekday(std::string_view name) {
  for (std::size_t i = 0; i < kDayNames.size(); ++i)
    if (iequal_prefix(name, kDayNames[i])) return static_cast<Weekday>(i);
  return std::nullopt;
}

std::string format_clock(Seconds t, Weekday first_day) {
  const Seconds day = t >= 0 ? t / kSecondsPerDay : (t - kSecondsPerDay + 1) / kSecondsPerDay;
  const Seconds rest = t - day * kSecondsPerDay;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3s %02d:%02d",
                weekday_name(weekday_after(first_day, static_cast<int>(day))).data(),
                static_cast<int>(rest / 3600), static_cast<int>((rest / 60) % 60));
  return buf;
}

}  // namespace socsim::household
