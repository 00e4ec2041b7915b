// GEOS-backed polygon operations: validity reasons with locations, boolean operations,
// shared boundaries between neighbouring rooms, dissolved boundaries, polygonize.
#include "core/geometry/geos.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

namespace socsim::geometry {
namespace {

Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

double total_length(const std::vector<Segment>& segs) {
  double l = 0;
  for (const auto& s : segs) l += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
  return l;
}

TEST(Geos, ValidPolygonPasses) {
  Geos geos;
  EXPECT_TRUE(geos.validity(rect(0, 0, 3, 2)).valid);
}

TEST(Geos, SelfCrossingPolygonIsReportedWithWhereItCrosses) {
  Geos geos;
  // A bow tie: the edges (0,0)-(4,4) and (4,0)-(0,4) cross at (2,2).
  const Polygon bow{{{0, 0}, {4, 4}, {4, 0}, {0, 4}}, {}};
  const Validity v = geos.validity(bow);
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("Self-intersection"), std::string::npos) << v.reason;
  ASSERT_TRUE(v.location.has_value());
  EXPECT_NEAR(v.location->x, 2.0, 1e-9);
  EXPECT_NEAR(v.location->y, 2.0, 1e-9);
}

TEST(Geos, DegenerateAndNonFiniteRingsAreRejectedBeforeGeos) {
  Geos geos;
  EXPECT_FALSE(geos.validity(Polygon{{{0, 0}, {1, 1}, {0, 0}}, {}}).valid);
  const Validity v = geos.validity(Polygon{{{0, 0}, {1, 0}, {1, std::nan("")}}, {}});
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("non-finite"), std::string::npos);
}

TEST(Geos, BooleanOperationsGiveExpectedAreas) {
  Geos geos;
  const MultiPolygon a{rect(0, 0, 4, 4)};
  const MultiPolygon b{rect(2, 2, 6, 6)};
  EXPECT_DOUBLE_EQ(geos.area(geos.unite(a, b)), 28.0);
  EXPECT_DOUBLE_EQ(geos.area(geos.intersection(a, b)), 4.0);
  EXPECT_DOUBLE_EQ(geos.area(geos.difference(a, b)), 12.0);
  EXPECT_DOUBLE_EQ(geos.area(geos.unite(MultiPolygon{rect(0, 0, 1, 1), rect(1, 0, 2, 1)})), 2.0);
  EXPECT_TRUE(geos.intersection(MultiPolygon{rect(0, 0, 1, 1)}, MultiPolygon{rect(5, 5, 6, 6)}).empty());
}

TEST(Geos, DifferenceCanLeaveAHole) {
  Geos geos;
  const auto r = geos.difference(MultiPolygon{rect(0, 0, 10, 10)}, MultiPolygon{rect(4, 4, 6, 6)});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].holes.size(), 1u);
}

TEST(Geos, BufferGrowsAndShrinks) {
  Geos geos;
  const MultiPolygon sq{rect(0, 0, 2, 2)};
  EXPECT_NEAR(geos.area(geos.buffer(sq, -0.5)), 1.0, 1e-9);
  EXPECT_GT(geos.area(geos.buffer(sq, 1.0)), 4.0 + 8.0);  // 4 + perimeter*1 + corner arcs
}

TEST(Geos, PointQueriesAndDistances) {
  Geos geos;
  const MultiPolygon sq{rect(0, 0, 2, 2)};
  EXPECT_TRUE(geos.covers(sq, {1, 1}));
  EXPECT_TRUE(geos.covers(sq, {2, 1}));  // boundary
  EXPECT_FALSE(geos.covers(sq, {3, 1}));
  EXPECT_DOUBLE_EQ(geos.distance(sq, Point{5, 1}), 3.0);
  EXPECT_DOUBLE_EQ(geos.distance(sq, MultiPolygon{rect(2, 5, 3, 6)}), 3.0);
}

