#include "format/byte_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace linemap {
namespace {

std::vector<std::uint8_t> VarintBytes(std::uint64_t v) {
  ByteWriter w;
  w.PutVarint(v);
  return w.bytes();
}

TEST(ByteWriterTest, VarintKnownAnswers) {
  EXPECT_EQ(VarintBytes(0), (std::vector<std::uint8_t>{0x00}));
  EXPECT_EQ(VarintBytes(127), (std::vector<std::uint8_t>{0x7F}));
  EXPECT_EQ(VarintBytes(128), (std::vector<std::uint8_t>{0x80, 0x01}));
  EXPECT_EQ(VarintBytes(300), (std::vector<std::uint8_t>{0xAC, 0x02}));
  EXPECT_EQ(
      VarintBytes(std::numeric_limits<std::uint64_t>::max()),
      (std::vector<std::uint8_t>{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01}));
}

TEST(ByteWriterTest, SignedVarintUsesZigzag) {
  ByteWriter w;
  w.PutSignedVarint(0);
  w.PutSignedVarint(-1);
  w.PutSignedVarint(1);
  w.PutSignedVarint(-2);
  w.PutSignedVarint(-64);
  EXPECT_EQ(w.bytes(), (std::vector<std::uint8_t>{0, 1, 2, 3, 127}));
}

TEST(ByteWriterTest, FixedWidthIsLittleEndian) {
  ByteWriter w;
  w.PutU16(0x0102);
  w.PutU32(0x03040506);
  w.PutU64(0x0708090A0B0C0D0Eull);
  EXPECT_EQ(w.bytes(), (std::vector<std::uint8_t>{0x02, 0x01, 0x06, 0x05, 0x04, 0x03, 0x0E, 0x0D,
                                                  0x0C, 0x0B, 0x0A, 0x09, 0x08, 0x07}));
}

TEST(ByteCursorTest, ReadsBackWhatWasWritten) {
  ByteWriter w;
  const std::int64_t signed_values[] = {0,
                                        1,
                                        -1,
                                        1000000,
                                        -1000000,
                                        std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::max()};
  for (std::int64_t v : signed_values) w.PutSignedVarint(v);
  w.PutU32(0xDEADBEEF);
  ByteCursor c(w.bytes());
  for (std::int64_t v : signed_values) {
    auto got = c.ReadSignedVarint("value");
    ASSERT_TRUE(got.ok());
    EXPECT_EQ(*got, v);
  }
  auto u = c.ReadU32("u32");
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(*u, 0xDEADBEEFu);
  EXPECT_TRUE(c.empty());
}

TEST(ByteCursorTest, TruncatedReadsFailAndKeepPosition) {
  const std::vector<std::uint8_t> bytes = {0x80, 0x80};  // varint without its end
  ByteCursor c(bytes);
  auto v = c.ReadVarint("count");
  ASSERT_FALSE(v.ok());
  EXPECT_EQ(v.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(v.status().message().find("count"), std::string::npos);
  EXPECT_EQ(c.position(), 0u);
  EXPECT_FALSE(c.ReadU32("u32").ok());
  EXPECT_FALSE(c.ReadBytes(3, "bytes").ok());
  EXPECT_TRUE(c.ReadBytes(2, "bytes").ok());
  EXPECT_FALSE(c.ReadU8("u8").ok());
}

TEST(ByteCursorTest, RejectsOverlongAndOversizedVarints) {
  // 0 written in two bytes: not the one encoding of 0.
  const std::vector<std::uint8_t> overlong = {0x80, 0x00};
  EXPECT_FALSE(ByteCursor(overlong).ReadVarint("v").ok());
  // 2^64: ten bytes whose last group is 2.
  const std::vector<std::uint8_t> too_big = {0x80, 0x80, 0x80, 0x80, 0x80,
                                             0x80, 0x80, 0x80, 0x80, 0x02};
  EXPECT_FALSE(ByteCursor(too_big).ReadVarint("v").ok());
  // Eleven bytes.
  const std::vector<std::uint8_t> too_long(11, 0x81);
  EXPECT_FALSE(ByteCursor(too_long).ReadVarint("v").ok());
}

TEST(ByteCursorTest, ReadVarintAtMostChecksTheBound) {
  const std::vector<std::uint8_t> bytes = {0xAC, 0x02};  // 300
  ByteCursor c(bytes);
  EXPECT_FALSE(c.ReadVarintAtMost(299, "n").ok());
  EXPECT_EQ(c.position(), 0u);
  auto ok = c.ReadVarintAtMost(300, "n");
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, 300u);
}

TEST(CheckedMulTest, DetectsOverflow) {
  std::uint64_t out = 0;
  EXPECT_TRUE(CheckedMul(100000, 100000, &out));
  EXPECT_EQ(out, 10000000000ull);
  EXPECT_FALSE(CheckedMul(std::uint64_t{1} << 32, std::uint64_t{1} << 32, &out));
}

}  // namespace
}  // namespace linemap
