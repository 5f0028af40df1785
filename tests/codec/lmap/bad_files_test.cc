// Must-fail .lmap files (tests/data/bad/lmap_decode/, named after their
// defect): each must be refused with an error that names the problem and,
// where the defect sits in one chunk, that chunk. The same files are
// replayed under the fuzz target by ctest (fuzz.replay.lmap_decode).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "codec/lmap/draco_segments.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

struct BadFile {
  const char* name;
  const char* expected;  // a substring of the error message, written by hand
};

const BadFile kBadFiles[] = {
    {"bad_crc.lmap", "fails its CRC check"},
    {"chunk_length_overflow.lmap", "chunk SEGS"},
    {"data_after_lend.lmap", "data after the LEND chunk"},
    {"draco_in_free_chunk.lmap", "chunk FREE: only SEGS may use the Draco payload coder"},
    {"draco_malformed.lmap", "chunk SEGS: Draco data"},
    {"draco_trailing_bytes.lmap", "chunk SEGS: Draco data has trailing bytes"},
    {"empty.lmap", "bad signature"},
    {"huge_dimensions.lmap", "over the limit"},
    {"inflate_bomb.lmap", "chunk FREE: inflated size"},
    {"negative_resolution.lmap", "chunk LMHD: resolution is not a positive number"},
    {"no_header_chunk.lmap", "the first chunk is not LMHD"},
    {"png_renamed.lmap", "bad signature"},
    {"repeated_chunk.lmap", "chunk SEGS: chunk out of order or repeated"},
    {"second_header_chunk.lmap", "a second LMHD chunk"},
    {"segment_outside_map.lmap", "chunk SEGS"},
    {"too_many_segments.lmap", "chunk SEGS: segment count"},
    {"truncated.lmap", "truncated"},
    {"unknown_critical_chunk.lmap", "chunk XTRA: unknown critical chunk"},
    {"unknown_payload_coder.lmap", "chunk FREE: unknown payload coder 7"},
    {"unsupported_version.lmap", "format version 3"},
    {"zero_resolution.lmap", "chunk LMHD: resolution is not a positive number"},
    // Version 2.0 (written by tests/data/make_v2_test_files.sh).
    {"v2_segs_chunk_in_version_2.lmap", "chunk SEGS: unknown critical chunk"},
    {"v2_tile_lengths_do_not_add_up.lmap", "chunk CELL: tile lengths do not add up"},
    {"v2_tile_size_below_16.lmap", "chunk CELL: tile size 8 outside 16..65536"},
    {"v2_wall_after_cell.lmap", "chunk WALL: chunk out of order or repeated"},
    {"v2_wall_count_over_limit.lmap", "chunk WALL: 1099511627776 walls exceed the segment limit"},
    {"v2_wall_stream_truncated.lmap", "chunk WALL: "},
    {"v2_room_count_over_object_limit.lmap", "chunk ROOM: 67108864 rooms exceed the object limit"},
    {"v2_tile_size_65537.lmap", "chunk CELL: tile size 65537 outside 16..65536"},
    {"v2_tile_length_over_body_size.lmap", "chunk CELL: tile length past the chunk's end"},
    {"v2_tile_count_over_bytes_left.lmap", "chunk CELL: tile index past the chunk's end"},
    {"v2_header_reserved_flag_bit_5.lmap", "chunk LMHD: reserved header flags are set"},
    {"v2_origin_x_nan.lmap", "chunk LMHD: origin x is not finite"},
    {"v2_origin_y_infinite.lmap", "chunk LMHD: origin y is not finite"},
    {"v2_meta_count_over_body_size.lmap", "chunk meta: entry count 7 exceeds 6"},
    // Version 2.1 (the same script).
    {"v2_1_block_side_1.lmap", "chunk BLKS: block side 1 outside 2..5"},
    {"v2_1_tile_side_not_a_multiple_of_the_block_side.lmap",
     "chunk BLKS: tile size 1024 outside 16..65536 or not a multiple of the block side"},
    {"v2_1_cell_and_blks.lmap", "chunk BLKS: chunk out of order or repeated"},
    {"v2_1_block_data_past_the_tile.lmap", "chunk BLKS: tile 0: block data past the tile's end"},
    // Version 2.2 (the same script).
    {"v2_2_section_side_8.lmap", "chunk LAYR: section side 8 outside 16..2^31-1"},
    {"v2_2_section_side_2_64_minus_1.lmap",
     "chunk LAYR: section side 18446744073709551615 outside 16..2^31-1"},
    {"v2_2_layr_and_wall.lmap", "chunk LAYR: LAYR in a file with WALL, ROOM or FURN"},
    {"v2_2_item_outside_its_section_box.lmap",
     "chunk LAYR: section 0: point out of the grid (or its section's box) or malformed"},
    {"v2_2_section_box_outside_the_grid.lmap", "chunk LAYR: section 0: box outside the grid"},
    {"v2_2_section_lengths_do_not_add_up.lmap",
     "chunk LAYR: the section streams do not fill the chunk"},
    {"v2_2_section_table_under_3_bytes_a_section.lmap",
     "chunk LAYR: 50 sections do not fit the chunk"},
    {"v2_2_layr_deflate_stream_truncated.lmap",
     "chunk LAYR: deflate stream is malformed or has the wrong length"},
    {"v2_2_section_room_count_2_32_beside_walls_over_the_limit.lmap",
     "chunk LAYR: 4294967296 rooms in one section, above 2^32 - 1"},
    // Version 2.3 (the same script).
    {"v2_3_tile_model_13.lmap", "chunk CELL: tile 0: tile cells: unknown model 13"},
    {"v2_3_meta_trailing_bytes.lmap", "chunk meta: metadata has trailing bytes"},
    // Checked whatever a decoder has to draw (the same script): layers in a
    // file without cells, the cells' chunk of a grid without cells.
    {"v2_2_layr_stream_corrupt_without_cells.lmap",
     "chunk LAYR: section 0: the section's range-coded data is malformed or truncated"},
    {"v2_empty_grid_tile_size_5.lmap", "chunk CELL: tile size 5 outside 16..65536"},
    {"v2_1_empty_grid_block_side_0.lmap", "chunk BLKS: block side 0 outside 2..5"},
};

