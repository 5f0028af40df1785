// Fuzz target: the vector-layer reader and window decoding of 2.0 files.
// Whatever the input, DecodeLmapVectors gives layers inside the map (walls of
// at least two points, closed 8-connected room and furniture chains) or an
// error; a window decode, with the window taken from the input's last bytes,
// gives that window's cells or an error, and when the whole grid decodes it
// gives the same cells as the whole grid there (a window reads only the
// tiles and layer sections that reach it). When the layers read whole, the
// header gives their map's size, the items in the window are those of the
// whole read whose box meets it, and the room at the window's corner is the
// smallest enclosing one of the whole read (spec 8.2 as written here), with
// the cells of its box. Anything else aborts.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "tests/fuzz/fix_chunk_crcs.h"
#include "tests/testing/reference_geometry.h"

namespace {

[[noreturn]] void Fail(const char* what) {
  std::fprintf(stderr, "lmap_vectors: %s\n", what);
  std::abort();
}

bool Inside(const linemap::CellIndex& p, const linemap::LmapVectors& v) {
  return p.col >= 0 && p.row >= 0 && p.col < v.width && p.row < v.height;
}

void CheckChain(const std::vector<linemap::CellIndex>& chain, const linemap::LmapVectors& v) {
  if (chain.empty()) Fail("empty chain");
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const linemap::CellIndex p = chain[i], q = chain[(i + 1) % chain.size()];
    if (!Inside(p, v)) Fail("chain cell outside the map");
    if (std::abs(p.col - q.col) > 1 || std::abs(p.row - q.row) > 1) Fail("chain not 8-connected");
  }
}

// Whether the box of `points` shares a cell with the half-open window.
bool MeetsWindow(const std::vector<linemap::CellIndex>& points, const linemap::CellWindow& w) {
  if (points.empty()) return false;
  int c0 = points[0].col, c1 = c0, r0 = points[0].row, r1 = r0;
  for (const linemap::CellIndex& p : points) {
    c0 = std::min(c0, p.col), c1 = std::max(c1, p.col);
    r0 = std::min(r0, p.row), r1 = std::max(r1, p.row);
  }
  return c0 < w.col1 && c1 >= w.col0 && r0 < w.row1 && r1 >= w.row0;
}

// 128-bit integers (a GCC and Clang extension, marked so for -Wpedantic).
__extension__ typedef __int128 Int128;

Int128 TwiceArea(const std::vector<linemap::CellIndex>& v) {
  Int128 sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const linemap::CellIndex p = v[i], q = v[(i + 1) % v.size()];
    sum += static_cast<long long>(p.col) * q.row - static_cast<long long>(q.col) * p.row;
  }
  return sum < 0 ? -sum : sum;
}

// The items in `w` read alone are those of the whole read that meet it.
void CheckItemsInWindow(const std::vector<std::uint8_t>& bytes, const linemap::LmapVectors& all,
                        const linemap::CellWindow& w, const linemap::DecodeLimits& limits) {
  const auto header = linemap::DecodeLmapHeader(bytes, limits);
  if (!header.ok() || header->width != all.width || header->height != all.height) {
    Fail("the header disagrees with the layers' map");
  }
  const auto near = linemap::DecodeLmapVectorsInWindow(bytes, w, limits);
  if (!near.ok()) Fail("the items of a window fail where the whole layers read");
  const auto same = [&](const auto& got, const auto& whole, auto points_of) {
    std::size_t k = 0;
    for (const auto& item : whole) {
      if (!MeetsWindow(points_of(item), w)) continue;
      if (k >= got.size() || !(got[k] == item)) return false;
      ++k;
    }
    return k == got.size();
  };
  if (!same(
          near->walls, all.walls, [](const auto& x) -> const auto& { return x.points; }) ||
      !same(
          near->rooms, all.rooms, [](const auto& x) -> const auto& { return x.polygon; }) ||
      !same(
          near->furniture, all.furniture, [](const auto& x) -> const auto& { return x.polygon; })) {
    Fail("the items of a window are not those of the whole read that meet it");
  }
}

