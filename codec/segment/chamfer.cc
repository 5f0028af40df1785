// Chamfer 3-4 distance transform (chamfer.h).
#include "codec/segment/chamfer.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace linemap::segment_internal {
namespace {

void ScanRowScalar(const std::uint16_t* t, std::uint16_t* row, int begin, int end, int run,
                   bool forward) {
  // The running value needs no test for walls: a wall's 0 is below
  // anything the step could bring.
  if (forward) {
    for (int c = begin; c < end; ++c) {
      run = std::min<int>(t[c], run + kChamferSide);
      row[c] = static_cast<std::uint16_t>(run);
    }
  } else {
    for (int c = end - 1; c >= begin; --c) {
      run = std::min<int>(t[c], run + kChamferSide);
      row[c] = static_cast<std::uint16_t>(run);
    }
  }
}

#if defined(__SSE2__)
// Unsigned 16-bit minimum from SSE2 alone (pminuw is SSE4.1): a - (a -sat b).
__m128i MinU16(__m128i a, __m128i b) { return _mm_sub_epi16(a, _mm_subs_epu16(a, b)); }

// Lane j of the result: min(x[j], x[j - lanes] + 3 lanes) in the direction
// of the scan (x[j + lanes] backwards); the lanes shifted in are 0xffff,
// above every value, so they never win.
template <bool kForward, int kLanes>
__m128i MinWithShifted(__m128i x) {
  const __m128i all = _mm_set1_epi16(-1);
  __m128i shifted;
  if constexpr (kForward) {
    shifted = _mm_or_si128(_mm_slli_si128(x, 2 * kLanes), _mm_srli_si128(all, 16 - 2 * kLanes));
  } else {
    shifted = _mm_or_si128(_mm_srli_si128(x, 2 * kLanes), _mm_slli_si128(all, 16 - 2 * kLanes));
  }
  return MinU16(x, _mm_adds_epu16(shifted, _mm_set1_epi16(kChamferSide * kLanes)));
}

// The serial chain run = min(t[c], run + 3) costs an add and a min per cell
// one after the other (about 3 cycles a cell, 2-3 % of an encode). Written
// as a prefix minimum, row[c] = min over k of t[k] + 3 |c - k|, it is taken
// 8 cells at a time: within a block by three shifted minimums (lanes 1, 2
// and 4 apart, so that each lane has seen the 7 before it), then against
// the block before it through one carried value, entering at lane 0
// forwards and at lane 7 backwards. Additions saturate at 0xffff, above any
// value of `t`, so a saturated term never wins and the result equals the
// serial chain's. Returns where the scalar scan takes over: forwards the
// first cell after the blocks, backwards the first cell of the last block
// (the scalar scan covers the cells before it).
template <bool kForward>
int ScanBlocks(const std::uint16_t* t, std::uint16_t* row, int end, int* run) {
  const __m128i ramp = kForward ? _mm_setr_epi16(3, 6, 9, 12, 15, 18, 21, 24)
                                : _mm_setr_epi16(24, 21, 18, 15, 12, 9, 6, 3);
  const __m128i zero = _mm_setzero_si128();
  __m128i carry = _mm_set1_epi16(static_cast<short>(*run));
  int c = kForward ? 1 : end - 8;  // the block's first cell
  for (; kForward ? c + 8 <= end : c >= 1; c += kForward ? 8 : -8) {
    __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t + c));
    // Eight walls (most blocks of unknown space and of thick walls): 0
    // whatever the carry, and 0 carried on.
    if (_mm_movemask_epi8(_mm_cmpeq_epi16(x, zero)) == 0xffff) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(row + c), zero);
      carry = zero;
      continue;
    }
    x = MinWithShifted<kForward, 4>(MinWithShifted<kForward, 2>(MinWithShifted<kForward, 1>(x)));
    x = MinU16(x, _mm_adds_epu16(carry, ramp));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(row + c), x);
    // Broadcast the block's last cell in the scan: lane 7 forwards, 0 back.
    if constexpr (kForward) {
      const __m128i high = _mm_shufflehi_epi16(x, 0xff);
      carry = _mm_unpackhi_epi64(high, high);
    } else {
      const __m128i low = _mm_shufflelo_epi16(x, 0);
      carry = _mm_unpacklo_epi64(low, low);
    }
  }
  *run = static_cast<std::uint16_t>(_mm_extract_epi16(carry, 0));
  return kForward ? c : c + 8;
}
#endif

