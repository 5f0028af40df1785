// FloodMergeTree() (merge_tree.h): the flood of step 3 of the room
// segmentation, from the highest clearance down.
#include "codec/segment/merge_tree.h"

#include <algorithm>
#include <cstddef>
#include <memory>

#include "codec/segment/chamfer.h"
#include "codec/segment/range_scan.h"
#include "format/large_vector.h"

namespace linemap::segment_internal {
namespace {

// Cells of the flood's order whose neighbours are fetched ahead.
constexpr std::size_t kPrefetchAhead = 48;

// The cells of the flooded levels, 1..top (ForEachInRange).
template <typename Visit>
void ForEachFlooded(const std::vector<std::uint16_t>& dist, std::uint16_t top, Visit&& visit) {
  ForEachInRange(dist.data(), dist.size(), 1, top, visit);
}

// A run [begin, end) of padded cells of one row above the flooded levels.
struct Run {
  std::int32_t begin;
  std::int32_t end;
};

// The runs of cells above `flooded_top`. The padded frame is 0, so no run
// reaches from one row into the next.
std::vector<Run> PlateauRuns(const std::vector<std::uint16_t>& dist, std::uint16_t flooded_top) {
  std::vector<Run> runs;
  ForEachRunAbove(dist.data(), dist.size(), flooded_top, [&](std::size_t begin, std::size_t end) {
    runs.push_back({static_cast<std::int32_t>(begin), static_cast<std::int32_t>(end)});
  });
  return runs;
}

// Joins the sets of the run-first cells a and b, keeping the lower root.
void JoinRuns(std::vector<std::int32_t>& parent, std::int32_t a, std::int32_t b) {
  a = FindRoot(parent, a);
  b = FindRoot(parent, b);
  if (a < b) std::swap(a, b);
  parent[a] = b;
}

// The flood above `flooded_top` (the highest level the flood visits cell by
// cell), where every piece that meets another joins it: the pieces at that
// level are then the 4-connected components of the cells above it, each
// rooted at one of its highest cells, which is all the flood below reads
// of them (a piece's peak, and which piece a cell is in). A raster pass
// finds them reading the grid in order, where the flood would visit those
// cells level by level all over the map: in the open halls of a warehouse
// most free cells lie more than a door's half-width from any wall. Cells at
// `flooded_top` and below keep parent -1.
// Only the parents it leaves matter (each cell at its component's first
// cell in raster order, that cell at the component's first highest cell,
// which is its own root), not how the components were found: they are
// joined run by run (a run of a row joins the runs above it that it
// overlaps), which reads a plateau's cells a few at a time.
void JoinPlateaus(const std::vector<std::uint16_t>& dist, int pw, std::uint16_t flooded_top,
                  std::vector<std::int32_t>* parent_out) {
  std::vector<std::int32_t>& parent = *parent_out;
  std::int32_t* p = parent.data();
  const std::vector<Run> runs = PlateauRuns(dist, flooded_top);
  // 1. Each run's cells point at its first cell, which joins the runs above
  //    it overlaps; the lower root is kept, so a component's root is its
  //    first cell in raster order, and every parent is a run's first cell
  //    before it (or itself).
  std::size_t above = 0;  // the first run that may reach under the next ones
  for (const Run& run : runs) {
    std::fill(p + run.begin, p + run.end, run.begin);
    const std::int32_t lo = run.begin - pw, hi = run.end - pw;
    // Both loops stop at the run itself at the latest (a run is shorter
    // than a row).
    while (runs[above].end <= lo) ++above;
    for (std::size_t k = above; runs[k].begin < hi; ++k) JoinRuns(parent, runs[k].begin, run.begin);
  }
  // 2. Each cell points at its component's first cell, whose entry holds
  //    the component's number coded -2 - k meanwhile (a run's parent is the
  //    first cell of a run before it, final by then); each component keeps
  //    its highest cell, the first of them in raster order.
  constexpr auto code = [](std::int32_t k) { return -2 - k; };  // its own inverse
  std::vector<std::int32_t> first, highest;
  for (const Run& run : runs) {
    const std::int32_t up = p[run.begin];
    std::int32_t k;
    if (up == run.begin) {
      k = static_cast<std::int32_t>(first.size());
      first.push_back(up);
      highest.push_back(up);
      std::fill(p + run.begin + 1, p + run.end, up);
      p[run.begin] = code(k);
    } else {
      const std::int32_t root = p[up] < 0 ? up : p[up];
      k = code(p[root]);
      std::fill(p + run.begin, p + run.end, root);
    }
    std::int32_t best = highest[k];
    std::uint16_t best_dist = dist[best];
    for (std::int32_t i = run.begin; i < run.end; ++i) {
      if (dist[i] > best_dist) {
        best_dist = dist[i];
        best = i;
      }
    }
    highest[k] = best;
  }
  // 3. The highest cell becomes the root, the first cell points at it: a
  //    cell is at most two steps from its root, which the flood's finds
  //    and the piece graph's shorten as they pass.
  for (std::size_t k = 0; k < first.size(); ++k) {
    parent[first[k]] = highest[k];
    parent[highest[k]] = highest[k];
  }
}

// The number of cells of each clearance 1..flooded_top (entry d; entries 0
// and flooded_top + 1 are 0).
std::vector<std::int32_t> CountLevels(const std::vector<std::uint16_t>& dist,
                                      std::uint16_t flooded_top) {
  std::vector<std::int32_t> count(static_cast<std::size_t>(flooded_top) + 2, 0);
  ForEachFlooded(dist, flooded_top, [&](std::size_t i) { ++count[dist[i]]; });
  return count;
}

// The root of the piece of padded cell `nb`, or -1 when it is not flooded
// yet. Most cells point at their root already: found without the write of
// path halving, which would dirty the cache line all the same.
std::int32_t NeighbourRoot(std::vector<std::int32_t>& parent, std::int32_t nb) {
  const std::int32_t up = parent[nb];
  if (up < 0) return -1;
  return parent[up] == up ? up : FindRoot(parent, nb);
}

// Cell `cell` at clearance `level` meets the pieces `roots` (of its
// neighbours, -1 for none; more than one distinct): it joins the highest
// piece (the first of them on a tie), and the others join it unless they
// meet at a doorway, where their contact is kept.
void JoinAtCell(const std::vector<std::uint16_t>& dist, int pw, const DoorRule& rule,
                bool keep_wide_narrowings, std::int32_t cell, int level,
                const std::int32_t (&roots)[4], std::vector<std::int32_t>* parent_out,
                std::vector<Contact>* contacts) {
  std::vector<std::int32_t>& parent = *parent_out;
  std::int32_t distinct[4];
  int n = 0;
  for (const std::int32_t root : roots) {
    if (root >= 0 && std::find(distinct, distinct + n, root) == distinct + n) distinct[n++] = root;
  }
  // The root of a piece is one of its highest cells (its first, or the
  // one JoinPlateaus picked), so dist[root] is the piece's peak clearance.
  std::int32_t primary = distinct[0];
  for (int k = 1; k < n; ++k) {
    if (dist[distinct[k]] > dist[primary]) primary = distinct[k];
  }
  parent[cell] = primary;
  const int s = level;
  for (int k = 0; k < n; ++k) {
    const std::int32_t other = distinct[k];
    if (other == primary) continue;
    const bool narrowing =
        dist[other] >= s + rule.constriction && dist[primary] >= s + rule.constriction;
    if (narrowing && (s <= rule.max_door || keep_wide_narrowings)) {
      const int width = PassageWidth(dist, pw, cell, s, roots, primary, other);
      contacts->push_back(
          {cell, other, static_cast<std::uint16_t>(s), static_cast<std::uint16_t>(width)});
    } else {
      parent[other] = primary;
    }
  }
}

}  // namespace

int PassageWidth(const std::vector<std::uint16_t>& dist, int pw, std::int32_t cell, int s,
                 const std::int32_t (&roots)[4], std::int32_t a, std::int32_t b) {
  const std::int32_t neighbours[4] = {cell - 1, cell + 1, cell - pw, cell + pw};  // W, E, N, S
  bool second_middle = false;
  for (int k = 0; k < 4; ++k) {
    if (roots[k] == a || roots[k] == b) continue;
    second_middle |= dist[neighbours[k]] == s;
  }
  return 2 * s - kChamferSide + (second_middle ? kChamferSide : 0);
}

std::vector<Contact> FloodMergeTree(const std::vector<std::uint16_t>& dist, int pw,
                                    const DoorRule& rule, bool join_plateaus,
                                    std::vector<std::int32_t>* parent_out) {
  // With a maximum room area, spaces joined by a wide narrowing are also
  // kept apart here, to be joined afterwards while their full areas allow.
  const bool keep_wide_narrowings = rule.max_room_cells > 0;
  std::uint16_t top = 0;
  for (const std::uint16_t d : dist) top = std::max(top, d);
  // Above a door's clearance every contact joins (unless wide narrowings
  // are kept): those levels are joined by JoinPlateaus, not flooded.
  const std::uint16_t flooded_top =
      keep_wide_narrowings || !join_plateaus
          ? top
          : static_cast<std::uint16_t>(std::min<int>(top, rule.max_door));
  std::vector<std::int32_t> start = CountLevels(dist, flooded_top);
  // Cells in descending clearance: bucket `flooded_top` first.
  std::int32_t acc = 0;
  for (int d = flooded_top; d >= 1; --d) {
    const std::int32_t n = start[d];
    start[d] = acc;
    acc += n;
  }
  // Every entry is written by the pass below, so the array is not zeroed
  // first.
  const std::size_t flooded = static_cast<std::size_t>(acc);
  const std::unique_ptr<std::int32_t[]> order =
      std::make_unique_for_overwrite<std::int32_t[]>(flooded);
  AdviseHugePages(order.get(), flooded * sizeof(std::int32_t));
  ForEachFlooded(dist, flooded_top,
                 [&](std::size_t i) { order[start[dist[i]]++] = static_cast<std::int32_t>(i); });
  std::vector<std::int32_t>& parent = *parent_out;
  AssignLarge<std::int32_t>(&parent, dist.size(), -1);
  if (flooded_top < top) JoinPlateaus(dist, pw, flooded_top, &parent);
  std::vector<Contact> contacts;
  // The clearance of the cells in order, from the buckets' ends (start[d]
  // now ends bucket d; bucket `flooded_top` starts at 0): reading it from `dist`
  // would be one more cache miss per cell.
  int level = flooded_top;
  for (std::size_t k = 0; k < flooded; ++k) {
    while (k >= static_cast<std::size_t>(start[level])) --level;
    const std::int32_t cell = order[k];
    // Cells of one clearance lie all over the map: on a large map their
    // neighbours' entries are cache misses, fetched ahead here.
    if (k + kPrefetchAhead < flooded) {
      const std::int32_t* ahead = parent.data() + order[k + kPrefetchAhead];
      __builtin_prefetch(ahead - pw);
      __builtin_prefetch(ahead);
      __builtin_prefetch(ahead + pw);
    }
    // The pieces of the four neighbours (-1: not flooded yet), in the order
    // W, E, N, S.
    const std::int32_t roots[4] = {NeighbourRoot(parent, cell - 1), NeighbourRoot(parent, cell + 1),
                                   NeighbourRoot(parent, cell - pw),
                                   NeighbourRoot(parent, cell + pw)};
    // Most cells meet one piece (or none, and start one): taken without the
    // list of distinct pieces that a cell between pieces needs.
    std::int32_t first = -1;
    bool one_piece = true;
    for (const std::int32_t root : roots) {
      if (root < 0) continue;
      if (first < 0) {
        first = root;
      } else {
        one_piece &= root == first;
      }
    }
    if (first < 0) {
      parent[cell] = cell;  // a new piece; its root is its highest cell
    } else if (one_piece) {
      parent[cell] = first;
    } else {
      JoinAtCell(dist, pw, rule, keep_wide_narrowings, cell, level, roots, &parent, &contacts);
    }
  }
  return contacts;
}

}  // namespace linemap::segment_internal
