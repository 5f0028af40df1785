// The contexts of the tile coder (spec/tile_coding.md sections 4 and 5): block
// sizes, the layout of a tile's table of bit models, and what the contexts
// are made of: the trinary template of the cells coded before a cell, its
// nearest cells, the class of its layer hint, the layer class of the walls,
// room borders, fills and furniture drawn around it, and the states and
// comparisons of the blocks below. Inline, for the per-cell runs
// (tile_cell_runs.h) and the scan (tile_scan.cc), the one file that
// includes them (its constants are per translation unit, which the inline
// functions read: a second file including it would need them `inline`).
#ifndef LINEMAP_CODEC_CELLS_TILE_CONTEXTS_H_
#define LINEMAP_CODEC_CELLS_TILE_CONTEXTS_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "codec/cells/tile_coder.h"
#include "codec/cells/tile_coder_internal.h"

namespace linemap::tile_coder_internal {

// Cells per block: a block of a row that equals the block below it is one
// decision; the cells of the other blocks are coded one by one, which is
// where decoding spends its time. On the tuning maps 16-cell blocks decode
// 11 % faster than 32-cell blocks for 1.7 % more bytes (32 against 16 before
// the flags had their present contexts: 4 % smaller); 8-cell blocks are
// both larger and slower (the flags cost more than the cells they skip).
constexpr int kBlockCells = 16;
// Blocks per super-block: a super-block (256 cells) that equals the row
// below is one decision, which saves the decode time of sixteen block flags
// in the quiet parts of a changing row (with 32-cell blocks: decode 7 %
// faster, 0.7 % larger; 128-cell super-blocks measure the same within the
// noise).
constexpr int kSuperBlocks = 16;

// Context counts (spec/tile_coding.md "Contexts").
constexpr unsigned kRowContexts = 3 * 2;
constexpr unsigned kBlockContexts = 3 * 3 * 3 * 2 * 4;
constexpr unsigned kSuperContexts = 3 * 3 * 2 * 4;
constexpr unsigned kHintClasses = 5;
constexpr unsigned kTemplateValues = 6561;  // 3^8 neighbour patterns
constexpr unsigned kCellContexts = kTemplateValues * kHintClasses;
constexpr unsigned kRowModel = 0;
constexpr unsigned kBlockModel = kRowModel + kRowContexts;
constexpr unsigned kSuperModel = kBlockModel + kBlockContexts;
constexpr unsigned kEqualModel = kSuperModel + kSuperContexts;
constexpr unsigned kOtherModel = kEqualModel + kCellContexts;
constexpr unsigned kNearModel = kOtherModel + 81 * kHintClasses;  // model 1 only
constexpr unsigned kModelCount = kNearModel + 81 * kHintClasses;
// The layer context (models 4-11, spec "Layer context") keeps the flag
// contexts and puts its two cell tables where models 0-3 have theirs: 81
// patterns of the nearest cells x 40 layer classes each, a table 1/10 the
// size of EQUAL's; then LBLOCK, the BLOCK table of the blocks next to a
// drawn wall.
constexpr unsigned kNearPatterns = 81;
constexpr unsigned kLayerClasses = 40;
constexpr unsigned kLayerEqualModel = kEqualModel;
constexpr unsigned kLayerOtherModel = kLayerEqualModel + kNearPatterns * kLayerClasses;
constexpr unsigned kLayerBlockModel = kLayerOtherModel + kNearPatterns * kLayerClasses;
constexpr unsigned kLayerModelCount = kLayerBlockModel + kBlockContexts;
// The mixed layer context (model 12) codes every cell of a changed row, so
// it has no block tables: EQUAL, NEAR and OTHER of the template where
// models 0-3 have them, then its own LEQUAL, LOTHER and WIDE (the 8-cell
// template with the cells two rows below beside N, NNW and NNE).
constexpr unsigned kMixedLayerEqualModel = kModelCount;
constexpr unsigned kMixedLayerOtherModel = kMixedLayerEqualModel + kNearPatterns * kLayerClasses;
constexpr unsigned kMixedLayerWideModel = kMixedLayerOtherModel + kNearPatterns * kLayerClasses;
constexpr unsigned kMixedLayerModelCount = kMixedLayerWideModel + kTemplateValues * 9;

// The hint byte's class in the cell context: the layer that predicts the
// cell most strongly wins (a wall is drawn over room fills and furniture).
constexpr std::array<std::uint8_t, 16> HintClasses() {
  std::array<std::uint8_t, 16> t{};
  for (unsigned h = 0; h < 16; ++h) {
    t[h] = (h & kHintWall)         ? 1
           : (h & kHintRoomBorder) ? 2
           : (h & kHintFurniture)  ? 3
           : (h & kHintRoomInside) ? 4
                                   : 0;
  }
  return t;
}
constexpr std::array<std::uint8_t, 16> kHintClass = HintClasses();

// Block states remembered for the row above: coded cell by cell, equal to
// the block below it (or the whole row was), or the tile's first row.
constexpr std::uint8_t kStateCoded = 0;
constexpr std::uint8_t kStateCopy = 1;
constexpr std::uint8_t kStateNone = 2;

inline LayerTerms LayerTermsOf(unsigned model) {
  const unsigned dropped = model - static_cast<unsigned>(TileModel::kLayerContext);
  LayerTerms terms;
  if (dropped & kLayerTermWestChange) terms.west_change = 0;
  if (dropped & kLayerTermNorthChange) terms.north_change = 0;
  if (dropped & kLayerTermWallNear) terms.far_from_walls = 0;
  return terms;
}

// The layer classes of cell i (spec "Layer context"), 0..39, from the hints
// (bits 0-3) of its row (`here`, `width` cells) and the rows below and
// above (zero rows outside the tile; columns outside it read as zero too,
// so no tile depends on another):
// - the hint class (0-4), as models 0-3 take it;
// - + 5 when the hint differs from W's: the cell starts a wall, a room
//   border, a furniture fill, or leaves one, so the run of W likely ends;
// - + 10 when it differs from N's (the same across rows);
// - + 20 when the cell is not on a wall and none of its four neighbours
//   is: far from the walls the map rarely changes, next to one its
//   thickness and scan noise do.
// These are what the template cannot see: a change at the cell itself
// and the cells ahead of the scan (E, the row above). The OTHER decision
// (which of the two other values) takes the class without the two change
// terms (`other`): which value follows W is a matter of what the cell is
// (wall, room, outside), and the change terms would split its few uses
// four ways (model 4 1.7 % larger at the tuning median with them).
struct LayerClasses {
  unsigned equal;  // of the "equals W" decision
  unsigned other;  // of the "which other value" decision
};

inline LayerClasses LayerClassesOf(const std::uint8_t* below, const std::uint8_t* here,
                                   const std::uint8_t* above, int i, int width,
                                   const LayerTerms& terms) {
  const unsigned h = here[i] & 15u;
  const unsigned west = i > 0 ? here[i - 1] & 15u : 0u;
  const unsigned east = i + 1 < width ? here[i + 1] & 15u : 0u;
  const unsigned hint_class = kHintClass[h];
  const unsigned north = below[i] & 15u;
  const unsigned wall_near = (west | east | north | above[i]) & kHintWall;
  const unsigned other =
      hint_class + (hint_class != 1 && wall_near == 0 ? terms.far_from_walls : 0u);
  return {other + (west != h ? terms.west_change : 0u) + (north != h ? terms.north_change : 0u),
          other};
}

// The 8-cell trinary template (spec "Cell context") of cell i: W, WW on
// this row; NWW, NW, N, NE, NEE on the row below; NN two rows below, as
// W + 3 (WW + 3 Below(i)), W the least significant digit.
inline unsigned Below(const std::uint8_t* n1, const std::uint8_t* n2, int i) {
  return n1[i - 2] +
         3u * (n1[i - 1] + 3u * (n1[i] + 3u * (n1[i + 1] + 3u * (n1[i + 2] + 3u * n2[i]))));
}

// The nearest-cells context of a cell (W, N, NW, NE and the hint class).
inline unsigned NearContext(unsigned west, const std::uint8_t* n1, int i, unsigned hint_class) {
  return (((west * 3 + n1[i]) * 3 + n1[i - 1]) * 3 + n1[i + 1]) * kHintClasses + hint_class;
}

// The hint class of `h` (kHintClass) by selects rather than a table
// lookup, so that LayerBases' loop over a block vectorises.
inline unsigned HintClassOf(unsigned h) {
  return (h & kHintWall)         ? 1u
         : (h & kHintRoomBorder) ? 2u
         : (h & kHintFurniture)  ? 3u
         : (h & kHintRoomInside) ? 4u
                                 : 0u;
}

// The layer terms of a tile as kBlockCells equal bytes each, made once per
// tile, which LayerBases loads as vectors: made from the terms in each
// block, the compiler broadcast each byte through a store and a wider load
// of it, which waited for the store (store forwarding fails on the wider
// load) in front of every coded block.
struct LayerTermBytes {
  std::uint8_t far[kBlockCells];
  std::uint8_t west_change[kBlockCells];
  std::uint8_t north_change[kBlockCells];
  explicit LayerTermBytes(const LayerTerms& terms) {
    std::memset(far, static_cast<int>(terms.far_from_walls), sizeof(far));
    std::memset(west_change, static_cast<int>(terms.west_change), sizeof(west_change));
    std::memset(north_change, static_cast<int>(terms.north_change), sizeof(north_change));
  }
};

// The layer context of `len` cells (at most kBlockCells) without W: the
// LEQUAL and LOTHER indices with W = 0 (pattern without W x 40 + the class;
// W adds W x 27 x 40 to both). Cell k reads n[k - 1 .. k + 1] of the row
// below, its hint hints[k], its W and E neighbours' hints west[k] and
// east[k] (zero outside the tile), and below[k] and above[k] of the hint
// rows around it. They depend on the hints and the row below alone, so a
// block's are computed before its cells are decoded, in a loop the
// compiler vectorises for a whole block, and the serial loop of range
// decoding is left with one load and one add per context (whole default
// files of ../shared/maps decode 4.5 % faster).
[[gnu::always_inline]] inline void LayerBases(const std::uint8_t* n, const std::uint8_t* west,
                                              const std::uint8_t* hints, const std::uint8_t* east,
                                              const std::uint8_t* below, const std::uint8_t* above,
                                              const LayerTermBytes& terms, int len,
                                              std::uint16_t* equal, std::uint16_t* other) {
  // In bytes (the class is below 40, the pattern below 27), so that a
  // vector holds 16 cells rather than 4: a third of the vector code, and
  // whole default files decode about 2 % faster than with `unsigned`.
  for (int k = 0; k < len; ++k) {
    const std::uint8_t h = hints[k] & 15;
    const std::uint8_t w = west[k] & 15;
    const std::uint8_t north = below[k] & 15;
    const std::uint8_t walls = (h | w | east[k] | north | above[k]) & kHintWall;
    // LayerClassesOf: the wall term where neither the cell nor a
    // neighbour is on a wall.
    const std::uint8_t cls = static_cast<std::uint8_t>(static_cast<std::uint8_t>(HintClassOf(h)) +
                                                       (walls != 0 ? 0 : terms.far[k]));
    const std::uint8_t changes = static_cast<std::uint8_t>(
        (w != h ? terms.west_change[k] : 0) + (north != h ? terms.north_change[k] : 0));
    const std::uint8_t pattern = static_cast<std::uint8_t>(n[k] * 9 + n[k - 1] * 3 + n[k + 1]);
    const std::uint16_t base = static_cast<std::uint16_t>(pattern * kLayerClasses + cls);
    other[k] = base;
    equal[k] = static_cast<std::uint16_t>(base + changes);
  }
}

// The 10-cell template of model 12's WIDE model: the 8-cell template and
// NNW, NNE (two rows below), without the hint class. Alone it learns too
// slowly within a tile (section 6 of the spec); in the mix it adds the
// shape of a wall two rows back where it has been seen often enough.
inline unsigned WideContext(unsigned west, unsigned west2, const std::uint8_t* n1,
                            const std::uint8_t* n2, int i) {
  return (west + 3u * (west2 + 3u * Below(n1, n2, i))) * 9u + n2[i - 1] * 3u + n2[i + 1];
}

// Whether `len` bytes at a and b are equal; `full` says len ==
// kBlockCells, which is compared inline (a library call per 16-cell block
// costs as much as coding a cell).
inline bool SameCells(const std::uint8_t* a, const std::uint8_t* b, std::size_t len, bool full) {
  if (!full) return std::memcmp(a, b, len) == 0;
  std::uint64_t x[2], y[2];
  static_assert(sizeof(x) == kBlockCells);
  std::memcpy(x, a, sizeof(x));
  std::memcpy(y, b, sizeof(y));
  return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
}

// Whether bit 0 (wall) is set in any of the `len` hints at `begin` of the
// rows below, at and above the block's row (`full`: len == kBlockCells,
// read as two 64-bit words per row).
inline bool WallNearBlock(const std::uint8_t* below, const std::uint8_t* here,
                          const std::uint8_t* above, int begin, std::size_t len, bool full) {
  if (!full) {
    unsigned any = 0;
    for (std::size_t c = 0; c < len; ++c) {
      any |= below[begin + c] | here[begin + c] | above[begin + c];
    }
    return (any & kHintWall) != 0;
  }
  std::uint64_t w[6];
  static_assert(sizeof(w) == 3 * kBlockCells);
  std::memcpy(w, below + begin, kBlockCells);
  std::memcpy(w + 2, here + begin, kBlockCells);
  std::memcpy(w + 4, above + begin, kBlockCells);
  constexpr std::uint64_t kWallBytes = 0x0101010101010101u * kHintWall;
  return ((w[0] | w[1] | w[2] | w[3] | w[4] | w[5]) & kWallBytes) != 0;
}

}  // namespace linemap::tile_coder_internal

#endif  // LINEMAP_CODEC_CELLS_TILE_CONTEXTS_H_