// One row of a pass: `row` relaxed from the row before it in the pass
// (`prev`) and from its own cell before it in the pass. The terms from
// `prev` do not depend on the row being written, so they are taken first,
// eight cells at a time; then the chain along the row. The minimum is the
// same whichever order its terms come in.
void ChamferRow(std::uint16_t* row, const std::uint16_t* prev, int pw, bool forward,
                std::vector<std::uint16_t>* scratch) {
  std::uint16_t* t = scratch->data();
  int c = 1;
#if defined(__SSE2__)
  // Eight cells at a time in 16 bits: GCC widens the loop below to 32-bit
  // lanes and emulates their minimum, four cells per step. The additions
  // saturate at 0xffff; a saturated term is above the 0xfffe the result is
  // capped at, so the result is the same.
  const __m128i side = _mm_set1_epi16(kChamferSide);
  const __m128i diagonal = _mm_set1_epi16(kChamferDiagonal);
  const __m128i cap = _mm_set1_epi16(static_cast<short>(0xfffe));
  const __m128i zero = _mm_setzero_si128();
  for (; c + 8 <= pw - 1; c += 8) {
    const auto load = [](const std::uint16_t* p) {
      return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    };
    const __m128i here = load(row + c);
    const __m128i wall = _mm_cmpeq_epi16(here, zero);
    // Eight walls stay 0 (most blocks of unknown space and thick walls).
    if (_mm_movemask_epi8(wall) == 0xffff) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(t + c), zero);
      continue;
    }
    __m128i best = MinU16(_mm_adds_epu16(load(prev + c), side),
                          _mm_adds_epu16(MinU16(load(prev + c - 1), load(prev + c + 1)), diagonal));
    best = MinU16(MinU16(best, here), cap);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(t + c), _mm_andnot_si128(wall, best));
  }
#endif
  for (; c < pw - 1; ++c) {
    int best =
        std::min(prev[c] + kChamferSide, std::min(prev[c - 1], prev[c + 1]) + kChamferDiagonal);
    best = std::min<int>(best, row[c]);
    t[c] = row[c] ? static_cast<std::uint16_t>(std::min(best, 0xfffe)) : 0;
  }
  ChamferScanRow(t, row, pw, forward);
}

}  // namespace

void ChamferScanRow(const std::uint16_t* t, std::uint16_t* row, int pw, bool forward) {
  int run = 0;  // the frame cell before the row
#if defined(__SSE2__)
  if (forward) {
    const int c = ScanBlocks<true>(t, row, pw - 1, &run);
    ScanRowScalar(t, row, c, pw - 1, run, true);
  } else {
    const int c = ScanBlocks<false>(t, row, pw - 1, &run);
    ScanRowScalar(t, row, 1, c, run, false);
  }
#else
  ScanRowScalar(t, row, 1, pw - 1, run, forward);
#endif
}

void ChamferScanRowSerial(const std::uint16_t* t, std::uint16_t* row, int pw, bool forward) {
  ScanRowScalar(t, row, 1, pw - 1, 0, forward);
}

void ChamferInPlace(std::vector<std::uint16_t>* dist, int pw, int ph) {
  std::uint16_t* d = dist->data();
  // The frame columns stay 0 in the scratch row, as in the grid.
  std::vector<std::uint16_t> scratch(static_cast<std::size_t>(pw), 0);
  for (int r = 1; r < ph - 1; ++r) {
    std::uint16_t* row = d + static_cast<std::size_t>(r) * pw;
    ChamferRow(row, row - pw, pw, true, &scratch);
  }
  for (int r = ph - 2; r >= 1; --r) {
    std::uint16_t* row = d + static_cast<std::size_t>(r) * pw;
    ChamferRow(row, row + pw, pw, false, &scratch);
  }
}

}  // namespace linemap::segment_internal
