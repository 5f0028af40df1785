// LayerIndex::TileHints (drawn from the polygons' edges, per tile) against a
// straightforward drawing of spec/format.md section 6.2 over the whole
// grid: each polygon's chain made whole (ChainOfPolygon) and its row
// crossings sorted, then compared with each tile.
#include "codec/layers/layer_hints.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

#include "codec/layers/raster.h"

namespace linemap {
namespace {

// The hints of the whole width x height grid, drawn as the spec says.
std::vector<std::uint8_t> SpecHints(int width, int height, const std::vector<WallPolyline>& walls,
                                    const std::vector<RoomOutline>& rooms,
                                    const std::vector<FurnitureObject>& furniture) {
  std::vector<std::uint8_t> hints(static_cast<std::size_t>(width) * height, 0);
  const auto at = [&](int c, int r) -> std::uint8_t& {
    return hints[static_cast<std::size_t>(r) * width + c];
  };
  const auto draw = [&](const std::vector<CellIndex>& polygon, std::uint8_t fill,
                        std::uint8_t chain_bits, std::uint8_t clear) {
    const std::vector<CellIndex> chain = ChainOfPolygon(polygon);
    // The fill of 6.2 is that of the crossings alone (FillChain would
    // also visit the chain's cells, which 6.2 draws after it).
    std::vector<std::pair<int, int>> crossings;
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const CellIndex p = chain[i], q = chain[(i + 1) % chain.size()];
      if (std::abs(p.row - q.row) != 1) continue;
      const int r = std::min(p.row, q.row);
      crossings.emplace_back(r, p.row == r ? p.col : q.col);
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
      for (int c = crossings[i].second; c < crossings[i + 1].second; ++c) {
        at(c, crossings[i].first) |= fill;
      }
    }
    for (const CellIndex& c : chain) {
      at(c.col, c.row) = static_cast<std::uint8_t>((at(c.col, c.row) & ~clear) | chain_bits);
    }
  };
  for (const RoomOutline& room : rooms) {
    draw(room.polygon, kHintRoomInside, kHintRoomBorder, kHintRoomInside);
  }
  for (const FurnitureObject& object : furniture) {
    draw(object.polygon, kHintFurniture, kHintFurniture, 0);
  }
  for (const WallPolyline& wall : walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      RasterizeSegment(wall.points[i - 1], wall.points[i], [&](int c, int r) { at(c, r) |= 1; });
    }
  }
  return hints;
}

std::vector<CellIndex> RandomPolygon(std::mt19937& rng, int width, int height) {
  std::uniform_int_distribution<int> count(1, 9);
  std::uniform_int_distribution<int> col(0, width - 1), row(0, height - 1);
  std::uniform_int_distribution<int> shape(0, 3);
  std::vector<CellIndex> polygon;
  const int k = count(rng);
  const int s = shape(rng);
  CellIndex p{col(rng), row(rng)};
  for (int i = 0; i < k; ++i) {
    if (s == 0) {
      p = {col(rng), row(rng)};  // anywhere: long, crossing edges
    } else {
      // Short axis-aligned or diagonal steps, as rooms and furniture are.
      std::uniform_int_distribution<int> step(-40, 40);
      p = {std::clamp(p.col + step(rng) * (s != 2), 0, width - 1),
           std::clamp(p.row + step(rng) * (s != 1), 0, height - 1)};
    }
    polygon.push_back(p);
    if (i > 0 && shape(rng) == 0) polygon.push_back(p);  // repeated vertices
  }
  return polygon;
}

