// Binary mathematical morphology on cell masks (Kosteley et al., section 2
// and 3.2 A/C): dilation, erosion, opening and closing with any odd-sized
// structuring element, e.g. the paper's 3x3 element "with zero angle units"
// (a cross) and its full 5x5 square.
//
// Definitions (B is the set of "on" offsets of the element, centred):
//   Dilate(A, B)(p) = 1  iff  A(p - b) = 1 for some b in B
//   Erode(A, B)(p)  = 1  iff  A(p + b) = 1 for every b in B
// Cells outside the mask count as 0 for both, so erosion also eats in from
// the mask's edges. Implementation: rows packed into 64-bit words, one
// shifted OR / AND of a whole row per "on" cell of the element, so the cost
// is (on cells) x (cells / 64) word operations.
#ifndef LINEMAP_MORPHOLOGY_H_
#define LINEMAP_MORPHOLOGY_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace linemap {

// A width x height binary image in grid-row order (index row * width + col);
// any non-zero byte is "set".
struct BinaryMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> bits;

  BinaryMask() = default;
  BinaryMask(int w, int h) : width(w), height(h), bits(static_cast<std::size_t>(w) * h, 0) {}

  bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
  std::size_t Index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(col);
  }
  bool at(int col, int row) const { return bits[Index(col, row)] != 0; }
  // False outside the mask.
  bool get(int col, int row) const { return Contains(col, row) && at(col, row); }
  void set(int col, int row, bool value) { bits[Index(col, row)] = value ? 1 : 0; }
  std::size_t Count() const;
  bool operator==(const BinaryMask&) const = default;
};

// A structuring element with odd width and height, centred on its middle
// cell; `on` in row order, row 0 = offset -height/2 (grid rows).
struct StructuringElement {
  int width = 1;
  int height = 1;
  std::vector<std::uint8_t> on{1};

  // The full n x n square (n odd), e.g. the paper's 5x5 "completely
  // colored" element.
  static StructuringElement Square(int n);
  // The 3x3 element "with zero angle units": centre and its 4 neighbours.
  static StructuringElement Cross3();
  bool at(int dx, int dy) const {  // offsets from the centre
    return on[static_cast<std::size_t>(dy + height / 2) * width + (dx + width / 2)] != 0;
  }
  bool Valid() const;  // odd sizes, on.size() == width * height
};

BinaryMask Dilate(const BinaryMask& mask, const StructuringElement& element);
BinaryMask Erode(const BinaryMask& mask, const StructuringElement& element);
// The elements applied in order, without unpacking in between.
BinaryMask DilateAll(const BinaryMask& mask, const std::vector<StructuringElement>& elements);
BinaryMask ErodeAll(const BinaryMask& mask, const std::vector<StructuringElement>& elements);
BinaryMask Open(const BinaryMask& mask, const StructuringElement& element);   // erode, dilate
BinaryMask Close(const BinaryMask& mask, const StructuringElement& element);  // dilate, erode

// Cell-wise a AND NOT b (same size required).
BinaryMask Subtract(const BinaryMask& a, const BinaryMask& b);
BinaryMask Union(const BinaryMask& a, const BinaryMask& b);
BinaryMask Intersect(const BinaryMask& a, const BinaryMask& b);

}  // namespace linemap

#endif  // LINEMAP_MORPHOLOGY_H_
