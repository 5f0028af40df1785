// WALL, ROOM and FURN bodies: round trips of random layers, the orders the
// encoder picks, and damaged bodies that must fail without crashing.
#include "codec/layers/layer_coding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "codec/layers/layer_order.h"

namespace linemap {
namespace {

constexpr int kW = 300, kH = 200;

std::vector<WallPolyline> RandomWalls(std::mt19937* rng, int count) {
  std::vector<WallPolyline> walls;
  for (int i = 0; i < count; ++i) {
    WallPolyline wall;
    CellIndex p{static_cast<int>((*rng)() % kW), static_cast<int>((*rng)() % kH)};
    wall.points.push_back(p);
    const int steps = 1 + static_cast<int>((*rng)() % 5);
    while (static_cast<int>(wall.points.size()) <= steps) {
      CellIndex q = p;
      if ((*rng)() % 3 == 0) {  // diagonal
        q.col += static_cast<int>((*rng)() % 41) - 20;
        q.row += static_cast<int>((*rng)() % 41) - 20;
      } else if ((*rng)() % 2) {
        q.col += static_cast<int>((*rng)() % 81) - 40;
      } else {
        q.row += static_cast<int>((*rng)() % 81) - 40;
      }
      q.col = std::clamp(q.col, 0, kW - 1);
      q.row = std::clamp(q.row, 0, kH - 1);
      if (q == p) continue;
      wall.points.push_back(q);
      p = q;
    }
    walls.push_back(std::move(wall));
  }
  return walls;
}

// A random closed polygon: a rectangle with one corner cut diagonally, or
// (sometimes) a single vertex.
std::vector<CellIndex> RandomPolygon(std::mt19937* rng) {
  const int c0 = static_cast<int>((*rng)() % (kW - 20)),
            r0 = static_cast<int>((*rng)() % (kH - 20));
  if ((*rng)() % 8 == 0) return {{c0, r0}};
  const int c1 = c0 + 2 + static_cast<int>((*rng)() % 17),
            r1 = r0 + 2 + static_cast<int>((*rng)() % 17);
  return {{c0, r0}, {c1, r0}, {c1, r1 - 1}, {c1 - 1, r1}, {c0, r1}};
}

RoomOutline Room(std::uint32_t id, RoomKind kind, std::vector<CellIndex> polygon) {
  std::vector<CellIndex> chain = ChainOfPolygon(polygon);
  return {id, kind, std::move(polygon), std::move(chain)};
}

FurnitureObject Object(std::uint32_t id, std::int32_t room, std::vector<CellIndex> polygon) {
  std::vector<CellIndex> outline = ChainOfPolygon(polygon);
  return {id, room, std::move(polygon), std::move(outline)};
}

TEST(LayerCodingTest, ChainOfPolygonIsTheClosedChainOfItsEdges) {
  // A 3 x 2 rectangle's corners: its ten border cells, counter-clockwise.
  const std::vector<CellIndex> chain = ChainOfPolygon({{0, 0}, {3, 0}, {3, 2}, {0, 2}});
  const std::vector<CellIndex> expected = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1},
                                           {3, 2}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_EQ(chain, expected);
  EXPECT_EQ(ChainOfPolygon({{5, 5}}), (std::vector<CellIndex>{{5, 5}}));
  // A diagonal edge steps diagonally.
  EXPECT_EQ(ChainOfPolygon({{0, 0}, {2, 2}}),
            (std::vector<CellIndex>{{0, 0}, {1, 1}, {2, 2}, {1, 1}}));
  std::mt19937 rng(3);
  for (int i = 0; i < 100; ++i)
    EXPECT_TRUE(IsStorableChain(ChainOfPolygon(RandomPolygon(&rng)), kW, kH));
}

TEST(LayerCodingTest, WallsRoundTrip) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<WallPolyline> walls = RandomWalls(&rng, trial * 3);
    CanonicalizeWalls(&walls);
    auto decoded = DecodeWalls(EncodeWalls(walls), kW, kH, DecodeLimits{});
    ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
    EXPECT_EQ(*decoded, walls);
  }
}

