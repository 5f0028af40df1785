// What a viewer reads without the rest of a file: the header, the layers'
// items near a window (equal to filtering the whole file's items by their
// boxes, on files of every layer layout), and the room at a cell (checked
// against a transcription of spec 8.2's even-odd rule, the smallest
// enclosing polygon, and the crop of the whole decode).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

std::vector<std::uint8_t> Fixture(const std::string& name) {
  StatusOr<std::vector<std::uint8_t>> bytes =
      ReadFileBytes(testing::SourceDir() + "/tests/data/lmap/" + name, std::uint64_t{1} << 30);
  EXPECT_TRUE(bytes.ok()) << name;
  return bytes.ok() ? *bytes : std::vector<std::uint8_t>();
}

// depot as the default encoder writes it, with layer sections of `side`
// cells (0: the encoder's choice, one section on depot).
std::vector<std::uint8_t> Depot(int side) {
  StatusOr<Grid> map = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  EXPECT_TRUE(map.ok());
  EncodeOptions options;
  options.layer_section_cells = side;
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*map, options);
  EXPECT_TRUE(bytes.ok());
  return *bytes;
}

// depot's layers in one section, in sections of 64 and of 16 cells (LAYR),
// in the 2.0 layer chunks, and as a 1.0 file whose chains are its layers.
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> DepotInEveryLayerLayout() {
  return {{"one section", Depot(0)},
          {"sections of 64", Fixture("depot_v2_2_sections_64.lmap")},
          {"sections of 16", Depot(16)},
          {"2.0 chunks", Fixture("depot_v2_0.lmap")},
          {"1.0", Fixture("depot_v1_room_chains.lmap")}};
}

// Whether the box of `points` shares a cell with the half-open window.
bool MeetsWindow(const std::vector<CellIndex>& points, const CellWindow& w) {
  int c0 = INT_MAX, r0 = INT_MAX, c1 = INT_MIN, r1 = INT_MIN;
  for (const CellIndex& p : points) {
    c0 = std::min(c0, p.col);
    c1 = std::max(c1, p.col);
    r0 = std::min(r0, p.row);
    r1 = std::max(r1, p.row);
  }
  return !points.empty() && c1 >= w.col0 && c0 <= w.col1 - 1 && r1 >= w.row0 && r0 <= w.row1 - 1;
}

// The whole file's items that meet `w`, by the test's own box test.
LmapVectors Filtered(const LmapVectors& all, const CellWindow& w) {
  LmapVectors out = all;
  out.walls.clear();
  out.rooms.clear();
  out.furniture.clear();
  for (const WallPolyline& x : all.walls) {
    if (MeetsWindow(x.points, w)) out.walls.push_back(x);
  }
  for (const RoomOutline& x : all.rooms) {
    if (MeetsWindow(x.polygon, w)) out.rooms.push_back(x);
  }
  for (const FurnitureObject& x : all.furniture) {
    if (MeetsWindow(x.polygon, w)) out.furniture.push_back(x);
  }
  return out;
}

// Corners, single cells, edge rows and columns, the whole map, random
// windows.
// "col0,row0,col1,row1", for traces.
std::string WindowName(const CellWindow& w) {
  return std::to_string(w.col0) + "," + std::to_string(w.row0) + "," + std::to_string(w.col1) +
         "," + std::to_string(w.row1);
}

std::vector<CellWindow> Windows(int w, int h, unsigned seed) {
  std::vector<CellWindow> out = {{0, 0, 1, 1},
                                 {w - 1, h - 1, w, h},
                                 {0, 0, w, h},
                                 {0, h / 2, w, h / 2 + 1},
                                 {w / 2, 0, w / 2 + 1, h}};
  std::mt19937 rng(seed);
  for (int k = 0; k < 40; ++k) {
    const int c0 = static_cast<int>(rng() % w), r0 = static_cast<int>(rng() % h);
    const int side = 1 + static_cast<int>(rng() % 120);
    out.push_back(
        {c0, r0, std::min(w, c0 + side), std::min(h, r0 + 1 + static_cast<int>(rng() % 80))});
  }
  return out;
}

void ExpectSameItems(const LmapVectors& got, const LmapVectors& want) {
  EXPECT_EQ(got.width, want.width);
  EXPECT_EQ(got.height, want.height);
  EXPECT_EQ(got.major, want.major);
  EXPECT_EQ(got.minor, want.minor);
  EXPECT_EQ(got.meta.resolution, want.meta.resolution);
  EXPECT_EQ(got.meta.origin.x, want.meta.origin.x);
  ASSERT_EQ(got.walls.size(), want.walls.size());
  for (std::size_t i = 0; i < got.walls.size(); ++i) EXPECT_EQ(got.walls[i], want.walls[i]);
  ASSERT_EQ(got.rooms.size(), want.rooms.size());
  for (std::size_t i = 0; i < got.rooms.size(); ++i) EXPECT_EQ(got.rooms[i], want.rooms[i]);
  ASSERT_EQ(got.furniture.size(), want.furniture.size());
  for (std::size_t i = 0; i < got.furniture.size(); ++i) {
    EXPECT_EQ(got.furniture[i], want.furniture[i]);
  }
}

