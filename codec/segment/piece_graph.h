// The pieces of the room flood's merge tree and their merging (room_flood.cc,
// steps 3b and 3c).
#ifndef LINEMAP_CODEC_SEGMENT_PIECE_GRAPH_H_
#define LINEMAP_CODEC_SEGMENT_PIECE_GRAPH_H_

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "codec/segment/merge_tree.h"

namespace linemap::segment_internal {

struct PieceEdge {
  std::uint16_t clearance = 0;
  std::uint16_t width = 0;  // the passage's there (PassageWidth), chamfer units
  std::int32_t cell = 0;    // padded cell of the widest contact
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
  std::int32_t Root(std::int32_t piece) { return FindRoot(parent_, piece); }
  std::int32_t size() const { return static_cast<std::int32_t>(area_.size()); }
  std::size_t Area(std::int32_t root) const { return area_[root]; }
  std::uint16_t Peak(std::int32_t piece) const { return peak_[piece]; }
  bool IsRoot(std::int32_t piece) const { return parent_[piece] == piece; }
  const std::unordered_map<std::int32_t, PieceEdge>& Neighbours(std::int32_t root) const {
    return adjacency_[root];
  }

 private:
  // The piece of the cell `cell` points up from: found by walking up the
  // forest to a piece's code or a root, which then starts a new piece.
  std::int32_t PieceAbove(std::int32_t cell, const std::vector<std::uint16_t>& clearance);
  void Connect(std::int32_t a, std::int32_t b, const PieceEdge& edge);
  void Merge(std::int32_t from, std::int32_t into);

  std::vector<std::int32_t> piece_of_;                                  // by padded cell
  std::vector<std::int32_t> parent_;                                    // union-find over pieces
  std::vector<std::size_t> area_;                                       // by root
  std::vector<std::uint16_t> peak_;                                     // by piece
  std::vector<std::unordered_map<std::int32_t, PieceEdge>> adjacency_;  // between roots
};

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_PIECE_GRAPH_H_
