// The size anchors of linemap bench run as real programs: JPEG XL (cjxl /
// djxl), WebP lossless (cwebp / dwebp) and xz -9e. Each file is decoded by the
// codec's own decoder, outside the bench's code, and compared cell for cell.
#include "tools/bench/image_anchors.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "tests/testing/test_support.h"
#include "tools/bench/general_codecs.h"
#include "tools/bench/subprocess.h"

namespace linemap::bench {
namespace {

// A small map with all three states in an irregular pattern (a fixed LCG),
// walls along two rows and a column so the image has some structure.
Grid PatternGrid(int width, int height) {
  Grid grid(width, height, Cell::kFree);
  std::uint32_t state = 12345;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      state = state * 1664525u + 1013904223u;
      const std::uint32_t pick = (state >> 24) % 8;
      if (pick == 0) grid.set(c, r, Cell::kOccupied);
      if (pick == 1) grid.set(c, r, Cell::kUnknown);
    }
  }
  for (int c = 0; c < width; ++c) grid.set(c, 0, Cell::kOccupied);
  for (int c = 0; c < width; ++c) grid.set(c, height - 1, Cell::kUnknown);
  for (int r = 0; r < height; ++r) grid.set(width / 2, r, Cell::kOccupied);
  return grid;
}

// map_saver's greys, straight from its documentation: 0 occupied, 254 free,
// 205 unknown.
Cell CellOfGrey(std::uint8_t grey) {
  if (grey == 0) return Cell::kOccupied;
  if (grey == 254) return Cell::kFree;
  EXPECT_EQ(grey, 205) << "a grey map_saver never writes";
  return Cell::kUnknown;
}

// The pixels of a netpbm file as the decoders write it here: "P5" or "P6",
// width, height, 255, one white-space byte, the samples.
struct Netpbm {
  int width = 0, height = 0, channels = 0;
  std::string samples;
};

Netpbm ParseNetpbm(const std::string& bytes) {
  Netpbm image;
  char magic[3] = {};
  int maxval = 0, consumed = 0;
  EXPECT_EQ(std::sscanf(bytes.c_str(), "%2s %d %d %d%n", magic, &image.width, &image.height,
                        &maxval, &consumed),
            4);
  EXPECT_EQ(maxval, 255);
  image.channels = std::string(magic) == "P6" ? 3 : 1;
  image.samples = bytes.substr(static_cast<std::size_t>(consumed) + 1);
  return image;
}

// Checks that `image` is `grid` drawn as map_saver draws it, row 0 = top.
void ExpectImageIsGrid(const Netpbm& image, const Grid& grid) {
  ASSERT_EQ(image.width, grid.width());
  ASSERT_EQ(image.height, grid.height());
  ASSERT_EQ(image.samples.size(), grid.size() * image.channels);
  int wrong = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * image.channels;
      const auto grey = static_cast<std::uint8_t>(image.samples[at]);
      for (int ch = 1; ch < image.channels; ++ch) {
        EXPECT_EQ(static_cast<std::uint8_t>(image.samples[at + ch]), grey);
      }
      if (CellOfGrey(grey) != grid.at(x, grid.height() - 1 - y)) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0);
}

// Encodes with the bench's wrapper, decodes with `decode` (argv with the
// .in / .out paths appended by the caller's lambda) and compares.
void ExpectRoundTrip(const ImageCodec& codec, const Grid& grid,
                     const std::vector<std::string>& decode_args, const std::string& extension) {
  StatusOr<AnchorFile> file = EncodeImageAnchor(grid, codec);
  ASSERT_TRUE(file.ok()) << file.status().message();
  EXPECT_GT(file->bytes.size(), 0u);
  EXPECT_GE(file->encode_cpu_ms, 0.0);
  const std::string dir = linemap::testing::MakeTempDir("bench-anchor");
  const std::string in = dir + "/" + codec.encoded_name;
  const std::string out = dir + "/back" + extension;
  linemap::testing::WriteFile(in, file->bytes);
  std::vector<std::string> argv;
  for (const std::string& arg : decode_args) {
    argv.push_back(arg == "IN" ? in : arg == "OUT" ? out : arg);
  }
  StatusOr<int> code = RunSubprocess(argv);
  ASSERT_TRUE(code.ok()) << code.status().message();
  ASSERT_EQ(*code, 0);
  ExpectImageIsGrid(ParseNetpbm(linemap::testing::ReadFile(out)), grid);
  // The bench's own check agrees.
  StatusOr<double> checked = DecodeAndCheckImageAnchor(grid, codec, file->bytes);
  EXPECT_TRUE(checked.ok()) << checked.status().message();
}

