// The size goal of .lmap against the codecs a user could pick instead: on
// every map of at least 100,000 cells the default .lmap 2.0 file (exact, with
// its wall, room and furniture layers) must be smaller than each anchor
// (PNG-9, WebP, JBIG1, zstd -19, xz -9e, JPEG XL).
#ifndef LINEMAP_TOOLS_BENCH_ANCHORS_H_
#define LINEMAP_TOOLS_BENCH_ANCHORS_H_

#include <string>
#include <vector>

#include "tools/bench/report.h"
#include "tools/bench/results.h"

namespace linemap::bench {

// Maps smaller than this are left out of the check: on a few thousand cells
// every format's fixed header decides the ranking, not its coding.
inline constexpr double kAnchorMinCells = 100000;

struct Anchor {
  std::string name;    // "PNG-9"
  std::string figure;  // its size in bytes
};

// The anchors, in the order the table lists them.
std::vector<Anchor> SizeAnchors();

// The file checked against the anchors: the default .lmap 2.0 file, layers
// included (not --raster-only, which would flatter the layers' cost away).
Anchor AnchorSubject();

// The files also compared with the anchors, for information: the --compact
// file with its layers and without (the anchors are measured at their
// highest efforts; --compact is ours).
std::vector<Anchor> ComparedSubjects();

struct AnchorOutcome {
  Anchor anchor;
  std::vector<const MapResult*> won;   // subject strictly smaller
  std::vector<const MapResult*> lost;  // subject as large or larger
};

// Per anchor, the maps of at least kAnchorMinCells cells that have both
// sizes of `subject` and the anchor, split into won and lost.
std::vector<AnchorOutcome> CheckAnchors(const std::vector<MapResult>& results,
                                        const Anchor& subject = AnchorSubject());

// A summary table (maps won per anchor, median and worst size ratio) and,
// when any map is lost, a table of the losses with both sizes. `goal`: the
// text calls winning every map the goal (else a comparison).
std::vector<NamedTable> AnchorTables(const std::vector<MapResult>& results,
                                     const Anchor& subject = AnchorSubject(), bool goal = true);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_ANCHORS_H_
