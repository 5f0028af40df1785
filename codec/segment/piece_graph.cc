// PieceGraph (piece_graph.h): the merge tree's pieces, the passages between
// them, and their merging into rooms.
#include "codec/segment/piece_graph.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>

namespace linemap::segment_internal {

PieceGraph::PieceGraph(std::vector<std::int32_t> parent,
                       const std::vector<std::uint16_t>& clearance,
                       const std::vector<Contact>& contacts)
    : piece_of_(std::move(parent)) {
  // Every cell straight to its root first (a root is its own parent, so
  // the forest stays valid while it is rewritten).
  // Most cells point at their root already: left as they are, without
  // the find's two writes.
  std::vector<std::int32_t>& forest = piece_of_;
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const std::int32_t up = forest[i];
    if (up >= 0 && forest[up] != up) forest[i] = FindRoot(forest, static_cast<std::int32_t>(i));
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

}  // namespace linemap::segment_internal
