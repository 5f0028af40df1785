// JBIG1 (ITU-T T.82) of a trinary map's two bit-planes, by JBIG-KIT's
// `pbmtojbg` run as a subprocess (JBIG-KIT is GPL: never linked).
// The planes: black = not free (occupied or unknown) and black = occupied,
// the pair the .lmap 2.0 size goals name; together they give the three
// states.
#ifndef LINEMAP_TOOLS_BENCH_JBIG_H_
#define LINEMAP_TOOLS_BENCH_JBIG_H_

#include <cstddef>
#include <string>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::bench {

enum class BitPlane { kNotFree, kOccupied };

// A binary PBM (P4) of the plane: 1 (black) where the cell is in the plane,
// image row 0 = top (grid row height-1).
std::string PbmPlane(const Grid& grid, BitPlane plane);

struct JbigOptions {
  std::string encoder = "pbmtojbg";
  // pbmtojbg's -q: sequential, one resolution layer (smaller than its default
  // progressive mode on maps).
  bool sequential = true;
};

struct JbigSizes {
  std::size_t not_free_plane = 0;
  std::size_t occupied_plane = 0;
  std::size_t total() const { return not_free_plane + occupied_plane; }
};

// The .jbg bytes of one PBM through the encoder.
StatusOr<std::string> JbigEncodePbm(const std::string& pbm, const JbigOptions& options = {});

StatusOr<JbigSizes> JbigTwoPlaneSizes(const Grid& grid, const JbigOptions& options = {});

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_JBIG_H_
