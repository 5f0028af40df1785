#include "tools/bench/lmap_figures.h"

namespace linemap::bench {

Status AddLmapFigures(const Grid& /*grid*/, int /*repeats*/, MapResult* /*result*/) {
  return UnsupportedError(
      "the .lmap codec (issue 6) is not merged into this tree yet: no .lmap columns");
}

}  // namespace linemap::bench
