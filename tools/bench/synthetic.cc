#include "tools/bench/synthetic.h"

#include <algorithm>
#include <cstddef>

namespace linemap::bench {
namespace {

constexpr int kRoomCells = 96;  // 4.8 m at 0.05 m/cell

// xorshift32: fully specified, so the map is identical everywhere (the
// standard distributions are not).
class Rng {
 public:
  explicit Rng(std::uint32_t seed) : state_(seed ? seed : 1) {}
  std::uint32_t Next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return state_;
  }
  int Uniform(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(Next() % static_cast<std::uint32_t>(hi - lo + 1));
  }

 private:
  std::uint32_t state_;
};

void FillRect(Grid* grid, int c0, int r0, int c1, int r1, Cell value) {
  c0 = std::max(c0, 0);
  r0 = std::max(r0, 0);
  c1 = std::min(c1, grid->width() - 1);
  r1 = std::min(r1, grid->height() - 1);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) grid->set(c, r, value);
  }
}

}  // namespace

Grid GenerateOfficeMap(int size, std::uint32_t seed) {
  size = std::max(size, 64);
  Grid grid(size, size, Cell::kUnknown);
  Rng rng(seed);
  const int margin = size / 16;
  const int lo = margin, hi = size - 1 - margin;
  FillRect(&grid, lo, lo, hi, hi, Cell::kOccupied);
  FillRect(&grid, lo + 2, lo + 2, hi - 2, hi - 2, Cell::kFree);
  // Interior walls on a jittered grid of rooms, each wall with a door.
  // Rooms of a fixed size, so that bigger maps have more rooms, not bigger ones.
  const int room = std::min(kRoomCells, size / 2);
  for (int x = lo + room; x < hi - room / 2; x += room) {
    const int wx = x + rng.Uniform(-room / 6, room / 6);
    FillRect(&grid, wx, lo, wx + 1, hi, Cell::kOccupied);
    for (int y = lo; y < hi; y += room) {
      const int door = y + rng.Uniform(3, room - 14);
      FillRect(&grid, wx, door, wx + 1, door + 9, Cell::kFree);
    }
  }
  for (int y = lo + room; y < hi - room / 2; y += room) {
    const int wy = y + rng.Uniform(-room / 6, room / 6);
    FillRect(&grid, lo, wy, hi, wy + 1, Cell::kOccupied);
    for (int x = lo; x < hi; x += room) {
      const int door = x + rng.Uniform(3, room - 14);
      FillRect(&grid, door, wy, door + 9, wy + 1, Cell::kFree);
    }
  }
  // Furniture: small solid blocks inside rooms.
  const int blocks = static_cast<int>(static_cast<long long>(size / room) * (size / room) * 2);
  for (int i = 0; i < blocks; ++i) {
    const int c = rng.Uniform(lo + 4, hi - 12);
    const int r = rng.Uniform(lo + 4, hi - 12);
    FillRect(&grid, c, r, c + rng.Uniform(2, 8), r + rng.Uniform(2, 8), Cell::kOccupied);
  }
  // Speckle: isolated occupied and unknown cells in free space.
  const int speckle = static_cast<int>(static_cast<long long>(size) * size / 2000);
  for (int i = 0; i < speckle; ++i) {
    const int c = rng.Uniform(lo + 3, hi - 3);
    const int r = rng.Uniform(lo + 3, hi - 3);
    if (grid.at(c, r) == Cell::kFree) grid.set(c, r, i % 2 ? Cell::kOccupied : Cell::kUnknown);
  }
  return grid;
}

Grid GenerateOfficeMapOfSize(int width, int height, std::uint32_t seed) {
  const Grid square = GenerateOfficeMap(std::max(width, height), seed);
  if (square.width() == width && square.height() == height) return square;
  Grid map(width, height);
  map.meta = square.meta;
  for (int r = 0; r < height; ++r) {
    std::copy_n(square.cells().begin() + static_cast<std::ptrdiff_t>(square.Index(0, r)), width,
                map.mutable_cells().begin() + static_cast<std::ptrdiff_t>(map.Index(0, r)));
  }
  return map;
}

}  // namespace linemap::bench
