// Rooms split at doorways (SegmentationMethod::kRooms), steps 1 to 3:
//   1. enclosed obstacles: furniture candidates count as room space;
//   2. clearance: chamfer 3-4 distance of every room-space cell to the
//      nearest wall or unknown cell (the map edge counts as wall);
//   3. flooding from the highest clearance down with a union-find (a merge
//      tree): pieces that meet at a doorway stay apart, all others join
//      (above a door's clearance all join, so those levels are joined in
//      one raster pass);
//      then pieces joined only through passages narrower than a door, and
//      pieces smaller than a room, are merged into their neighbours.
// The work is done on a copy of the grid padded by one wall cell on every
// side, so that neighbours are index offsets without bounds checks.
#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "codec/segment/chamfer.h"
#include "codec/segment/segment_internal.h"
#include "format/large_vector.h"

namespace linemap::segment_internal {
namespace {

// Clearances are in chamfer units (chamfer.h): 3 per side step.
constexpr int kSide = kChamferSide;
constexpr std::uint16_t kFar = kChamferFar;

// A thin shape of area A and perimeter P (cell edges) is about P / 2 long
// and 2 A / P thick, whatever its bends (an L or a T of wall between doors).
bool IsWallPiece(std::size_t cells, std::size_t perimeter, const SegmentationOptions& options,
                 double res) {
  if (perimeter == 0) return false;
  const double length = perimeter / 2.0;
  const double thickness = 2.0 * static_cast<double>(cells) / static_cast<double>(perimeter);
  return length * res >= options.wall_min_length_m &&
         thickness * res <= options.wall_max_thickness_m;
}

// Cell edges between each enclosed component and the cells around it.
std::vector<std::size_t> Perimeters(const Labeling& labels,
                                    const std::vector<std::uint8_t>& enclosed) {
  std::vector<std::size_t> perimeter(labels.components.size() + 1, 0);
  // Enclosed components stay off the map edge (TouchesEdge), so their
  // cells' neighbours are all on the map.
  const std::size_t w = static_cast<std::size_t>(labels.width);
  const std::int32_t* l = labels.labels.data();
  ForEachFlaggedCell(labels, enclosed, [&](std::size_t i) {
    const std::int32_t k = l[i];
    perimeter[k] += (l[i - 1] != k) + (l[i + 1] != k) + (l[i - w] != k) + (l[i + w] != k);
  });
  return perimeter;
}

bool TouchesEdge(const BoundingBox& box, int width, int height) {
  return box.min_col == 0 || box.min_row == 0 || box.max_col == width - 1 ||
         box.max_row == height - 1;
}

std::int32_t Find(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

// A contact between two pieces kept apart: the cell where they met, one
// cell of the other piece, and the clearance there.
struct Contact {
  std::int32_t cell;
  std::int32_t other;
  std::uint16_t clearance;
};

// Thresholds of the flooding in chamfer units.
struct DoorRule {
  int max_door = 0;                 // largest clearance of a doorway
  int min_door = 0;                 // smallest clearance of a doorway
  int constriction = 0;             // margin both pieces' peaks need over the passage
  std::int64_t max_room_cells = 0;  // 0: no limit
};

DoorRule MakeDoorRule(const SegmentationOptions& options, double res) {
  // width = 2 * clearance - 1 cell, with one cell of tolerance at each end.
  auto clearance_of_width = [&](double width_m, double slack_cells) {
    return static_cast<int>(std::lround(kSide * (width_m / res + 1.0 + slack_cells) / 2.0));
  };
  DoorRule rule;
  rule.max_door = clearance_of_width(options.max_door_width_m, 1.0);
  rule.min_door = clearance_of_width(options.min_door_width_m, -1.0);
  // Never under two cells: a single wall speck narrows a passage by one.
  rule.constriction =
      std::max(2 * kSide, static_cast<int>(std::lround(kSide * options.door_constriction_m / res)));
  rule.max_room_cells =
      options.max_room_area_m2 > 0
          ? static_cast<std::int64_t>(std::ceil(options.max_room_area_m2 / (res * res)))
          : 0;
  return rule;
}

// Cells of the flood's order whose neighbours are fetched ahead.
constexpr std::size_t kPrefetchAhead = 48;

// The first index >= i of dist[0, end) above `top`, or `end`. Most cells of
// a map are walls, unknown or within a door's clearance of a wall: where
// SSE2 is at hand they are passed over eight at a time.
std::size_t NextAbove(const std::uint16_t* dist, std::size_t i, std::size_t end,
                      std::uint16_t top) {
#if defined(__SSE2__)
  const __m128i limit = _mm_set1_epi16(static_cast<short>(top));
  const __m128i zero = _mm_setzero_si128();
  for (; i + 8 <= end; i += 8) {
    const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(dist + i));
    // The saturated difference d - top is non-zero exactly where d > top.
    if (_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_subs_epu16(d, limit), zero)) != 0xffff) break;
  }
#endif
  while (i < end && dist[i] <= top) ++i;
  return i;
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
void JoinPlateaus(const std::vector<std::uint16_t>& dist, int pw, std::uint16_t flooded_top,
                  std::vector<std::int32_t>* parent_out) {
  std::vector<std::int32_t>& parent = *parent_out;
  const auto plateau = [&](std::size_t i) { return dist[i] > flooded_top; };
  // 1. Components rooted at their first cell in raster order: a root
  //    changes only where two components meet, so paths stay short. The
  //    padded frame is 0, so the left neighbour and the one in the previous
  //    row exist.
  const std::size_t row = static_cast<std::size_t>(pw);
  const std::size_t cells = dist.size();
  const auto next = [&](std::size_t i) { return NextAbove(dist.data(), i, cells, flooded_top); };
  for (std::size_t i = next(0); i < cells; i = next(i + 1)) {
    // Inside a plateau W and N are joined already through NW (its east
    // and north neighbours): W's root is the root of all three. Most
    // plateau cells lie inside, in the open halls.
    if (plateau(i - 1) && plateau(i - row) && plateau(i - row - 1)) {
      parent[i] = Find(parent, static_cast<std::int32_t>(i - 1));
      continue;
    }
    std::int32_t root = static_cast<std::int32_t>(i);
    for (const std::size_t nb : {i - 1, i - row}) {
      if (!plateau(nb)) continue;
      std::int32_t other = Find(parent, static_cast<std::int32_t>(nb));
      if (other < root) std::swap(root, other);
      if (other != root && other != static_cast<std::int32_t>(i)) parent[other] = root;
    }
    parent[i] = root;
  }
  // 2. Each cell points at its component's first cell, whose entry holds
  //    the component's number coded -2 - k meanwhile (a cell's parent comes
  //    before it, so it is final by then); each component keeps its
  //    highest cell, the first of them in raster order.
  constexpr auto code = [](std::int32_t k) { return -2 - k; };  // its own inverse
  std::vector<std::int32_t> first, highest;
  for (std::size_t i = next(0); i < cells; i = next(i + 1)) {
    const std::int32_t up = parent[i];
    if (up == static_cast<std::int32_t>(i)) {
      parent[i] = code(static_cast<std::int32_t>(first.size()));
      first.push_back(up);
      highest.push_back(up);
      continue;
    }
    const std::int32_t root = parent[up] < 0 ? up : parent[up];
    const std::int32_t k = code(parent[root]);
    if (dist[i] > dist[highest[k]]) highest[k] = static_cast<std::int32_t>(i);
    parent[i] = root;
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
// and flooded_top + 1 are 0). Counted without a branch, in four tallies
// (cell index mod 4) summed at the end: a run of cells that share an entry
// (a wall's 0s, a hall above flooded_top, a corridor's middle) would
// otherwise wait on each increment's store before the next.
std::vector<std::int32_t> CountLevels(const std::vector<std::uint16_t>& dist,
                                      std::uint16_t flooded_top) {
  constexpr std::size_t kTallies = 4;
  const std::size_t above = static_cast<std::size_t>(flooded_top) + 1;  // levels not flooded
  const std::size_t levels = above + 1;
  std::vector<std::int32_t> tally(kTallies * levels, 0);
  const auto level = [&](std::size_t i) { return std::min<std::size_t>(dist[i], above); };
  std::size_t i = 0;
  for (; i + kTallies <= dist.size(); i += kTallies) {
    for (std::size_t k = 0; k < kTallies; ++k) ++tally[k * levels + level(i + k)];
  }
  for (; i < dist.size(); ++i) ++tally[level(i)];
  std::vector<std::int32_t> count(levels, 0);
  for (std::size_t d = 1; d < above; ++d) {
    for (std::size_t k = 0; k < kTallies; ++k) count[d] += tally[k * levels + d];
  }
  return count;
}

// Step 3a: the merge tree. Returns the contacts of pieces kept apart;
// `parent` ends as a union-find forest over padded cells (-1: no room space).
std::vector<Contact> Flood(const std::vector<std::uint16_t>& dist, int pw, const DoorRule& rule,
                           bool join_plateaus, std::vector<std::int32_t>* parent_out) {
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
  std::vector<std::int32_t> order = LargeVector<std::int32_t>(static_cast<std::size_t>(acc), 0);
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (dist[i] && dist[i] <= flooded_top) order[start[dist[i]]++] = static_cast<std::int32_t>(i);
  }
  std::vector<std::int32_t>& parent = *parent_out;
  AssignLarge<std::int32_t>(&parent, dist.size(), -1);
  if (flooded_top < top) JoinPlateaus(dist, pw, flooded_top, &parent);
  std::vector<Contact> contacts;
  const std::int32_t offsets[4] = {-1, 1, -pw, pw};
  // The clearance of the cells in order, from the buckets' ends (start[d]
  // now ends bucket d; bucket `flooded_top` starts at 0): reading it from `dist`
  // would be one more cache miss per cell.
  int level = flooded_top;
  for (std::size_t k = 0; k < order.size(); ++k) {
    while (k >= static_cast<std::size_t>(start[level])) --level;
    const std::int32_t cell = order[k];
    // Cells of one clearance lie all over the map: on a large map their
    // neighbours' entries are cache misses, fetched ahead here.
    if (k + kPrefetchAhead < order.size()) {
      const std::int32_t* ahead = parent.data() + order[k + kPrefetchAhead];
      __builtin_prefetch(ahead - pw);
      __builtin_prefetch(ahead);
      __builtin_prefetch(ahead + pw);
    }
    std::int32_t roots[4];
    int n = 0;
    for (const std::int32_t off : offsets) {
      const std::int32_t nb = cell + off;
      const std::int32_t up = parent[nb];
      if (up < 0) continue;
      // Most cells point at their root already: found without the write of
      // path halving, which would dirty the cache line all the same.
      const std::int32_t root = parent[up] == up ? up : Find(parent, nb);
      if (std::find(roots, roots + n, root) == roots + n) roots[n++] = root;
    }
    if (n == 0) {
      parent[cell] = cell;  // a new piece; its root is its highest cell
      continue;
    }
    // The root of a piece is one of its highest cells (its first, or the
    // one JoinPlateaus picked), so dist[root] is the piece's peak clearance.
    std::int32_t primary = roots[0];
    for (int k = 1; k < n; ++k) {
      if (dist[roots[k]] > dist[primary]) primary = roots[k];
    }
    parent[cell] = primary;
    const int s = level;
    for (int k = 0; k < n; ++k) {
      const std::int32_t other = roots[k];
      if (other == primary) continue;
      const bool narrowing =
          dist[other] >= s + rule.constriction && dist[primary] >= s + rule.constriction;
      if (narrowing && (s <= rule.max_door || keep_wide_narrowings)) {
        contacts.push_back({cell, other, static_cast<std::uint16_t>(s)});
      } else {
        parent[other] = primary;
      }
    }
  }
  return contacts;
}

struct PieceEdge {
  std::uint16_t clearance = 0;
  std::int32_t cell = 0;  // padded cell of the widest contact
};

// The pieces of the merge tree, their areas, peaks and the passages between
// them (widest contact per pair), and their merging (steps 3b and 3c).
class PieceGraph {
 public:
  // Takes over the flood's union-find forest (`parent`), whose storage
  // becomes the piece of each cell: a large map holds one such array, not
  // two.
  PieceGraph(std::vector<std::int32_t> parent, const std::vector<std::uint16_t>& clearance,
             const std::vector<Contact>& contacts);

  // Step 3b: pieces joined by passages wider than a door are one room, as
  // long as it stays within `max_cells` (widest passage first); then pieces
  // joined by passages narrower than a door are one room.
  void MergeWidePassages(int max_door, std::int64_t max_cells);
  void MergeNarrowPassages(int min_door);
  // Step 3c: pieces below `min_cells` join the neighbour they share the
  // widest passage with, smallest first.
  void MergeSmallPieces(std::size_t min_cells);

  // The piece of a padded cell (-1: no room space), and its final root.
  std::int32_t PieceOf(std::size_t padded_cell) const { return piece_of_[padded_cell]; }
  // Hands over the pieces of the padded cells (PieceOf() is not to be
  // called after).
  std::vector<std::int32_t> TakePieces() { return std::move(piece_of_); }
  std::int32_t Root(std::int32_t piece) { return Find(parent_, piece); }
  std::int32_t size() const { return static_cast<std::int32_t>(area_.size()); }
  std::size_t Area(std::int32_t root) const { return area_[root]; }
  std::uint16_t Peak(std::int32_t piece) const { return peak_[piece]; }
  bool IsRoot(std::int32_t piece) const { return parent_[piece] == piece; }
  const std::unordered_map<std::int32_t, PieceEdge>& Neighbours(std::int32_t root) const {
    return adjacency_[root];
  }

 private:
  void Connect(std::int32_t a, std::int32_t b, const PieceEdge& edge);
  void Merge(std::int32_t from, std::int32_t into);

  std::vector<std::int32_t> piece_of_;                                  // by padded cell
  std::vector<std::int32_t> parent_;                                    // union-find over pieces
  std::vector<std::size_t> area_;                                       // by root
  std::vector<std::uint16_t> peak_;                                     // by piece
  std::vector<std::unordered_map<std::int32_t, PieceEdge>> adjacency_;  // between roots
};

PieceGraph::PieceGraph(std::vector<std::int32_t> parent,
                       const std::vector<std::uint16_t>& clearance,
                       const std::vector<Contact>& contacts)
    : piece_of_(std::move(parent)) {
  // Every cell straight to its root first (a root is its own parent, so
  // the forest stays valid while it is rewritten).
  std::vector<std::int32_t>& forest = piece_of_;
  for (std::size_t i = 0; i < forest.size(); ++i) {
    if (forest[i] >= 0) forest[i] = Find(forest, static_cast<std::int32_t>(i));
  }
  // Then, in cell order, pieces numbered as their first cells come. A
  // root's entry turns into its piece, coded -2 - piece, when the piece's
  // first cell is met, so that the piece's later cells find it there; the
  // other cells take their pieces as they go (no later cell reads them),
  // and the roots last.
  constexpr auto code = [](std::int32_t piece) { return -2 - piece; };  // its own inverse
  std::vector<std::int32_t> root_cells;                                 // by piece
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const std::int32_t root = forest[i];
    if (root == -1) continue;  // no room space
    if (root < 0) {            // a root, coded when its piece's first cell came
      ++area_[code(root)];
      continue;
    }
    if (forest[root] >= 0) {  // the piece's first cell
      forest[root] = code(static_cast<std::int32_t>(area_.size()));
      root_cells.push_back(root);
      area_.push_back(0);
      peak_.push_back(clearance[root]);  // a root is its piece's highest cell
    }
    const std::int32_t piece = code(forest[root]);
    ++area_[piece];
    if (static_cast<std::size_t>(root) != i) forest[i] = piece;
  }
  for (std::size_t k = 0; k < root_cells.size(); ++k) {
    forest[root_cells[k]] = static_cast<std::int32_t>(k);
  }
  parent_.resize(area_.size());
  for (std::size_t k = 0; k < parent_.size(); ++k) parent_[k] = static_cast<std::int32_t>(k);
  adjacency_.resize(area_.size());
  for (const Contact& contact : contacts) {
    const std::int32_t a = piece_of_[contact.cell];
    const std::int32_t b = piece_of_[contact.other];
    if (a != b) Connect(a, b, {contact.clearance, contact.cell});
  }
}

void PieceGraph::Connect(std::int32_t a, std::int32_t b, const PieceEdge& edge) {
  PieceEdge& ab = adjacency_[a][b];
  if (edge.clearance > ab.clearance) ab = edge;
  PieceEdge& ba = adjacency_[b][a];
  if (edge.clearance > ba.clearance) ba = edge;
}

void PieceGraph::Merge(std::int32_t from, std::int32_t into) {
  parent_[from] = into;
  area_[into] += area_[from];
  std::unordered_map<std::int32_t, PieceEdge> moved = std::move(adjacency_[from]);
  adjacency_[from].clear();
  adjacency_[into].erase(from);
  for (const auto& [other, edge] : moved) {
    adjacency_[other].erase(from);
    if (other != into) Connect(into, other, edge);
  }
}

void PieceGraph::MergeWidePassages(int max_door, std::int64_t max_cells) {
  std::vector<std::tuple<std::uint16_t, std::int32_t, std::int32_t>> wide;
  for (std::int32_t a = 0; a < size(); ++a) {
    for (const auto& [b, edge] : adjacency_[a]) {
      if (a < b && edge.clearance > max_door) wide.push_back({edge.clearance, a, b});
    }
  }
  std::sort(wide.begin(), wide.end(), [](const auto& x, const auto& y) { return x > y; });
  for (const auto& [clearance, a0, b0] : wide) {
    const std::int32_t a = Root(a0);
    const std::int32_t b = Root(b0);
    if (a == b || static_cast<std::int64_t>(area_[a] + area_[b]) > max_cells) continue;
    if (area_[a] >= area_[b]) {
      Merge(b, a);
    } else {
      Merge(a, b);
    }
  }
}

void PieceGraph::MergeNarrowPassages(int min_door) {
  std::vector<std::pair<std::int32_t, std::int32_t>> narrow;
  for (std::int32_t a = 0; a < size(); ++a) {
    for (const auto& [b, edge] : adjacency_[a]) {
      if (a < b && edge.clearance < min_door) narrow.push_back({a, b});
    }
  }
  for (const auto& [a0, b0] : narrow) {
    const std::int32_t a = Root(a0);
    const std::int32_t b = Root(b0);
    if (a == b) continue;
    if (area_[a] >= area_[b]) {
      Merge(b, a);
    } else {
      Merge(a, b);
    }
  }
}

void PieceGraph::MergeSmallPieces(std::size_t min_cells) {
  using Item = std::pair<std::size_t, std::int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::int32_t k = 0; k < size(); ++k) {
    if (IsRoot(k) && area_[k] < min_cells) queue.push({area_[k], k});
  }
  while (!queue.empty()) {
    const auto [area, k] = queue.top();
    queue.pop();
    // Stale entries (merged since, or grown) and pieces alone are skipped.
    if (!IsRoot(k) || area_[k] != area || adjacency_[k].empty()) continue;
    std::int32_t best = -1;
    std::uint16_t best_clearance = 0;
    for (const auto& [other, edge] : adjacency_[k]) {
      // Widest passage, then the larger neighbour, then the lower number
      // (so that the hash map's order never decides).
      const bool wider =
          best < 0 || edge.clearance > best_clearance ||
          (edge.clearance == best_clearance &&
           (area_[other] > area_[best] || (area_[other] == area_[best] && other < best)));
      if (wider) {
        best = other;
        best_clearance = edge.clearance;
      }
    }
    Merge(k, best);
    if (area_[best] < min_cells) queue.push({area_[best], best});
  }
}

