// Logistic mixing of bit models for the tile coder (spec/tile_coding.md
// "Mixing"), in integers only: probabilities of a 1 in units of 2^-12,
// their logits ("stretch") in units of 2^-8, as in lpaq1 (Matt Mahoney,
// public domain). A mixer combines the logits of several models with
// weights it learns online, so that a large sparse context and a small
// dense one each count where they predict well.
#ifndef LINEMAP_CODEC_CELLS_TILE_MIXER_H_
#define LINEMAP_CODEC_CELLS_TILE_MIXER_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace linemap {

// 4096 / (1 + e^(-d / 256)) for d in [-2047, 2047], interpolated from 33
// points; 0 below, 4095 above.
inline constexpr int kSquashPoints[33] = {1,    2,    3,    6,    10,   16,   27,   45,   73,
                                          120,  194,  310,  488,  747,  1101, 1546, 2047, 2549,
                                          2994, 3348, 3607, 3785, 3901, 3975, 4022, 4050, 4068,
                                          4079, 4085, 4089, 4092, 4093, 4094};
constexpr int Squash(int d) {
  if (d > 2047) return 4095;
  if (d < -2047) return 0;
  const int w = d & 127;
  const int k = (d >> 7) + 16;
  return (kSquashPoints[k] * (128 - w) + kSquashPoints[k + 1] * w + 64) >> 7;
}

// stretch(p): the least d in [-2047, 2047] with Squash(d) >= p, 2047 if none
// (the inverse of Squash on its range).
struct StretchTable {
  std::array<std::int16_t, 4096> t{};
  constexpr StretchTable() {
    int pi = 0;
    for (int x = -2047; x <= 2047; ++x) {
      const int v = Squash(x);
      for (int i = pi; i <= v; ++i) t[i] = static_cast<std::int16_t>(x);
      pi = v + 1;
    }
    for (int i = pi; i < 4096; ++i) t[i] = 2047;
  }
};
inline constexpr StretchTable kStretch{};

// A mixer of kInputs logits with one weight vector per selector value.
template <int kInputs>
class TileMixer {
 public:
  // Weights start at 0.3 each (16.16 fixed point). The learning rate 2
  // codes 3.5 % smaller than lpaq1's 7 on the tuning maps (a tile is short
  // for a mixer; a slow one does not chase noise).
  static constexpr std::int32_t kInitialWeight = 19661;
  static constexpr int kLearningRate = 2;
  static constexpr std::int32_t kWeightLimit = 1 << 24;

  explicit TileMixer(int sets)
      : weights_(static_cast<std::size_t>(sets) * kInputs, kInitialWeight) {}

  // Sets the inputs (probabilities of a 0 in units of 2^-16, as
  // TileBitModel::p0) and the weight set; returns the mixed probability of
  // a 0 in units of 2^-16, in [16, 65520].
  std::uint32_t Mix(const std::uint32_t* p0, int set) {
    w_ = &weights_[static_cast<std::size_t>(set) * kInputs];
    std::int64_t dot = 0;
    for (int k = 0; k < kInputs; ++k) {
      st_[k] = kStretch.t[(65535u - p0[k]) >> 4];
      dot += static_cast<std::int64_t>(w_[k]) * st_[k];
    }
    int d = static_cast<int>(dot >> 16);
    d = d < -2047 ? -2047 : d > 2047 ? 2047 : d;
    p1_ = Squash(d);
    p1_ = p1_ < 1 ? 1 : p1_ > 4095 ? 4095 : p1_;
    return static_cast<std::uint32_t>(4096 - p1_) << 4;
  }
  void Update(int bit) {
    const int err = ((bit << 12) - p1_) * kLearningRate;
    // Weights stay within +-2^24 (256.0), so that no sum can overflow
    // whatever the data.
    for (int k = 0; k < kInputs; ++k) {
      const std::int32_t w = w_[k] + ((st_[k] * err) >> 10);
      w_[k] = w < -kWeightLimit ? -kWeightLimit : w > kWeightLimit ? kWeightLimit : w;
    }
  }

 private:
  std::vector<std::int32_t> weights_;
  std::int32_t* w_ = nullptr;
  int st_[kInputs] = {};
  int p1_ = 2048;
};

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_TILE_MIXER_H_