TEST(BenchImageAnchorsTest, MapSaverPgmByHand) {
  Grid grid(3, 2, Cell::kFree);
  grid.set(0, 1, Cell::kOccupied);  // top image row, left
  grid.set(2, 0, Cell::kUnknown);   // bottom image row, right
  const std::string pgm = MapSaverPgm(grid);
  const std::string pixels("\x00\xfe\xfe\xfe\xfe\xcd", 6);
  ASSERT_GT(pgm.size(), pixels.size());
  EXPECT_EQ(pgm.substr(pgm.size() - 6), pixels);
  EXPECT_EQ(pgm.substr(0, 3), "P5\n");
  int width = 0, height = 0;
  StatusOr<std::vector<std::uint8_t>> grey = ReadNetpbmGrey(pgm, "t", &width, &height);
  ASSERT_TRUE(grey.ok()) << grey.status().message();
  EXPECT_EQ(width, 3);
  EXPECT_EQ(height, 2);
  EXPECT_EQ(*grey, std::vector<std::uint8_t>(pixels.begin(), pixels.end()));
}

TEST(BenchImageAnchorsTest, JpegXlIsLossless) {
  if (!ToolAvailable("cjxl") || !ToolAvailable("djxl")) {
    GTEST_SKIP() << "libjxl-tools (cjxl, djxl) is not installed";
  }
  const Grid grid = PatternGrid(61, 37);
  ExpectRoundTrip(JpegXlCodec(), grid, {"djxl", "IN", "OUT"}, ".pgm");
}

TEST(BenchImageAnchorsTest, JpegXlFilesAreReproducible) {
  if (!ToolAvailable("cjxl")) GTEST_SKIP() << "libjxl-tools (cjxl) is not installed";
  const Grid grid = PatternGrid(40, 30);
  StatusOr<AnchorFile> a = EncodeImageAnchor(grid, JpegXlCodec());
  StatusOr<AnchorFile> b = EncodeImageAnchor(grid, JpegXlCodec());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->bytes, b->bytes);
}

TEST(BenchImageAnchorsTest, WebpIsLossless) {
  if (!ToolAvailable("cwebp") || !ToolAvailable("dwebp")) {
    GTEST_SKIP() << "webp (cwebp, dwebp) is not installed";
  }
  const Grid grid = PatternGrid(61, 37);
  ExpectRoundTrip(WebpCodec(), grid, {"dwebp", "IN", "-ppm", "-o", "OUT"}, ".ppm");
}

// The LZMA2 data of a one-block .xz stream with its padding and check: what
// follows the 12-byte stream header and the block header, up to the index.
// The xz program records the block's sizes in its block header and liblzma's
// buffer encoder does not, so whole files differ while this part must not.
std::string XzBlockData(const std::string& xz) {
  if (xz.size() < 32) return "";
  const std::size_t header = (static_cast<std::uint8_t>(xz[12]) + 1u) * 4u;
  std::uint32_t backward = 0;  // footer: CRC32, backward size, flags, magic
  for (int i = 3; i >= 0; --i)
    backward = backward << 8 | static_cast<std::uint8_t>(xz[xz.size() - 8 + i]);
  const std::size_t index = (static_cast<std::size_t>(backward) + 1) * 4;
  if (12 + header + index + 12 > xz.size()) return "";
  return xz.substr(12 + header, xz.size() - 12 - index - 12 - header);
}

TEST(BenchImageAnchorsTest, XzExtremeIsWhatXz9eWrites) {
  if (!ToolAvailable("xz")) GTEST_SKIP() << "xz-utils is not installed";
  const Grid grid = PatternGrid(200, 150);
  const std::span<const std::uint8_t> raw = RawCells(grid);
  const std::string raw_text(raw.begin(), raw.end());
  StatusOr<std::string> ours = XzCompress(raw, 9, /*extreme=*/true);
  ASSERT_TRUE(ours.ok());
  const std::string dir = linemap::testing::MakeTempDir("bench-xz");
  // xz -d turns our stream back into the cells.
  linemap::testing::WriteFile(dir + "/ours.xz", *ours);
  StatusOr<int> code = RunSubprocess({"xz", "-d", "-k", dir + "/ours.xz"});
  ASSERT_TRUE(code.ok() && *code == 0);
  EXPECT_EQ(linemap::testing::ReadFile(dir + "/ours"), raw_text);
  // The xz program at -9e, single-threaded, codes the cells the same way,
  // and at plain -9 differently (so the comparison can tell them apart).
  linemap::testing::WriteFile(dir + "/cells", raw_text);
  code = RunSubprocess({"xz", "-9e", "-T1", "-k", dir + "/cells"});
  ASSERT_TRUE(code.ok() && *code == 0);
  const std::string xz9e = linemap::testing::ReadFile(dir + "/cells.xz");
  ASSERT_FALSE(XzBlockData(*ours).empty());
  EXPECT_EQ(XzBlockData(*ours), XzBlockData(xz9e));
  StatusOr<std::string> plain = XzCompress(raw, 9, /*extreme=*/false);
  ASSERT_TRUE(plain.ok());
  EXPECT_NE(XzBlockData(*plain), XzBlockData(xz9e));
}

