// TEMPORARY stand-in: the 1.0 planes on the whole tile (tile == grid).
#include "codec/codec/tile_coder.h"

#include "codec/codec/plane_coder.h"
#include "format/byte_io.h"

namespace linemap {

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t*, int width,
                                          int height, CellRect) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<std::uint8_t> occ(n), fr(n);
  std::vector<Cell> canvas(n, Cell::kUnknown);
  for (std::size_t i = 0; i < n; ++i) {
    occ[i] = cells[i] == Cell::kOccupied;
    fr[i] = cells[i] == Cell::kFree;
  }
  std::vector<std::uint8_t> a = EncodeOccupiedPlane(occ, canvas, width, height);
  for (std::size_t i = 0; i < n; ++i) {
    if (occ[i]) canvas[i] = Cell::kOccupied;
  }
  std::vector<std::uint8_t> b = EncodeFreePlane(fr, canvas, width, height);
  ByteWriter out;
  out.PutVarint(a.size());
  out.PutBytes(a);
  out.PutBytes(b);
  return std::move(out.mutable_bytes());
}

Status DecodeTileCells(const std::uint8_t* data, std::size_t size, const std::uint8_t*, int width,
                       int height, CellRect, Cell* canvas) {
  ByteCursor cur(data, size);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t a, cur.ReadVarintAtMost(cur.remaining(), "occ"));
  const std::size_t off = cur.position();
  std::vector<Cell> c(static_cast<std::size_t>(width) * height, Cell::kUnknown);
  LINEMAP_RETURN_IF_ERROR(DecodeOccupiedPlane(data + off, a, width, height, &c));
  LINEMAP_RETURN_IF_ERROR(DecodeFreePlane(data + off + a, size - off - a, width, height, &c));
  std::copy(c.begin(), c.end(), canvas);
  return Status::Ok();
}

}  // namespace linemap