// The room at `cell` is the smallest whose chain encloses it, or none, with
// the cells of its box as the whole grid has them (when it decodes: else
// the room's cells may be the corrupt part).
void CheckRoomAt(const std::vector<std::uint8_t>& bytes, const linemap::LmapVectors& all,
                 linemap::CellIndex cell, const linemap::DecodeLimits& limits,
                 const linemap::StatusOr<linemap::Grid>& whole) {
  const linemap::RoomOutline* want = nullptr;
  for (const auto& room : all.rooms) {
    if (linemap::testing::ReferenceChainEncloses(room.chain, cell.col, cell.row) &&
        (want == nullptr || TwiceArea(room.polygon) < TwiceArea(want->polygon))) {
      want = &room;
    }
  }
  const auto got = linemap::DecodeLmapRoomAt(bytes, cell, limits);
  if (!got.ok()) {
    if (whole.ok()) Fail("room at a cell: fails where the whole grid decodes");
    return;
  }
  if (got->has_value() != (want != nullptr)) Fail("room at a cell: found where none is, or not");
  if (want == nullptr) return;
  const linemap::LmapRoom& room = **got;
  if (!(room.room == *want)) Fail("room at a cell: not the smallest enclosing room");
  if (room.grid.width() != room.window.col1 - room.window.col0 ||
      room.grid.height() != room.window.row1 - room.window.row0) {
    Fail("room at a cell: grid of the wrong size");
  }
  if (!whole.ok()) return;
  for (int r = room.window.row0; r < room.window.row1; ++r) {
    for (int c = room.window.col0; c < room.window.col1; ++c) {
      if (room.grid.at(c - room.window.col0, r - room.window.row0) != whole->at(c, r)) {
        Fail("room at a cell: its cells differ from the whole grid");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> bytes = linemap::fuzzing::WithChunkCrcsFixed(data, size);
  linemap::DecodeLimits limits;
  limits.max_cells = std::uint64_t{1} << 24;
  // As fuzz_lmap_decode: an empty stream holds any number of small items.
  limits.max_segments = std::uint64_t{1} << 16;
  limits.max_chain_length = std::uint64_t{1} << 18;
  limits.max_objects = std::uint64_t{1} << 14;
  limits.max_threads = 1;
  const auto vectors = linemap::DecodeLmapVectors(bytes, limits);
  if (!vectors.ok()) return 0;
  for (const auto& wall : vectors->walls) {
    if (wall.points.size() < 2) Fail("wall of fewer than two points");
    for (const auto& p : wall.points) {
      if (!Inside(p, *vectors)) Fail("wall point outside the map");
    }
  }
  for (const auto& room : vectors->rooms) CheckChain(room.chain, *vectors);
  for (const auto& object : vectors->furniture) CheckChain(object.outline, *vectors);
  if (vectors->width > 0 && vectors->height > 0 && size >= 4) {
    linemap::CellWindow w;
    w.col0 = data[size - 4] % vectors->width;
    w.row0 = data[size - 3] % vectors->height;
    w.col1 = w.col0 + 1 + data[size - 2] % (vectors->width - w.col0);
    w.row1 = w.row0 + 1 + data[size - 1] % (vectors->height - w.row0);
    const auto region = linemap::DecodeLmapRegion(bytes, w, limits);
    if (region.ok() &&
        (region->width() != w.col1 - w.col0 || region->height() != w.row1 - w.row0)) {
      Fail("window of the wrong size");
    }
    CheckItemsInWindow(bytes, *vectors, w, limits);
    const auto whole = linemap::DecodeLmap(bytes, limits);
    CheckRoomAt(bytes, *vectors, {w.col0, w.row0}, limits, whole);
    if (whole.ok()) {
      if (!region.ok()) Fail("a window of a grid that decodes fails");
      for (int r = w.row0; r < w.row1; ++r) {
        for (int c = w.col0; c < w.col1; ++c) {
          if (region->at(c - w.col0, r - w.row0) != whole->at(c, r)) {
            Fail("a window differs from the whole grid");
          }
        }
      }
    }
  }
  return 0;
}
