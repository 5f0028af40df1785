// The per-cell loops of the tile coder, where decoding spends its time: the
// cells of a row that differs from the row below, coded one by one with the
// template (models 0-3), the layer context (models 4-11) or the mixed layer
// context (model 12), reading the rows below from a RowRing padded so that
// no template tests bounds. Templates over the bit coder (encode or decode),
// always inlined into the scan (tile_scan.cc), the one file that includes
// them.
#ifndef LINEMAP_CODEC_CELLS_TILE_CELL_RUNS_H_
#define LINEMAP_CODEC_CELLS_TILE_CELL_RUNS_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "codec/cells/tile_contexts.h"
#include "codec/cells/tile_mixer.h"
#include "codec/cells/tile_range_coder.h"

namespace linemap::tile_coder_internal {

// Cell values as stored in the row buffers (Cell's own values).
constexpr std::uint8_t kUnknownValue = 2;

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

// Codes cells [begin, end) of the row `cur` with the layer context: the
// nearest cells' pattern (W, N, NW, NE) x the layer class ("equals W";
// "which other value" takes the class without the change terms), each
// decision with its own table. The smaller pattern is what lets the layer class pay: with the
// 8-cell template x 40 classes the tables learn too slowly within a tile.
template <typename Io>
[[gnu::always_inline]] inline void CodeLayerCellRun(
    Io& io, TileModelTable& models, std::uint8_t* cur, const std::uint8_t* n1,
    const std::uint8_t* below, const std::uint8_t* here, const std::uint8_t* above, int width,
    const LayerTermBytes& terms, int begin, int end) {
  unsigned west = cur[begin - 1];
  for (int run = begin; run < end; run += kBlockCells) {
    const int len = std::min(end - run, kBlockCells);
    std::uint16_t equal[kBlockCells];
    std::uint16_t other[kBlockCells];
    const std::uint8_t* hints = here + run;
    if (len == kBlockCells && run > 0 && run + kBlockCells < width) {
      // A whole block inside the tile (vectorised, its length known to
      // the compiler): W's and E's hints read from the row itself.
      LayerBases(n1 + run, hints - 1, hints, hints + 1, below + run, above + run, terms,
                 kBlockCells, equal, other);
    } else {
      // At the tile's sides: the row's hints with zeros beside them.
      std::uint8_t row[kBlockCells + 2];
      row[0] = run > 0 ? hints[-1] : 0;
      std::memcpy(row + 1, hints, static_cast<std::size_t>(len));
      row[len + 1] = run + len < width ? hints[len] : 0;
      if (len == kBlockCells) {
        LayerBases(n1 + run, row, row + 1, row + 2, below + run, above + run, terms, kBlockCells,
                   equal, other);
      } else {
        LayerBases(n1 + run, row, row + 1, row + 2, below + run, above + run, terms, len, equal,
                   other);
      }
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
  const LayerTermBytes* term_bytes;  // the same terms, for LayerBases
};

}  // namespace linemap::tile_coder_internal

#endif  // LINEMAP_CODEC_CELLS_TILE_CELL_RUNS_H_
