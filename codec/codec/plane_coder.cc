#include "codec/codec/plane_coder.h"

#include "format/range_coder.h"

namespace linemap {
namespace {

// A width x height bit plane with 2 cells of zero padding on the left, right
// and below row 0, so the templates never test bounds.
class PaddedPlane {
 public:
  PaddedPlane(int width, int height, std::uint8_t pad)
      : stride_(static_cast<std::size_t>(width) + 4),
        bits_(stride_ * (static_cast<std::size_t>(height) + 2), pad) {}
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

// The 10-cell causal template (spec "Plane template"): W, WW, and the cells
// at columns -1..+1, -2, +2 of the previous row and -1..+1 two rows back.
inline unsigned Template10(const PaddedPlane& g, std::size_t i) {
  const std::size_t s = g.stride();
  const std::size_t n = i - s;
  const std::size_t nn = n - s;
  return g[i - 1] | g[i - 2] << 1 | g[n - 1] << 2 | g[n] << 3 | g[n + 1] << 4 | g[n - 2] << 5 |
         g[n + 2] << 6 | g[nn] << 7 | g[nn - 1] << 8 | g[nn + 1] << 9;
}

constexpr unsigned kTemplateContexts = 1u << 10;

inline bool IsFree(Cell c) { return c == Cell::kFree; }
inline bool IsOccupied(Cell c) { return c == Cell::kOccupied; }

// Extra context of the OCCP plane from the canvas around cell (col, row):
// bit 0 canvas cell free, bit 1 east or next-row neighbour occupied, bit 2
// any 4-neighbour free.
unsigned OccupiedCanvasContext(const std::vector<Cell>& canvas, int width, int height, int col,
                               int row) {
  const std::size_t i = static_cast<std::size_t>(row) * width + col;
  const bool e_occ = col + 1 < width && IsOccupied(canvas[i + 1]);
  const bool s_occ = row + 1 < height && IsOccupied(canvas[i + width]);
  const bool any_free =
      (col > 0 && IsFree(canvas[i - 1])) || (col + 1 < width && IsFree(canvas[i + 1])) ||
      (row > 0 && IsFree(canvas[i - width])) || (row + 1 < height && IsFree(canvas[i + width]));
  return (IsFree(canvas[i]) ? 1u : 0u) | (e_occ || s_occ ? 2u : 0u) | (any_free ? 4u : 0u);
}

Status CheckEnd(const RangeDecoder& dec, std::size_t size, const char* plane) {
  // A stream holds exactly the bytes its decoding reads (5 to start, one per
  // renormalisation), so a shorter or longer one is corrupt.
  if (!dec.valid_start() || dec.overrun() > 0 || dec.consumed() != size) {
    return CorruptError(std::string(plane) + " range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

}  // namespace

std::vector<std::uint8_t> EncodeFreePlane(const std::vector<FreeTarget>& target,
                                          const std::vector<Cell>& canvas, int width, int height,
                                          std::vector<std::uint8_t>* decided) {
  PaddedPlane g(width, height, 0);
  std::vector<std::uint16_t> probs(2 * kTemplateContexts, kProbInit);
  RangeEncoder enc;
  decided->assign(canvas.size(), 0);
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      const unsigned ctx = Template10(g, i) | (IsFree(canvas[cell]) ? kTemplateContexts : 0u);
      std::uint16_t* p = &probs[ctx];
      int bit = static_cast<int>(target[cell]);
      if (target[cell] == FreeTarget::kDontCare) bit = *p >= kProbInit ? 0 : 1;
      enc.Encode(p, bit);
      g[i] = static_cast<std::uint8_t>(bit);
      (*decided)[cell] = static_cast<std::uint8_t>(bit);
    }
  }
  enc.Finish();
  return enc.bytes();
}

Status DecodeFreePlane(const std::uint8_t* data, std::size_t size, int width, int height,
                       std::vector<Cell>* canvas) {
  PaddedPlane g(width, height, 0);
  std::vector<std::uint16_t> probs(2 * kTemplateContexts, kProbInit);
  RangeDecoder dec(data, size);
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      Cell& c = (*canvas)[cell];
      const unsigned ctx = Template10(g, i) | (IsFree(c) ? kTemplateContexts : 0u);
      const int bit = dec.Decode(&probs[ctx]);
      g[i] = static_cast<std::uint8_t>(bit);
      if (bit) {
        c = Cell::kFree;
      } else if (IsFree(c)) {
        c = Cell::kUnknown;
      }
    }
    if (dec.overrun() > 0) break;
  }
  return CheckEnd(dec, size, "FREE");
}

std::vector<std::uint8_t> EncodeOccupiedPlane(const std::vector<std::uint8_t>& target,
                                              const std::vector<Cell>& canvas, int width,
                                              int height) {
  PaddedPlane g(width, height, 0);
  std::vector<std::uint16_t> probs(8 * kTemplateContexts, kProbInit);
  RangeEncoder enc;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      if (IsOccupied(canvas[cell])) {
        g[i] = 1;
        continue;
      }
      const unsigned ctx = Template10(g, i) | OccupiedCanvasContext(canvas, width, height, col, row)
                                                  << 10;
      const int bit = target[cell] ? 1 : 0;
      enc.Encode(&probs[ctx], bit);
      g[i] = static_cast<std::uint8_t>(bit);
    }
  }
  enc.Finish();
  return enc.bytes();
}

Status DecodeOccupiedPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas) {
  PaddedPlane g(width, height, 0);
  std::vector<std::uint16_t> probs(8 * kTemplateContexts, kProbInit);
  RangeDecoder dec(data, size);
  std::vector<Cell>& cv = *canvas;
  // Cells turned occupied are recorded in g and applied after the row, so the
  // canvas context of later cells sees the canvas as it was before OCCP.
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const std::size_t i = g.At(col, row);
      if (IsOccupied(cv[cell])) {
        g[i] = 1;
        continue;
      }
      const unsigned ctx = Template10(g, i) | OccupiedCanvasContext(cv, width, height, col, row)
                                                  << 10;
      g[i] = static_cast<std::uint8_t>(dec.Decode(&probs[ctx]));
    }
    if (dec.overrun() > 0) break;
  }
  LINEMAP_RETURN_IF_ERROR(CheckEnd(dec, size, "OCCP"));
  cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      if (g[g.At(col, row)]) cv[cell] = Cell::kOccupied;
    }
  }
  return Status::Ok();
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

std::vector<std::uint8_t> EncodeResidualPlane(const std::vector<Cell>& truth,
                                              const std::vector<Cell>& canvas, int width,
                                              int height) {
  std::vector<std::uint16_t> probs(2 * kResidualContexts, kProbInit);
  RangeEncoder enc;
  std::size_t cell = 0;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col, ++cell) {
      const unsigned ctx = ResidualContext(truth, canvas, width, height, col, row);
      const bool differs = truth[cell] != canvas[cell];
      enc.Encode(&probs[ctx], differs ? 1 : 0);
      if (differs) {
        enc.Encode(&probs[ctx + 1], truth[cell] == Alternative(canvas[cell], 1) ? 1 : 0);
      }
    }
  }
  enc.Finish();
  return enc.bytes();
}

Status DecodeResidualPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas) {
  std::vector<std::uint16_t> probs(2 * kResidualContexts, kProbInit);
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
    if (dec.overrun() > 0) break;
  }
  return CheckEnd(dec, size, "RESD");
}

}  // namespace linemap
