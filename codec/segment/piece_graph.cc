// PieceGraph (piece_graph.h): the merge tree's pieces, the passages between
// them, and their merging into rooms.
#include "codec/segment/piece_graph.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>

namespace linemap::segment_internal {

namespace {

// A piece as held in the forest while it is numbered: -2 - piece, below the
// -1 of "no room space" and the cell indices of the forest.
constexpr std::int32_t Code(std::int32_t piece) { return -2 - piece; }  // its own inverse

// Codes back into pieces (the -1 of "no room space" stays).
void DecodePieces(std::vector<std::int32_t>* forest) {
  for (std::int32_t& v : *forest) v = v < -1 ? Code(v) : v;
}

}  // namespace

PieceGraph::PieceGraph(std::vector<std::int32_t> parent,
                       const std::vector<std::uint16_t>& clearance,
                       const std::vector<Contact>& contacts)
    : piece_of_(std::move(parent)) {
  // In cell order, pieces numbered as their first cells come: each cell's
  // entry becomes its piece, coded, as it is met, so that later cells find
  // it by their first step up; a root ahead of the cell takes its piece's
  // code when the piece's first cell is met, and the cells walked up to it
  // take it too (a walk passes them once). One pass over the forest, not
  // one to point every cell at its root and one to number the pieces.
  // The areas are counted by runs of cells of one piece (most of a row's
  // room cells lie in one piece): an increment of the piece's area per
  // cell waited each time on the one before it.
  std::vector<std::int32_t>& forest = piece_of_;
  std::int32_t run_code = -1;  // the coded piece of the run (-1: none yet)
  std::size_t run = 0;
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const std::int32_t up = forest[i];
    if (up == -1) continue;  // no room space
    // Most cells point at a root, or at a cell met before: coded already.
    std::int32_t coded = up < -1 ? up : forest[up];
    if (coded >= -1) coded = Code(PieceAbove(up, clearance));
    forest[i] = coded;
    if (coded != run_code) {
      if (run > 0) area_[Code(run_code)] += run;
      run_code = coded;
      run = 0;
    }
    ++run;
  }
  if (run > 0) area_[Code(run_code)] += run;
  DecodePieces(&forest);
  parent_.resize(area_.size());
  for (std::size_t k = 0; k < parent_.size(); ++k) parent_[k] = static_cast<std::int32_t>(k);
  adjacency_.resize(area_.size());
  for (const Contact& contact : contacts) {
    const std::int32_t a = piece_of_[contact.cell];
    const std::int32_t b = piece_of_[contact.other];
    if (a != b) Connect(a, b, {contact.clearance, contact.width, contact.cell});
  }
}

std::int32_t PieceGraph::PieceAbove(std::int32_t cell,
                                    const std::vector<std::uint16_t>& clearance) {
  std::vector<std::int32_t>& forest = piece_of_;
  std::int32_t x = cell;
  std::int32_t piece;
  for (;;) {
    const std::int32_t up = forest[x];
    if (up < -1) {  // met before, or walked over
      piece = Code(up);
      break;
    }
    if (up == x) {  // the root of a piece not met yet
      piece = static_cast<std::int32_t>(area_.size());
      area_.push_back(0);
      peak_.push_back(clearance[x]);  // a root is its piece's highest cell
      forest[x] = Code(piece);
      break;
    }
    x = up;
  }
  for (x = cell; forest[x] >= 0;) {
    const std::int32_t up = forest[x];
    forest[x] = Code(piece);
    x = up;
  }
  return piece;
}

void PieceGraph::Connect(std::int32_t a, std::int32_t b, const PieceEdge& edge) {
  // The widest contact: the highest clearance, then the widest passage.
  const auto wider = [&](const PieceEdge& than) {
    return edge.clearance > than.clearance ||
           (edge.clearance == than.clearance && edge.width > than.width);
  };
  PieceEdge& ab = adjacency_[a][b];
  if (wider(ab)) ab = edge;
  PieceEdge& ba = adjacency_[b][a];
  if (wider(ba)) ba = edge;
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

}  // namespace linemap::segment_internal
