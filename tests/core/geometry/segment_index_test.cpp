// SegmentIndex: queries agree with a scan of every segment; pieces_near gives what
// Geos::shared_boundary gives (the shared walls of rooms, a T-junction, no contact) without a buffer.
#include "core/geometry/segment_index.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"

namespace socsim::geometry {
namespace {

std::vector<Segment> zigzag(int n) {
  std::vector<Segment> out;
  for (int i = 0; i < n; ++i)
    out.push_back({{i * 0.37, std::sin(i * 1.3) * 3.0}, {i * 0.37 + 0.5, std::cos(i * 0.7) * 2.0}});
  return out;
}

TEST(SegmentIndex, QueriesAgreeWithAScan) {
  const auto segs = zigzag(400);
  SegmentIndex index(segs);
  for (int q = 0; q < 50; ++q) {
    const Point p{q * 3.1 - 10.0, std::sin(q) * 4.0};
    std::vector<std::size_t> want;
    std::size_t nearest = 0;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (distance(segs[i], p) <= 0.8) want.push_back(i);
      if (distance(segs[i], p) < distance(segs[nearest], p)) nearest = i;
    }
    EXPECT_EQ(index.within(p, 0.8), want);
    auto n = index.nearest(p);
    ASSERT_TRUE(n);
    EXPECT_EQ(n->index, nearest);
    EXPECT_EQ(n->distance, distance(segs[nearest], p));
  }
  const Segment probe{{5, -1}, {9, 1}};
  std::vector<std::size_t> want;
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (distance(segs[i], probe) <= 0.3) want.push_back(i);
  EXPECT_EQ(index.within(probe, 0.3), want);
  SegmentIndex grown;
  for (const auto& s : segs) grown.insert(s);
  EXPECT_EQ(grown.within(probe, 0.3), want);
  EXPECT_FALSE(SegmentIndex().nearest({0, 0}));
}

std::vector<Segment> sorted(std::vector<Segment> v) {
  for (auto& s : v)
    if (s.b.x < s.a.x || (s.b.x == s.a.x && s.b.y < s.a.y)) std::swap(s.a, s.b);
  std::sort(v.begin(), v.end(), [](const Segment& x, const Segment& y) {
    return std::tie(x.a.x, x.a.y, x.b.x, x.b.y) < std::tie(y.a.x, y.a.y, y.b.x, y.b.y);
  });
  return v;
}

void expect_near(const std::vector<Segment>& got, const std::vector<Segment>& want, double tol) {
  ASSERT_EQ(got.size(), want.size());
  const auto g = sorted(got), w = sorted(want);
  for (std::size_t i = 0; i < g.size(); ++i) {
    EXPECT_NEAR(g[i].a.x, w[i].a.x, tol);
    EXPECT_NEAR(g[i].a.y, w[i].a.y, tol);
    EXPECT_NEAR(g[i].b.x, w[i].b.x, tol);
    EXPECT_NEAR(g[i].b.y, w[i].b.y, tol);
  }
}

TEST(SegmentIndex, PiecesNearMatchTheSharedBoundaryOfGeos) {
  const double tol = 0.01;
  const Polygon room{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  const Polygon beside{{{4, 1}, {7, 1}, {7, 3}, {4, 3}}, {}};  // T-junction on room's east wall
  const Polygon corridor{{{0, 4}, {2, 4}, {4, 4}, {4, 6}, {0, 6}},
                         {}};  // collinear vertex on the shared wall
  const Polygon apart{{{10, 10}, {11, 10}, {11, 11}}, {}};
  Geos geos;
  for (const Polygon* other : {&beside, &corridor, &apart}) {
    const SegmentIndex index(edges(other->outer));
    const auto got = pieces_near({room.outer}, index, tol);
    const auto want = geos.shared_boundary(room, *other, tol);
    expect_near(got, want, 1e-3);  // GEOS approximates the tolerance's round ends by chords
  }
}

}  // namespace
}  // namespace socsim::geometry