// Step 1: the obstacles the free space encloses (8-connected components of
// the non-free cells that stay off the map edge), and which of them are
// furniture candidates.
void FindFurnitureCandidates(const Grid& grid, const SegmentationOptions& options,
                             RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const double res = grid.meta.resolution;
  BinaryMask blocked(w, h);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    blocked.bits[i] = grid.cells()[i] != Cell::kFree;
  }
  flood->enclosed = LabelComponents(blocked, Connectivity::kEight);
  std::vector<std::uint8_t>& candidate = flood->furniture_candidate;
  candidate.assign(flood->enclosed.components.size() + 1, 0);
  const double max_cells = options.max_furniture_area_m2 / (res * res);
  for (std::size_t k = 0; k < flood->enclosed.components.size(); ++k) {
    const ComponentStats& stats = flood->enclosed.components[k];
    candidate[k + 1] = !TouchesEdge(stats.box, w, h) && stats.cell_count <= max_cells;
  }
  const std::vector<std::size_t> perimeter = Perimeters(flood->enclosed, candidate);
  for (std::size_t k = 1; k < candidate.size(); ++k) {
    if (candidate[k] &&
        IsWallPiece(flood->enclosed.components[k - 1].cell_count, perimeter[k], options, res)) {
      candidate[k] = 0;
    }
  }
}