TEST(LayerCodingTest, OrderKeepsEveryWallAndItsSegments) {
  std::mt19937 rng(8);
  std::vector<WallPolyline> walls = RandomWalls(&rng, 200);
  std::vector<WallPolyline> ordered = walls;
  OrderWallsForCoding(&ordered);
  ASSERT_EQ(ordered.size(), walls.size());
  // The same polylines, each either as it was or reversed.
  auto key = [](std::vector<CellIndex> p) {
    std::vector<CellIndex> r(p.rbegin(), p.rend());
    const auto less = [](const std::vector<CellIndex>& a, const std::vector<CellIndex>& b) {
      return std::lexicographical_compare(
          a.begin(), a.end(), b.begin(), b.end(),
          [](CellIndex x, CellIndex y) { return std::tie(x.row, x.col) < std::tie(y.row, y.col); });
    };
    return less(r, p) ? r : p;
  };
  std::vector<std::vector<CellIndex>> a, b;
  for (const auto& w : walls) a.push_back(key(w.points));
  for (const auto& w : ordered) b.push_back(key(w.points));
  const auto cmp = [](const std::vector<CellIndex>& x, const std::vector<CellIndex>& y) {
    return std::lexicographical_compare(
        x.begin(), x.end(), y.begin(), y.end(),
        [](CellIndex p, CellIndex q) { return std::tie(p.row, p.col) < std::tie(q.row, q.col); });
  };
  std::sort(a.begin(), a.end(), cmp);
  std::sort(b.begin(), b.end(), cmp);
  EXPECT_EQ(a, b);
  // Greedy: each next start is the nearest remaining end (checked by brute
  // force for the first wall).
  long best = 1L << 40;
  for (const auto& w : walls) {
    for (CellIndex p : {w.points.front(), w.points.back()})
      best = std::min(best, long{p.col} + p.row);
  }
  EXPECT_EQ(long{ordered[0].points[0].col} + ordered[0].points[0].row, best);
}

TEST(LayerCodingTest, RoomsAndFurnitureRoundTrip) {
  std::mt19937 rng(9);
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
  for (int i = 0; i < 30; ++i) {
    rooms.push_back(Room(static_cast<std::uint32_t>(i * 3 + (i % 2)), static_cast<RoomKind>(i % 3),
                         RandomPolygon(&rng)));
    furniture.push_back(
        Object(static_cast<std::uint32_t>(i), i % 4 == 0 ? -1 : i, RandomPolygon(&rng)));
  }
  furniture.push_back(Object(30, 5, {{4, 4}}));  // a one-cell object
  auto r = DecodeRooms(EncodeRooms(rooms), kW, kH, DecodeLimits{});
  ASSERT_TRUE(r.ok()) << r.status().ToString();
  EXPECT_EQ(*r, rooms);
  auto f = DecodeFurniture(EncodeFurniture(furniture), kW, kH, DecodeLimits{});
  ASSERT_TRUE(f.ok()) << f.status().ToString();
  EXPECT_EQ(*f, furniture);
}

// Steps whose two components are equal (a tie for the main axis), one cell
// long, reaching the grid's corners, in every direction: each decodes to
// the point it was.
TEST(LayerCodingTest, StepsOfEveryShapeRoundTrip) {
  std::vector<WallPolyline> walls = {
      {{{0, 0}, {kW - 1, kH - 1}, {kW - 1, 0}, {0, kH - 1}}},
      {{{10, 10}, {11, 11}, {10, 12}, {9, 11}, {10, 10}}},  // diagonal unit steps, closed
      {{{50, 50}, {60, 60}, {50, 70}, {40, 60}}},           // ties after each heading
      {{{100, 100}, {101, 100}, {101, 101}, {100, 101}}},   // unit axis steps
      {{{120, 20}, {120, 21}}},
      {{{kW - 1, kH - 1}, {0, 0}}},
  };
  auto decoded = DecodeWalls(EncodeWalls(walls), kW, kH, DecodeLimits{});
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  EXPECT_EQ(*decoded, walls);
  std::vector<RoomOutline> rooms = {
      Room(1, RoomKind::kRoom, {{5, 5}, {9, 9}, {5, 13}, {1, 9}}),
      Room(2, RoomKind::kCorridor, {{0, 0}, {kW - 1, 0}, {kW - 1, kH - 1}, {0, kH - 1}})};
  auto r = DecodeRooms(EncodeRooms(rooms), kW, kH, DecodeLimits{});
  ASSERT_TRUE(r.ok()) << r.status().ToString();
  EXPECT_EQ(*r, rooms);
}

// Runs of objects in one room code the room once; the ids still come back.
TEST(LayerCodingTest, FurnitureRoomsRoundTripAcrossRuns) {
  std::mt19937 rng(13);
  std::vector<FurnitureObject> furniture;
  const std::int32_t rooms[] = {-1, -1, 3, 3, 3, 0, 7, -1, 7, 7, 2147483647, 2147483647, -1};
  for (std::int32_t room : rooms) {
    furniture.push_back(
        Object(static_cast<std::uint32_t>(furniture.size()), room, RandomPolygon(&rng)));
  }
  auto f = DecodeFurniture(EncodeFurniture(furniture), kW, kH, DecodeLimits{});
  ASSERT_TRUE(f.ok()) << f.status().ToString();
  EXPECT_EQ(*f, furniture);
}

