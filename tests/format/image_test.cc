// PGM and PNG decoding of hand-made images, and their classification into
// grids through LoadMapImage / LoadRosMap.
#include "format/image.h"

#include <gtest/gtest.h>
#include <png.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <random>
#include <vector>

#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::MakeTempDir;
using testing::WriteFile;

struct PngSpec {
  int width = 0;
  int height = 0;
  int color_type = PNG_COLOR_TYPE_GRAY;
  int bit_depth = 8;
  std::vector<std::vector<std::uint8_t>> rows;  // packed as PNG stores them
  std::vector<png_color> palette;
  std::vector<png_byte> trns;
  int interlace = PNG_INTERLACE_NONE;
};

void WritePng(const std::string& path, const PngSpec& spec) {
  FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, spec.width, spec.height, spec.bit_depth, spec.color_type, spec.interlace,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!spec.palette.empty()) {
    png_set_PLTE(png, info, spec.palette.data(), static_cast<int>(spec.palette.size()));
  }
  if (!spec.trns.empty()) {
    png_set_tRNS(png, info, spec.trns.data(), static_cast<int>(spec.trns.size()), nullptr);
  }
  png_write_info(png, info);
  const int passes = png_set_interlace_handling(png);
  for (int pass = 0; pass < passes; ++pass) {
    for (const auto& row : spec.rows) png_write_row(png, row.data());
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

// Cells of a grid listed top image row first, left to right, as letters:
// F free, O occupied, U unknown.
std::string TopDown(const Grid& grid) {
  std::string s;
  for (int row = grid.height() - 1; row >= 0; --row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Cell c = grid.at(col, row);
      s += c == Cell::kFree ? 'F' : c == Cell::kOccupied ? 'O' : 'U';
    }
  }
  return s;
}

Grid MustLoad(const std::string& path, const MapMetadata& meta = MapMetadata()) {
  StatusOr<Grid> grid = LoadMapImage(path, meta);
  EXPECT_TRUE(grid.ok()) << grid.status().message();
  return grid.ok() ? *grid : Grid();
}

TEST(ImageTest, BinaryPgmRowsTopFirst) {
  const std::string dir = MakeTempDir("img");
  // 3 x 2: top row black, white, 205; bottom row 254, 0, 128.
  WriteFile(dir + "/a.pgm",
            std::string("P5\n# comment\n3 2\n255\n") + std::string("\x00\xff\xcd\xfe\x00\x80", 6));
  const Grid grid = MustLoad(dir + "/a.pgm");
  ASSERT_EQ(grid.width(), 3);
  ASSERT_EQ(grid.height(), 2);
  EXPECT_EQ(TopDown(grid), "OFUFOU");
  EXPECT_EQ(grid.at(0, 1), Cell::kOccupied);  // grid row 1 is the top image row
}

TEST(ImageTest, AsciiPgm) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/a.pgm", "P2\n2 2\n15\n0 15\n# mid comment\n 8 15\n");
  // maxval 15: 8 -> 8/15 = 0.533 shade -> occ 0.467 unknown.
  EXPECT_EQ(TopDown(MustLoad(dir + "/a.pgm")), "OFUF");
}

TEST(ImageTest, SixteenBitPgm) {
  const std::string dir = MakeTempDir("img");
  // Big-endian samples: 0, 65535, 52690 (unknown: occ 0.19600...), 52691 (free).
  WriteFile(dir + "/a.pgm",
            std::string("P5 4 1 65535\n") + std::string("\x00\x00\xff\xff\xcd\xd2\xcd\xd3", 8));
  EXPECT_EQ(TopDown(MustLoad(dir + "/a.pgm")), "OFUF");
}

TEST(ImageTest, GreyPng8And16Bit) {
  const std::string dir = MakeTempDir("img");
  PngSpec g8{2, 1, PNG_COLOR_TYPE_GRAY, 8, {{0, 254}}, {}, {}};
  WritePng(dir + "/g8.png", g8);
  EXPECT_EQ(TopDown(MustLoad(dir + "/g8.png")), "OF");
  PngSpec g16{2, 1, PNG_COLOR_TYPE_GRAY, 16, {{0xcd, 0xd2, 0xcd, 0xd3}}, {}, {}};
  WritePng(dir + "/g16.png", g16);
  EXPECT_EQ(TopDown(MustLoad(dir + "/g16.png")), "UF");
}

