#include "format/range_coder.h"

namespace linemap {
namespace {
constexpr std::uint32_t kTopValue = 1u << 24;
}  // namespace

void RangeEncoder::ShiftLow() {
  if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
    const std::uint8_t carry = static_cast<std::uint8_t>(low_ >> 32);
    std::uint8_t temp = cache_;
    do {
      out_.push_back(static_cast<std::uint8_t>(temp + carry));
      temp = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = static_cast<std::uint8_t>(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::Encode(std::uint16_t* prob, int bit) {
  const std::uint32_t bound = (range_ >> kProbBits) * *prob;
  if (bit == 0) {
    range_ = bound;
    *prob = static_cast<std::uint16_t>(*prob + (((1u << kProbBits) - *prob) >> kProbShift));
  } else {
    low_ += bound;
    range_ -= bound;
    *prob = static_cast<std::uint16_t>(*prob - (*prob >> kProbShift));
  }
  while (range_ < kTopValue) {
    range_ <<= 8;
    ShiftLow();
  }
}

void RangeEncoder::Finish() {
  for (int i = 0; i < 5; ++i) ShiftLow();
}

RangeDecoder::RangeDecoder(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {
  valid_start_ = NextByte() == 0;
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | NextByte();
  if (code_ == range_) valid_start_ = false;
}

std::uint8_t RangeDecoder::NextByte() {
  if (pos_ < size_) return data_[pos_++];
  ++overrun_;
  return 0;
}

int RangeDecoder::Decode(std::uint16_t* prob) {
  const std::uint32_t bound = (range_ >> kProbBits) * *prob;
  int bit;
  if (code_ < bound) {
    range_ = bound;
    *prob = static_cast<std::uint16_t>(*prob + (((1u << kProbBits) - *prob) >> kProbShift));
    bit = 0;
  } else {
    range_ -= bound;
    code_ -= bound;
    *prob = static_cast<std::uint16_t>(*prob - (*prob >> kProbShift));
    bit = 1;
  }
  while (range_ < kTopValue) {
    range_ <<= 8;
    code_ = (code_ << 8) | NextByte();
  }
  return bit;
}

}  // namespace linemap
