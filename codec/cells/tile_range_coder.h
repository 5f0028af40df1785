// The binary range coder of the tile cell coder (spec/tile_coding.md
// "Range coder"): the LZMA range coder of format/range_coder.h with
// two-rate probability models, and an exact end: the encoder reports how
// many zero bytes it dropped from the stream's tail, the tile stores that
// count, and the decoder checks it, so that any truncation is an error.
#ifndef LINEMAP_CODEC_CELLS_TILE_RANGE_CODER_H_
#define LINEMAP_CODEC_CELLS_TILE_RANGE_CODER_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#include "format/range_coder.h"

namespace linemap {

// An adaptive bit model: the probability that the next bit is 0, in units
// of 2^-16, is the mean of a fast estimate and a slow one. The slow one is a
// running mean at first (its n-th update moves 1/2^floor(log2(n + 2)) of
// the gap, about 1/(n + 2)) and then an exponential one at 1/128, so a
// context seen a few dozen times in a tile (most of them) is estimated from
// all its uses; the fast one moves 1/4 of the gap and follows the last few
// uses (contexts are used in runs: along a wall's edge, in a patch of scan
// noise). On the tuning maps (tools/bench_tiles) this codes 1.6 % smaller
// without hints and 3.8 % smaller with them than the slow rate reaching
// 1/64 after six updates; 1/4 codes 1.5 % smaller than 1/8 for the fast
// one.
//
// All-zero bytes are the initial state (both estimates at one half are
// stored XOR 2^15), so a table of models comes zeroed from calloc.
struct TileBitModel {
  static constexpr int kFastShift = 2;
  static constexpr int kSlowShift = 7;
  static constexpr std::uint32_t kHalf = 1u << 15;
  static constexpr int kCountLimit = (1 << kSlowShift) - 2;

  std::uint16_t fast_x;  // fast estimate XOR kHalf
  std::uint16_t slow_x;  // slow estimate XOR kHalf
  // Updates so far, saturating at kCountLimit; 16 bits rather than a byte,
  // whose stores may alias anything (same size: padded to 6 bytes).
  std::uint16_t n;

  std::uint32_t p0() const { return ((fast_x ^ kHalf) + (slow_x ^ kHalf)) >> 1; }
  inline void Update(int bit);
};
static_assert(std::is_trivially_default_constructible_v<TileBitModel>);
static_assert(sizeof(TileBitModel) == 6);

// The shifts of an update after n updates, slow | fast << 4: the slow one
// floor(log2(n + 2)) capped at kSlowShift (rate ~1/(n + 2), a running mean
// at first), the fast one that capped at kFastShift.
constexpr std::array<std::uint8_t, TileBitModel::kCountLimit + 1> TileBitShifts() {
  std::array<std::uint8_t, TileBitModel::kCountLimit + 1> t{};
  for (int n = 0; n <= TileBitModel::kCountLimit; ++n) {
    int ss = 0;
    while ((n + 2) >> (ss + 1)) ++ss;
    ss = ss < TileBitModel::kSlowShift ? ss : TileBitModel::kSlowShift;
    const int fs = ss < TileBitModel::kFastShift ? ss : TileBitModel::kFastShift;
    t[static_cast<std::size_t>(n)] = static_cast<std::uint8_t>(ss | fs << 4);
  }
  return t;
}
inline constexpr std::array<std::uint8_t, TileBitModel::kCountLimit + 1> kTileBitShifts =
    TileBitShifts();

void TileBitModel::Update(int bit) {
  // The two shifts of the n-th update, from a table: in a run of cells
  // with one context the update lies on the path from one cell to the
  // next, and the table is shorter than the bit scan and the two minima.
  const int ss = kTileBitShifts[n] & 15;
  const int fs = kTileBitShifts[n] >> 4;
  std::uint32_t fast = fast_x ^ kHalf;
  std::uint32_t slow = slow_x ^ kHalf;
  if (bit == 0) {
    fast += (65536u - fast) >> fs;
    slow += (65536u - slow) >> ss;
  } else {
    fast -= fast >> fs;
    slow -= slow >> ss;
  }
  fast_x = static_cast<std::uint16_t>(fast ^ kHalf);
  slow_x = static_cast<std::uint16_t>(slow ^ kHalf);
  // Added rather than branched on: whether a model has saturated varies
  // from one cell's context to the next (fresh and well-used contexts mix
  // in every changed block), and a branch on it was mispredicted often.
  n = static_cast<std::uint16_t>(n + (n < kCountLimit ? 1 : 0));
}

// `size` models in their initial state, from calloc: fresh pages cost
// nothing until a context is first used, which matters for small tiles.
class TileModelTable {
 public:
  explicit TileModelTable(std::size_t size)
      : models_(static_cast<TileBitModel*>(std::calloc(size, sizeof(TileBitModel)))) {
    if (models_ == nullptr && size > 0) throw std::bad_alloc();
  }
  TileBitModel& operator[](std::size_t i) { return models_.get()[i]; }

 private:
  struct Free {
    void operator()(TileBitModel* p) const { std::free(p); }
  };
  std::unique_ptr<TileBitModel, Free> models_;
};

// The LZMA range coder of format/range_coder.h, driven by TileBitModels
// and by the mixer's probabilities.
class TileRangeEncoder {
 public:
  void Encode(TileBitModel* m, int bit) {
    encoder_.EncodeWithProbability(m->p0(), bit);
    m->Update(bit);
  }
  // Codes `bit` with a probability of 0 of p0 / 2^16 (1 <= p0 <= 65535)
  // given by the caller (a mixer), no model update.
  void EncodeP(std::uint32_t p0, int bit) { encoder_.EncodeWithProbability(p0, bit); }
  // Writes the final bytes, dropping up to kMaxDropped zero bytes of the
  // tail (the decoder implies them); returns how many were dropped.
  static constexpr int kMaxDropped = 7;
  int Finish() { return static_cast<int>(encoder_.Finish(kMaxDropped)); }
  const std::vector<std::uint8_t>& bytes() const { return encoder_.bytes(); }

 private:
  RangeEncoder encoder_;
};

// Never reads outside [data, data + size): past the end it reads zeros and
// counts them.
class TileRangeDecoder {
 public:
  TileRangeDecoder(const std::uint8_t* data, std::size_t size)
      : decoder_(data, size), size_(size) {}
  int Decode(TileBitModel* m) {
    const int bit = decoder_.DecodeWithProbability(m->p0());
    m->Update(bit);
    return bit;
  }
  // Decodes a bit coded with EncodeP(p0, bit).
  int DecodeP(std::uint32_t p0) { return decoder_.DecodeWithProbability(p0); }
  // True when every byte was read and exactly `dropped` zero bytes were
  // implied past the end, as the encoder's Finish() reported.
  bool EndsCleanly(int dropped) const {
    return decoder_.consumed() == size_ && decoder_.overrun() == static_cast<std::size_t>(dropped);
  }

 private:
  RangeDecoder decoder_;
  std::size_t size_;
};

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_TILE_RANGE_CODER_H_
