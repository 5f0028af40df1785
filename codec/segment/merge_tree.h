// The merge tree of the room flood (room_flood.cc, step 3a): the cells of
// room space flooded from the highest clearance down, with a union-find
// over the padded grid's cells; pieces that meet at a doorway stay apart.
#ifndef LINEMAP_CODEC_SEGMENT_MERGE_TREE_H_
#define LINEMAP_CODEC_SEGMENT_MERGE_TREE_H_

#include <cstdint>
#include <vector>

namespace linemap::segment_internal {

// The root of x, halving the path on the way.
inline std::int32_t FindRoot(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

// A contact between two pieces kept apart: the cell where they met, one
// cell of the other piece, the clearance there and the passage's width
// (PassageWidth).
struct Contact {
  std::int32_t cell;
  std::int32_t other;
  std::uint16_t clearance;
  std::uint16_t width;
};

// Thresholds of the flooding in chamfer units.
struct DoorRule {
  int max_door = 0;                 // largest clearance of a doorway
  int min_door = 0;                 // smallest clearance of a doorway
  int constriction = 0;             // margin both pieces' peaks need over the passage
  std::int64_t max_room_cells = 0;  // 0: no limit
};

// The width of the passage where pieces `a` and `b` meet at cell `cell` of
// clearance s (chamfer units, 3 per cell), in chamfer units: what is
// reported of a doorway (the rule that decides one takes the clearance). An
// opening of n cells between two walls along the grid has clearance
// 3 (n + 1) / 2 in its middle cell when n is odd, so width 2 s - 3; when n
// is even its two middle cells both have clearance 3 n / 2, so width 2 s.
// The second middle cell is a 4-neighbour of `cell` of the same clearance
// in neither piece (across the passage, not along it, where the pieces
// lie). `roots` are the pieces of the W, E, N and S neighbours (-1: not
// flooded yet). Passages at a slant are measured as the nearest of these.
int PassageWidth(const std::vector<std::uint16_t>& dist, int pw, std::int32_t cell, int s,
                 const std::int32_t (&roots)[4], std::int32_t a, std::int32_t b);

// Step 3a: the merge tree of the clearance `dist` (chamfer units, padded
// grid of row length `pw`, 0 outside room space). Returns the contacts of
// pieces kept apart; `parent_out` ends as a union-find forest over padded
// cells (-1: no room space). With `join_plateaus`, the levels above a
// door's clearance are joined in one raster pass, not flooded.
std::vector<Contact> FloodMergeTree(const std::vector<std::uint16_t>& dist, int pw,
                                    const DoorRule& rule, bool join_plateaus,
                                    std::vector<std::int32_t>* parent_out);

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_MERGE_TREE_H_
