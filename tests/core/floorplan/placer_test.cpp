// Placer::walkable keeps the last passing grid and checks one more footprint only around it
// when it can show the answer equal to a full flood fill. Property: over long random sequences
// of placements (kept when walkable, removed when not), the cached answer always equals that of
// a fresh Placer, which floods from scratch.
#include "core/floorplan/placer.hpp"

#include <gtest/gtest.h>

#include "core/common/rng.hpp"

namespace socsim::floorplan {
namespace {

Zone room(double w, double h) {
  Zone z;
  z.name = "hall";
  z.type = "sales_floor";
  z.polygon = Polygon{{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}};
  return z;
}

TEST(Placer, CachedWalkabilityEqualsAFullFloodFill) {
  const char* types[] = {"shelf", "bench", "table"};
  int kept = 0, refused = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const double w = 14.0, h = seed % 2 == 0 ? 4.0 : 7.0;
    const Zone z = room(w, h);
    const Box box{{0, 0}, {w, h}};
    const std::vector<DoorAt> doors = {{{0.0, h / 2}, 0.9, true, "", "west"},
                                       {{w, h / 3}, 0.9, false, "corridor", "east"},
                                       {{w / 2, h}, 0.9, false, "corridor", "north"}};
    Furnishing out;
    Placer cached(z, Frame(box, 0), doors, out);
    Rng rng(seed, 42);
    for (int i = 0; i < 120; ++i) {
      const std::string type = types[rng.below(3)];
      const Pose2 pose{0.4 + rng.uniform() * (w - 0.8), 0.4 + rng.uniform() * (h - 0.8),
                       rng.chance(0.5) ? 0.0 : 1.5707963267948966};
      out.entities.push_back({type, "e" + std::to_string(i), pose, {}});
      const bool quick = cached.walkable();
      const bool full = Placer(z, Frame(box, 0), doors, out).walkable();
      ASSERT_EQ(quick, full) << "seed " << seed << ", placement " << i;
      if (quick) {
        ++kept;
      } else {
        out.entities.pop_back();
        ++refused;
      }
    }
  }
  // Both answers occur often enough for the property to mean something.
  EXPECT_GT(kept, 100);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace socsim::floorplan
