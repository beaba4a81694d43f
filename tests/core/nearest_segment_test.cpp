// NearestSegment against a pass over every segment: the same distance, bit for bit, for
// points near, among and far from the segments, with degenerate segments, a segment that is
// not finite and no segments at all.
#include "core/nearest_segment.h"

#include "core/distances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace holebench {
namespace {

double nearest_by_pass(const std::vector<SegmentEnds>& segments, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments)
    best = std::min(best, point_segment_distance(p, s.a, s.b));
  return best;
}

// Short segments along a noisy polyline (the sharp edges of a patch) and some scattered ones.
std::vector<SegmentEnds> polyline_and_scattered(std::mt19937& random, int count) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<SegmentEnds> segments;
  Point at(0.0, 0.0, 0.0);
  for (int i = 0; i < count; ++i) {
    const Point next = at + Point(0.01, 0.003 * unit(random), 0.003 * unit(random));
    segments.push_back({at, next});
    at = next;
  }
  for (int i = 0; i < count / 4; ++i) {
    const Point a(unit(random), unit(random), unit(random));
    segments.push_back({a, a + Point(0.1 * unit(random), 0.1 * unit(random), 0.0)});
  }
  segments.push_back({Point(0.5, 0.5, 0.5), Point(0.5, 0.5, 0.5)});  // a point
  return segments;
}

TEST(NearestSegment, EqualsThePassOverEverySegmentBitForBit) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int count : {1, 3, 4, 5, 17, 200, 3000}) {
    const auto segments = polyline_and_scattered(random, count);
    const NearestSegment nearest(segments);
    EXPECT_EQ(nearest.size(), segments.size());
    for (int i = 0; i < 500; ++i) {
      // Points on the segments (distance 0 or rounding), beside them and far away.
      const SegmentEnds& s = segments[random() % segments.size()];
      const double t = 0.5 * (unit(random) + 1.0);
      const Point on = s.a + (s.b - s.a) * t;
      for (const Point& p :
           {on, on + Point(1e-6, 0.0, -1e-6), Point(unit(random), unit(random), unit(random)),
            Point(100.0 * unit(random), 5.0, -40.0)}) {
        ASSERT_EQ(nearest.distance(p), nearest_by_pass(segments, p))
            << "count " << count << " at " << p;
      }
    }
  }
}

TEST(NearestSegment, CoordinatesFarFromTheOriginKeepTheAnswer) {
  // A model placed far away: the margin follows the coordinates, not an absolute length.
  std::mt19937 random(11);
  auto segments = polyline_and_scattered(random, 400);
  for (auto& s : segments) {
    s.a += Point(1e5, -2e5, 3e4);
    s.b += Point(1e5, -2e5, 3e4);
  }
  const NearestSegment nearest(segments);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Point p = Point(1e5, -2e5, 3e4) + Point(unit(random), unit(random), unit(random));
    ASSERT_EQ(nearest.distance(p), nearest_by_pass(segments, p));
  }
}

TEST(NearestSegment, NoSegmentsIsInfinitelyFarAndNonFiniteSegmentsAreStillAsked) {
  EXPECT_EQ(NearestSegment({}).distance(Point(0, 0, 0)), std::numeric_limits<double>::infinity());
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<SegmentEnds> segments{{Point(0, 0, 0), Point(1, 0, 0)},
                                          {Point(inf, 0, 0), Point(2, 0, 0)},
                                          {Point(0, 0, 3), Point(1, 0, 3)}};
  const NearestSegment nearest(segments);
  EXPECT_EQ(nearest.size(), 3u);
  for (const Point& p : {Point(0.5, 1, 0), Point(5, 0, 0), Point(0.5, 0, 2.9)})
    EXPECT_EQ(nearest.distance(p), nearest_by_pass(segments, p));
}

}  // namespace
}  // namespace holebench