// Paths code relative to where the last one ended and its heading, so a
// wall that runs on from the last one costs less than the same wall coded
// after a jump across the map.
TEST(LayerCodingTest, AWallRunningOnFromTheLastCostsLittle) {
  std::vector<WallPolyline> near_walls, far_walls;
  for (int i = 0; i < 40; ++i) {
    near_walls.push_back({{{5 * i, 10}, {5 * i + 3, 10}}});
    far_walls.push_back({{{(97 * i) % 290, (31 * i) % 190}, {(97 * i) % 290 + 3, (31 * i) % 190}}});
  }
  EXPECT_LT(EncodeWalls(near_walls).size() * 3, EncodeWalls(far_walls).size());
}

TEST(LayerCodingTest, LayersOutsideASmallerGridAreCorrupt) {
  std::mt19937 rng(10);
  std::vector<WallPolyline> walls = RandomWalls(&rng, 20);
  CanonicalizeWalls(&walls);
  auto w = DecodeWalls(EncodeWalls(walls), 10, 10, DecodeLimits{});
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.status().code(), StatusCode::kCorrupt);
  std::vector<RoomOutline> rooms = {Room(0, RoomKind::kRoom, {{2, 2}, {40, 2}, {40, 30}})};
  auto r = DecodeRooms(EncodeRooms(rooms), 10, 10, DecodeLimits{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kCorrupt);
}

TEST(LayerCodingTest, LimitsAreResourceExhausted) {
  std::mt19937 rng(11);
  std::vector<WallPolyline> walls = RandomWalls(&rng, 20);
  CanonicalizeWalls(&walls);
  DecodeLimits limits;
  limits.max_segments = 5;
  auto w = DecodeWalls(EncodeWalls(walls), kW, kH, limits);
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.status().code(), StatusCode::kResourceExhausted);
  limits = DecodeLimits{};
  limits.max_chain_length = 10;
  auto r = DecodeRooms(EncodeRooms({Room(0, RoomKind::kRoom, {{0, 0}, {20, 0}, {20, 20}})}), kW, kH,
                       limits);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kResourceExhausted);
  // Two rooms against an object limit of one.
  limits = DecodeLimits{};
  limits.max_objects = 1;
  const std::vector<RoomOutline> two = {Room(0, RoomKind::kRoom, {{0, 0}, {5, 0}, {5, 5}}),
                                        Room(1, RoomKind::kRoom, {{9, 9}, {12, 9}, {12, 12}})};
  auto o = DecodeRooms(EncodeRooms(two), kW, kH, limits);
  ASSERT_FALSE(o.ok());
  EXPECT_EQ(o.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(o.status().message().find("2 rooms exceed the object limit"), std::string::npos)
      << o.status().ToString();
  limits.max_objects = 2;
  EXPECT_TRUE(DecodeRooms(EncodeRooms(two), kW, kH, limits).ok());
  // And two furniture objects.
  const std::vector<FurnitureObject> pair = {{0, -1, {{1, 1}, {3, 1}, {3, 3}}, {}},
                                             {1, -1, {{9, 9}, {11, 9}, {11, 11}}, {}}};
  limits.max_objects = 1;
  auto f = DecodeFurniture(EncodeFurniture(pair), kW, kH, limits, false);
  ASSERT_FALSE(f.ok());
  EXPECT_EQ(f.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(f.status().message().find("2 objects exceed the object limit"), std::string::npos)
      << f.status().ToString();
  limits.max_objects = 2;
  EXPECT_TRUE(DecodeFurniture(EncodeFurniture(pair), kW, kH, limits, false).ok());
}

TEST(LayerCodingTest, DamagedBodiesFailOrDecodeInsideTheGrid) {
  std::mt19937 rng(12);
  std::vector<WallPolyline> walls = RandomWalls(&rng, 30);
  CanonicalizeWalls(&walls);
  const std::vector<std::uint8_t> wall_body = EncodeWalls(walls);
  std::vector<RoomOutline> rooms = {Room(0, RoomKind::kRoom, RandomPolygon(&rng)),
                                    Room(4, RoomKind::kCorridor, RandomPolygon(&rng))};
  const std::vector<std::uint8_t> room_body = EncodeRooms(rooms);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::uint8_t> w = wall_body, r = room_body;
    w[rng() % w.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    r[rng() % r.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    if (trial % 3 == 0) w.resize(rng() % w.size());
    auto dw = DecodeWalls(w, kW, kH, DecodeLimits{});
    if (dw.ok()) {
      for (const auto& wall : *dw) {
        for (CellIndex p : wall.points)
          ASSERT_TRUE(p.col >= 0 && p.col < kW && p.row >= 0 && p.row < kH);
      }
    }
    auto dr = DecodeRooms(r, kW, kH, DecodeLimits{});
    if (dr.ok()) {
      for (const auto& room : *dr) EXPECT_TRUE(IsStorableChain(room.chain, kW, kH));
    }
  }
}

}  // namespace
}  // namespace linemap
