// Binary dilation and erosion (Kosteley et al., section 2, "mathematic
// morphology"; used in 3.2 A and C). Rows are packed into 64-bit words and
// every "on" cell of the structuring element contributes one shifted row, so
// any odd-sized element is supported at (on cells) x (cells / 64) word
// operations; the 5x5 square on a 4000 x 4000 map is ~6 M word operations.
#include "linemap/morphology.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstring>

namespace linemap {
namespace {

struct Offset {
  int dx = 0;
  int dy = 0;
};

std::vector<Offset> OnOffsets(const StructuringElement& element) {
  std::vector<Offset> offsets;
  for (int dy = -element.height / 2; dy <= element.height / 2; ++dy) {
    for (int dx = -element.width / 2; dx <= element.width / 2; ++dx) {
      if (element.at(dx, dy)) offsets.push_back({dx, dy});
    }
  }
  return offsets;
}

static_assert(std::endian::native == std::endian::little, "byte packing assumes little-endian");

// Bit i of the result = (byte i of the 8 bytes at `p` != 0).
inline std::uint64_t PackEightBytes(const std::uint8_t* p) {
  std::uint64_t x;
  std::memcpy(&x, p, 8);
  constexpr std::uint64_t kLow7 = 0x7f7f7f7f7f7f7f7fULL;
  // Top bit of each byte set iff the byte is non-zero, then moved to bit 0.
  x = (((x & kLow7) + kLow7) | x) >> 7 & 0x0101010101010101ULL;
  return (x * 0x0102040810204080ULL) >> 56;  // gathers byte i's bit 0 into bit i
}

// kSpreadByte[b] has byte i = bit i of b (little-endian), for unpacking.
constexpr std::array<std::uint64_t, 256> MakeSpreadTable() {
  std::array<std::uint64_t, 256> table{};
  for (int b = 0; b < 256; ++b) {
    for (int i = 0; i < 8; ++i) {
      if (b >> i & 1) table[b] |= std::uint64_t{1} << (8 * i);
    }
  }
  return table;
}
constexpr std::array<std::uint64_t, 256> kSpreadByte = MakeSpreadTable();

// Rows packed 64 cells to a word; bits past the width are always 0.
class PackedMask {
 public:
  PackedMask(int width, int height)
      : width_(width),
        height_(height),
        words_(std::max(1, (width + 63) / 64)),
        data_(static_cast<std::size_t>(words_) * std::max(height, 0), 0) {}

  static PackedMask Pack(const BinaryMask& mask) {
    PackedMask packed(mask.width, mask.height);
    for (int row = 0; row < mask.height; ++row) {
      const std::uint8_t* src = &mask.bits[mask.Index(0, row)];
      std::uint64_t* dst = packed.Row(row);
      for (int j = 0; j < packed.words_; ++j) {
        const int begin = 64 * j;
        const int count = std::min(64, mask.width - begin);
        std::uint64_t word = 0;
        if (count == 64) {
          for (int g = 0; g < 8; ++g) word |= PackEightBytes(src + begin + 8 * g) << (8 * g);
        } else {
          for (int i = 0; i < count; ++i) word |= std::uint64_t{src[begin + i] != 0} << i;
        }
        dst[j] = word;
      }
    }
    return packed;
  }

  BinaryMask Unpack() const {
    BinaryMask mask(width_, height_);
    for (int row = 0; row < height_; ++row) {
      const std::uint64_t* src = Row(row);
      std::uint8_t* dst = mask.bits.data() + mask.Index(0, row);
      for (int j = 0; j < words_; ++j) {
        const int begin = 64 * j;
        const int count = std::min(64, width_ - begin);
        const std::uint64_t word = src[j];
        if (count == 64) {
          for (int g = 0; g < 8; ++g) {
            const std::uint64_t bytes = kSpreadByte[(word >> (8 * g)) & 0xff];
            std::memcpy(dst + begin + 8 * g, &bytes, 8);
          }
        } else {
          for (int i = 0; i < count; ++i) dst[begin + i] = (word >> i) & 1;
        }
      }
    }
    return mask;
  }

  int height() const { return height_; }
  int words() const { return words_; }
  std::uint64_t* Row(int row) { return data_.data() + static_cast<std::size_t>(row) * words_; }
  const std::uint64_t* Row(int row) const {
    return data_.data() + static_cast<std::size_t>(row) * words_;
  }
  // Clears the bits past the width in the last word of `row`.
  void ClearTail(int row) {
    const int used = width_ - (words_ - 1) * 64;
    if (used < 64) Row(row)[words_ - 1] &= (std::uint64_t{1} << used) - 1;
  }
  void Fill(std::uint64_t value) { std::fill(data_.begin(), data_.end(), value); }