TEST(VectorQueriesTest, HeaderGivesTheDecodedMapsSizeAndFrame) {
  for (const char* name : {"depot_v2.lmap", "depot_v2_0.lmap", "depot_v2_raster_only.lmap",
                           "depot_lossless.lmap", "willow_v2_2_tolerance_1.lmap",
                           "willow_v2_3_tolerance_1.lmap", "depot_v1_room_chains.lmap"}) {
    SCOPED_TRACE(name);
    const std::vector<std::uint8_t> bytes = Fixture(name);
    StatusOr<LmapHeader> header = DecodeLmapHeader(bytes);
    ASSERT_TRUE(header.ok()) << header.status().message();
    StatusOr<LmapContents> whole = DecodeLmapContents(bytes);
    ASSERT_TRUE(whole.ok());
    EXPECT_EQ(header->major, whole->major);
    EXPECT_EQ(header->minor, whole->minor);
    EXPECT_EQ(header->lossless, whole->lossless);
    EXPECT_EQ(header->width, whole->grid.width());
    EXPECT_EQ(header->height, whole->grid.height());
    EXPECT_EQ(header->meta.resolution, whole->grid.meta.resolution);
    EXPECT_EQ(header->meta.origin.x, whole->grid.meta.origin.x);
    EXPECT_EQ(header->meta.origin.y, whole->grid.meta.origin.y);
    EXPECT_EQ(header->meta.origin.yaw, whole->grid.meta.origin.yaw);
    EXPECT_EQ(header->metadata, whole->metadata);
  }
  // With metadata: a fixture of 1.0 holds four entries, a tolerance file
  // of 2.3 its T.
  const StatusOr<LmapHeader> v1 = DecodeLmapHeader(Fixture("depot_v1_room_chains.lmap"));
  ASSERT_TRUE(v1.ok());
  EXPECT_EQ(v1->metadata.size(), 4u);
  const StatusOr<LmapHeader> t1 = DecodeLmapHeader(Fixture("willow_v2_3_tolerance_1.lmap"));
  ASSERT_TRUE(t1.ok());
  EXPECT_EQ(t1->metadata, (std::vector<std::pair<std::string, std::string>>{{"tolerance", "1"}}));
  EXPECT_EQ(DecodeLmapHeader(Fixture("willow_v2_2_tolerance_1.lmap"))->metadata.size(), 0u)
      << "written before files named their tolerance";
  EXPECT_FALSE(DecodeLmapHeader(Fixture("truncated.lmap")).ok());
  // A corrupt `meta` chunk rejects the file here as in the whole-file read.
  const StatusOr<LmapHeader> bad_meta = LoadLmapHeader(
      testing::SourceDir() + "/tests/data/bad/lmap_decode/v2_3_meta_trailing_bytes.lmap");
  ASSERT_FALSE(bad_meta.ok());
  EXPECT_NE(bad_meta.status().message().find("chunk meta: metadata has trailing bytes"),
            std::string::npos)
      << bad_meta.status().message();
  const StatusOr<LmapHeader> missing = LoadLmapHeader("/nonexistent/dir/map.lmap");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("/nonexistent/dir/map.lmap"), std::string::npos);
}

// The layers are read without the cells' body, but a cells' chunk whose
// payload coder no decoder reads (Draco is for 1.0 segments; 7 is reserved)
// refuses the file as the whole read does, rather than exporting its
// layers as if the file were fine. depot_v2.lmap with the CELL payload's
// first byte replaced.
TEST(VectorQueriesTest, LayersAloneRefuseACellsChunkOfAnUnknownCoder) {
  const std::vector<std::uint8_t> depot = Fixture("depot_v2.lmap");
  for (const auto& [coder, code, message] :
       {std::tuple{std::uint8_t{7}, StatusCode::kUnsupported,
                   "chunk CELL: unknown payload coder 7"},
        std::tuple{std::uint8_t{2}, StatusCode::kCorrupt,
                   "chunk CELL: the Draco payload coder is for SEGS only"}}) {
    StatusOr<ContainerView> view = ParseContainer(depot, 1 << 20);
    ASSERT_TRUE(view.ok());
    ContainerWriter out(view->major, view->minor);
    for (const Chunk& chunk : view->chunks) {
      std::vector<std::uint8_t> payload(chunk.payload, chunk.payload + chunk.size);
      if (chunk.type == "CELL") payload[0] = coder;
      if (chunk.type != "LEND") out.AddChunk(chunk.type, payload);
    }
    const std::vector<std::uint8_t> bytes = out.Finish();
    const StatusOr<LmapVectors> vectors = DecodeLmapVectors(bytes);
    ASSERT_FALSE(vectors.ok()) << int{coder};
    EXPECT_EQ(vectors.status().code(), code);
    EXPECT_NE(vectors.status().message().find(message), std::string::npos)
        << vectors.status().message();
    const StatusOr<LmapContents> whole = DecodeLmapContents(bytes);
    ASSERT_FALSE(whole.ok());
    EXPECT_EQ(whole.status().code(), code);
  }
  EXPECT_TRUE(DecodeLmapVectors(depot).ok());
}

