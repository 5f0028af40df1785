// Adaptive integer and symbol models over the binary range coder, for the
// vector layers of 2.0 files (spec/format.md section "Coded integers").
//
// An unsigned v is coded as an adaptive Exp-Golomb code of v + 1: n = the
// bit length of (v + 1) minus 1, sent in unary (n ones then a zero, bit i of
// the unary part with its own model), then the n bits of (v + 1) below its
// top bit, most significant first: the first with a model per n, the others
// with one shared model per n. Short values cost a fraction of a bit once
// the models have adapted (an axis-aligned wall's turn, a chain's straight
// step), long ones about 2 log2(v) bits at worst.
#ifndef LINEMAP_CODEC_LAYERS_INT_CODING_H_
#define LINEMAP_CODEC_LAYERS_INT_CODING_H_

#include <cstdint>

#include "format/range_coder.h"

namespace linemap {

// Largest n (bit length of v + 1, minus 1) a stream may use: values up to
// 2^41 - 2; a longer unary prefix is corrupt.
inline constexpr int kMaxIntBits = 40;

struct UIntModel {
  BitModel prefix[kMaxIntBits + 1];
  BitModel first[kMaxIntBits + 1];
  BitModel rest[kMaxIntBits + 1];
};

inline void EncodeUInt(RangeEncoder* enc, UIntModel* m, std::uint64_t v) {
  const std::uint64_t x = v + 1;
  int n = 0;
  while ((x >> (n + 1)) != 0) ++n;
  for (int i = 0; i < n; ++i) enc->Encode(&m->prefix[i], 1);
  enc->Encode(&m->prefix[n], 0);
  for (int j = n - 1; j >= 0; --j) {
    enc->Encode(j == n - 1 ? &m->first[n] : &m->rest[n], static_cast<int>((x >> j) & 1));
  }
}

// False when the unary prefix exceeds kMaxIntBits (corrupt).
inline bool DecodeUInt(RangeDecoder* dec, UIntModel* m, std::uint64_t* v) {
  int n = 0;
  while (dec->Decode(&m->prefix[n]) == 1) {
    if (++n > kMaxIntBits) return false;
  }
  std::uint64_t x = 1;
  if (n == 0) {
    *v = 0;
    return true;
  }
  x = (x << 1) | static_cast<std::uint64_t>(dec->Decode(&m->first[n]));
  // The bits after the first share one model: it is held in a local for
  // them and stored once, rather than each update being stored and loaded
  // back by the next bit.
  BitModel rest = m->rest[n];
  for (int j = n - 2; j >= 0; --j) {
    const int bit = dec->DecodeWithProbability(rest.p());
    rest.Update(bit);
    x = (x << 1) | static_cast<std::uint64_t>(bit);
  }
  m->rest[n] = rest;
  *v = x - 1;
  return true;
}

// Signed values by zigzag: 0, -1, 1, -2, ... as 0, 1, 2, 3, ...
inline void EncodeSInt(RangeEncoder* enc, UIntModel* m, std::int64_t v) {
  const std::uint64_t z =
      v < 0 ? (static_cast<std::uint64_t>(-(v + 1)) << 1) | 1 : static_cast<std::uint64_t>(v) << 1;
  EncodeUInt(enc, m, z);
}

inline bool DecodeSInt(RangeDecoder* dec, UIntModel* m, std::int64_t* v) {
  std::uint64_t z = 0;
  if (!DecodeUInt(dec, m, &z)) return false;
  *v = (z & 1) ? -static_cast<std::int64_t>(z >> 1) - 1 : static_cast<std::int64_t>(z >> 1);
  return true;
}

// A symbol of `Bits` bits as a binary tree: the k-th bit (most significant
// first) with the model of the bits before it (2^Bits - 1 models).
template <int Bits>
struct SymbolModel {
  BitModel node[1 << Bits];
};

template <int Bits>
inline void EncodeSymbol(RangeEncoder* enc, SymbolModel<Bits>* m, unsigned symbol) {
  unsigned node = 1;
  for (int k = Bits - 1; k >= 0; --k) {
    const int bit = static_cast<int>((symbol >> k) & 1);
    enc->Encode(&m->node[node], bit);
    node = (node << 1) | static_cast<unsigned>(bit);
  }
}

template <int Bits>
inline unsigned DecodeSymbol(RangeDecoder* dec, SymbolModel<Bits>* m) {
  unsigned node = 1;
  for (int k = 0; k < Bits; ++k)
    node = (node << 1) | static_cast<unsigned>(dec->Decode(&m->node[node]));
  return node - (1u << Bits);
}

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_INT_CODING_H_