TEST(LayerHintsTest, TilesEqualTheSpecDrawingOfTheWholeGrid) {
  std::mt19937 rng(19);
  for (int round = 0; round < 40; ++round) {
    const int width = 50 + static_cast<int>(rng() % 700);
    const int height = 50 + static_cast<int>(rng() % 700);
    std::vector<WallPolyline> walls;
    std::vector<RoomOutline> rooms;
    std::vector<FurnitureObject> furniture;
    for (int i = 0; i < 20; ++i)
      rooms.push_back({0, RoomKind::kRoom, RandomPolygon(rng, width, height), {}});
    for (int i = 0; i < 20; ++i) {
      furniture.push_back({0, -1, RandomPolygon(rng, width, height), {}});
    }
    for (int i = 0; i < 30; ++i) walls.push_back({RandomPolygon(rng, width, height)});
    const std::vector<std::uint8_t> whole = SpecHints(width, height, walls, rooms, furniture);
    const LayerIndex index(walls, rooms, furniture);
    for (int tile_size : {16, 100, 256, 1024}) {
      for (int y0 = 0; y0 < height; y0 += tile_size) {
        for (int x0 = 0; x0 < width; x0 += tile_size) {
          const CellRect t{x0, y0, std::min(width, x0 + tile_size),
                           std::min(height, y0 + tile_size)};
          const std::vector<std::uint8_t> hints = index.TileHints(t);
          const int tw = t.x1 - t.x0;
          for (int r = t.y0; r < t.y1; ++r) {
            for (int c = t.x0; c < t.x1; ++c) {
              ASSERT_EQ(hints[static_cast<std::size_t>(r - t.y0) * tw + (c - t.x0)],
                        whole[static_cast<std::size_t>(r) * width + c])
                  << "round " << round << " tile " << tile_size << " cell " << c << "," << r;
            }
          }
        }
      }
    }
  }
}

// The index makes its buckets for the first tile that does not cover every
// item: tiles drawn from several threads at once, with the layers in one
// part of the grid (tiles that cover them all look at every item, the
// others at the buckets), equal the spec's drawing.
TEST(LayerHintsTest, TilesDrawnFromThreadsEqualTheSpecDrawing) {
  std::mt19937 rng(23);
  for (int round = 0; round < 8; ++round) {
    const int width = 200 + static_cast<int>(rng() % 500);
    const int height = 200 + static_cast<int>(rng() % 500);
    // The layers' part: from a corner to a third of the grid or all of it.
    const int part_w = width / 3 + static_cast<int>(rng() % (width - width / 3 + 1));
    const int part_h = height / 3 + static_cast<int>(rng() % (height - height / 3 + 1));
    std::vector<WallPolyline> walls;
    std::vector<RoomOutline> rooms;
    std::vector<FurnitureObject> furniture;
    for (int i = 0; i < 10; ++i) {
      rooms.push_back({0, RoomKind::kRoom, RandomPolygon(rng, part_w, part_h), {}});
      furniture.push_back({0, -1, RandomPolygon(rng, part_w, part_h), {}});
      walls.push_back({RandomPolygon(rng, part_w, part_h)});
    }
    const std::vector<std::uint8_t> whole = SpecHints(width, height, walls, rooms, furniture);
    for (int tile_size : {32, 128, 512}) {
      const LayerIndex index(walls, rooms, furniture);
      std::vector<CellRect> tiles;
      for (int y0 = 0; y0 < height; y0 += tile_size) {
        for (int x0 = 0; x0 < width; x0 += tile_size) {
          tiles.push_back(
              {x0, y0, std::min(width, x0 + tile_size), std::min(height, y0 + tile_size)});
        }
      }
      std::vector<std::vector<std::uint8_t>> drawn(tiles.size());
      constexpr int kThreads = 4;
      std::vector<std::thread> threads;
      for (int k = 0; k < kThreads; ++k) {
        threads.emplace_back([&, k] {
          for (std::size_t i = static_cast<std::size_t>(k); i < tiles.size(); i += kThreads) {
            drawn[i] = index.TileHints(tiles[i]);
          }
        });
      }
      for (std::thread& t : threads) t.join();
      for (std::size_t i = 0; i < tiles.size(); ++i) {
        const CellRect& t = tiles[i];
        const int tw = t.x1 - t.x0;
        for (int r = t.y0; r < t.y1; ++r) {
          for (int c = t.x0; c < t.x1; ++c) {
            ASSERT_EQ(drawn[i][static_cast<std::size_t>(r - t.y0) * tw + (c - t.x0)],
                      whole[static_cast<std::size_t>(r) * width + c])
                << "round " << round << " tile " << tile_size << " cell " << c << "," << r;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace linemap
