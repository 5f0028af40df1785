// Adaptive binary range coder (the LZMA "rc" coder, Igor Pavlov, public
// domain; specified bit for bit in spec/format.md section "Binary range
// coder"). All arithmetic is on unsigned integers, so every platform produces
// and reads the same bytes.
#ifndef LINEMAP_FORMAT_RANGE_CODER_H_
#define LINEMAP_FORMAT_RANGE_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace linemap {

// Probability that the next bit is 0, in units of 1/4096; starts at one half.
inline constexpr int kProbBits = 12;
inline constexpr std::uint16_t kProbInit = 1 << (kProbBits - 1);
// Adaptation speed: each coded bit moves the probability by 1/2^5 of the gap.
inline constexpr int kProbShift = 5;

class RangeEncoder {
 public:
  void Encode(std::uint16_t* prob, int bit);
  // Writes the final bytes; call once, then take bytes().
  void Finish();
  const std::vector<std::uint8_t>& bytes() const { return out_; }

 private:
  void ShiftLow();
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cache_size_ = 1;
  std::vector<std::uint8_t> out_;
};

// Never reads outside [data, data + size): past the end it reads zero bytes
// and counts them; overrun() > 0 after decoding means the input was short.
class RangeDecoder {
 public:
  RangeDecoder(const std::uint8_t* data, std::size_t size);
  int Decode(std::uint16_t* prob);
  // False when the first byte is not 0 (a corrupt stream).
  bool valid_start() const { return valid_start_; }
  std::size_t overrun() const { return overrun_; }
  std::size_t consumed() const { return pos_; }

 private:
  std::uint8_t NextByte();
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::size_t overrun_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t code_ = 0;
  bool valid_start_ = true;
};

}  // namespace linemap

#endif  // LINEMAP_FORMAT_RANGE_CODER_H_
