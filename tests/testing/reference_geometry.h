// Plain geometry for tests that check the line code against a reference that
// shares no code with it.
#ifndef LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_
#define LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_

#include <algorithm>
#include <cmath>

#include "linemap/lines.h"

namespace linemap::testing {

// Distance from (x, y) to the segment: to its closest point, found by
// projection onto the segment's line and clamped to its ends.
inline double ReferencePointSegmentDistance(double x, double y, const LineSegment& s) {
  const double vx = s.x2 - s.x1, vy = s.y2 - s.y1;
  const double len2 = vx * vx + vy * vy;
  const double t =
      std::clamp(len2 > 0 ? ((x - s.x1) * vx + (y - s.y1) * vy) / len2 : 0.0, 0.0, 1.0);
  return std::hypot(x - (s.x1 + t * vx), y - (s.y1 + t * vy));
}

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_
