// CompareGrids() in parts, for the lossy encoder, which compares one map
// with several candidate decodings and labels the map's free space once.
#ifndef LINEMAP_CODEC_CODEC_COMPARE_INTERNAL_H_
#define LINEMAP_CODEC_CODEC_COMPARE_INTERNAL_H_

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/labeling.h"

namespace linemap::codec_internal {

// The 4-connected free components of `grid` (two-pass labelling: linear and
// cache-friendly on maps of any size).
Labeling LabelFree(const Grid& grid);

// CompareGrids(original, decoded); `original_free` is LabelFree(original)
// when the caller has it, else null (it is then made when needed).
GridComparison CompareGrids(const Grid& original, const Labeling* original_free,
                            const Grid& decoded);

}  // namespace linemap::codec_internal

#endif  // LINEMAP_CODEC_CODEC_COMPARE_INTERNAL_H_