std::string BadDir() { return testing::SourceDir() + "/tests/data/bad/lmap_decode/"; }

class LmapBadFileTest : public ::testing::TestWithParam<BadFile> {};

// Refused by every way in: the whole file (what `linemap info` reads), the
// grid alone (LoadLmap, which reads LAYR band by band and skips what it
// need not draw), and the decode to a map YAML + PGM (`linemap decode`),
// which leaves no file behind.
TEST_P(LmapBadFileTest, FailsNamingTheProblem) {
  const BadFile& bad = GetParam();
  auto bytes = ReadFileBytes(BadDir() + bad.name, std::uint64_t{1} << 20);
  ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
  auto decoded = DecodeLmapContents(*bytes);
  ASSERT_FALSE(decoded.ok()) << bad.name << " decoded without error";
  EXPECT_NE(decoded.status().ToString().find(bad.expected), std::string::npos)
      << bad.name << ": " << decoded.status().ToString();
  auto grid = DecodeLmap(*bytes);
  ASSERT_FALSE(grid.ok()) << bad.name << " decoded by DecodeLmap without error";
  EXPECT_NE(grid.status().ToString().find(bad.expected), std::string::npos)
      << bad.name << ": " << grid.status().ToString();
  const std::string dir = testing::MakeTempDir("lmap_bad_files");
  auto saved = DecodeLmapToRosMap(BadDir() + bad.name, dir + "/out.yaml", DecodeLimits{},
                                  Durability::kUnsynced);
  ASSERT_FALSE(saved.ok()) << bad.name << " decoded to a map without error";
  EXPECT_NE(saved.status().ToString().find(bad.expected), std::string::npos)
      << bad.name << ": " << saved.status().ToString();
  EXPECT_TRUE(testing::ListDir(dir).empty()) << bad.name << " left a file behind";
}

INSTANTIATE_TEST_SUITE_P(AllBadFiles, LmapBadFileTest, ::testing::ValuesIn(kBadFiles),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           return name.substr(0, name.find('.'));
                         });

TEST(LmapBadFiles, EveryFileInTheFolderHasARow) {
  const std::vector<std::string> files = testing::ListDir(BadDir());
  ASSERT_FALSE(files.empty());
  for (const std::string& file : files) {
    bool listed = false;
    for (const BadFile& bad : kBadFiles) listed = listed || file.ends_with(bad.name);
    EXPECT_TRUE(listed) << file << " has no row in kBadFiles";
  }
}