// Step 2: clearance over room space (free cells and furniture
// candidates): chamfer 3-4 units on the grid padded by one cell on every
// side ((width + 2) x (height + 2)), 0 outside room space.
std::vector<std::uint16_t> ComputeClearance(const Grid& grid, RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const int pw = w + 2, ph = h + 2;
  flood->width = w;
  flood->height = h;
  std::vector<std::uint16_t> clearance =
      LargeVector<std::uint16_t>(static_cast<std::size_t>(pw) * ph, 0);
  const Cell* cells = grid.cells().data();
  for (int r = 0; r < h; ++r) {
    std::uint16_t* out = clearance.data() + static_cast<std::size_t>(r + 1) * pw + 1;
    const Cell* in = cells + grid.Index(0, r);
    for (int c = 0; c < w; ++c) out[c] = in[c] == Cell::kFree ? kFar : 0;
  }
  const std::size_t wide = static_cast<std::size_t>(w);
  ForEachFlaggedCell(flood->enclosed, flood->furniture_candidate, [&](std::size_t i) {
    clearance[(i / wide + 1) * pw + (i % wide + 1)] = kFar;
  });
  ChamferInPlace(&clearance, pw, ph);
  return clearance;
}

// Room ids in raster order of the rooms' first cells; pieces still below
// `min_cells` (free specks with no neighbour) are no rooms. Returns the room
// of each root piece (-1: none). The graph's pieces of the cells are
// rewritten into the rooms of the cells where they lie (a grid cell's index
// is below its padded cell's, so raster order reads each entry before it is
// overwritten): a large map holds one such array, not two.
std::vector<std::int32_t> NumberRooms(const Grid& grid, PieceGraph* graph, std::size_t min_cells,
                                      RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const std::size_t pw = static_cast<std::size_t>(w) + 2;
  std::vector<std::int32_t> room_of_piece(graph->size(), -1);
  // Each piece's root once, not once per cell: the union-find is final.
  std::vector<std::int32_t> root_of(graph->size());
  for (std::int32_t k = 0; k < graph->size(); ++k) root_of[k] = graph->Root(k);
  // Pieces are numbered in raster order of their first cells (PieceGraph),
  // so a room's lowest piece holds the room's first cell: numbered as their
  // pieces come, the rooms are numbered in raster order of their first cells.
  std::int32_t rooms = 0;
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    const std::int32_t root = root_of[k];
    if (graph->Area(root) >= min_cells && room_of_piece[root] < 0) room_of_piece[root] = ++rooms;
  }
  // The room of each piece, one entry up, so that "no room space" (-1)
  // reads 0 without a test per cell.
  std::vector<std::int32_t> room_of(static_cast<std::size_t>(graph->size()) + 1, 0);
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    room_of[static_cast<std::size_t>(k) + 1] = std::max(room_of_piece[root_of[k]], 0);
  }
  std::vector<std::int32_t> cells = graph->TakePieces();
  for (int r = 0; r < h; ++r) {
    const std::int32_t* in = cells.data() + (r + 1) * pw + 1;
    std::int32_t* out = cells.data() + grid.Index(0, r);
    for (int c = 0; c < w; ++c) out[c] = room_of[static_cast<std::size_t>(in[c] + 1)];
  }
  cells.resize(grid.size());
  flood->room_of_cell = std::move(cells);
  flood->room_count = rooms;
  flood->peak.assign(static_cast<std::size_t>(rooms) + 1, 0);
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    const std::int32_t room = room_of_piece[root_of[k]];
    if (room > 0) flood->peak[room] = std::max(flood->peak[room], graph->Peak(k));
  }
  return room_of_piece;
}