TEST(ImageTest, OneBitPng) {
  const std::string dir = MakeTempDir("img");
  // 1-bit grey: 1 = white. Row bits 1010 0000.
  PngSpec b1{4, 1, PNG_COLOR_TYPE_GRAY, 1, {{0xa0}}, {}, {}};
  WritePng(dir + "/b1.png", b1);
  EXPECT_EQ(TopDown(MustLoad(dir + "/b1.png")), "FOFO");
}

TEST(ImageTest, GreyAlphaAndRgbaPng) {
  const std::string dir = MakeTempDir("img");
  // (white, opaque), (white, transparent) -> F, U (alpha averaged in).
  PngSpec ga{2, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 8, {{255, 255, 255, 0}}, {}, {}};
  WritePng(dir + "/ga.png", ga);
  EXPECT_EQ(TopDown(MustLoad(dir + "/ga.png")), "FU");
  PngSpec rgba{2, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, {{0, 0, 0, 255, 255, 255, 255, 0}}, {}, {}};
  WritePng(dir + "/rgba.png", rgba);
  EXPECT_EQ(TopDown(MustLoad(dir + "/rgba.png")), "OU");
}

TEST(ImageTest, RgbPngUsesPlainMean) {
  const std::string dir = MakeTempDir("img");
  // Yellow: mean 2/3 -> occ 0.333 unknown; grey 205 in RGB -> unknown; white free.
  PngSpec rgb{3, 1, PNG_COLOR_TYPE_RGB, 8, {{255, 255, 0, 205, 205, 205, 255, 255, 255}}, {}, {}};
  WritePng(dir + "/rgb.png", rgb);
  EXPECT_EQ(TopDown(MustLoad(dir + "/rgb.png")), "UUF");
}

TEST(ImageTest, PalettePngWithTransparency) {
  const std::string dir = MakeTempDir("img");
  PngSpec pal{3,
              1,
              PNG_COLOR_TYPE_PALETTE,
              8,
              {{0, 1, 2}},
              {{0, 0, 0}, {254, 254, 254}, {255, 255, 255}},
              {255, 255, 0}};
  WritePng(dir + "/pal.png", pal);
  // Entry 2 is white but fully transparent -> shade 0.75 -> unknown.
  EXPECT_EQ(TopDown(MustLoad(dir + "/pal.png")), "OFU");
}

TEST(ImageTest, NegateAndThresholdsFromYaml) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/a.pgm", std::string("P5 3 1 255\n") + std::string("\x00\xff\x80", 3));
  WriteFile(dir + "/a.yaml",
            "image: a.pgm\nresolution: 0.1\norigin: [1.5, -2, 0.25]\nnegate: 1\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  StatusOr<Grid> grid = LoadRosMap(dir + "/a.yaml");
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  EXPECT_EQ(TopDown(*grid), "FOU");
  EXPECT_DOUBLE_EQ(grid->meta.resolution, 0.1);
  EXPECT_EQ(grid->meta.origin, (Pose2D{1.5, -2.0, 0.25}));
  EXPECT_TRUE(grid->meta.negate);
}

TEST(ImageTest, BareImageGetsDefaultsAndOverrides) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/a.pgm", std::string("P5 2 1 255\n") + std::string("\x00\xcd", 2));
  StatusOr<Grid> plain = LoadRosMap(dir + "/a.pgm");
  ASSERT_TRUE(plain.ok());
  EXPECT_DOUBLE_EQ(plain->meta.resolution, 0.05);
  EXPECT_EQ(TopDown(*plain), "OU");
  MapLoadOptions options;
  options.free_thresh = 0.25;  // 205 -> occ 0.196 < 0.25 -> free
  options.resolution = 0.2;
  StatusOr<Grid> tuned = LoadRosMap(dir + "/a.pgm", options);
  ASSERT_TRUE(tuned.ok());
  EXPECT_EQ(TopDown(*tuned), "OF");
  EXPECT_DOUBLE_EQ(tuned->meta.resolution, 0.2);
}

TEST(ImageTest, RejectsMalformedImages) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/truncated.pgm", "P5 10 10 255\nabc");
  WriteFile(dir + "/text.pgm", "hello");
  WriteFile(dir + "/empty.pgm", "");
  WriteFile(dir + "/huge.pgm", "P5 100000 100000 255\n");
  WriteFile(dir + "/bad.png", std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
  for (const char* name : {"truncated.pgm", "text.pgm", "empty.pgm", "huge.pgm", "bad.png"}) {
    StatusOr<Grid> grid = LoadRosMap(dir + "/" + name);
    ASSERT_FALSE(grid.ok()) << name;
    EXPECT_NE(grid.status().message().find(name), std::string::npos)
        << "message should name the file: " << grid.status().message();
  }
  EXPECT_EQ(LoadRosMap(dir + "/huge.pgm").status().code(), StatusCode::kResourceExhausted);
}

