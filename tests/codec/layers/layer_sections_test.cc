// LAYR bodies (spec/format.md 5.6): round trips of random layers in sections
// of several sides, the sections a region reads, the table laid out by hand
// from the spec, and bodies that must fail.
#include "codec/layers/layer_sections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "codec/layers/layer_coding.h"
#include "codec/layers/section_order.h"
#include "format/byte_io.h"
#include "format/range_coder.h"

namespace linemap {
namespace {

constexpr int kW = 300, kH = 200;

CellIndex RandomPoint(std::mt19937* rng) {
  return {static_cast<int>((*rng)() % kW), static_cast<int>((*rng)() % kH)};
}

CellIndex Clamped(CellIndex p) {
  return {std::clamp(p.col, 0, kW - 1), std::clamp(p.row, 0, kH - 1)};
}

std::vector<WallPolyline> RandomWalls(std::mt19937* rng, int count) {
  std::vector<WallPolyline> walls;
  for (int i = 0; i < count; ++i) {
    WallPolyline wall{{RandomPoint(rng)}};
    const int points = 2 + static_cast<int>((*rng)() % 4);
    while (static_cast<int>(wall.points.size()) < points) {
      CellIndex q = wall.points.back();
      q.col += static_cast<int>((*rng)() % 61) - 30;
      q.row += static_cast<int>((*rng)() % 61) - 30;
      q = Clamped(q);
      if (!(q == wall.points.back())) wall.points.push_back(q);
    }
    walls.push_back(std::move(wall));
  }
  return walls;
}

std::vector<CellIndex> RandomPolygon(std::mt19937* rng) {
  const CellIndex a{static_cast<int>((*rng)() % (kW - 30)), static_cast<int>((*rng)() % (kH - 30))};
  const int w = 2 + static_cast<int>((*rng)() % 25), h = 2 + static_cast<int>((*rng)() % 25);
  return {a, {a.col + w, a.row}, {a.col + w, a.row + h}, {a.col, a.row + h}};
}

struct Layers {
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
};

// Random layers with room ids 10, 13, 16, ... (gaps, increasing in the
// order made, which the grouping by section breaks) and objects in random
// rooms or none.
Layers RandomLayers(std::mt19937* rng) {
  Layers l;
  l.walls = RandomWalls(rng, 40);
  for (int i = 0; i < 12; ++i) {
    std::vector<CellIndex> polygon = RandomPolygon(rng);
    std::vector<CellIndex> chain = ChainOfPolygon(polygon);
    l.rooms.push_back({static_cast<std::uint32_t>(10 + 3 * i), static_cast<RoomKind>(i % 3),
                       std::move(polygon), std::move(chain)});
  }
  for (int i = 0; i < 15; ++i) {
    std::vector<CellIndex> polygon = RandomPolygon(rng);
    std::vector<CellIndex> outline = ChainOfPolygon(polygon);
    const std::int32_t room = (*rng)() % 4 == 0 ? -1 : static_cast<std::int32_t>(10 + 3 * (i % 12));
    l.furniture.push_back(
        {static_cast<std::uint32_t>(i), room, std::move(polygon), std::move(outline)});
  }
  return l;
}

// The table read, then the sections meeting `region` (all when null).
StatusOr<DecodedLayers> ReadAndDecode(const std::vector<std::uint8_t>& body,
                                      const DecodeLimits& limits, const CellRect* region) {
  LINEMAP_ASSIGN_OR_RETURN(LayerSectionTable table, ReadLayerSectionTable(body, kW, kH, limits));
  return DecodeLayerSections(body, table, kW, kH, limits, true, region);
}

void Arrange(int side, Layers* l) {
  ArrangeLayersInSections(kW, kH, side, &l->walls, &l->rooms, &l->furniture);
}

std::vector<std::uint8_t> Encode(const Layers& l, int side) {
  return EncodeLayerSections(l.walls, l.rooms, l.furniture, kW, kH, side);
}

// The smallest box of a list of points meets the region.
bool PointsMeet(const std::vector<CellIndex>& points, const CellRect& r) {
  int c0 = kW, r0 = kH, c1 = -1, r1 = -1;
  for (const CellIndex& p : points) {
    c0 = std::min(c0, p.col);
    r0 = std::min(r0, p.row);
    c1 = std::max(c1, p.col);
    r1 = std::max(r1, p.row);
  }
  return c0 < r.x1 && c1 >= r.x0 && r0 < r.y1 && r1 >= r.y0;
}

TEST(LayerSectionsTest, ArrangedLayersRoundTripInSectionsOfAnySide) {
  std::mt19937 rng(7);
  for (int side : {16, 37, 64, 150, 300}) {
    Layers l = RandomLayers(&rng);
    const std::size_t walls = l.walls.size(), rooms = l.rooms.size(), objects = l.furniture.size();
    Arrange(side, &l);
    ASSERT_EQ(l.walls.size(), walls);
    ASSERT_EQ(l.rooms.size(), rooms);
    ASSERT_EQ(l.furniture.size(), objects);
    auto decoded = ReadAndDecode(Encode(l, side), DecodeLimits{}, nullptr);
    ASSERT_TRUE(decoded.ok()) << side << ": " << decoded.status().ToString();
    EXPECT_EQ(decoded->walls, l.walls) << side;
    EXPECT_EQ(decoded->rooms, l.rooms) << side;
    EXPECT_EQ(decoded->furniture, l.furniture) << side;
  }
}

TEST(LayerSectionsTest, RenumberedRoomsKeepTheirObjects) {
  std::mt19937 rng(11);
  Layers l = RandomLayers(&rng);
  // Each object's room polygon before the arrangement.
  std::vector<std::vector<CellIndex>> room_of_object;
  for (const FurnitureObject& o : l.furniture) {
    std::vector<CellIndex> polygon;
    for (const RoomOutline& r : l.rooms) {
      if (static_cast<std::int32_t>(r.id) == o.room_id) polygon = r.polygon;
    }
    room_of_object.push_back(polygon);
  }
  std::vector<std::vector<CellIndex>> object_polygons;
  for (const FurnitureObject& o : l.furniture) object_polygons.push_back(o.polygon);
  Arrange(37, &l);
  for (std::size_t i = 1; i < l.rooms.size(); ++i) EXPECT_GT(l.rooms[i].id, l.rooms[i - 1].id);
  for (std::size_t i = 0; i < l.furniture.size(); ++i) {
    const FurnitureObject& o = l.furniture[i];
    EXPECT_EQ(o.id, i);
    // Find the object as it was (its polygon may start at another vertex).
    std::size_t was = object_polygons.size();
    for (std::size_t k = 0; k < object_polygons.size(); ++k) {
      if (std::is_permutation(object_polygons[k].begin(), object_polygons[k].end(),
                              o.polygon.begin(), o.polygon.end())) {
        was = k;
      }
    }
    ASSERT_LT(was, object_polygons.size());
    std::vector<CellIndex> room_now;
    for (const RoomOutline& r : l.rooms) {
      if (static_cast<std::int32_t>(r.id) == o.room_id) room_now = r.polygon;
    }
    EXPECT_EQ(room_now, room_of_object[was]) << "object " << i;
  }
}

// A region reads every item that can reach it, and no section's items
// partly: the result is the items of whole sections, in file order.
TEST(LayerSectionsTest, ARegionReadsEverySectionThatReachesIt) {
  std::mt19937 rng(13);
  Layers l = RandomLayers(&rng);
  Arrange(64, &l);
  const std::vector<std::uint8_t> body = Encode(l, 64);
  for (int trial = 0; trial < 40; ++trial) {
    CellRect r;
    r.x0 = static_cast<int>(rng() % kW);
    r.y0 = static_cast<int>(rng() % kH);
    r.x1 = r.x0 + 1 + static_cast<int>(rng() % (kW - r.x0));
    r.y1 = r.y0 + 1 + static_cast<int>(rng() % (kH - r.y0));
    auto part = ReadAndDecode(body, DecodeLimits{}, &r);
    ASSERT_TRUE(part.ok()) << part.status().ToString();
    for (const WallPolyline& w : l.walls) {
      if (PointsMeet(w.points, r)) {
        EXPECT_NE(std::find(part->walls.begin(), part->walls.end(), w), part->walls.end());
      }
    }
    for (const RoomOutline& room : l.rooms) {
      if (PointsMeet(room.polygon, r)) {
        EXPECT_NE(std::find(part->rooms.begin(), part->rooms.end(), room), part->rooms.end());
      }
    }
    for (const FurnitureObject& o : l.furniture) {
      if (PointsMeet(o.polygon, r)) {
        // With its id: objects are numbered through the whole chunk.
        EXPECT_NE(std::find(part->furniture.begin(), part->furniture.end(), o),
                  part->furniture.end());
      }
    }
    EXPECT_LE(part->walls.size(), l.walls.size());
  }
  // A region away from every item reads nothing.
  Layers corner;
  corner.walls = {WallPolyline{{{1, 1}, {5, 1}}}};
  Arrange(64, &corner);
  const CellRect far{200, 150, 300, 200};
  auto none = ReadAndDecode(Encode(corner, 64), DecodeLimits{}, &far);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->walls.empty());
}

// The body as spec 5.6 lays it out, written here field by field: the side,
// then per section (row-major) its three counts and, if any, its box (more
// than one section) and stream length; then the streams, each the section's
// walls, rooms and objects coded from the box's lower corner.
TEST(LayerSectionsTest, BodyIsLaidOutAsTheSpecSays) {
  Layers l;
  l.walls = {WallPolyline{{{10, 10}, {40, 10}, {40, 30}}}, WallPolyline{{{200, 20}, {250, 20}}}};
  l.rooms = {RoomOutline{1, RoomKind::kRoom, {{210, 150}, {260, 150}, {260, 190}}, {}}};
  l.rooms[0].chain = ChainOfPolygon(l.rooms[0].polygon);
  l.furniture = {FurnitureObject{0, 1, {{220, 160}, {225, 160}, {225, 165}}, {}}};
  l.furniture[0].outline = ChainOfPolygon(l.furniture[0].polygon);
  const int side = 128;  // 3 x 2 sections: (0,0) holds wall 0, (1,0) wall 1, (1,1) the rest
  Arrange(side, &l);
  ByteWriter expected;
  expected.PutVarint(side);
  ByteWriter streams;
  const auto section = [&](std::size_t w0, std::size_t wn, std::size_t r0, std::size_t rn,
                           std::size_t o0, std::size_t on, int c0, int row0, int c1, int row1) {
    expected.PutVarint(wn);
    expected.PutVarint(rn);
    expected.PutVarint(on);
    expected.PutVarint(c0);
    expected.PutVarint(row0);
    expected.PutVarint(c1 - c0);
    expected.PutVarint(row1 - row0);
    RangeEncoder enc;
    EncodeWallItems(&enc, l.walls.data() + w0, wn, {c0, row0});
    EncodeRoomItems(&enc, l.rooms.data() + r0, rn, {c0, row0});
    EncodeFurnitureItems(&enc, l.furniture.data() + o0, on, {c0, row0});
    enc.Finish();
    expected.PutVarint(enc.bytes().size());
    streams.PutBytes(enc.bytes());
  };
  const auto empty = [&] {
    expected.PutVarint(0);
    expected.PutVarint(0);
    expected.PutVarint(0);
  };
  section(0, 1, 0, 0, 0, 0, 10, 10, 40, 30);      // section 0: columns 0..127, rows 0..127
  section(1, 1, 0, 0, 0, 0, 200, 20, 250, 20);    // section 1: columns 128..255
  empty();                                        // section 2: columns 256..299
  empty();                                        // section 3: rows 128..199
  section(2, 0, 0, 1, 0, 1, 210, 150, 260, 190);  // section 4
  empty();                                        // section 5
  expected.PutBytes(streams.bytes());
  EXPECT_EQ(Encode(l, side), expected.bytes());
  // One section: no box, the stream coded from (0, 0).
  ByteWriter single;
  single.PutVarint(300);
  single.PutVarint(2);
  single.PutVarint(1);
  single.PutVarint(1);
  RangeEncoder enc;
  EncodeWallItems(&enc, l.walls.data(), 2, {0, 0});
  EncodeRoomItems(&enc, l.rooms.data(), 1, {0, 0});
  EncodeFurnitureItems(&enc, l.furniture.data(), 1, {0, 0});
  enc.Finish();
  single.PutVarint(enc.bytes().size());
  single.PutBytes(enc.bytes());
  EXPECT_EQ(Encode(l, 300), single.bytes());
}

void ExpectCorrupt(const std::vector<std::uint8_t>& body, const std::string& what) {
  auto decoded = ReadAndDecode(body, DecodeLimits{}, nullptr);
  ASSERT_FALSE(decoded.ok()) << what;
  EXPECT_EQ(decoded.status().code(), StatusCode::kCorrupt)
      << what << ": " << decoded.status().ToString();
  EXPECT_NE(decoded.status().message().find(what), std::string::npos)
      << decoded.status().ToString();
}

TEST(LayerSectionsTest, MalformedBodiesAreCorrupt) {
  Layers l;
  l.walls = {WallPolyline{{{10, 10}, {40, 10}}}, WallPolyline{{{200, 150}, {250, 150}}}};
  Arrange(128, &l);
  const std::vector<std::uint8_t> good = Encode(l, 128);
  ASSERT_TRUE(ReadAndDecode(good, DecodeLimits{}, nullptr).ok());
  ExpectCorrupt({8}, "section side 8 outside");
  ExpectCorrupt({}, "section side");
  // Six sections need at least 18 bytes of table.
  ExpectCorrupt({128, 1, 0, 0}, "sections do not fit the chunk");
  std::vector<std::uint8_t> longer = good;
  longer.push_back(0);
  ExpectCorrupt(longer, "do not fill the chunk");
  // Section 0's box one column narrower than its wall: the wall's end is
  // outside it.
  std::vector<std::uint8_t> narrow = good;
  // side (1 byte: 128 is 2 bytes as a varint), counts 1 0 0, box 10 10 30 0.
  ASSERT_EQ(narrow[2], 1);
  ASSERT_EQ(narrow[7], 30);
  narrow[7] = 29;
  ExpectCorrupt(narrow, "section's box");
  std::vector<std::uint8_t> outside = good;
  outside[6] = 100;  // rows 100..200 of a 200-row grid
  outside[8] = 100;
  ExpectCorrupt(outside, "box outside the grid");
  // Two sections whose room ids do not increase in file order.
  Layers rooms;
  rooms.rooms = {RoomOutline{5, RoomKind::kRoom, {{10, 10}, {20, 10}, {20, 20}}, {}},
                 RoomOutline{3, RoomKind::kRoom, {{200, 150}, {220, 150}, {220, 160}}, {}}};
  ExpectCorrupt(EncodeLayerSections(rooms.walls, rooms.rooms, rooms.furniture, kW, kH, 128),
                "room ids do not increase");
}

// A side near 2^64 is refused before anything divides by it or rounds it
// up (decoders cut the map into bands of a side's rows).
TEST(LayerSectionsTest, HugeSidesAreCorrupt) {
  for (std::uint64_t side : {std::uint64_t{1} << 31, ~std::uint64_t{0}, ~std::uint64_t{0} - 5}) {
    ByteWriter body;
    body.PutVarint(side);
    ExpectCorrupt(body.bytes(), "outside 16..2^31-1");
  }
}

// Empty sections cost three bytes in the file and nothing in memory: the
// table keeps the sections that hold items (a table of 2^16 empty sections,
// as a deflated chunk could hold in a few hundred bytes).
TEST(LayerSectionsTest, EmptySectionsAreNotKept) {
  ByteWriter body;
  body.PutVarint(16);
  const int w = 16 * 256, h = 16 * 256;
  for (int k = 0; k < 256 * 256; ++k) {
    body.PutVarint(0);
    body.PutVarint(0);
    body.PutVarint(0);
  }
  auto table = ReadLayerSectionTable(body.bytes(), w, h, DecodeLimits{});
  ASSERT_TRUE(table.ok()) << table.status().ToString();
  EXPECT_TRUE(table->sections.empty());
  EXPECT_EQ(table->side, 16);
}

TEST(LayerSectionsTest, CountsAboveTheLimitsAreResourceExhausted) {
  std::mt19937 rng(3);
  Layers l = RandomLayers(&rng);
  Arrange(64, &l);
  const std::vector<std::uint8_t> body = Encode(l, 64);
  DecodeLimits few_walls;
  few_walls.max_segments = 10;
  auto w = ReadAndDecode(body, few_walls, nullptr);
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.status().code(), StatusCode::kResourceExhausted) << w.status().ToString();
  DecodeLimits short_chains;
  short_chains.max_chain_length = 50;
  auto c = ReadAndDecode(body, short_chains, nullptr);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.status().code(), StatusCode::kResourceExhausted) << c.status().ToString();
  // 12 rooms and 15 objects, each counted against the object limit apart.
  ASSERT_EQ(l.rooms.size(), 12u);
  ASSERT_EQ(l.furniture.size(), 15u);
  DecodeLimits objects;
  objects.max_objects = 15;
  EXPECT_TRUE(ReadAndDecode(body, objects, nullptr).ok());
  // Below 12 either count may pass the limit first (the sums run section by
  // section); at 14 only the objects do.
  for (const auto& [limit, what] : {std::pair<std::uint64_t, const char*>{11, "exceed"},
                                    std::pair<std::uint64_t, const char*>{14, "objects exceed"}}) {
    objects.max_objects = limit;
    auto o = ReadAndDecode(body, objects, nullptr);
    ASSERT_FALSE(o.ok()) << limit;
    EXPECT_EQ(o.status().code(), StatusCode::kResourceExhausted) << o.status().ToString();
    EXPECT_NE(o.status().message().find(std::string(what) + " the object limit"), std::string::npos)
        << o.status().ToString();
  }
}