// The passage between each pair of neighbouring rooms, at its widest.
void ListDoors(PieceGraph* graph, const std::vector<std::int32_t>& room_of_piece, int pw,
               double res, RoomFlood* flood) {
  for (std::int32_t a = 0; a < graph->size(); ++a) {
    if (!graph->IsRoot(a) || room_of_piece[a] < 0) continue;
    for (const auto& [b, edge] : graph->Neighbours(a)) {
      if (room_of_piece[b] < 0 || room_of_piece[a] >= room_of_piece[b]) continue;
      Doorway door;
      door.room_a = room_of_piece[a];
      door.room_b = room_of_piece[b];
      door.cell = {edge.cell % pw - 1, edge.cell / pw - 1};
      door.width_m = (2.0 * edge.clearance / kSide - 1.0) * res;
      flood->doors.push_back(door);
    }
  }
  std::sort(flood->doors.begin(), flood->doors.end(), [](const Doorway& x, const Doorway& y) {
    return std::tie(x.room_a, x.room_b) < std::tie(y.room_a, y.room_b);
  });
}

}  // namespace

RoomFlood FloodRooms(const Grid& grid, const SegmentationOptions& options,
                     SegmentationTimings* timings, bool join_plateaus) {
  const double res = grid.meta.resolution;
  RoomFlood flood;
  double start = ThreadCpuMs();
  FindFurnitureCandidates(grid, options, &flood);
  std::vector<std::uint16_t> clearance = ComputeClearance(grid, &flood);
  timings->clearance_ms += ThreadCpuMs() - start;

  start = ThreadCpuMs();
  const int pw = grid.width() + 2;
  const DoorRule rule = MakeDoorRule(options, res);
  std::vector<std::int32_t> parent;
  const std::vector<Contact> contacts = Flood(clearance, pw, rule, join_plateaus, &parent);
  PieceGraph graph(std::move(parent), clearance, contacts);
  // The pieces hold their peaks: the clearance's memory is given back.
  std::vector<std::uint16_t>().swap(clearance);
  if (rule.max_room_cells > 0) graph.MergeWidePassages(rule.max_door, rule.max_room_cells);
  graph.MergeNarrowPassages(rule.min_door);
  const std::size_t min_cells =
      static_cast<std::size_t>(std::ceil(options.min_room_area_m2 / (res * res)));
  graph.MergeSmallPieces(min_cells);
  const std::vector<std::int32_t> room_of_piece = NumberRooms(grid, &graph, min_cells, &flood);
  ListDoors(&graph, room_of_piece, pw, res, &flood);
  timings->flooding_ms += ThreadCpuMs() - start;
  return flood;
}

double ClearanceCells(std::uint16_t chamfer) { return static_cast<double>(chamfer) / kSide; }

}  // namespace linemap::segment_internal