// A grid's sides are ints: an image wider than 2^31 - 1 is refused as
// unsupported, not as over a limit, since no max_cells makes it loadable.
TEST(ImageTest, SideAbove31BitsIsUnsupportedWhateverTheCellLimit) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/wide.pgm", "P5 2147483648 1 255\n");
  StatusOr<RawImage> image = ReadImageFile(dir + "/wide.pgm", UINT64_MAX);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), StatusCode::kUnsupported) << image.status().ToString();
  EXPECT_EQ(image.status().limit(), Limit::kNone);
  EXPECT_NE(image.status().message().find("wide.pgm"), std::string::npos);
  EXPECT_NE(image.status().message().find("2^31 - 1"), std::string::npos);
  // Within the side but over the cells: the cell limit, which names itself.
  WriteFile(dir + "/long.pgm", "P5 2147483647 3 255\n");
  StatusOr<RawImage> over = ReadImageFile(dir + "/long.pgm", std::uint64_t{1} << 32);
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.status().code(), StatusCode::kResourceExhausted) << over.status().ToString();
  EXPECT_EQ(over.status().limit(), Limit::kCells);
}

TEST(ImageTest, RefusesANonImageOnItsFirstBytes) {
  // An endless stream: read whole, it would take gigabytes before the
  // signature check.
  StatusOr<RawImage> image = ReadImageFile("/dev/zero", std::uint64_t{1} << 28);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(image.status().message().find("/dev/zero"), std::string::npos);
}

TEST(ImageTest, AsciiPgmClaimingMoreCellsThanItsBytesIsTruncated) {
  const std::string dir = MakeTempDir("img");
  WriteFile(dir + "/short_ascii.pgm", "P2 16384 16383 255\n0 0 0\n");
  StatusOr<RawImage> image = ReadImageFile(dir + "/short_ascii.pgm", std::uint64_t{1} << 28);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(image.status().message().find("truncated"), std::string::npos);
}

}  // namespace
}  // namespace linemap