// The valid counterparts of the must-fail files without cells: the
// bundled 2.2 file without its CELL chunk decodes, whole and in a window,
// to all unknown cells (its layers read and valid); a grid of 0 x 5 cells
// with a well-formed CELL body (a tile side and no tiles) decodes to an
// empty grid. Each file is rebuilt from depot_v2.lmap's chunks.
std::vector<std::uint8_t> RebuiltDepot(bool keep_cells, bool empty_grid) {
  StatusOr<std::vector<std::uint8_t>> bytes =
      ReadFileBytes(testing::SourceDir() + "/tests/data/lmap/depot_v2.lmap", 1 << 20);
  EXPECT_TRUE(bytes.ok());
  if (!bytes.ok()) return {};
  StatusOr<ContainerView> view = ParseContainer(*bytes, 1 << 20);
  EXPECT_TRUE(view.ok());
  if (!view.ok()) return {};
  ContainerWriter out(view->major, view->minor);
  for (const Chunk& chunk : view->chunks) {
    std::vector<std::uint8_t> payload(chunk.payload, chunk.payload + chunk.size);
    if (empty_grid && chunk.type == "LMHD") {
      // Width and height are the first two varints (604 and 307: 2 bytes each).
      payload.erase(payload.begin(), payload.begin() + 4);
      payload.insert(payload.begin(), {0, 5});
    }
    if (empty_grid && chunk.type == "LAYR") continue;  // nothing lies in such a grid
    if (empty_grid && chunk.type == "CELL") payload = {0, 0x80, 0x08};  // coder 0, tile side 1024
    if (!keep_cells && chunk.type == "CELL") continue;
    out.AddChunk(chunk.type, payload);
  }
  return out.Finish();
}

TEST(LmapBadFiles, ValidFilesWithoutCellsDecode) {
  const std::vector<std::uint8_t> no_cells = RebuiltDepot(false, false);
  StatusOr<LmapContents> contents = DecodeLmapContents(no_cells);
  ASSERT_TRUE(contents.ok()) << contents.status().ToString();
  EXPECT_GT(contents->walls.size(), 0u);
  EXPECT_EQ(contents->grid.Count().unknown, std::size_t{604} * 307);
  StatusOr<Grid> grid = DecodeLmap(no_cells);
  ASSERT_TRUE(grid.ok()) << grid.status().ToString();
  EXPECT_EQ(grid->Count().unknown, std::size_t{604} * 307);
  StatusOr<Grid> window = DecodeLmapRegion(no_cells, CellWindow{10, 20, 110, 70});
  ASSERT_TRUE(window.ok()) << window.status().ToString();
  EXPECT_EQ(window->Count().unknown, std::size_t{100} * 50);

  StatusOr<LmapContents> empty = DecodeLmapContents(RebuiltDepot(true, true));
  ASSERT_TRUE(empty.ok()) << empty.status().ToString();
  EXPECT_EQ(empty->grid.width(), 0);
  EXPECT_EQ(empty->grid.height(), 5);
}

// A Draco SEGS body whose header claims 2^31 - 1 points: refused from the
// header, before the Draco decoder could allocate for that many points
// (corrupt: more than 1024 points per body byte).
TEST(LmapBadFiles, DracoPointCountIsCheckedBeforeDraco) {
  const std::vector<LatticeSegment> segments = {{{0, 0}, {5, 0}}, {{1, 2}, {1, 7}}};
  std::vector<std::uint8_t> body = EncodeSegmentsDraco(segments);
  ASSERT_GE(body.size(), 15u);
  ASSERT_EQ(std::memcmp(body.data(), "DRACO", 5), 0);
  ASSERT_EQ(body[11], 2u);  // the point count, little-endian int32 at byte 11
  ASSERT_EQ(body[12] | body[13] | body[14], 0);
  auto ok = DecodeSegmentsDraco(body, 10, 10, DecodeLimits{});
  ASSERT_TRUE(ok.ok()) << ok.status().ToString();
  EXPECT_EQ(*ok, segments);

  body[11] = body[12] = body[13] = 0xFF;
  body[14] = 0x7F;
  auto huge = DecodeSegmentsDraco(body, 10, 10, DecodeLimits{});
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.status().code(), StatusCode::kCorrupt) << huge.status().ToString();
  EXPECT_NE(huge.status().message().find("2147483647 segments"), std::string::npos);

  DecodeLimits tight;
  tight.max_segments = 1;
  body[11] = 2;
  body[12] = body[13] = body[14] = 0;
  EXPECT_EQ(DecodeSegmentsDraco(body, 10, 10, tight).status().code(),
            StatusCode::kResourceExhausted);
}

}  // namespace
}  // namespace linemap