TEST(BenchImageAnchorsTest, AMissingProgramIsNamedWithItsPackage) {
  JxlOptions jxl;
  jxl.encoder = "linemap-no-such-cjxl";
  StatusOr<AnchorFile> file = EncodeImageAnchor(PatternGrid(8, 8), JpegXlCodec(jxl));
  ASSERT_FALSE(file.ok());
  EXPECT_EQ(file.status().code(), StatusCode::kNotFound);
  EXPECT_NE(file.status().message().find("linemap-no-such-cjxl not found"), std::string::npos)
      << file.status().message();
  EXPECT_NE(file.status().message().find("libjxl-tools"), std::string::npos);

  WebpOptions webp;
  webp.decoder = "linemap-no-such-dwebp";
  StatusOr<double> decoded = DecodeAndCheckImageAnchor(PatternGrid(8, 8), WebpCodec(webp), "x");
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.status().code(), StatusCode::kNotFound);
  EXPECT_NE(decoded.status().message().find("(Debian package webp)"), std::string::npos);
}

// A "codec" whose decoder is `cp`: the check must pass on the map's own PGM
// and name the first wrong pixel of another map's.
TEST(BenchImageAnchorsTest, TheLosslessCheckCatchesAWrongPixel) {
  const ImageCodec copy = {
      "copy", "coreutils", {"cp", "{in}", "{out}"}, "map.pgm", {"cp", "{in}", "{out}"}, "back.pgm"};
  const Grid grid = PatternGrid(20, 10);
  EXPECT_TRUE(DecodeAndCheckImageAnchor(grid, copy, MapSaverPgm(grid)).ok());
  Grid other = grid;
  other.set(3, 9, other.at(3, 9) == Cell::kFree ? Cell::kUnknown : Cell::kFree);  // image (3, 0)
  StatusOr<double> checked = DecodeAndCheckImageAnchor(grid, copy, MapSaverPgm(other));
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(checked.status().message().find("pixel (3, 0)"), std::string::npos)
      << checked.status().message();
  StatusOr<double> small = DecodeAndCheckImageAnchor(grid, copy, MapSaverPgm(PatternGrid(20, 9)));
  ASSERT_FALSE(small.ok());
  EXPECT_NE(small.status().message().find("20 x 9"), std::string::npos);
}

TEST(BenchImageAnchorsTest, NetpbmGreyReader) {
  int w = 0, h = 0;
  StatusOr<std::vector<std::uint8_t>> ppm =
      ReadNetpbmGrey(std::string("P6\n# c\n2 1\n255\n\x05\x05\x05\xcd\xcd\xcd", 21), "t", &w, &h);
  ASSERT_TRUE(ppm.ok()) << ppm.status().message();
  EXPECT_EQ(w, 2);
  EXPECT_EQ(h, 1);
  EXPECT_EQ(*ppm, (std::vector<std::uint8_t>{5, 205}));
  EXPECT_FALSE(ReadNetpbmGrey(std::string("P6\n1 1\n255\n\x01\x02\x01", 14), "t", &w, &h).ok());
  EXPECT_FALSE(ReadNetpbmGrey("P5\n2 2\n255\n\x01\x02\x03", "t", &w, &h).ok());  // truncated
  EXPECT_FALSE(ReadNetpbmGrey("P5\n1 1\n65535\n\x01\x02", "t", &w, &h).ok());
  EXPECT_FALSE(ReadNetpbmGrey("P2\n1 1\n255\n1\n", "t", &w, &h).ok());
}

TEST(BenchSubprocessTest, TimedRunReportsCpuTime) {
  StatusOr<SubprocessRun> run =
      RunSubprocessTimed({"sh", "-c", "i=0; while [ $i -lt 200000 ]; do i=$((i+1)); done"});
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(run->exit_code, 0);
  EXPECT_GT(run->cpu_ms, 1.0);
}

}  // namespace
}  // namespace linemap::bench