namespace linemap {
namespace {

// Files that must fail, named after their defect (tests/data/bad/map_image).
TEST(ImageTest, MustFailFilesFail) {
  const std::string dir = testing::SourceDir() + "/tests/data/bad/map_image";
  int checked = 0;
  for (const std::string& name : testing::ListDir(dir)) {
    StatusOr<RawImage> image = ReadImageFile(dir + "/" + name, std::uint64_t{1} << 28);
    EXPECT_FALSE(image.ok()) << name << " decoded";
    if (!image.ok()) {
      EXPECT_NE(image.status().message().find(name), std::string::npos);
    }
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

}  // namespace
}  // namespace linemap

namespace linemap {
namespace {

// The quantum a PGM sample v of maxval m becomes (GraphicsMagick's
// rounding), written out here for the reference.
std::uint16_t Quantum(unsigned v, unsigned maxval) {
  return static_cast<std::uint16_t>((v * 65535u + maxval / 2) / maxval);
}

// Images several times the 256 KiB read buffer, so that rows, samples and
// ASCII numbers straddle its refills.
TEST(ImageRowsTest, LargePgmsReadFromFileGiveTheirSamples) {
  const std::string dir = testing::MakeTempDir("img_rows");
  constexpr int kWidth = 701, kHeight = 503;
  std::mt19937 rng(5);
  std::vector<unsigned> values(kWidth * kHeight);
  std::uniform_int_distribution<unsigned> value(0, 1000);
  for (unsigned& v : values) v = value(rng);
  // ASCII with maxval 1000, uneven spacing and a comment mid-raster.
  std::string ascii = "P2\n" + std::to_string(kWidth) + " " + std::to_string(kHeight) + "\n1000\n";
  for (std::size_t i = 0; i < values.size(); ++i) {
    ascii += std::to_string(values[i]);
    ascii += i % 17 == 0 ? "\n" : (i % 5 == 0 ? "   " : " ");
    if (i == values.size() / 2) ascii += "# half way\n";
  }
  WriteFile(dir + "/ascii.pgm", ascii);
  // Binary 16-bit, big-endian.
  std::string binary = "P5 " + std::to_string(kWidth) + " " + std::to_string(kHeight) + " 1000\n";
  for (unsigned v : values) {
    binary += static_cast<char>(v >> 8);
    binary += static_cast<char>(v & 0xff);
  }
  WriteFile(dir + "/binary.pgm", binary);
  for (const char* name : {"ascii.pgm", "binary.pgm"}) {
    SCOPED_TRACE(name);
    StatusOr<std::unique_ptr<ImageRowReader>> rows =
        OpenImageRows(dir + "/" + name, std::uint64_t{1} << 28);
    ASSERT_TRUE(rows.ok()) << rows.status().message();
    ASSERT_EQ((*rows)->width(), kWidth);
    ASSERT_EQ((*rows)->height(), kHeight);
    ASSERT_EQ((*rows)->channels(), 1);
    std::vector<std::uint16_t> row(kWidth);
    for (int y = 0; y < kHeight; ++y) {
      ASSERT_TRUE((*rows)->ReadRow(row.data()).ok()) << "row " << y;
      for (int x = 0; x < kWidth; ++x) {
        ASSERT_EQ(row[x], Quantum(values[y * kWidth + x], 1000)) << "x " << x << " y " << y;
      }
    }
  }
}

// Adam7 rows come out only after the last pass: such PNGs are read whole
// first, and must give the same cells.
TEST(ImageRowsTest, InterlacedPngLoadsLikeItsPlainTwin) {
  const std::string dir = testing::MakeTempDir("img_rows");
  PngSpec spec{37, 23, PNG_COLOR_TYPE_GRAY, 8, {}, {}, {}};
  std::string want;
  for (int y = 0; y < spec.height; ++y) {
    std::vector<std::uint8_t> row;
    for (int x = 0; x < spec.width; ++x) {
      const std::uint8_t grey = (x * 7 + y * 3) % 3 == 0 ? 0 : ((x + y) % 4 == 0 ? 205 : 254);
      row.push_back(grey);
      want += grey == 0 ? 'O' : grey == 205 ? 'U' : 'F';
    }
    spec.rows.push_back(row);
  }
  WritePng(dir + "/plain.png", spec);
  spec.interlace = PNG_INTERLACE_ADAM7;
  WritePng(dir + "/adam7.png", spec);
  EXPECT_EQ(TopDown(MustLoad(dir + "/plain.png")), want);
  EXPECT_EQ(TopDown(MustLoad(dir + "/adam7.png")), want);
}

// A pipe has no size to check a header against: the image is read as it
// comes, and a short one fails on the row that is missing.
TEST(ImageRowsTest, PgmFromAPipeLoadsAndATruncatedOneFails) {
  const std::string dir = testing::MakeTempDir("img_rows");
  const std::string fifo = dir + "/map.pgm";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string whole =
      std::string("P5 3 2 255\n") + std::string("\x00\xff\xcd\xfe\x00\x80", 6);
  for (const std::size_t size : {whole.size(), whole.size() - 2}) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      FILE* out = std::fopen(fifo.c_str(), "wb");
      if (out != nullptr) {
        std::fwrite(whole.data(), 1, size, out);
        std::fclose(out);
      }
      _exit(0);
    }
    StatusOr<Grid> grid = LoadMapImage(fifo, MapMetadata());
    ::waitpid(pid, nullptr, 0);
    if (size == whole.size()) {
      ASSERT_TRUE(grid.ok()) << grid.status().message();
      EXPECT_EQ(TopDown(*grid), "OFUFOU");
    } else {
      ASSERT_FALSE(grid.ok());
      EXPECT_EQ(grid.status().code(), StatusCode::kCorrupt);
      EXPECT_NE(grid.status().message().find("truncated"), std::string::npos);
      EXPECT_NE(grid.status().message().find("map.pgm"), std::string::npos);
    }
  }
}

// The must-fail files fail through the row reader too (LoadMapImage), with
// their name in the message.
TEST(ImageRowsTest, MustFailFilesFailWhenLoaded) {
  const std::string dir = testing::SourceDir() + "/tests/data/bad/map_image";
  for (const std::string& name : testing::ListDir(dir)) {
    StatusOr<Grid> grid = LoadMapImage(dir + "/" + name, MapMetadata(), std::uint64_t{1} << 28);
    EXPECT_FALSE(grid.ok()) << name << " loaded";
    if (!grid.ok()) {
      EXPECT_NE(grid.status().message().find(name), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace linemap