// Ids are 32-bit, so a section of 2^32 walls or more is corrupt however
// far a caller lifts the limits: no limit it names would let it be read.
TEST(LayerSectionsTest, SectionCountsAbove32BitsAreCorruptWithEveryLimitLifted) {
  DecodeLimits lifted;
  lifted.max_segments = UINT64_MAX;
  lifted.max_objects = UINT64_MAX;
  const std::uint64_t over = std::uint64_t{1} << 32;
  for (int field = 0; field < 3; ++field) {
    ByteWriter body;
    body.PutVarint(std::max(kW, kH));  // one section
    for (int f = 0; f < 3; ++f) body.PutVarint(f == field ? over : 0);
    body.PutVarint(0);  // stream length
    auto table = ReadLayerSectionTable(body.bytes(), kW, kH, lifted);
    ASSERT_FALSE(table.ok()) << field;
    EXPECT_EQ(table.status().code(), StatusCode::kCorrupt) << table.status().ToString();
    EXPECT_EQ(table.status().limit(), Limit::kNone) << field;
    EXPECT_NE(table.status().message().find("4294967296"), std::string::npos)
        << table.status().ToString();
  }
}

// Every prefix and every single-byte change of a body fails cleanly or
// decodes to points inside the grid.
TEST(LayerSectionsTest, DamagedBodiesFailOrDecodeInsideTheGrid) {
  std::mt19937 rng(17);
  Layers l = RandomLayers(&rng);
  Arrange(64, &l);
  const std::vector<std::uint8_t> body = Encode(l, 64);
  const auto inside = [](const DecodedLayers& d) {
    for (const WallPolyline& w : d.walls) {
      for (const CellIndex& p : w.points) {
        if (p.col < 0 || p.row < 0 || p.col >= kW || p.row >= kH) return false;
      }
    }
    return true;
  };
  for (std::size_t n = 0; n < body.size(); ++n) {
    std::vector<std::uint8_t> cut(body.begin(), body.begin() + static_cast<std::ptrdiff_t>(n));
    auto d = ReadAndDecode(cut, DecodeLimits{}, nullptr);
    if (d.ok()) {
      EXPECT_TRUE(inside(*d));
    }
  }
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> bad = body;
    bad[rng() % bad.size()] ^= static_cast<std::uint8_t>(1 + rng() % 255);
    auto d = ReadAndDecode(bad, DecodeLimits{}, nullptr);
    if (d.ok()) {
      EXPECT_TRUE(inside(*d));
    }
  }
}

}  // namespace
}  // namespace linemap
