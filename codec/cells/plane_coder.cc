#include "codec/cells/plane_coder.h"

#include <array>

#include "format/range_coder.h"

namespace linemap {
namespace {

// A width x height bit plane with padding (2 cells left and right, 2 rows
// below row 0, 1 row above the last), so the templates never test bounds.
class PaddedPlane {
 public:
  PaddedPlane(int width, int height, std::uint8_t pad)
      : stride_(static_cast<std::size_t>(width) + 4),
        bits_(stride_ * (static_cast<std::size_t>(height) + 3), pad) {}
  std::size_t At(int col, int row) const {
    return (static_cast<std::size_t>(row) + 2) * stride_ + static_cast<std::size_t>(col) + 2;
  }
  std::uint8_t& operator[](std::size_t i) { return bits_[i]; }
  std::uint8_t operator[](std::size_t i) const { return bits_[i]; }
  std::size_t stride() const { return stride_; }

 private:
  std::size_t stride_;
  std::vector<std::uint8_t> bits_;
};

// RollingTemplate's registers hold column k-2 of the previous row in bit k
// and column k-1 of the row before in bit k; these tables move those bits
// to their places in the template's context.
constexpr std::array<std::uint16_t, 32> AboveBits() {
  std::array<std::uint16_t, 32> t{};
  for (unsigned r = 0; r < 32; ++r) {
    t[r] = static_cast<std::uint16_t>((r & 1) << 5 | (r >> 1 & 1) << 2 | (r >> 2 & 1) << 3 |
                                      (r >> 3 & 1) << 4 | (r >> 4 & 1) << 6);
  }
  return t;
}
constexpr std::array<std::uint16_t, 8> Above2Bits() {
  std::array<std::uint16_t, 8> t{};
  for (unsigned r = 0; r < 8; ++r) {
    t[r] = static_cast<std::uint16_t>((r & 1) << 8 | (r >> 1 & 1) << 7 | (r >> 2 & 1) << 9);
  }
  return t;
}
constexpr std::array<std::uint16_t, 32> kAboveBits = AboveBits();
constexpr std::array<std::uint16_t, 8> kAbove2Bits = Above2Bits();

// The 10-cell causal template (spec "Plane template"): W (context bit 0),
// WW (1), the previous row's columns -1, 0, +1, -2, +2 (bits 2-6) and the
// row before's columns 0, -1, +1 (bits 7-9). Reads bit 0 of each byte (the
// FREE plane keeps more in the others). The scan keeps the template in
// shift registers as it moves east, loading two cells per step instead of
// ten: the plane coders spend most of their time here.
class RollingTemplate {
 public:
  // At column 0 of `row`.
  RollingTemplate(const PaddedPlane& g, int row)
      : g_(g), above_index_(g.At(0, row) - g.stride()), above2_index_(above_index_ - g.stride()) {
    const std::size_t i = g.At(0, row);
    west_ = Bit(i - 1) | Bit(i - 2) << 1;
    above_ = Bit(above_index_ - 2) | Bit(above_index_ - 1) << 1 | Bit(above_index_) << 2 |
             Bit(above_index_ + 1) << 3 | Bit(above_index_ + 2) << 4;
    above2_ = Bit(above2_index_ - 1) | Bit(above2_index_) << 1 | Bit(above2_index_ + 1) << 2;
  }
  unsigned Context() const { return west_ | kAboveBits[above_] | kAbove2Bits[above2_]; }
  // Moves one cell east; `bit` is bit 0 of the cell just left, as stored now.
  void Advance(unsigned bit) {
    west_ = (west_ & 1u) << 1 | bit;
    ++above_index_;
    ++above2_index_;
    // The loads past the row's end read the next row's padding, in bounds.
    above_ = above_ >> 1 | Bit(above_index_ + 2) << 4;
    above2_ = above2_ >> 1 | Bit(above2_index_ + 1) << 2;
  }

 private:
  unsigned Bit(std::size_t j) const { return g_[j] & 1u; }

