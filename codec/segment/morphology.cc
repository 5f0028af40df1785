// Binary dilation and erosion (Kosteley et al., section 2, "mathematic
// morphology"; used in 3.2 A and C). Rows are packed into 64-bit words and
// every "on" cell of the structuring element contributes one shifted row, so
// any odd-sized element is supported at (on cells) x (cells / 64) word
// operations; the 5x5 square on a 4000 x 4000 map is ~6 M word operations.
#include "linemap/morphology.h"

#include <algorithm>
#include <cassert>

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
      for (int col = 0; col < mask.width; ++col) {
        if (src[col]) dst[col >> 6] |= std::uint64_t{1} << (col & 63);
      }
    }
    return packed;
  }

  BinaryMask Unpack() const {
    BinaryMask mask(width_, height_);
    for (int row = 0; row < height_; ++row) {
      const std::uint64_t* src = Row(row);
      std::uint8_t* dst = mask.bits.data() + mask.Index(0, row);
      for (int col = 0; col < width_; ++col) dst[col] = (src[col >> 6] >> (col & 63)) & 1;
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

BinaryMask Dilate(const BinaryMask& mask, const StructuringElement& element) {
  assert(element.Valid());
  const PackedMask in = PackedMask::Pack(mask);
  PackedMask out(mask.width, mask.height);
  const std::vector<Offset> offsets = OnOffsets(element);
  const int words = in.words();
  for (int row = 0; row < mask.height; ++row) {
    std::uint64_t* dst = out.Row(row);
    for (const Offset& b : offsets) {  // out(p) |= in(p - b)
      const int src_row = row - b.dy;
      if (src_row < 0 || src_row >= mask.height) continue;
      const std::uint64_t* src = in.Row(src_row);
      for (int j = 0; j < words; ++j) dst[j] |= ShiftedWord(src, words, j, -b.dx);
    }
    out.ClearTail(row);
  }
  return out.Unpack();
}

BinaryMask Erode(const BinaryMask& mask, const StructuringElement& element) {
  assert(element.Valid());
  const PackedMask in = PackedMask::Pack(mask);
  PackedMask out(mask.width, mask.height);
  out.Fill(~std::uint64_t{0});
  const std::vector<Offset> offsets = OnOffsets(element);
  const int words = in.words();
  for (int row = 0; row < mask.height; ++row) {
    std::uint64_t* dst = out.Row(row);
    for (const Offset& b : offsets) {  // out(p) &= in(p + b)
      const int src_row = row + b.dy;
      if (src_row < 0 || src_row >= mask.height) {
        std::fill(dst, dst + words, 0);
        break;
      }
      const std::uint64_t* src = in.Row(src_row);
      for (int j = 0; j < words; ++j) dst[j] &= ShiftedWord(src, words, j, b.dx);
    }
    out.ClearTail(row);
  }
  return out.Unpack();
}

BinaryMask Open(const BinaryMask& mask, const StructuringElement& element) {
  return Dilate(Erode(mask, element), element);
}

BinaryMask Close(const BinaryMask& mask, const StructuringElement& element) {
  return Erode(Dilate(mask, element), element);
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
