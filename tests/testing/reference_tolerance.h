// Brute-force references for the guarantees of a map saved within a
// tolerance (include/linemap/tolerance.h): window scans for Chebyshev
// distances, flood fills for regions, breadth-first plans; never the
// module's own distance transforms.
#ifndef LINEMAP_TESTS_TESTING_REFERENCE_TOLERANCE_H_
#define LINEMAP_TESTS_TESTING_REFERENCE_TOLERANCE_H_

#include <cstddef>
#include <string>
#include <vector>

#include "linemap/grid.h"

namespace linemap::testing {

// True when `grid` has a cell of `value` within Chebyshev distance t of
// (c, r), by scanning the window.
bool HasWithin(const Grid& grid, int c, int r, Cell value, int t);

// Exact directed Hausdorff distance (Chebyshev) from `a`'s occupied cells to
// `b`'s, by comparing every pair; -1 when b has none and a has some.
int BruteHausdorff(const Grid& a, const Grid& b);

// Steps of a 4-connected path over free cells from cell index `from` to
// every cell (-1 where none), breadth first.
std::vector<int> BfsSteps(const Grid& g, int from);

// Original free regions of kLeakRegionCells+ cells (4-connected) joined in
// the decode (`leaks`: regions beyond the first of each decoded component)
// and split (`splits`), by flood fill.
struct TopologyCount {
  int leaks = 0;
  int splits = 0;
};
TopologyCount BruteTopology(const Grid& original, const Grid& decoded);

// The encoder's local plan check, by its definition: from every cell free
// in both maps beside a cell free in one only, each plan of up to `depth`
// steps on one map to a cell free on the other is there in as many steps.
// The plans counted and those that are not.
struct LocalPlanFigures {
  std::size_t plans = 0;
  std::size_t bad = 0;
};
LocalPlanFigures BruteLocalPlans(const Grid& o, const Grid& s, int depth);

// The plan depth the encoder holds beside a change at tolerance t: 16
// steps, 32 with blocks of 3 cells or more (t >= 2; spec/format.md 9).
inline int LocalPlanSteps(int t) { return t >= 2 ? 32 : 16; }

// Every guarantee of tolerance t between the original `o` and the decode
// `s`, by the references above (gtest failures, traced with `what`), and
// CheckTolerance as well.
void ExpectGuarantees(const Grid& o, const Grid& s, int t, const std::string& what);

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_REFERENCE_TOLERANCE_H_
