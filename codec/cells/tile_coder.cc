#include "codec/cells/tile_coder.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <type_traits>

#include "codec/cells/tile_mixer.h"
#include "codec/cells/tile_range_coder.h"

namespace linemap {
namespace {

// Cell values as stored in the row buffers (Cell's own values).
constexpr std::uint8_t kUnknownValue = 2;

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

// The first byte of a tile's data: bits 0-4 name the model the cells were
// coded with, bits 5-7 count the zero bytes dropped from the stream's end.
constexpr std::uint8_t kModelMask = 31;
constexpr int kDroppedShift = 5;

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

// Encoder and decoder share one scan (CodeTile) so that their contexts
// cannot drift apart; these adapters either code the known bit or decode it.
class EncodeIo {
 public:
  static constexpr bool kEncoding = true;
  int Code(TileBitModel* m, int bit) {
    enc_.Encode(m, bit);
    return bit;
  }
  int CodeP(std::uint32_t p0, int bit) {
    enc_.EncodeP(p0, bit);
    return bit;
  }
  TileRangeEncoder& encoder() { return enc_; }

 private:
  TileRangeEncoder enc_;
};

class DecodeIo {
 public:
  static constexpr bool kEncoding = false;
  DecodeIo(const std::uint8_t* data, std::size_t size) : dec_(data, size) {}
  int Code(TileBitModel* m, int /*bit*/) { return dec_.Decode(m); }
  int CodeP(std::uint32_t p0, int /*bit*/) { return dec_.DecodeP(p0); }
  const TileRangeDecoder& decoder() const { return dec_; }

 private:
  TileRangeDecoder dec_;
};

// Three rows of the tile (the row being coded and the two below it), each
// with two unknown cells of padding at both ends, so that the template never
// tests bounds. Rows below the tile's first row are all unknown.
class RowRing {
 public:
  explicit RowRing(int tile_width)
      : stride_(static_cast<std::size_t>(tile_width) + 4), cells_(3 * stride_, kUnknownValue) {}
  std::uint8_t* Row(int r) { return &cells_[static_cast<std::size_t>(r % 3) * stride_ + 2]; }

