// Plain geometry for tests that check the line code against a reference that
// shares no code with it.
#ifndef LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_
#define LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "linemap/cells.h"
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

// Spec/format.md section 8.2 as written: cell (c, r) is enclosed by the
// closed chain when it is a chain cell, or when an odd number of steps
// p -> q (the last closing the chain) have (p.row > r) != (q.row > r) and
// x > c, x the column of whichever of p, q lies on row r.
inline bool ReferenceChainEncloses(const std::vector<CellIndex>& chain, int c, int r) {
  int crossings = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const CellIndex p = chain[i];
    const CellIndex q = chain[(i + 1) % chain.size()];
    if (p.col == c && p.row == r) return true;
    if ((p.row > r) == (q.row > r)) continue;
    const int x = p.row == r ? p.col : q.col;
    if (x > c) ++crossings;
  }
  return crossings % 2 == 1;
}

// ReferenceChainEncloses for many cells of one chain: per row, the sorted
// columns x of the steps that cross it, and the chain's own cells.
class ReferenceChainInterior {
 public:
  explicit ReferenceChainInterior(const std::vector<CellIndex>& chain) {
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const CellIndex p = chain[i];
      const CellIndex q = chain[(i + 1) % chain.size()];
      on_chain_.insert({p.col, p.row});
      // Steps between rows r and r + 1 cross row r (rows differ by at most
      // one along an 8-connected chain; a longer step crosses each row it
      // spans, at its end on that row or else at q's column).
      for (int r = std::min(p.row, q.row); r < std::max(p.row, q.row); ++r) {
        crossings_[r].push_back(p.row == r ? p.col : q.col);
      }
    }
    for (auto& [row, xs] : crossings_) std::sort(xs.begin(), xs.end());
  }
  bool Encloses(int c, int r) const {
    if (on_chain_.count({c, r})) return true;
    const auto row = crossings_.find(r);
    if (row == crossings_.end()) return false;
    const auto right =
        row->second.end() - std::upper_bound(row->second.begin(), row->second.end(), c);
    return right % 2 == 1;
  }

 private:
  std::map<int, std::vector<int>> crossings_;
  std::set<std::pair<int, int>> on_chain_;
};

// Twice the area a polygon encloses, |shoelace sum|, in doubles (exact for
// the test maps' coordinates).
inline double ReferenceTwiceArea(const std::vector<CellIndex>& v) {
  double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const CellIndex p = v[i], q = v[(i + 1) % v.size()];
    sum += static_cast<double>(p.col) * q.row - static_cast<double>(q.col) * p.row;
  }
  return std::abs(sum);
}

// The room a viewer picks at `cell`: of the rooms whose chain encloses it,
// the one whose polygon has the smallest area, the first on a tie; null
// when none does.
template <typename Room>
const Room* ReferenceRoomAt(const std::vector<Room>& rooms, int col, int row) {
  const Room* best = nullptr;
  for (const Room& room : rooms) {
    if (ReferenceChainEncloses(room.chain, col, row) &&
        (best == nullptr || ReferenceTwiceArea(room.polygon) < ReferenceTwiceArea(best->polygon))) {
      best = &room;
    }
  }
  return best;
}

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_REFERENCE_GEOMETRY_H_
