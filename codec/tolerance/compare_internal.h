// The free-space labelling CompareGrids() uses, shared with the tolerance
// checks, which label the free space of a map and its decode too.
#ifndef LINEMAP_CODEC_TOLERANCE_COMPARE_INTERNAL_H_
#define LINEMAP_CODEC_TOLERANCE_COMPARE_INTERNAL_H_

#include "linemap/grid.h"
#include "linemap/labeling.h"

namespace linemap::codec_internal {

// The 4-connected free components of `grid` (two-pass labelling: linear and
// cache-friendly on maps of any size).
Labeling LabelFree(const Grid& grid);

}  // namespace linemap::codec_internal

#endif  // LINEMAP_CODEC_TOLERANCE_COMPARE_INTERNAL_H_
