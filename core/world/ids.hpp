#pragma once
// Type-safe indices into a World's element lists: a ZoneId cannot be passed where a DoorId is meant.
#include <compare>
#include <cstddef>
#include <cstdint>

namespace socsim::world {

template <class Tag>
class Id {
 public:
  constexpr explicit Id(std::uint32_t value) : value_(value) {}
  [[nodiscard]] constexpr std::uint32_t value() const { return value_; }
  [[nodiscard]] constexpr std::size_t index() const { return value_; }
  friend constexpr bool operator==(Id, Id) = default;
  friend constexpr auto operator<=>(Id, Id) = default;

 private:
  std::uint32_t value_;
};

using ZoneId = Id<struct ZoneTag>;
using WallId = Id<struct WallTag>;
using DoorId = Id<struct DoorTag>;
using RoiId = Id<struct RoiTag>;
using EntityId = Id<struct EntityTag>;

}  // namespace socsim::world
