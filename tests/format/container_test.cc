#include "format/container.h"

#include <gtest/gtest.h>

#include <vector>

#include "format/deflate.h"

namespace linemap {
namespace {

constexpr std::uint64_t kNoLimit = std::uint64_t{1} << 40;

TEST(ContainerTest, EmptyFileHasTheSpecifiedBytes) {
  ContainerWriter writer;
  const std::vector<std::uint8_t> bytes = writer.Finish();
  // Signature, version 2.0, then LEND: type, length 0, CRC-32("LEND").
  const std::vector<std::uint8_t> expected = {0x8A, 'L', 'M', 'A', 'P', 0x0D, 0x0A, 0x1A, 2,   0,
                                              'L',  'E', 'N', 'D', 0,   0xB0, 0x90, 0x9C, 0x99};
  EXPECT_EQ(bytes, expected);
  auto view = ParseContainer(bytes, kNoLimit);
  ASSERT_TRUE(view.ok()) << view.status().ToString();
  EXPECT_TRUE(view->chunks.empty());
}

TEST(ContainerTest, ChunksRoundTrip) {
  ContainerWriter writer;
  writer.AddChunk("LMHD", {1, 2, 3});
  writer.AddChunk("meta", std::vector<std::uint8_t>(300, 7));
  const std::vector<std::uint8_t> bytes = writer.Finish();
  auto view = ParseContainer(bytes, kNoLimit);
  ASSERT_TRUE(view.ok()) << view.status().ToString();
  ASSERT_EQ(view->chunks.size(), 2u);
  EXPECT_EQ(view->chunks[0].type, "LMHD");
  EXPECT_TRUE(view->chunks[0].critical());
  EXPECT_EQ(std::vector<std::uint8_t>(view->chunks[0].payload, view->chunks[0].payload + 3),
            (std::vector<std::uint8_t>{1, 2, 3}));
  EXPECT_EQ(view->chunks[1].type, "meta");
  EXPECT_FALSE(view->chunks[1].critical());
  EXPECT_EQ(view->chunks[1].size, 300u);
}

std::vector<std::uint8_t> SmallFile() {
  ContainerWriter writer;
  writer.AddChunk("LMHD", {1, 2, 3, 4, 5});
  writer.AddChunk("OCCP", {9, 8, 7});
  return writer.Finish();
}

TEST(ContainerTest, EveryTruncationIsAnError) {
  const std::vector<std::uint8_t> bytes = SmallFile();
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + n);
    EXPECT_FALSE(ParseContainer(cut, kNoLimit).ok()) << "prefix of " << n << " bytes";
  }
}

TEST(ContainerTest, EverySingleBitFlipIsDetected) {
  const std::vector<std::uint8_t> bytes = SmallFile();
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<std::uint8_t> bad = bytes;
      bad[i] ^= static_cast<std::uint8_t>(1 << bit);
      auto view = ParseContainer(bad, kNoLimit);
      // A flip in the minor version is the only harmless one.
      if (i == 9) continue;
      EXPECT_FALSE(view.ok()) << "byte " << i << " bit " << bit;
    }
  }
}

TEST(ContainerTest, BadCrcNamesTheChunk) {
  std::vector<std::uint8_t> bytes = SmallFile();
  bytes[10 + 4 + 1 + 2] ^= 0x01;  // inside LMHD's payload
  auto view = ParseContainer(bytes, kNoLimit);
  ASSERT_FALSE(view.ok());
  EXPECT_EQ(view.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(view.status().message().find("LMHD"), std::string::npos);
  EXPECT_NE(view.status().message().find("CRC"), std::string::npos);
}

TEST(ContainerTest, RejectsWrongSignatureMajorVersionAndTrailingData) {
  std::vector<std::uint8_t> bytes = SmallFile();
  std::vector<std::uint8_t> png = bytes;
  png[1] = 'P';
  EXPECT_EQ(ParseContainer(png, kNoLimit).status().code(), StatusCode::kCorrupt);
  std::vector<std::uint8_t> v3 = bytes;
  v3[8] = 3;
  EXPECT_EQ(ParseContainer(v3, kNoLimit).status().code(), StatusCode::kUnsupported);
  std::vector<std::uint8_t> v0 = bytes;
  v0[8] = 0;
  EXPECT_EQ(ParseContainer(v0, kNoLimit).status().code(), StatusCode::kUnsupported);
  std::vector<std::uint8_t> v1 = bytes;
  v1[8] = 1;
  EXPECT_TRUE(ParseContainer(v1, kNoLimit).ok());
  std::vector<std::uint8_t> trailing = bytes;
  trailing.push_back(0);
  EXPECT_FALSE(ParseContainer(trailing, kNoLimit).ok());
}

TEST(ContainerTest, ChunkLengthOverTheLimitIsRefused) {
  ContainerWriter writer;
  writer.AddChunk("OCCP", std::vector<std::uint8_t>(1000, 1));
  auto view = ParseContainer(writer.Finish(), 999);
  ASSERT_FALSE(view.ok());
  EXPECT_EQ(view.status().code(), StatusCode::kResourceExhausted);
}

// A chunk whose payload fits the file but whose CRC does not is past the
// end of the file: corrupt (truncated) whatever the chunk limit, as a
// payload past the end is, and not "over the limit" with a small one.
TEST(ContainerTest, ChunkWhoseCrcIsCutOffIsTruncatedWhateverTheLimit) {
  ContainerWriter writer;
  writer.AddChunk("meta", std::vector<std::uint8_t>(40, 7));
  std::vector<std::uint8_t> bytes = writer.Finish();
  // Signature (8), version (2), "meta" (4), length (1), 40 bytes: the file
  // ends there, without the chunk's CRC and the LEND chunk.
  bytes.resize(8 + 2 + 4 + 1 + 40);
  for (std::uint64_t limit : {kNoLimit, std::uint64_t{20}}) {
    auto view = ParseContainer(bytes, limit);
    ASSERT_FALSE(view.ok());
    EXPECT_EQ(view.status().code(), StatusCode::kCorrupt) << limit;
    EXPECT_EQ(view.status().message(), "chunk meta is truncated") << limit;
  }
}

TEST(DeflateTest, Crc32CheckValue) {
  const std::string text = "123456789";
  EXPECT_EQ(Crc32(0, reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0xCBF43926u);
}

TEST(DeflateTest, InflateChecksTheAnnouncedSize) {
  const std::vector<std::uint8_t> data(5000, 42);
  const std::vector<std::uint8_t> z = DeflateBytes(data.data(), data.size());
  auto ok = InflateBytes(z.data(), z.size(), data.size());
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, data);
  EXPECT_FALSE(InflateBytes(z.data(), z.size(), data.size() - 1).ok());
  EXPECT_FALSE(InflateBytes(z.data(), z.size(), data.size() + 1).ok());
  EXPECT_FALSE(InflateBytes(z.data(), z.size() - 1, data.size()).ok());
}

}  // namespace
}  // namespace linemap
