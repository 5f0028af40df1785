// A plain flood fill of the free space, for tests that check the library's
// labelling and segmentation against a reference that shares no code with
// them.
#ifndef LINEMAP_TESTS_TESTING_REFERENCE_COMPONENTS_H_
#define LINEMAP_TESTS_TESTING_REFERENCE_COMPONENTS_H_

#include <cstddef>
#include <vector>

#include "linemap/cells.h"
#include "linemap/grid.h"

namespace linemap::testing {

struct FreeComponents {
  std::vector<int> id;             // per cell, 1.. for free cells, 0 elsewhere
  std::vector<std::size_t> sizes;  // cells of component k at sizes[k]; sizes[0] = 0
};

// The 4-connected components of the free cells, numbered in raster order of
// their first cells.
FreeComponents FreeComponentsByFloodFill(const Grid& grid);

// Among the cells free in both grids (same size), how far "a 4-connected
// plan over free cells exists" differs between them: for each component of
// one grid, the components of the other that its cells fall into, beyond
// the first, counted both ways. 0 exactly when every pair of those cells
// has a plan on both grids or on neither. -1 for grids of different sizes.
int PlansOnOneGridOnly(const Grid& a, const Grid& b);

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_REFERENCE_COMPONENTS_H_
