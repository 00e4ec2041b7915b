#pragma once
// Shared vocabulary of the household module: room types, weekdays and the time axis
// (seconds from 00:00 of a scene's first day).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace socsim::household {

// The four room types of ProcTHOR houses (paper 000 §IV-C).
enum class RoomType : std::uint8_t { kBedroom = 0, kBathroom = 1, kLivingRoom = 2, kKitchen = 3 };
inline constexpr std::size_t kRoomTypeCount = 4;
inline constexpr std::array<RoomType, kRoomTypeCount> kRoomTypes = {
    RoomType::kBedroom, RoomType::kBathroom, RoomType::kLivingRoom, RoomType::kKitchen};
std::string_view room_type_name(RoomType type);  // "Bedroom", "Bathroom", "LivingRoom", "Kitchen"
std::optional<RoomType> parse_room_type(std::string_view name);
inline std::size_t index_of(RoomType type) {
  return static_cast<std::size_t>(type);
}

enum class Weekday : std::uint8_t {
  kMonday = 0,
  kTuesday,
  kWednesday,
  kThursday,
  kFriday,
  kSaturday,
  kSunday
};
std::string_view weekday_name(Weekday day);                   // "Monday" …
std::optional<Weekday> parse_weekday(std::string_view name);  // case-insensitive, "wed" or "Wednesday"
inline Weekday weekday_after(Weekday first, int days) {
  return static_cast<Weekday>((static_cast<int>(first) + days % 7 + 7) % 7);
}
inline bool is_weekend(Weekday day) {
  return day == Weekday::kSaturday || day == Weekday::kSunday;
}

using Seconds = std::int64_t;
inline constexpr Seconds kSecondsPerDay = 86400;
inline constexpr int kMinutesPerDay = 1440;

// "Wed 07:30" style label of a time on the scene axis.
std::string format_clock(Seconds t, Weekday first_day);

}  // namespace socsim::household