 private:
  int width_;
  int height_;
  int words_;
  std::vector<std::uint64_t> data_;
};

// Word j of the row shifted so that bit c of the result is bit c + k of the
// source (0 outside the row).
inline std::uint64_t ShiftedWord(const std::uint64_t* row, int words, int j, int k) {
  const int start = 64 * j + k;
  const int q = start >= 0 ? start / 64 : -((-start + 63) / 64);
  const int s = start - 64 * q;
  const std::uint64_t lo = (q >= 0 && q < words) ? row[q] : 0;
  if (s == 0) return lo;
  const std::uint64_t hi = (q + 1 >= 0 && q + 1 < words) ? row[q + 1] : 0;
  return (lo >> s) | (hi << (64 - s));
}

}  // namespace

std::size_t BinaryMask::Count() const {
  return static_cast<std::size_t>(
      std::count_if(bits.begin(), bits.end(), [](std::uint8_t b) { return b != 0; }));
}

StructuringElement StructuringElement::Square(int n) {
  StructuringElement element;
  element.width = n;
  element.height = n;
  element.on.assign(static_cast<std::size_t>(std::max(n, 0)) * std::max(n, 0), 1);
  return element;
}

StructuringElement StructuringElement::Cross3() {
  StructuringElement element;
  element.width = 3;
  element.height = 3;
  element.on = {0, 1, 0, 1, 1, 1, 0, 1, 0};
  return element;
}

bool StructuringElement::Valid() const {
  return width > 0 && height > 0 && width % 2 == 1 && height % 2 == 1 &&
         on.size() == static_cast<std::size_t>(width) * height;
}

namespace {

// out(p) = OR over b of in(p - b).
PackedMask DilatePacked(const PackedMask& in, int width, const std::vector<Offset>& offsets) {
  PackedMask out(width, in.height());
  const int words = in.words();
  for (int row = 0; row < in.height(); ++row) {
    std::uint64_t* dst = out.Row(row);
    for (const Offset& b : offsets) {
      const int src_row = row - b.dy;
      if (src_row < 0 || src_row >= in.height()) continue;
      const std::uint64_t* src = in.Row(src_row);
      for (int j = 0; j < words; ++j) dst[j] |= ShiftedWord(src, words, j, -b.dx);
    }
    out.ClearTail(row);
  }
  return out;
}

// out(p) = AND over b of in(p + b); outside the mask counts as 0.
PackedMask ErodePacked(const PackedMask& in, int width, const std::vector<Offset>& offsets) {
  PackedMask out(width, in.height());
  out.Fill(~std::uint64_t{0});
  const int words = in.words();
  for (int row = 0; row < in.height(); ++row) {
    std::uint64_t* dst = out.Row(row);
    for (const Offset& b : offsets) {
      const int src_row = row + b.dy;
      if (src_row < 0 || src_row >= in.height()) {
        std::fill(dst, dst + words, 0);
        break;
      }
      const std::uint64_t* src = in.Row(src_row);
      for (int j = 0; j < words; ++j) dst[j] &= ShiftedWord(src, words, j, b.dx);
    }
    out.ClearTail(row);
  }
  return out;
}

bool IsFullRectangle(const StructuringElement& element) {
  return std::all_of(element.on.begin(), element.on.end(), [](std::uint8_t b) { return b != 0; });
}

// A full w x h rectangle is the Minkowski sum of a 1-row and a 1-column
// element, so it runs as two passes of w and h shifts instead of w * h.
std::vector<std::vector<Offset>> Passes(const StructuringElement& element) {
  if (!IsFullRectangle(element) || element.width * element.height <= 9) {
    return {OnOffsets(element)};
  }
  std::vector<Offset> row_pass, col_pass;
  for (int dx = -element.width / 2; dx <= element.width / 2; ++dx) row_pass.push_back({dx, 0});
  for (int dy = -element.height / 2; dy <= element.height / 2; ++dy) col_pass.push_back({0, dy});
  return {row_pass, col_pass};
}

}  // namespace

BinaryMask DilateAll(const BinaryMask& mask, const std::vector<StructuringElement>& elements) {
  PackedMask packed = PackedMask::Pack(mask);
  for (const StructuringElement& element : elements) {
    assert(element.Valid());
    for (const std::vector<Offset>& pass : Passes(element)) {
      packed = DilatePacked(packed, mask.width, pass);
    }
  }
  return packed.Unpack();
}

BinaryMask ErodeAll(const BinaryMask& mask, const std::vector<StructuringElement>& elements) {
  PackedMask packed = PackedMask::Pack(mask);
  for (const StructuringElement& element : elements) {
    assert(element.Valid());
    for (const std::vector<Offset>& pass : Passes(element)) {
      packed = ErodePacked(packed, mask.width, pass);
    }
  }
  return packed.Unpack();
}

BinaryMask Dilate(const BinaryMask& mask, const StructuringElement& element) {
  return DilateAll(mask, {element});
}

BinaryMask Erode(const BinaryMask& mask, const StructuringElement& element) {
  return ErodeAll(mask, {element});
}

BinaryMask Open(const BinaryMask& mask, const StructuringElement& element) {
  assert(element.Valid());
  PackedMask packed = PackedMask::Pack(mask);
  for (const auto& pass : Passes(element)) packed = ErodePacked(packed, mask.width, pass);
  for (const auto& pass : Passes(element)) packed = DilatePacked(packed, mask.width, pass);
  return packed.Unpack();
}

BinaryMask Close(const BinaryMask& mask, const StructuringElement& element) {
  assert(element.Valid());
  PackedMask packed = PackedMask::Pack(mask);
  for (const auto& pass : Passes(element)) packed = DilatePacked(packed, mask.width, pass);
  for (const auto& pass : Passes(element)) packed = ErodePacked(packed, mask.width, pass);
  return packed.Unpack();
}

namespace {
template <typename Op>
BinaryMask CellWise(const BinaryMask& a, const BinaryMask& b, Op op) {
  assert(a.width == b.width && a.height == b.height);
  BinaryMask out(a.width, a.height);
  for (std::size_t i = 0; i < out.bits.size(); ++i)
    out.bits[i] = op(a.bits[i] != 0, b.bits[i] != 0);
  return out;
}
}  // namespace

BinaryMask Subtract(const BinaryMask& a, const BinaryMask& b) {
  return CellWise(a, b, [](bool x, bool y) { return x && !y; });
}
BinaryMask Union(const BinaryMask& a, const BinaryMask& b) {
  return CellWise(a, b, [](bool x, bool y) { return x || y; });
}
BinaryMask Intersect(const BinaryMask& a, const BinaryMask& b) {
  return CellWise(a, b, [](bool x, bool y) { return x && y; });
}

}  // namespace linemap