TEST(Geos, SharedBoundaryOfTwoRoomsIsTheCommonWallPart) {
  Geos geos;
  // Room A spans x 0..6, room B sits on top of its right part (x 3..8).
  const auto shared = geos.shared_boundary(rect(0, 0, 6, 4), rect(3, 4, 8, 7), 0.0);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_DOUBLE_EQ(total_length(shared), 3.0);
  const double xs[] = {shared[0].a.x, shared[0].b.x};
  EXPECT_DOUBLE_EQ(std::min(xs[0], xs[1]), 3.0);
  EXPECT_DOUBLE_EQ(std::max(xs[0], xs[1]), 6.0);
}

TEST(Geos, SharedBoundaryIgnoresCornerContactAndToleratesSmallGaps) {
  Geos geos;
  EXPECT_TRUE(geos.shared_boundary(rect(0, 0, 1, 1), rect(1, 1, 2, 2), 0.0).empty());
  // 1 cm gap between the rooms is bridged by a 2 cm tolerance, not by a 5 mm one.
  EXPECT_NEAR(total_length(geos.shared_boundary(rect(0, 0, 4, 4), rect(4.01, 0, 8, 4), 0.02)), 4.0, 1e-9);
  EXPECT_TRUE(geos.shared_boundary(rect(0, 0, 4, 4), rect(4.01, 0, 8, 4), 0.005).empty());
}

TEST(Geos, BoundarySegmentsDissolveSharedEdgesAndMergeCollinearPieces) {
  Geos geos;
  // Two 4x4 rooms side by side: outline 8+4+8+4 = 24 plus the middle wall 4, each once.
  const auto segs = geos.boundary_segments(MultiPolygon{rect(0, 0, 4, 4), rect(4, 0, 8, 4)});
  EXPECT_DOUBLE_EQ(total_length(segs), 28.0);
  // The bottom edge is noded at x=4 (the middle wall meets it), so it comes as two pieces.
  const auto bottom =
      std::count_if(segs.begin(), segs.end(), [](const Segment& s) { return s.a.y == 0 && s.b.y == 0; });
  EXPECT_EQ(bottom, 2);
  EXPECT_EQ(segs.size(), 7u);
}

TEST(Geos, LengthOutsideMeasuresWhatLeavesTheShape) {
  Geos geos;
  const std::vector<Segment> segs{{{1, 1}, {5, 1}}};
  EXPECT_NEAR(geos.length_outside(segs, MultiPolygon{rect(0, 0, 3, 3)}, 1e-6), 2.0, 1e-4);
  EXPECT_NEAR(geos.length_outside(segs, MultiPolygon{rect(0, 0, 6, 3)}, 1e-6), 0.0, 1e-9);
}

TEST(Geos, PolygonizeFindsTheRoomsEnclosedBySegments) {
  Geos geos;
  // A square with a dividing line: two faces. A dangling segment encloses nothing.
  const std::vector<Segment> segs{{{0, 0}, {4, 0}}, {{4, 0}, {4, 2}},  {{4, 2}, {0, 2}},
                                  {{0, 2}, {0, 0}}, {{2, -1}, {2, 3}}, {{10, 10}, {11, 11}}};
  const auto faces = geos.polygonize(segs);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_DOUBLE_EQ(geos.area(faces), 8.0);
}

TEST(Geos, ContextsAreIndependentPerThread) {
  std::vector<double> areas(4, 0.0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([t, &areas] {
      Geos geos;
      double sum = 0;
      for (int i = 0; i < 50; ++i)
        sum += geos.area(geos.unite(MultiPolygon{rect(0, 0, t + 1, 1), rect(t, 0, t + 2, 1)}));
      areas[static_cast<std::size_t>(t)] = sum;
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_DOUBLE_EQ(areas[static_cast<std::size_t>(t)], 50.0 * (t + 2));
}

}  // namespace
}  // namespace socsim::geometry
