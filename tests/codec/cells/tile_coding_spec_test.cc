// The tile cell coder's bytes against spec/tile_coding.md: an independent
// encoder written from the spec's words must give the library's bytes for
// every model, on random grids and tiles and on the bundled maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "codec/cells/tile_hints.h"
#include "tests/codec/cells/tile_test_grids.h"

namespace linemap {
namespace {

using tile_test::BundledMaps;
using tile_test::Bytes;
using tile_test::RandomGrid;
using tile_test::RandomTile;

// An independent encoder written from spec/tile_coding.md's words, plainly
// (no row buffers, no padding, bounds tested per cell): the library's bytes
// must equal it, so the spec and the code say the same thing.
class SpecEncoder {
 public:
  // `model` as the tile's model id: for 0-3 bit 0 mixed, bit 1 every cell;
  // 4-11 the layer context without the terms of the bits of model - 4; 12
  // every cell with the mixed layer context.
  SpecEncoder(const std::vector<Cell>& cells, const std::vector<std::uint8_t>& hints, int width,
              CellRect tile, int model)
      : cells_(cells),
        hints_(hints),
        width_(width),
        t_(tile),
        model_(model),
        mixed_(model < 4 && (model & 1) != 0),
        all_cells_((model < 4 && (model & 2) != 0) || model == 12),
        layer_(model >= 4 && model <= 11),
        mixed_layer_(model == 12),
        dropped_(model >= 4 && model <= 11 ? model - 4 : 0) {}

  Bytes Encode() {
    const int tw = t_.x1 - t_.x0;
    const int th = t_.y1 - t_.y0;
    if (tw == 0 || th == 0) return {};
    const int blocks = (tw + 15) / 16;
    std::vector<int> above_block(blocks, 2), above_super((blocks + 15) / 16, 2);
    int row_state = 2;
    for (int r = 0; r < th; ++r) {
      const bool row_copy = RangeEqualsBelow(0, tw, r);
      Bit(0 + row_state * 2 + HintsSame(0, tw, r), row_copy);
      if (row_copy) {
        row_state = 1;
        std::fill(above_block.begin(), above_block.end(), 1);
        std::fill(above_super.begin(), above_super.end(), 1);
        continue;
      }
      row_state = 0;
      if (all_cells_) {
        for (int c = 0; c < tw; ++c) CodeCell(c, r);
        continue;
      }
      const std::vector<int> below_block = above_block;  // states after the row below
      int left = 2, left_super = 2;
      for (int k = 0; k * 16 < blocks; ++k) {
        const int b_end = std::min(16 * k + 16, blocks);
        const int a = 256 * k, e = std::min(256 * k + 256, tw);
        const bool super_copy = RangeEqualsBelow(a, e, r);
        Bit(kSuper + ((above_super[k] * 3 + left_super) * 2 + HintsSame(a, e, r)) * 4 +
                Uniform(a, e, r),
            super_copy);
        above_super[k] = left_super = super_copy ? 1 : 0;
        if (super_copy) {
          for (int b = 16 * k; b < b_end; ++b) above_block[b] = 1;
          left = 1;
          continue;
        }
        bool changed = false;
        for (int b = 16 * k; b < b_end; ++b) {
          const int ba = 16 * b, be = std::min(16 * b + 16, tw);
          const int above_right = b + 1 < blocks ? below_block[b + 1] : 2;
          bool copy = RangeEqualsBelow(ba, be, r);
          if (b + 1 == b_end && !changed) {
            copy = false;  // implied
          } else {
            // Model 4: LBLOCK (after LEQUAL and LOTHER) next to a drawn wall.
            const int table = layer_ && WallNear(ba, be, r) ? kEqual + 2 * 3240 : kBlock;
            Bit(table +
                    (((below_block[b] * 3 + left) * 3 + above_right) * 2 + HintsSame(ba, be, r)) *
                        4 +
                    Uniform(ba, be, r),
                copy);
          }
          if (!copy) {
            changed = true;
            for (int c = ba; c < be; ++c) CodeCell(c, r);
          }
          above_block[b] = left = copy ? 1 : 0;
        }
      }
    }
    for (int b = 15; b >= 0; --b) Code(32768, (0xA55A >> b) & 1);  // end marker
    return Finish();
  }

 private:
  static constexpr int kBlock = 6, kSuper = kBlock + 216, kEqual = kSuper + 72,
                       kOther = kEqual + 32805, kNear = kOther + 405;
  // Model 12's LEQUAL, LOTHER and WIDE (any place of their own will do).
  static constexpr int kMixedLayer = kNear + 405, kWide = kMixedLayer + 2 * 3240;
  struct Model {
    std::uint32_t fast = 32768, slow = 32768, n = 0;
  };

