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

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_REFERENCE_COMPONENTS_H_
