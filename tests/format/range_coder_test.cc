#include "format/range_coder.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace linemap {
namespace {

// Encodes `bits` with `contexts` models chosen by index % contexts.
std::vector<std::uint8_t> EncodeBits(const std::vector<int>& bits, int contexts) {
  BitModelTable models(contexts);
  RangeEncoder enc;
  for (std::size_t i = 0; i < bits.size(); ++i) enc.Encode(&models[i % contexts], bits[i]);
  enc.Finish();
  return enc.bytes();
}

std::vector<int> DecodeBits(std::size_t n, int contexts, RangeDecoder* dec) {
  BitModelTable models(contexts);
  std::vector<int> bits;
  for (std::size_t i = 0; i < n; ++i) bits.push_back(dec->Decode(&models[i % contexts]));
  return bits;
}

TEST(RangeCoderTest, RoundTripsRandomStreams) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = rng() % 5000;
    const double p_one = (rng() % 1000) / 1000.0;
    std::vector<int> bits(n);
    for (int& b : bits) b = (rng() % 1000) < p_one * 1000 ? 1 : 0;
    const int contexts = 1 + static_cast<int>(rng() % 8);
    const std::vector<std::uint8_t> bytes = EncodeBits(bits, contexts);
    RangeDecoder dec(bytes.data(), bytes.size());
    EXPECT_EQ(DecodeBits(n, contexts, &dec), bits) << "trial " << trial;
    EXPECT_TRUE(dec.valid_start());
    EXPECT_EQ(dec.consumed(), bytes.size()) << "trial " << trial;
    if (!bytes.empty()) {
      EXPECT_NE(bytes.back(), 0) << "the zero tail is dropped";
    }
  }
}

TEST(RangeCoderTest, PredictableBitsCostLittle) {
  // 100000 zeros: the steady-state cost is about 0.0007 bits each, so the
  // stream must stay far below one byte per thousand bits.
  const std::vector<int> bits(100000, 0);
  EXPECT_LT(EncodeBits(bits, 1).size(), 40u);
}

TEST(RangeCoderTest, ModelAdaptsWithTheDocumentedSchedule) {
  BitModel m{};
  EXPECT_EQ(m.p(), 32768);
  m.Update(0);  // shift 1: p += (65536 - 32768) >> 1
  EXPECT_EQ(m.p(), 49152);
  m.Update(1);  // shift 2: p -= 49152 >> 2
  EXPECT_EQ(m.p(), 36864);
  m.Update(0);  // shift 3: p += (65536 - 36864) >> 3 = 3584
  EXPECT_EQ(m.p(), 40448);
}

TEST(RangeCoderTest, NeverReadsPastTheEnd) {
  // A decoder over a short buffer keeps returning bits from zero padding.
  const std::vector<std::uint8_t> bytes = {0x12};
  RangeDecoder dec(bytes.data(), bytes.size());
  BitModel m{};
  for (int i = 0; i < 1000; ++i) dec.Decode(&m);
  EXPECT_EQ(dec.consumed(), 1u);
  EXPECT_GT(dec.overrun(), 0u);
}

}  // namespace
}  // namespace linemap
