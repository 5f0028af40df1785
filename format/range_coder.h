// Adaptive binary range coder (after the LZMA "rc" coder, Igor Pavlov, public
// domain; specified bit for bit in spec/format.md section "Binary range
// coder"). All arithmetic is on unsigned integers, so every platform produces
// and reads the same bytes.
#ifndef LINEMAP_FORMAT_RANGE_CODER_H_
#define LINEMAP_FORMAT_RANGE_CODER_H_

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace linemap {

// An adaptive bit model: p() is the probability that the next bit is 0, in
// units of 2^-16, starting at one half. Each coded bit moves p towards the
// bit by 1/2^shift of the gap, with shift = kAdaptShift[n] for the model's
// n-th update (fast at first, then steady at 1/32), so contexts learn quickly
// and a certain bit costs only ~0.0007 bits.
inline constexpr int kProbBits = 16;
inline constexpr int kAdaptSteps = 5;
inline constexpr std::uint8_t kAdaptShift[kAdaptSteps + 1] = {1, 2, 3, 4, 4, 5};
// The coders renormalise (shift a byte) when the range drops below this.
inline constexpr std::uint32_t kRangeTop = 1u << 24;

// All-zero bytes are the initial state (p = one half is stored as 0), so a
// value-initialised model (`BitModel{}`) or table (BitModelTable) is a
// memset.
struct BitModel {
  static constexpr std::uint16_t kHalf = 1u << (kProbBits - 1);
  std::uint16_t p_xor_half;  // p() ^ kHalf
  // Updates so far, saturating at kAdaptSteps. Not a byte: a store to a
  // byte may alias any object, which would make the coders reload their
  // state from memory after every model update (same size: the struct is
  // padded to 4 bytes anyway).
  std::uint16_t n;
  std::uint32_t p() const { return p_xor_half ^ kHalf; }
  void Update(int bit) {
    const std::uint32_t old = p();
    const int shift = kAdaptShift[n];
    const std::uint32_t next =
        bit == 0 ? old + (((1u << kProbBits) - old) >> shift) : old - (old >> shift);
    p_xor_half = static_cast<std::uint16_t>(next ^ kHalf);
    // Added rather than branched on: fresh and settled models take turns
    // (an integer's unary prefix, a path's turns), and a branch on which
    // was mispredicted often.
    n = static_cast<std::uint16_t>(n + (n < kAdaptSteps ? 1 : 0));
  }
};
static_assert(std::is_trivially_default_constructible_v<BitModel>);
static_assert(sizeof(BitModel) == 4);

// `size` models in their initial state. The plane coders make tens of
// thousands per plane; set one by one (as a std::vector fills them) or even
// memset they cost more than coding a small map, so the table comes from
// calloc, which hands out fresh pages without touching them.
class BitModelTable {
 public:
  explicit BitModelTable(std::size_t size)
      : models_(static_cast<BitModel*>(std::calloc(size, sizeof(BitModel)))) {
    if (models_ == nullptr && size > 0) throw std::bad_alloc();
  }
  BitModel& operator[](std::size_t i) { return models_.get()[i]; }

 private:
  struct Free {
    void operator()(BitModel* p) const { std::free(p); }
  };
  std::unique_ptr<BitModel, Free> models_;
};

class RangeEncoder {
 public:
  // Inline: the plane encoders call it once per cell.
  void Encode(BitModel* model, int bit) {
    EncodeWithProbability(model->p(), bit);
    model->Update(bit);
  }
  // Codes `bit` with a probability of 0 of p0 / 2^16 (1 <= p0 <= 65535)
  // given by the caller: for models of other kinds (the tile coder's
  // two-rate models, its mixer), which update themselves.
  void EncodeWithProbability(std::uint32_t p0, int bit) {
    const std::uint32_t bound = (range_ >> kProbBits) * p0;
    if (bit == 0) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    while (range_ < kRangeTop) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  // Writes the final bytes, dropping every zero byte of the tail (the
  // decoder implies them); call once, then take bytes().
  void Finish() { Finish(SIZE_MAX); }
  // The same, dropping at most `max_dropped` zero bytes; returns how many
  // it dropped (a format that stores the count can check its end exactly).
  std::size_t Finish(std::size_t max_dropped);
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
// (the encoder drops the zero tail). A valid stream does not end in a zero
// byte and has every byte read by the end of decoding.
class RangeDecoder {
 public:
  RangeDecoder(const std::uint8_t* data, std::size_t size);
  // Inline: the plane decoders call it once per cell.
  int Decode(BitModel* model) {
    const int bit = DecodeWithProbability(model->p());
    model->Update(bit);
    return bit;
  }
  // Decodes a bit coded with EncodeWithProbability(p0, bit).
  int DecodeWithProbability(std::uint32_t p0) {
    const std::uint32_t bound = (range_ >> kProbBits) * p0;
    int bit;
    if (code_ < bound) {
      range_ = bound;
      bit = 0;
    } else {
      range_ -= bound;
      code_ -= bound;
      bit = 1;
    }
    while (range_ < kRangeTop) {
      range_ <<= 8;
      code_ = (code_ << 8) | NextByte();
    }
    return bit;
  }
  // False when the stream ends in a zero byte (not canonical: corrupt).
  bool valid_start() const { return valid_start_; }
  std::size_t overrun() const { return overrun_; }
  std::size_t consumed() const { return pos_; }

 private:
  std::uint8_t NextByte() {
    if (pos_ < size_) return data_[pos_++];
    ++overrun_;
    return 0;
  }
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
