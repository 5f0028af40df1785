#include "format/range_coder.h"

namespace linemap {

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

std::size_t RangeEncoder::Finish(std::size_t max_dropped) {
  // Any value in [low, low + range) identifies the stream; take the one
  // with the most trailing zero bits, so the flushed tail is zero bytes,
  // which are dropped (the decoder reads missing bytes as zero).
  const std::uint64_t hi = low_ + range_ - 1;
  for (int bits = 32; bits >= 0; --bits) {
    const std::uint64_t v = hi & ~((std::uint64_t{1} << bits) - 1);
    if (v >= low_) {
      low_ = v;
      break;
    }
  }
  for (int i = 0; i < 5; ++i) ShiftLow();
  // The first byte is always 0 (the code value is below 1): not stored.
  out_.erase(out_.begin());
  const std::size_t full = out_.size();
  while (!out_.empty() && out_.back() == 0 && full - out_.size() < max_dropped) out_.pop_back();
  return full - out_.size();
}

RangeDecoder::RangeDecoder(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {
  valid_start_ = size == 0 || data[size - 1] != 0;  // canonical: no trailing zero byte
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | NextByte();
}

}  // namespace linemap