// depot in every layer layout, read whole and in the windows of
// Windows(seed), each read checked to succeed (a failed one is reported and
// left out).
struct WindowRead {
  CellWindow window;
  LmapVectors got;
};
struct LayoutReads {
  std::string name;
  LmapVectors all;
  std::vector<WindowRead> windows;
};
std::vector<LayoutReads> ReadsOfEveryLayout(unsigned seed) {
  std::vector<LayoutReads> out;
  for (const auto& [name, bytes] : DepotInEveryLayerLayout()) {
    StatusOr<LmapVectors> all = DecodeLmapVectors(bytes);
    if (!all.ok()) {
      ADD_FAILURE() << name << ": " << all.status().message();
      continue;
    }
    LayoutReads reads{name, *std::move(all), {}};
    for (const CellWindow& w : Windows(reads.all.width, reads.all.height, seed)) {
      StatusOr<LmapVectors> got = DecodeLmapVectorsInWindow(bytes, w);
      if (!got.ok()) {
        ADD_FAILURE() << name << " " << WindowName(w) << ": " << got.status().message();
        continue;
      }
      reads.windows.push_back({w, *std::move(got)});
    }
    out.push_back(std::move(reads));
  }
  return out;
}

TEST(VectorQueriesTest, ItemsInAWindowAreTheWholeFilesItemsThatMeetIt) {
  for (const LayoutReads& layout : ReadsOfEveryLayout(7)) {
    SCOPED_TRACE(layout.name);
    ASSERT_FALSE(layout.all.rooms.empty());
    for (const auto& [w, got] : layout.windows) {
      SCOPED_TRACE(WindowName(w));
      ExpectSameItems(got, Filtered(layout.all, w));
    }
  }
}

// A wall has no stored id: its id is its index among the file's walls, so
// a window's walls carry their whole-file indices (exports of several
// windows merge). The expected indices are the positions, in the whole
// read, of the walls the test's own box test keeps; on files of sections
// of 16 and 64 cells most windows skip the sections before theirs.
TEST(VectorQueriesTest, WallsInAWindowKeepTheirIndicesInTheWholeFile) {
  for (const LayoutReads& layout : ReadsOfEveryLayout(11)) {
    SCOPED_TRACE(layout.name);
    const LmapVectors& all = layout.all;
    // The whole read numbers its walls 0, 1, ... and says so by an empty list.
    EXPECT_TRUE(all.wall_indices.empty());
    for (std::size_t i = 0; i < all.walls.size(); ++i) EXPECT_EQ(all.WallIndex(i), i);
    std::size_t renumbered = 0;  // windows whose first wall is not the file's first
    for (const auto& [w, got] : layout.windows) {
      SCOPED_TRACE(WindowName(w));
      std::vector<std::uint64_t> want;
      for (std::size_t i = 0; i < all.walls.size(); ++i) {
        if (MeetsWindow(all.walls[i].points, w)) want.push_back(i);
      }
      ASSERT_EQ(got.walls.size(), want.size());
      EXPECT_EQ(got.wall_indices, want);
      for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(got.WallIndex(i), want[i]);
        EXPECT_EQ(got.walls[i], all.walls[want[i]]);
      }
      renumbered += !want.empty() && want[0] != 0;
    }
    // (The 1.0 fixture has no segments.)
    if (!all.walls.empty()) {
      EXPECT_GT(renumbered, 0u) << "no window tells the indices from positions";
    }
  }
}

