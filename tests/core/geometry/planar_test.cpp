// Plain-double plane geometry: distances, areas, containment and frame transforms.
#include "core/geometry/planar.hpp"
#include "core/geometry/hull.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace socsim::geometry {
namespace {

const Polygon kSquare{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};

TEST(Planar, DistanceToSegmentUsesTheClosestPointNotTheLine) {
  const Segment s{{0, 0}, {10, 0}};
  EXPECT_DOUBLE_EQ(distance(s, Point{5, 3}), 3.0);
  EXPECT_DOUBLE_EQ(distance(s, Point{13, 4}), 5.0);  // beyond the end: distance to the end point
  EXPECT_DOUBLE_EQ(distance(Segment{{2, 2}, {2, 2}}, Point{5, 6}), 5.0);
}

TEST(Planar, SegmentToSegmentDistanceIsZeroWhenTheyCross) {
  EXPECT_DOUBLE_EQ(distance(Segment{{0, 0}, {4, 4}}, Segment{{0, 4}, {4, 0}}), 0.0);
  EXPECT_DOUBLE_EQ(distance(Segment{{0, 0}, {4, 0}}, Segment{{0, 2}, {4, 2}}), 2.0);
}

TEST(Planar, AreaSubtractsHolesAndSignFollowsOrientation) {
  EXPECT_DOUBLE_EQ(signed_area(kSquare.outer), 16.0);
  const std::vector<Point> clockwise{{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  EXPECT_DOUBLE_EQ(signed_area(clockwise), -16.0);
  Polygon with_hole = kSquare;
  with_hole.holes.push_back({{1, 1}, {2, 1}, {2, 2}, {1, 2}});
  EXPECT_DOUBLE_EQ(area(with_hole), 15.0);
}

TEST(Planar, CentroidOfAnLShapeLiesInItsBulk) {
  const std::vector<Point> l{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  const Point c = centroid(l);
  // Two 4x1 and 1x3 rectangles: x = (4*2 + 3*0.5)/7, y symmetric.
  EXPECT_NEAR(c.x, (4 * 2.0 + 3 * 0.5) / 7.0, 1e-12);
  EXPECT_NEAR(c.y, (4 * 0.5 + 3 * 2.5) / 7.0, 1e-12);
}

TEST(Planar, ContainsCountsBoundaryAndExcludesHoles) {
  Polygon p = kSquare;
  p.holes.push_back({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  EXPECT_TRUE(contains(p, {0.5, 0.5}));
  EXPECT_TRUE(contains(p, {4, 2}));   // on the outer boundary
  EXPECT_FALSE(contains(p, {2, 2}));  // in the hole
  EXPECT_TRUE(contains(p, {1, 2}));   // on the hole's boundary
  EXPECT_FALSE(contains(p, {5, 2}));
}

TEST(Planar, ToParentRotatesThenTranslates) {
  const Pose2 frame{10, 5, std::numbers::pi / 2};
  const Point p = to_parent(frame, Point{1, 0});
  EXPECT_NEAR(p.x, 10, 1e-12);
  EXPECT_NEAR(p.y, 6, 1e-12);
  const Pose2 q = to_parent(frame, Pose2{0, 2, 0.5});
  EXPECT_NEAR(q.x, 8, 1e-12);
  EXPECT_NEAR(q.y, 5, 1e-12);
  EXPECT_NEAR(q.yaw, 0.5 + std::numbers::pi / 2, 1e-12);
}

TEST(Planar, EdgesCloseTheRing) {
  const auto e = edges(kSquare.outer);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e.back(), (Segment{{0, 4}, {0, 0}}));
}

// The building diagonal of compliance reports was a loop over every pair of vertices (6.4e9
// distances for eight 10k-vertex zones); diameter() must give exactly the same maximum.
TEST(Planar, DiameterIsTheLargestPairwiseDistance) {
  const auto brute = [](const std::vector<Point>& pts) {
    double best = 0.0;
    for (const Point& p : pts)
      for (const Point& q : pts) best = std::max(best, distance(p, q));
    return best;
  };
  std::vector<Point> circle, jagged, line;
  for (int i = 0; i < 500; ++i) {
    const double a = 2 * std::numbers::pi * i / 500;
    circle.push_back({10 * std::cos(a), 7 * std::sin(a)});
    jagged.push_back({i * 0.01, (i % 2) * 0.5 + std::sin(i * 0.37)});
    line.push_back({i * 0.5, i * 0.25});
  }
  for (const auto* pts : {&circle, &jagged, &line}) EXPECT_EQ(diameter(*pts), brute(*pts));
  EXPECT_EQ(diameter(std::vector<Point>{{1, 1}}), 0.0);
  EXPECT_EQ(diameter(std::vector<Point>{{0, 0}, {3, 4}, {3, 4}}), 5.0);
}

}  // namespace
}  // namespace socsim::geometry