  const PaddedPlane& g_;
  std::size_t above_index_;
  std::size_t above2_index_;
  unsigned west_;
  unsigned above_;
  unsigned above2_;
};

inline bool IsFree(Cell c) { return c == Cell::kFree; }
inline bool IsOccupied(Cell c) { return c == Cell::kOccupied; }

Status CheckEnd(const RangeDecoder& dec, std::size_t size, const char* plane) {
  // Decoding must read every stored byte (the zero tail it reads beyond is
  // implied), so a stream with extra bytes is corrupt.
  if (!dec.valid_start() || dec.consumed() != size) {
    return CorruptError(std::string(plane) + " range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

// The canvas's occupied cells as a padded plane, each as `occupied_value`.
PaddedPlane OccupiedPlane(const std::vector<Cell>& canvas, int width, int height,
                          std::uint8_t occupied_value) {
  PaddedPlane occ(width, height, 0);
  for (int row = 0; row < height; ++row) {
    // Row pointers, so that the compiler vectorises the copy.
    const Cell* from = canvas.data() + static_cast<std::size_t>(row) * width;
    std::uint8_t* to = &occ[occ.At(0, row)];
    for (int col = 0; col < width; ++col) {
      to[col] = IsOccupied(from[col]) ? occupied_value : 0;
    }
  }
  return occ;
}

// OCCP context: the template over the occupancy so far (cells the canvas
// already holds as occupied count, also ahead of the scan), the canvas
// occupancy east and on the next row, and whether the canvas cell is free.
inline unsigned OccupiedContext(const RollingTemplate& t, const PaddedPlane& g, std::size_t i,
                                bool canvas_free) {
  return t.Context() | g[i + 1] << 10 | g[i + g.stride()] << 11 | (canvas_free ? 1u : 0u) << 12;
}
constexpr unsigned kOccupiedContexts = 1u << 13;

// The FREE plane holds two bits per cell: bit 0 the free bits coded so far,
// bit 1 the canvas occupancy (one array rather than two: the decoder's peak
// memory and the encoder's fresh memory per candidate).
constexpr std::uint8_t kFreeBit = 1;
constexpr std::uint8_t kCanvasOccupiedBit = 2;

// FREE context: the template over the free bits, the canvas occupancy at the
// four neighbours, and whether the canvas cell is free.
inline unsigned FreeContext(const RollingTemplate& t, const PaddedPlane& fo, std::size_t i,
                            bool canvas_free) {
  const std::size_t s = fo.stride();
  const auto occ = [&](std::size_t j) { return static_cast<unsigned>(fo[j]) >> 1; };
  return t.Context() | occ(i - 1) << 10 | occ(i + 1) << 11 | occ(i - s) << 12 | occ(i + s) << 13 |
         (canvas_free ? 1u : 0u) << 14;
}
constexpr unsigned kFreeContexts = 1u << 15;

}  // namespace

std::vector<std::uint8_t> EncodeOccupiedPlane(const std::vector<std::uint8_t>& target,
                                              const std::vector<Cell>& canvas, int width,
                                              int height) {
  PaddedPlane g = OccupiedPlane(canvas, width, height, 1);
  BitModelTable models(kOccupiedContexts);
  RangeEncoder enc;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    RollingTemplate t(g, row);
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      if (!IsOccupied(canvas[cell])) {
        const int bit = target[cell] ? 1 : 0;
        enc.Encode(&models[OccupiedContext(t, g, i, IsFree(canvas[cell]))], bit);
        g[i] = static_cast<std::uint8_t>(bit);
      }
      t.Advance(g[i]);
    }
  }
  enc.Finish();
  return enc.bytes();
}

Status DecodeOccupiedPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas) {
  PaddedPlane g = OccupiedPlane(*canvas, width, height, 1);
  BitModelTable models(kOccupiedContexts);
  RangeDecoder dec(data, size);
  std::vector<Cell>& cv = *canvas;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    RollingTemplate t(g, row);
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      if (!IsOccupied(cv[cell]) &&
          dec.Decode(&models[OccupiedContext(t, g, i, IsFree(cv[cell]))])) {
        g[i] = 1;
        cv[cell] = Cell::kOccupied;
      }
      t.Advance(g[i]);
    }
  }
  return CheckEnd(dec, size, "OCCP");
}