TEST(VectorQueriesTest, WindowsEmptyOrPastTheBorderAreRefused) {
  const std::vector<std::uint8_t> bytes = Depot(0);  // 604 x 307
  for (const CellWindow& w : std::vector<CellWindow>{
           {0, 0, 0, 5}, {3, 3, 3, 4}, {-1, 0, 5, 5}, {0, 0, 605, 5}, {0, 300, 5, 308}}) {
    const StatusOr<LmapVectors> got = DecodeLmapVectorsInWindow(bytes, w);
    ASSERT_FALSE(got.ok());
    EXPECT_EQ(got.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(got.status().message().find("604 x 307"), std::string::npos)
        << got.status().message();
  }
}

TEST(VectorQueriesTest, RoomAtIsTheSmallestRoomWhoseBorderEnclosesTheCell) {
  const std::vector<std::uint8_t> bytes = Depot(64);
  StatusOr<LmapVectors> all = DecodeLmapVectors(bytes);
  ASSERT_TRUE(all.ok());
  ASSERT_GE(all->rooms.size(), 2u);
  StatusOr<Grid> whole = DecodeLmap(bytes);
  ASSERT_TRUE(whole.ok());
  // Random cells, and cells of each room's border and just inside it
  // (where rooms meet).
  std::mt19937 rng(3);
  std::vector<CellIndex> cells;
  for (int k = 0; k < 150; ++k) {
    cells.push_back({static_cast<int>(rng() % all->width), static_cast<int>(rng() % all->height)});
  }
  for (const RoomOutline& room : all->rooms) {
    for (std::size_t i = 0; i < room.chain.size(); i += 1 + room.chain.size() / 6) {
      const CellIndex p = room.chain[i];
      cells.push_back(p);
      if (p.col + 1 < all->width) cells.push_back({p.col + 1, p.row});
    }
  }
  int found = 0;
  std::set<std::uint32_t> ids;
  for (const CellIndex& cell : cells) {
    SCOPED_TRACE(std::to_string(cell.col) + "," + std::to_string(cell.row));
    const RoomOutline* want = testing::ReferenceRoomAt(all->rooms, cell.col, cell.row);
    StatusOr<std::optional<LmapRoom>> got = DecodeLmapRoomAt(bytes, cell);
    ASSERT_TRUE(got.ok()) << got.status().message();
    ASSERT_EQ(got->has_value(), want != nullptr);
    if (want == nullptr) continue;
    ++found;
    ids.insert(want->id);
    const LmapRoom& room = **got;
    EXPECT_EQ(room.room, *want);
    // The window is the box of the border's cells, and the grid its crop.
    int c0 = INT_MAX, r0 = INT_MAX, c1 = INT_MIN, r1 = INT_MIN;
    for (const CellIndex& p : want->chain) {
      c0 = std::min(c0, p.col);
      c1 = std::max(c1, p.col);
      r0 = std::min(r0, p.row);
      r1 = std::max(r1, p.row);
    }
    EXPECT_EQ(room.window.col0, c0);
    EXPECT_EQ(room.window.row0, r0);
    EXPECT_EQ(room.window.col1, c1 + 1);
    EXPECT_EQ(room.window.row1, r1 + 1);
    ASSERT_EQ(room.grid.width(), c1 + 1 - c0);
    ASSERT_EQ(room.grid.height(), r1 + 1 - r0);
    std::size_t differ = 0;
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) differ += room.grid.at(c - c0, r - r0) != whole->at(c, r);
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_NEAR(room.grid.meta.origin.x, whole->meta.origin.x + c0 * whole->meta.resolution, 1e-9);
    EXPECT_NEAR(room.grid.meta.origin.y, whole->meta.origin.y + r0 * whole->meta.resolution, 1e-9);
  }
  // depot's corridor encloses most of the map and the rooms off it: most
  // cells have a room, and every room is the answer somewhere.
  EXPECT_GT(found, static_cast<int>(cells.size()) / 2);
  EXPECT_EQ(ids.size(), all->rooms.size());
}

TEST(VectorQueriesTest, RoomAtHasNoRoomWithoutRoomsAndRefusesCellsOffTheMap) {
  const StatusOr<std::optional<LmapRoom>> none =
      DecodeLmapRoomAt(Fixture("depot_v2_raster_only.lmap"), {300, 150});
  ASSERT_TRUE(none.ok()) << none.status().message();
  EXPECT_FALSE(none->has_value());
  const std::vector<std::uint8_t> bytes = Depot(0);
  for (const CellIndex cell : {CellIndex{-1, 0}, CellIndex{0, 307}, CellIndex{604, 10}}) {
    const StatusOr<std::optional<LmapRoom>> off = DecodeLmapRoomAt(bytes, cell);
    ASSERT_FALSE(off.ok());
    EXPECT_EQ(off.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(off.status().message().find("outside the map's 604 x 307 cells"), std::string::npos)
        << off.status().message();
  }
  const StatusOr<std::optional<LmapRoom>> missing =
      LoadLmapRoomAt("/nonexistent/dir/map.lmap", {1, 1});
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("/nonexistent/dir/map.lmap"), std::string::npos);
}

}  // namespace
}  // namespace linemap