  int V(int c, int r) const {
    if (c < 0 || r < 0 || c >= t_.x1 - t_.x0) return 2;
    return static_cast<int>(cells_[static_cast<std::size_t>(t_.y0 + r) * width_ + t_.x0 + c]);
  }
  int H(int c, int r) const {
    return hints_.empty() ? 0 : hints_[static_cast<std::size_t>(t_.y0 + r) * width_ + t_.x0 + c];
  }
  bool RangeEqualsBelow(int a, int e, int r) const {
    for (int c = a; c < e; ++c) {
      if (V(c, r) != V(c, r - 1)) return false;
    }
    return true;
  }
  int HintsSame(int a, int e, int r) const {
    if (r == 0) return 0;
    for (int c = a; c < e; ++c) {
      if (H(c, r) != H(c, r - 1)) return 0;
    }
    return 1;
  }
  int Uniform(int a, int e, int r) const {
    for (int c = a - 1; c <= e; ++c) {
      if (V(c, r - 1) != V(a, r - 1)) return 0;
    }
    return 1 + V(a, r - 1);
  }
  // Whether bit 0 is set in a hint of columns [a, e) of rows r - 1 .. r + 1
  // (inside the tile).
  bool WallNear(int a, int e, int r) const {
    for (int rr = r - 1; rr <= r + 1; ++rr) {
      for (int c = a; c < e; ++c) {
        if (LayerH(c, rr) & 1) return true;
      }
    }
    return false;
  }
  // Model 4's hint: bits 0-3 inside the tile, 0 outside it.
  int LayerH(int c, int r) const {
    if (c < 0 || r < 0 || c >= t_.x1 - t_.x0 || r >= t_.y1 - t_.y0) return 0;
    return H(c, r) & 15;
  }
  // Model 4 ("Layer context"): class and pattern as the spec's table says.
  void CodeLayerCell(int c, int r) {
    const int h = LayerH(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const bool wall_next =
        ((LayerH(c - 1, r) | LayerH(c + 1, r) | LayerH(c, r - 1) | LayerH(c, r + 1)) & 1) != 0;
    int other_class = hc;
    if (!(dropped_ & 4) && hc != 1 && !wall_next) other_class += 20;
    int layer_class = other_class;
    if (!(dropped_ & 1) && LayerH(c - 1, r) != h) layer_class += 5;
    if (!(dropped_ & 2) && LayerH(c, r - 1) != h) layer_class += 10;
    const int w = V(c - 1, r), v = V(c, r);
    const int pattern = ((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1);
    const int ctx = pattern * 40 + layer_class;
    Bit(kEqual + ctx, v == w);
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kEqual + 3240 + pattern * 40 + other_class, v == hi);
  }
  // The layer classes of section 5.2 (`dropped_` terms left out).
  void LayerClasses(int c, int r, int* layer_class, int* other_class) const {
    const int h = LayerH(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const bool wall_next =
        ((LayerH(c - 1, r) | LayerH(c + 1, r) | LayerH(c, r - 1) | LayerH(c, r + 1)) & 1) != 0;
    *other_class = hc;
    if (!(dropped_ & 4) && hc != 1 && !wall_next) *other_class += 20;
    *layer_class = *other_class;
    if (!(dropped_ & 1) && LayerH(c - 1, r) != h) *layer_class += 5;
    if (!(dropped_ & 2) && LayerH(c, r - 1) != h) *layer_class += 10;
  }
  // Step 4's template T of cell (c, r) (W the least significant digit).
  int Template(int c, int r) const {
    return V(c - 1, r) +
           3 * (V(c - 2, r) +
                3 * (V(c - 2, r - 1) +
                     3 * (V(c - 1, r - 1) +
                          3 * (V(c, r - 1) +
                               3 * (V(c + 1, r - 1) + 3 * (V(c + 2, r - 1) + 3 * V(c, r - 2)))))));
  }
  // Model 12 (section 5.3): EQUAL, LEQUAL, NEAR and WIDE mixed where EQUAL
  // is unsure; LEQUAL learns from every cell.
  void CodeMixedLayerCell(int c, int r) {
    const int h = H(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    int layer_class = 0, other_class = 0;
    LayerClasses(c, r, &layer_class, &other_class);
    const int w = V(c - 1, r), v = V(c, r);
    const int t = Template(c, r);
    const int pattern = ((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1);
    const int a = kEqual + t * 5 + hc;
    const int b = kMixedLayer + pattern * 40 + layer_class;
    const int near = kNear + pattern * 5 + hc;
    const int wide = kWide + t * 9 + V(c - 1, r - 2) * 3 + V(c + 1, r - 2);
    const std::uint32_t p_equal = P0(models_[a]);
    if (p_equal < 2048 || p_equal > 63488) {
      Bit(a, v == w);
      Update(models_[b], v == w);
    } else {
      const int inputs[4] = {a, b, near, wide};
      const int set = other_class * 2 + (w == V(c, r - 1) ? 1 : 0);
      MixedBitOf(inputs, 4, &weights12_[static_cast<std::size_t>(set) * 4], v == w);
    }
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kMixedLayer + 3240 + pattern * 40 + other_class, v == hi);
  }
  void CodeCell(int c, int r) {
    if (layer_) return CodeLayerCell(c, r);
    if (mixed_layer_) return CodeMixedLayerCell(c, r);
    const int h = H(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const int w = V(c - 1, r), v = V(c, r);
    const int t = Template(c, r);
    const int near = (((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1)) * 5 + hc;
    const std::uint32_t p_equal = P0(models_[kEqual + t * 5 + hc]);
    if (mixed_ && p_equal >= 2048 && p_equal <= 63488) {
      MixedBit(kEqual + t * 5 + hc, kNear + near, hc * 2 + (w == V(c, r - 1) ? 1 : 0), v == w);
    } else {
      Bit(kEqual + t * 5 + hc, v == w);
    }
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kOther + near, v == hi);
  }
  static std::uint32_t P0(const Model& m) { return (m.fast + m.slow) >> 1; }
  static int Squash(int d) {
    static const int kT[33] = {1,    2,    3,    6,    10,   16,   27,   45,   73,   120,  194,
                               310,  488,  747,  1101, 1546, 2047, 2549, 2994, 3348, 3607, 3785,
                               3901, 3975, 4022, 4050, 4068, 4079, 4085, 4089, 4092, 4093, 4094};
    const int k = static_cast<int>(std::floor(d / 128.0)) + 16;
    const int w = d - (k - 16) * 128;
    return (kT[k] * (128 - w) + kT[k + 1] * w + 64) / 128;
  }
  // The least d in [-2047, 2047] with Squash(d) >= p, else 2047 (found by
  // search, once per p).
  int Stretch(int p) {
    std::vector<int>& memo = stretch_memo_;
    if (memo[p] == 4096) {
      memo[p] = 2047;
      for (int d = -2047; d <= 2047; ++d) {
        if (Squash(d) >= p) {
          memo[p] = d;
          break;
        }
      }
    }
    return memo[p];
  }
  void MixedBit(int equal, int near, int set, bool one) {
    const int inputs[2] = {equal, near};
    MixedBitOf(inputs, 2, weights_[set], one);
  }
  // Section 5.1 with `n` inputs (the models at `inputs`) and weights `w`.
  void MixedBitOf(const int* inputs, int n, std::int64_t* w, bool one) {
    int st[4] = {};
    std::int64_t dot = 0;
    for (int k = 0; k < n; ++k) {
      st[k] = Stretch(static_cast<int>((65535 - P0(models_[inputs[k]])) / 16));
      dot += w[k] * st[k];
    }
    const std::int64_t d = std::clamp<std::int64_t>(
        static_cast<std::int64_t>(std::floor(static_cast<double>(dot) / 65536.0)), -2047, 2047);
    const int p1 = std::clamp(Squash(static_cast<int>(d)), 1, 4095);
    Code(static_cast<std::uint32_t>(4096 - p1) * 16, one);
    const int err = ((one ? 4096 : 0) - p1) * 2;
    for (int k = 0; k < n; ++k) {
      w[k] = std::clamp<std::int64_t>(
          w[k] + static_cast<std::int64_t>(std::floor(st[k] * err / 1024.0)), -(1 << 24), 1 << 24);
    }
    for (int k = 0; k < n; ++k) Update(models_[inputs[k]], one);
  }
  void Code(std::uint32_t p0, bool one) {
    const std::uint32_t bound = (range_ >> 16) * p0;
    if (!one) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  static void Update(Model& m, bool one) {
    const std::uint32_t ss =
        std::min(static_cast<std::uint32_t>(std::floor(std::log2(m.n + 2.0))), 7u);
    const std::uint32_t fs = std::min(ss, 2u);
    if (!one) {
      m.fast += (65536 - m.fast) >> fs;
      m.slow += (65536 - m.slow) >> ss;
    } else {
      m.fast -= m.fast >> fs;
      m.slow -= m.slow >> ss;
    }
    m.n = std::min(m.n + 1, 126u);
  }
  void Bit(int context, bool one) {
    Model& m = models_[context];
    const std::uint32_t bound = (range_ >> 16) * ((m.fast + m.slow) >> 1);
    if (!one) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    Update(m, one);
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  void ShiftLow() {
    if (low_ < 0xFF000000u || low_ >= (std::uint64_t{1} << 32)) {
      const int carry = static_cast<int>(low_ >> 32);
      out_.push_back(static_cast<std::uint8_t>(cache_ + carry));
      for (; pending_ff_ > 0; --pending_ff_)
        out_.push_back(static_cast<std::uint8_t>(0xFF + carry));
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    } else {
      ++pending_ff_;
    }
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }
  Bytes Finish() {
    for (int k = 32; k >= 0; --k) {
      const std::uint64_t v = (low_ + range_ - 1) & ~((std::uint64_t{1} << k) - 1);
      if (v >= low_) {
        low_ = v;
        break;
      }
    }
    for (int i = 0; i < 5; ++i) ShiftLow();
    out_.erase(out_.begin());
    int dropped = 0;
    while (!out_.empty() && out_.back() == 0 && dropped < 7) {
      out_.pop_back();
      ++dropped;
    }
    out_.insert(out_.begin(), static_cast<std::uint8_t>(dropped << 5 | model_));
    return out_;
  }

  const std::vector<Cell>& cells_;
  const std::vector<std::uint8_t>& hints_;
  int width_;
  CellRect t_;
  int model_;
  bool mixed_;
  bool all_cells_;
  bool layer_;
  bool mixed_layer_;
  int dropped_;  // layer terms left out: 1 change from W, 2 from N, 4 wall
  std::vector<int> stretch_memo_ = std::vector<int>(4096, 4096);  // 4096: not searched yet
  std::vector<Model> models_ = std::vector<Model>(kWide + 59049);
  std::vector<std::int64_t> weights12_ = std::vector<std::int64_t>(50 * 4, 19661);  // model 12
  std::int64_t weights_[10][2] = {{19661, 19661}, {19661, 19661}, {19661, 19661}, {19661, 19661},
                                  {19661, 19661}, {19661, 19661}, {19661, 19661}, {19661, 19661},
                                  {19661, 19661}, {19661, 19661}};
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  int pending_ff_ = 0;
  Bytes out_;
};

TEST(TileCoderTest, BytesFollowTheSpec) {
  std::mt19937 rng(31337);
  for (int iter = 0; iter < 200; ++iter) {
    // Up to 600 columns, so rows hold several super-blocks.
    const int width = static_cast<int>(rng() % 600);
    const int height = static_cast<int>(rng() % 12);
    const std::vector<Cell> cells = RandomGrid(rng, width, height);
    std::vector<std::uint8_t> hints;
    if (iter % 2) {
      hints.resize(cells.size());
      // Bits 4-7 are set in some tiles: they count in the flags' "hints same"
      // and are ignored by model 4's layer class.
      const unsigned values = iter % 4 == 1 ? 256 : 16;
      for (auto& h : hints) h = rng() % 4 == 0 ? static_cast<std::uint8_t>(rng() % values) : 0;
    }
    const CellRect tile = iter % 3 ? RandomTile(rng, width, height) : CellRect{0, 0, width, height};
    SCOPED_TRACE("iteration " + std::to_string(iter));
    const std::uint8_t* hint_ptr = hints.empty() ? nullptr : hints.data();
    EXPECT_EQ(EncodeTileCells(cells.data(), hint_ptr, width, height, tile),
              SpecEncoder(cells, hints, width, tile, 0).Encode());
    for (int model = 0; model <= 12; ++model) {
      EXPECT_EQ(EncodeTileCells(cells.data(), hint_ptr, width, height, tile,
                                static_cast<TileModel>(model)),
                SpecEncoder(cells, hints, width, tile, model).Encode())
          << "model " << model;
    }
  }
  for (const Grid& g : BundledMaps()) {
    StatusOr<std::vector<std::uint8_t>> hints = BuildLayerHints(g);
    ASSERT_TRUE(hints.ok()) << hints.status().ToString();
    const std::vector<std::uint8_t> none;
    const CellRect all{0, 0, g.width(), g.height()};
    EXPECT_EQ(EncodeTileCells(g.cells().data(), nullptr, g.width(), g.height(), all),
              SpecEncoder(g.cells(), none, g.width(), all, 0).Encode());
    for (int model = 1; model <= 12; ++model) {
      EXPECT_EQ(EncodeTileCells(g.cells().data(), hints->data(), g.width(), g.height(), all,
                                static_cast<TileModel>(model)),
                SpecEncoder(g.cells(), *hints, g.width(), all, model).Encode())
          << "model " << model;
    }
  }
}

}  // namespace
}  // namespace linemap