std::vector<std::uint8_t> EncodeFreePlane(const std::vector<std::uint8_t>& target,
                                          const std::vector<Cell>& canvas, int width, int height) {
  PaddedPlane fo = OccupiedPlane(canvas, width, height, kCanvasOccupiedBit);
  BitModelTable models(kFreeContexts);
  RangeEncoder enc;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    RollingTemplate t(fo, row);
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = fo.At(col, row);
      unsigned bit = 0;
      if (!IsOccupied(canvas[cell])) {
        bit = target[cell] ? 1 : 0;
        enc.Encode(&models[FreeContext(t, fo, i, IsFree(canvas[cell]))], static_cast<int>(bit));
        if (bit) fo[i] |= kFreeBit;
      }
      t.Advance(bit);
    }
  }
  enc.Finish();
  return enc.bytes();
}

Status DecodeFreePlane(const std::uint8_t* data, std::size_t size, int width, int height,
                       std::vector<Cell>* canvas) {
  PaddedPlane fo = OccupiedPlane(*canvas, width, height, kCanvasOccupiedBit);
  BitModelTable models(kFreeContexts);
  RangeDecoder dec(data, size);
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    RollingTemplate t(fo, row);
    for (int col = 0; col < width; ++col, ++cell) {
      Cell& c = (*canvas)[cell];
      const std::size_t i = fo.At(col, row);
      unsigned bit = 0;
      if (!IsOccupied(c)) {
        bit = static_cast<unsigned>(dec.Decode(&models[FreeContext(t, fo, i, IsFree(c))]));
        if (bit) fo[i] |= kFreeBit;
        c = bit ? Cell::kFree : Cell::kUnknown;
      }
      t.Advance(bit);
    }
  }
  return CheckEnd(dec, size, "FREE");
}

namespace {

constexpr unsigned kResidualContexts = 81 * 27;

// RESD context: the true values already decoded at W, N, NW, NE (unknown
// outside the grid) and the lossy canvas at the cell, east and next row.
inline unsigned ResidualContext(const std::vector<Cell>& truth, const std::vector<Cell>& canvas,
                                int width, int height, int col, int row) {
  const std::size_t i = static_cast<std::size_t>(row) * width + col;
  auto t = [&](int dc, int dr) -> unsigned {
    const int c = col + dc;
    const int r = row + dr;
    if (c < 0 || c >= width || r < 0) return 2;
    return static_cast<unsigned>(truth[static_cast<std::size_t>(r) * width + c]);
  };
  const unsigned lc = static_cast<unsigned>(canvas[i]);
  const unsigned le = col + 1 < width ? static_cast<unsigned>(canvas[i + 1]) : 2u;
  const unsigned ls = row + 1 < height ? static_cast<unsigned>(canvas[i + width]) : 2u;
  const unsigned causal = t(-1, 0) + 3 * t(0, -1) + 9 * t(-1, -1) + 27 * t(1, -1);
  return (causal * 27 + lc + 3 * le + 9 * ls) * 2;
}

// The two values other than `predicted`, in increasing order.
inline Cell Alternative(Cell predicted, int which) {
  const int p = static_cast<int>(predicted);
  const int lo = p == 0 ? 1 : 0;
  const int hi = p == 2 ? 1 : 2;
  return static_cast<Cell>(which ? hi : lo);
}

}  // namespace

Status DecodeResidualPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas) {
  BitModelTable probs(2 * kResidualContexts);
  RangeDecoder dec(data, size);
  const std::vector<Cell> lossy = *canvas;
  std::vector<Cell>& truth = *canvas;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const unsigned ctx = ResidualContext(truth, lossy, width, height, col, row);
      if (dec.Decode(&probs[ctx])) {
        truth[cell] = Alternative(lossy[cell], dec.Decode(&probs[ctx + 1]));
      }
    }
  }
  return CheckEnd(dec, size, "RESD");
}

}  // namespace linemap