 private:
  std::size_t stride_;
  std::vector<std::uint8_t> cells_;
};

// The addends of the layer class's terms (LayerClassesOf): a tile of model
// 4 + d drops the terms of the LayerTerm bits of d (their addend is 0).
struct LayerTerms {
  unsigned west_change = 5, north_change = 10, far_from_walls = 20;
};

LayerTerms LayerTermsOf(unsigned model) {
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

// Codes cells [begin, end) of the row `cur` one by one. Each is coded as
// "equals W" and, if not, as which of the two other values it is.
// Model 1 mixes where the template's estimate of "equals W" lies between
// 1/32 and 31/32; where it is surer, mixing would not change the cost but
// would cost decode time (most coded cells are sure).
constexpr std::uint32_t kSureLow = 65536 / 32;
constexpr std::uint32_t kSureHigh = 65536 - 65536 / 32;
// Mixer weight sets: hint class x (W == N).
constexpr int kMixerSets = static_cast<int>(kHintClasses) * 2;
// Model 12's weight sets: layer class without the change terms (0..24) x
// (W == N).
constexpr int kMixedLayerSets = 25 * 2;
static_assert(kMixedLayerSets == 2 * (4 + 20 + 1), "the classes without change terms: 0..24");

// The nearest-cells context of a cell (W, N, NW, NE and the hint class).
inline unsigned NearContext(unsigned west, const std::uint8_t* n1, int i, unsigned hint_class) {
  return (((west * 3 + n1[i]) * 3 + n1[i - 1]) * 3 + n1[i + 1]) * kHintClasses + hint_class;
}

// The value of a cell that is not W: one of the two others, `lo` < `hi`,
// decided with model `m` (bit 1 means hi).
template <typename Io>
[[gnu::always_inline]] inline unsigned CodeOtherValue(Io& io, TileBitModel* m, unsigned west,
                                                      unsigned v) {
  const unsigned lo = west == 0 ? 1 : 0;
  const unsigned hi = west == 2 ? 1 : 2;
  return io.Code(m, v == hi) ? hi : lo;
}

// Codes cells [begin, end) of the row `cur` one by one. Each is coded as
// "equals W" and, if not, as which of the two other values it is. With
// kMix (model 1), an unsure "equals W" is coded with the logistic mix of
// the template's model and the nearest cells' model.
template <bool kMix, typename Io, typename Mixer>
[[gnu::always_inline]] inline void CodeCellRun(Io& io, TileModelTable& models, Mixer& mixer,
                                               std::uint8_t* cur, const std::uint8_t* n1,
                                               const std::uint8_t* n2, const std::uint8_t* hint_row,
                                               int begin, int end) {
  // W and WW are carried in registers rather than read back from `cur`
  // (a store-to-load round trip on the path from one cell to the next);
  // the rest of the template (Below) reads rows already coded.
  unsigned west = cur[begin - 1];
  unsigned west2 = cur[begin - 2];
  for (int i = begin; i < end; ++i) {
    const unsigned hc = kHintClass[hint_row[i] & 15];
    const unsigned ctx = (west + 3u * (west2 + 3u * Below(n1, n2, i))) * kHintClasses + hc;
    const unsigned v = Io::kEncoding ? cur[i] : 0;
    TileBitModel& equal = models[kEqualModel + ctx];
    int eq;
    if (!kMix || equal.p0() < kSureLow || equal.p0() > kSureHigh) {
      eq = io.Code(&equal, v == west);
    } else {
      TileBitModel& near = models[kNearModel + NearContext(west, n1, i, hc)];
      const std::uint32_t inputs[2] = {equal.p0(), near.p0()};
      const std::uint32_t p0 = mixer.Mix(inputs, static_cast<int>(hc * 2 + (west == n1[i])));
      eq = io.CodeP(p0, v == west);
      mixer.Update(eq);
      equal.Update(eq);
      near.Update(eq);
    }
    unsigned value = west;
    if (!eq) {
      // Which of the two others is decided by the nearest neighbours alone
      // (W, N, NW, NE and the hint): a smaller table, learned faster.
      value = CodeOtherValue(io, &models[kOtherModel + NearContext(west, n1, i, hc)], west, v);
    }
    cur[i] = static_cast<std::uint8_t>(value);
    west2 = west;
    west = value;
  }
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

// The layer context of cells [begin, begin + len) without W: the LEQUAL
// and LOTHER indices with W = 0 (pattern without W x 40 + the class;
// W adds W x 27 x 40 to both). They depend on the hints and the row below
// alone, so a block's are computed before its cells are decoded, in a
// loop the compiler vectorises for a whole block, and the serial loop of
// range decoding is left with one load and one add per context (whole
// default files of ../shared/maps decode 4.5 % faster).
[[gnu::always_inline]] inline void LayerBases(const std::uint8_t* n1, const std::uint8_t* below,
                                              const std::uint8_t* here, const std::uint8_t* above,
                                              int width, const LayerTerms& terms, int begin,
                                              int len, std::uint16_t* equal, std::uint16_t* other) {
  // The row's hints with W's and E's beside them: zero outside the tile.
  std::uint8_t row[kBlockCells + 2];
  row[0] = begin > 0 ? here[begin - 1] : 0;
  std::memcpy(row + 1, here + begin, static_cast<std::size_t>(len));
  row[len + 1] = begin + len < width ? here[begin + len] : 0;
  const std::uint8_t* n = n1 + begin;
  // In bytes (the class is below 40, the pattern below 27), so that a
  // vector holds 16 cells rather than 4: a third of the vector code, and
  // whole default files decode about 2 % faster than with `unsigned`.
  const auto far = static_cast<std::uint8_t>(terms.far_from_walls);
  const auto west_change = static_cast<std::uint8_t>(terms.west_change);
  const auto north_change = static_cast<std::uint8_t>(terms.north_change);
  for (int k = 0; k < len; ++k) {
    const std::uint8_t h = row[k + 1] & 15;
    const std::uint8_t west = row[k] & 15;
    const std::uint8_t north = below[begin + k] & 15;
    const std::uint8_t walls = (h | west | row[k + 2] | north | above[begin + k]) & kHintWall;
    // LayerClassesOf: the wall term where neither the cell nor a
    // neighbour is on a wall.
    const std::uint8_t cls = static_cast<std::uint8_t>(static_cast<std::uint8_t>(HintClassOf(h)) +
                                                       (walls != 0 ? 0 : far));
    const std::uint8_t changes =
        static_cast<std::uint8_t>((west != h ? west_change : 0) + (north != h ? north_change : 0));
    const std::uint8_t pattern = static_cast<std::uint8_t>(n[k] * 9 + n[k - 1] * 3 + n[k + 1]);
    const std::uint16_t base = static_cast<std::uint16_t>(pattern * kLayerClasses + cls);
    other[k] = base;
    equal[k] = static_cast<std::uint16_t>(base + changes);
  }
}

// Codes cells [begin, end) of the row `cur` with the layer context: the
// nearest cells' pattern (W, N, NW, NE) x the layer class ("equals W";
// "which other value" takes the class without the change terms), each
// decision with its own table. The smaller pattern is what lets the layer class pay: with the
// 8-cell template x 40 classes the tables learn too slowly within a tile.
template <typename Io>
[[gnu::always_inline]] inline void CodeLayerCellRun(Io& io, TileModelTable& models,
                                                    std::uint8_t* cur, const std::uint8_t* n1,
                                                    const std::uint8_t* below,
                                                    const std::uint8_t* here,
                                                    const std::uint8_t* above, int width,
                                                    const LayerTerms& terms, int begin, int end) {
  unsigned west = cur[begin - 1];
  for (int run = begin; run < end; run += kBlockCells) {
    const int len = std::min(end - run, kBlockCells);
    std::uint16_t equal[kBlockCells];
    std::uint16_t other[kBlockCells];
    // A whole block with its length known to the compiler (vectorised).
    if (len == kBlockCells) {
      LayerBases(n1, below, here, above, width, terms, run, kBlockCells, equal, other);
    } else {
      LayerBases(n1, below, here, above, width, terms, run, len, equal, other);
    }
    for (int k = 0; k < len; ++k) {
      const unsigned w = west * (27 * kLayerClasses);
      const unsigned v = Io::kEncoding ? cur[run + k] : 0;
      unsigned value = west;
      if (!io.Code(&models[kLayerEqualModel + w + equal[k]], v == west)) {
        value = CodeOtherValue(io, &models[kLayerOtherModel + w + other[k]], west, v);
      }
      cur[run + k] = static_cast<std::uint8_t>(value);
      west = value;
    }
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

// Codes cells [begin, end) of the row `cur` with the mixed layer context
// (model 12): "equals W" is predicted by the 8-cell template x hint class
// (as models 0-3); where that is unsure it is mixed with the nearest
// cells' pattern x layer class (as models 4-11), the nearest cells x hint
// class (NEAR) and the 10-cell template (WIDE), with a weight set per
// layer class (without the change terms) and W == N. The template sees
// the shapes of the cells coded so far, the layer class what they cannot:
// the walls, borders and fills ahead of the scan.
template <typename Io>
[[gnu::always_inline]] inline void CodeMixedLayerCellRun(
    Io& io, TileModelTable& models, TileMixer<4>& mixer, std::uint8_t* cur, const std::uint8_t* n1,
    const std::uint8_t* n2, const std::uint8_t* below, const std::uint8_t* here,
    const std::uint8_t* above, int width, const LayerTerms& terms, int begin, int end) {
  unsigned west = cur[begin - 1];
  unsigned west2 = cur[begin - 2];
  for (int i = begin; i < end; ++i) {
    const unsigned hc = kHintClass[here[i] & 15];
    const unsigned ctx = (west + 3u * (west2 + 3u * Below(n1, n2, i))) * kHintClasses + hc;
    const unsigned pattern = ((west * 3 + n1[i]) * 3 + n1[i - 1]) * 3 + n1[i + 1];
    const LayerClasses classes = LayerClassesOf(below, here, above, i, width, terms);
    const unsigned v = Io::kEncoding ? cur[i] : 0;
    TileBitModel& equal = models[kEqualModel + ctx];
    TileBitModel& layer = models[kMixedLayerEqualModel + pattern * kLayerClasses + classes.equal];
    int eq;
    if (equal.p0() < kSureLow || equal.p0() > kSureHigh) {
      eq = io.Code(&equal, v == west);
      layer.Update(eq);
    } else {
      TileBitModel& near = models[kNearModel + NearContext(west, n1, i, hc)];
      TileBitModel& wide = models[kMixedLayerWideModel + WideContext(west, west2, n1, n2, i)];
      const std::uint32_t inputs[4] = {equal.p0(), layer.p0(), near.p0(), wide.p0()};
      const std::uint32_t pm =
          mixer.Mix(inputs, static_cast<int>(classes.other * 2 + (west == n1[i])));
      eq = io.CodeP(pm, v == west);
      mixer.Update(eq);
      equal.Update(eq);
      layer.Update(eq);
      near.Update(eq);
      wide.Update(eq);
    }
    unsigned value = west;
    if (!eq) {
      const unsigned other_ctx = pattern * kLayerClasses + classes.other;
      value = CodeOtherValue(io, &models[kMixedLayerOtherModel + other_ctx], west, v);
    }
    cur[i] = static_cast<std::uint8_t>(value);
    west2 = west;
    west = value;
  }
}

// The rows a run of cells reads: the row being coded and the two below
// it; the hints of the row and (layer context) of the rows below and
// above it, zero rows outside the tile.
struct CellRows {
  std::uint8_t* cur;
  const std::uint8_t* n1;
  const std::uint8_t* n2;
  const std::uint8_t* hint_row;
  const std::uint8_t* hint_below;
  const std::uint8_t* hint_above;
  int width;
  LayerTerms terms;
};

template <bool kMix, bool kLayer, typename Io, typename Mixer>
void CodeCellsIn(Io& io, TileModelTable& models, Mixer& mixer, const CellRows& rows, int begin,
                 int end) {
  if constexpr (kLayer && kMix) {
    CodeMixedLayerCellRun(io, models, mixer, rows.cur, rows.n1, rows.n2, rows.hint_below,
                          rows.hint_row, rows.hint_above, rows.width, rows.terms, begin, end);
  } else if constexpr (kLayer) {
    CodeLayerCellRun(io, models, rows.cur, rows.n1, rows.hint_below, rows.hint_row, rows.hint_above,
                     rows.width, rows.terms, begin, end);
  } else {
    CodeCellRun<kMix>(io, models, mixer, rows.cur, rows.n1, rows.n2, rows.hint_row, begin, end);
  }
}

// The decoder's state in a local for the run (see CodeTile): the cells
// are stored as bytes, which may alias any object, so a decoder reached
// through a reference would be reloaded from memory after every cell.
template <bool kMix, bool kLayer, typename Io, typename Mixer>
void CodeCells(Io& io, TileModelTable& models, Mixer& mixer, const CellRows& rows, int begin,
               int end) {
  if constexpr (Io::kEncoding) {
    CodeCellsIn<kMix, kLayer>(io, models, mixer, rows, begin, end);
  } else {
    Io local = io;
    CodeCellsIn<kMix, kLayer>(local, models, mixer, rows, begin, end);
    io = local;
  }
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

// A tile's rows as the scan reads and writes them (the encoder reads
// `cells`, the decoder writes `canvas`; `hints` null = all zero).
struct TileRows {
  int width = 0, height = 0;
  const Cell* cells = nullptr;
  std::ptrdiff_t cell_stride = 0;
  Cell* canvas = nullptr;
  std::ptrdiff_t canvas_stride = 0;
  // Decoder: `hints` may be the canvas's own rows (DecodeTileRowsOverHints):
  // the scan writes row r's cells only once row r + 1 has read row r's
  // hints, and reads no hints of the rows below that.
  const std::uint8_t* hints = nullptr;
  std::ptrdiff_t hint_stride = 0;
  LayerTerms layer_terms;  // of the layer context (models 4-11)
  // Decoder: the rows to decode, from the tile's first (1..height; a
  // window that ends inside the tile needs no more; DecodeTile refuses
  // others). The scan is the same up to there, so those rows decode
  // exactly as in a full decode.
  int rows_wanted = -1;
};

// The scan shared by encoder and decoder (spec "Scan"). `cells` is read by
// the encoder, `canvas` written by the decoder; `hints` is width*height.
template <bool kMix, bool kFlags, bool kLayer, typename Io>
void CodeTileScan(Io& io, const TileRows& t) {
  const int tw = t.width;
  const int th = t.height;
  const std::uint8_t* hints = t.hints;
  const int blocks = (tw + kBlockCells - 1) / kBlockCells;
  TileModelTable models(kLayer && kMix ? kMixedLayerModelCount
                        : kLayer       ? kLayerModelCount
                                       : kModelCount);
  // Model 12 mixes four predictions, models 1 and 3 two.
  using Mixer = std::conditional_t<kLayer && kMix, TileMixer<4>, TileMixer<2>>;
  Mixer mixer(kLayer && kMix ? kMixedLayerSets : kMix ? kMixerSets : 0);
  RowRing ring(tw);
  std::vector<std::uint8_t> above_state(static_cast<std::size_t>(blocks), kStateNone);
  std::vector<std::uint8_t> above_super(
      static_cast<std::size_t>((blocks + kSuperBlocks - 1) / kSuperBlocks), kStateNone);
  // Without layers every hint is zero: all rows read this one (the layer
  // context reads it for the rows outside the tile as well).
  const std::vector<std::uint8_t> zero_hints(
      hints == nullptr || kLayer ? static_cast<std::size_t>(tw) : 0, 0);
  unsigned row_state = kStateNone;
  const int rows_end = Io::kEncoding ? th : t.rows_wanted;
  for (int r = 0; r < rows_end; ++r) {
    std::uint8_t* cur = ring.Row(r + 2);
    const std::uint8_t* n1 = ring.Row(r + 1);
    const std::uint8_t* n2 = ring.Row(r);
    const std::uint8_t* hint_row = hints ? hints + r * t.hint_stride : zero_hints.data();
    // The hints one row below (read only for r > 0: inside the tile). With
    // the hints in the canvas, that row's cells are not written yet.
    const std::uint8_t* hint_below =
        !hints || r == 0 ? zero_hints.data() : hint_row - t.hint_stride;
    if constexpr (Io::kEncoding) {
      std::memcpy(cur, t.cells + r * t.cell_stride, static_cast<std::size_t>(tw));
    }
    const std::uint8_t* hint_above =
        hints && r + 1 < th ? hint_row + t.hint_stride : zero_hints.data();
    const CellRows cell_rows{cur, n1, n2, hint_row, hint_below, hint_above, tw, t.layer_terms};
    const bool hints_same =
        r > 0 && (hints == nullptr || std::memcmp(hint_row, hint_below, tw) == 0);
    const unsigned row_ctx = row_state * 2 + (hints_same ? 1 : 0);
    const int row_copy =
        io.Code(&models[kRowModel + row_ctx], Io::kEncoding && std::memcmp(cur, n1, tw) == 0);
    if (row_copy) {
      if constexpr (!Io::kEncoding) std::memcpy(cur, n1, static_cast<std::size_t>(tw));
      std::fill(above_state.begin(), above_state.end(), kStateCopy);
      std::fill(above_super.begin(), above_super.end(), kStateCopy);
      row_state = kStateCopy;
    } else if (!kFlags) {
      CodeCells<kMix, kLayer>(io, models, mixer, cell_rows, 0, tw);
      row_state = kStateCoded;
    } else {
      unsigned left = kStateNone;
      unsigned super_left = kStateNone;
      for (int sb = 0; sb < blocks; sb += kSuperBlocks) {
        const int sb_end = std::min(sb + kSuperBlocks, blocks);
        const int s_begin = sb * kBlockCells;
        const int s_end = std::min(sb_end * kBlockCells, tw);
        const std::size_t s_len = static_cast<std::size_t>(s_end - s_begin);
        const std::size_t si = static_cast<std::size_t>(sb / kSuperBlocks);
        // Hints equal over the row are equal over each of its parts: no
        // comparison then (and likewise for a super-block's blocks).
        const bool super_hints_same =
            hints_same ||
            (r > 0 && (hints == nullptr ||
                       std::memcmp(hint_row + s_begin, hint_below + s_begin, s_len) == 0));
        const unsigned super_uniform =
            std::memcmp(n1 + s_begin - 1, n1 + s_begin, s_len + 1) == 0 ? 1u + n1[s_begin] : 0u;
        const unsigned super_ctx =
            ((above_super[si] * 3 + super_left) * 2 + (super_hints_same ? 1 : 0)) * 4 +
            super_uniform;
        const int super_copy =
            io.Code(&models[kSuperModel + super_ctx],
                    Io::kEncoding && std::memcmp(cur + s_begin, n1 + s_begin, s_len) == 0);
        super_left = super_copy ? kStateCopy : kStateCoded;
        above_super[si] = static_cast<std::uint8_t>(super_left);
        if (super_copy) {
          if constexpr (!Io::kEncoding) std::memcpy(cur + s_begin, n1 + s_begin, s_len);
          for (int b = sb; b < sb_end; ++b) above_state[b] = kStateCopy;
          left = kStateCopy;
          continue;
        }
        bool changed = false;
        for (int b = sb; b < sb_end; ++b) {
          const int begin = b * kBlockCells;
          const int end = std::min(begin + kBlockCells, tw);
          const std::size_t len = static_cast<std::size_t>(end - begin);
          const bool full = len == kBlockCells;
          const bool block_hints_same =
              super_hints_same ||
              (r > 0 &&
               (hints == nullptr || SameCells(hint_row + begin, hint_below + begin, len, full)));
          const unsigned above_right = b + 1 < blocks ? above_state[b + 1] : kStateNone;
          // Whether the row below is one value over the block and its two
          // neighbours (and which): a uniform area rarely starts a structure.
          // (n1[begin - 1 .. end] all equal each their right neighbour.)
          const unsigned uniform =
              SameCells(n1 + begin - 1, n1 + begin, len, full) && n1[end - 1] == n1[end]
                  ? 1u + n1[begin]
                  : 0u;
          const unsigned ctx =
              ((((above_state[b] * 3 + left) * 3 + above_right) * 2 + (block_hints_same ? 1 : 0)) *
                   4 +
               uniform);
          // The super-block differs, so when every block before the last was
          // equal, the last one differs: no decision.
          // Layer context: a block next to a drawn wall changes more often
          // than one in the open (LBLOCK; 0.6 % smaller at the tuning median
          // with the file's layers).
          const bool wall_near =
              kLayer && WallNearBlock(hint_below, hint_row, cell_rows.hint_above, begin, len, full);
          const int copy =
              b + 1 == sb_end && !changed
                  ? 0
                  : io.Code(&models[(wall_near ? kLayerBlockModel : kBlockModel) + ctx],
                            Io::kEncoding && SameCells(cur + begin, n1 + begin, len, full));
          if (copy) {
            if constexpr (!Io::kEncoding) {
              if (full) {
                std::memcpy(cur + begin, n1 + begin, kBlockCells);
              } else {
                std::memcpy(cur + begin, n1 + begin, len);
              }
            }
          } else {
            CodeCells<kMix, kLayer>(io, models, mixer, cell_rows, begin, end);
            changed = true;
          }
          left = copy ? kStateCopy : kStateCoded;
          above_state[b] = static_cast<std::uint8_t>(left);
        }
      }
      row_state = kStateCoded;
    }
    // The decoder writes a row's cells one row late, once the row above
    // it has read its hints: with the hints in the canvas (a tile decoded
    // over its hints), they are still there to read, not copied aside row
    // by row (1 % of the decode time over ../shared/maps).
    if constexpr (!Io::kEncoding) {
      if (r > 0) {
        std::memcpy(t.canvas + (r - 1) * t.canvas_stride, n1, static_cast<std::size_t>(tw));
      }
    }
  }
  if constexpr (!Io::kEncoding) {
    if (rows_end > 0) {
      std::memcpy(t.canvas + (rows_end - 1) * t.canvas_stride, ring.Row(rows_end + 1),
                  static_cast<std::size_t>(tw));
    }
  }
}

// The decoder's state is copied into a local for the scan: the cells and
// the models' counts are stored as bytes, which may alias any object, so
// a decoder reached through a reference would be reloaded from memory after
// every cell; a local whose address is never taken stays in registers
// (decode ~10 % faster).
template <bool kMix, bool kFlags, bool kLayer, typename Io>
void CodeTile(Io& io, const TileRows& t) {
  if constexpr (Io::kEncoding) {
    CodeTileScan<kMix, kFlags, kLayer>(io, t);
  } else {
    Io local = io;
    CodeTileScan<kMix, kFlags, kLayer>(local, t);
    io = local;
  }
}

// After the cells, 16 bits of a fixed value at probability 1/2 each: data
// cut short or altered decodes other cells, and then, but for a chance of
// 2^-16, another value here; the end check on the bytes read alone misses
// the truncations that happen to read as many bytes as the stream holds.
constexpr unsigned kEndMarker = 0xA55A;

template <typename Io>
unsigned CodeEndMarker(Io& io) {
  unsigned value = 0;
  for (int b = 15; b >= 0; --b) {
    value = value << 1 | static_cast<unsigned>(io.CodeP(1u << 15, (kEndMarker >> b) & 1));
  }
  return value;
}

bool TileInside(CellRect t, int width, int height) {
  return width >= 0 && height >= 0 && t.x0 >= 0 && t.y0 >= 0 && t.x0 <= t.x1 && t.y0 <= t.y1 &&
         t.x1 <= width && t.y1 <= height;
}

// Runs the scan of `model` (models 0-3: bit 0 mixed, bit 1 every cell of
// a changed row, no block flags; models 4-11: block flags, layer context
// with the terms model - 4 drops).
template <typename Io>
void CodeTileAs(Io& io, TileRows rows, unsigned model) {
  switch (model) {
    case 0:
      return CodeTile<false, true, false>(io, rows);
    case 1:
      return CodeTile<true, true, false>(io, rows);
    case 2:
      return CodeTile<false, false, false>(io, rows);
    case 3:
      return CodeTile<true, false, false>(io, rows);
    case static_cast<unsigned>(TileModel::kMixedLayerAllCells):
      return CodeTile<true, false, true>(io, rows);
    default:
      rows.layer_terms = LayerTermsOf(model);
      return CodeTile<false, true, true>(io, rows);
  }
}

// Codes the tile's cells and the end marker; returns the tile's bytes.
std::vector<std::uint8_t> EncodeTile(const TileRows& rows, TileModel model) {
  if (rows.width <= 0 || rows.height <= 0) return {};
  EncodeIo io;
  CodeTileAs(io, rows, static_cast<unsigned>(model));
  CodeEndMarker(io);
  const int dropped = io.encoder().Finish();
  std::vector<std::uint8_t> out;
  out.reserve(io.encoder().bytes().size() + 1);
  out.push_back(static_cast<std::uint8_t>(static_cast<unsigned>(model) | dropped << kDroppedShift));
  out.insert(out.end(), io.encoder().bytes().begin(), io.encoder().bytes().end());
  return out;
}

Status DecodeTile(const std::uint8_t* data, std::size_t size, const TileRows& rows) {
  if (rows.width == 0 || rows.height == 0) {
    if (size != 0) return CorruptError("tile cells: an empty tile has data");
    return Status::Ok();
  }
  if (rows.rows_wanted < 1 || rows.rows_wanted > rows.height) {
    return InvalidArgumentError("tile cells: rows wanted " + std::to_string(rows.rows_wanted) +
                                " of " + std::to_string(rows.height));
  }
  if (size == 0) return CorruptError("tile cells: no data");
  const unsigned model = data[0] & kModelMask;
  if (model > static_cast<unsigned>(TileModel::kMixedLayerAllCells)) {
    return CorruptError("tile cells: unknown model " + std::to_string(model));
  }
  DecodeIo io(data + 1, size - 1);
  CodeTileAs(io, rows, model);
  // A tile decoded in part ends before its end marker: the chunk's CRC has
  // checked its bytes, and the range decoder never reads past them.
  if (rows.rows_wanted < rows.height) return Status::Ok();
  if (CodeEndMarker(io) != kEndMarker) {
    return CorruptError("tile cells: range-coded data is malformed or truncated");
  }
  // Decoding must read every stored byte and imply exactly the zero bytes
  // the encoder dropped, so extra or missing bytes mean the data is corrupt.
  if (!io.decoder().EndsCleanly(data[0] >> kDroppedShift)) {
    return CorruptError("tile cells: range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

// The rows of `tile` inside a width-wide grid.
TileRows GridTile(int width, CellRect tile, const std::uint8_t* hints) {
  TileRows rows;
  rows.width = tile.x1 - tile.x0;
  rows.height = tile.y1 - tile.y0;
  const std::size_t origin = static_cast<std::size_t>(tile.y0) * width + tile.x0;
  if (hints != nullptr) rows.hints = hints + origin;
  rows.hint_stride = rows.cell_stride = rows.canvas_stride = width;
  rows.rows_wanted = rows.height;
  return rows;
}

}  // namespace

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile) {
  return EncodeTileCells(cells, hints, width, height, tile, TileModel::kTemplate);
}

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile, TileModel model) {
  if (!TileInside(tile, width, height) || tile.x0 == tile.x1 || tile.y0 == tile.y1) return {};
  TileRows rows = GridTile(width, tile, hints);
  rows.cells = cells + (static_cast<std::size_t>(tile.y0) * width + tile.x0);
  return EncodeTile(rows, model);
}

Status DecodeTileCells(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                       int width, int height, CellRect tile, Cell* canvas) {
  if (!TileInside(tile, width, height)) {
    return InvalidArgumentError("tile [" + std::to_string(tile.x0) + ", " +
                                std::to_string(tile.x1) + ") x [" + std::to_string(tile.y0) + ", " +
                                std::to_string(tile.y1) + ") lies outside the " +
                                std::to_string(width) + " x " + std::to_string(height) + " grid");
  }
  TileRows rows = GridTile(width, tile, hints);
  rows.canvas = canvas + (static_cast<std::size_t>(tile.y0) * width + tile.x0);
  return DecodeTile(data, size, rows);
}

std::vector<std::uint8_t> EncodeTileRows(const Cell* cells, std::ptrdiff_t cell_stride,
                                         const std::uint8_t* hints, std::ptrdiff_t hint_stride,
                                         int tile_width, int tile_height, TileModel model) {
  TileRows rows;
  rows.width = tile_width;
  rows.height = tile_height;
  rows.cells = cells;
  rows.cell_stride = cell_stride;
  rows.hints = hints;
  rows.hint_stride = hint_stride;
  return EncodeTile(rows, model);
}

namespace {

// The rows a decode writes into `canvas`, reading `hints`; refuses a
// negative size and rows wanted outside 1..tile_height (0 for an empty
// tile).
StatusOr<TileRows> CanvasRows(int tile_width, int tile_height, int rows_wanted, Cell* canvas,
                              std::ptrdiff_t canvas_stride, const std::uint8_t* hints,
                              std::ptrdiff_t hint_stride) {
  if (tile_width < 0 || tile_height < 0) {
    return InvalidArgumentError("tile of " + std::to_string(tile_width) + " x " +
                                std::to_string(tile_height) + " cells");
  }
  if (rows_wanted < std::min(tile_height, 1) || rows_wanted > tile_height) {
    return InvalidArgumentError("rows wanted " + std::to_string(rows_wanted) + " of a tile of " +
                                std::to_string(tile_height));
  }
  TileRows rows;
  rows.width = tile_width;
  rows.height = tile_height;
  rows.canvas = canvas;
  rows.canvas_stride = canvas_stride;
  rows.hints = hints;
  rows.hint_stride = hint_stride;
  rows.rows_wanted = rows_wanted;
  return rows;
}

}  // namespace

Status DecodeTileRows(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                      std::ptrdiff_t hint_stride, int tile_width, int tile_height, int rows_wanted,
                      Cell* canvas, std::ptrdiff_t canvas_stride) {
  LINEMAP_ASSIGN_OR_RETURN(TileRows rows, CanvasRows(tile_width, tile_height, rows_wanted, canvas,
                                                     canvas_stride, hints, hint_stride));
  return DecodeTile(data, size, rows);
}

Status DecodeTileRowsOverHints(const std::uint8_t* data, std::size_t size, int tile_width,
                               int tile_height, int rows_wanted, Cell* canvas,
                               std::ptrdiff_t canvas_stride) {
  LINEMAP_ASSIGN_OR_RETURN(
      TileRows rows, CanvasRows(tile_width, tile_height, rows_wanted, canvas, canvas_stride,
                                reinterpret_cast<const std::uint8_t*>(canvas), canvas_stride));
  const Status status = DecodeTile(data, size, rows);
  if (!status.ok()) {
    // Rows not reached still hold hints, which are no cells: the rows
    // wanted and the one after them, whose hints were read.
    for (int r = 0; r < std::min(tile_height, rows_wanted + 1); ++r) {
      std::fill_n(canvas + r * canvas_stride, tile_width, Cell::kUnknown);
    }
  }
  return status;
}

}  // namespace linemap
