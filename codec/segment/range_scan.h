// ForEachInRange(): the cells of a clearance map whose value lies in a
// range, and ForEachRunAbove(): its runs of cells above a value, eight
// cells at a time where SSE2 is at hand; FirstOtherThan(): the end of a
// stretch of one value in an array of labels, four at a time.
#ifndef LINEMAP_CODEC_SEGMENT_RANGE_SCAN_H_
#define LINEMAP_CODEC_SEGMENT_RANGE_SCAN_H_

#include <bit>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace linemap::segment_internal {

// Calls visit(i) for each index i of dist[0, n) with lo <= dist[i] <= hi,
// in increasing order. Most cells of a map are walls or unknown (0), within
// a door's clearance of a wall (the flooded levels) or above it (the
// plateaus): where SSE2 is at hand eight cells are tested at once and only
// those in range visited (the flood's passes over every cell, one cell
// after another, were 4-6 % of an encode).
template <typename Visit>
void ForEachInRange(const std::uint16_t* dist, std::size_t n, std::uint16_t lo, std::uint16_t hi,
                    Visit&& visit) {
  if (lo > hi) return;
  std::size_t i = 0;
#if defined(__SSE2__)
  const __m128i low = _mm_set1_epi16(static_cast<short>(lo));
  const __m128i span = _mm_set1_epi16(static_cast<short>(hi - lo));
  const __m128i zero = _mm_setzero_si128();
  for (; i + 8 <= n; i += 8) {
    // d - lo wraps the values below lo round above hi - lo; the lanes in
    // range are those where the saturated difference (d - lo) - (hi - lo)
    // is 0.
    const __m128i d =
        _mm_sub_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(dist + i)), low);
    unsigned mask =
        static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_subs_epu16(d, span), zero)));
    while (mask != 0) {
      const int bit = std::countr_zero(mask);  // even: two mask bits per lane
      visit(i + static_cast<std::size_t>(bit / 2));
      mask &= ~(3u << bit);
    }
  }
#endif
  for (; i < n; ++i) {
    if (dist[i] >= lo && dist[i] <= hi) visit(i);
  }
}

// The first index i >= `from` of dist[0, n) with (dist[i] > t) == `above`,
// or n; eight cells at a time where SSE2 is at hand.
inline std::size_t FirstWhereAbove(const std::uint16_t* dist, std::size_t from, std::size_t n,
                                   std::uint16_t t, bool above) {
  std::size_t i = from;
#if defined(__SSE2__)
  const __m128i limit = _mm_set1_epi16(static_cast<short>(t));
  const __m128i zero = _mm_setzero_si128();
  // Two mask bits per lane, set where the lane is not above t.
  const unsigned flip = above ? 0xffffu : 0u;
  for (; i + 8 <= n; i += 8) {
    const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(dist + i));
    const unsigned mask =
        (static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_subs_epu16(d, limit), zero))) ^
         flip);
    if (mask != 0) return i + static_cast<std::size_t>(std::countr_zero(mask) / 2);
  }
#endif
  while (i < n && (dist[i] > t) != above) ++i;
  return i;
}

// Calls visit(begin, end) for each maximal run [begin, end) of dist[0, n)
// whose values are all above t, in increasing order. The room flood's
// plateaus are a few long runs per row: joined run by run, not cell by cell.
template <typename Visit>
void ForEachRunAbove(const std::uint16_t* dist, std::size_t n, std::uint16_t t, Visit&& visit) {
  for (std::size_t begin = FirstWhereAbove(dist, 0, n, t, true); begin < n;) {
    const std::size_t end = FirstWhereAbove(dist, begin, n, t, false);
    visit(begin, end);
    begin = FirstWhereAbove(dist, end, n, t, true);
  }
}

// The first index i >= `from` of values[0, n) with values[i] != `value`, or
// n; four entries at a time where SSE2 is at hand. The rooms' statistics
// walk the rooms of a map's cells with it: no room (walls, unknown space)
// and one room's cells lie in long stretches of a row.
inline std::size_t FirstOtherThan(const std::int32_t* values, std::size_t from, std::size_t n,
                                  std::int32_t value) {
  std::size_t i = from;
#if defined(__SSE2__)
  const __m128i same = _mm_set1_epi32(value);
  for (; i + 4 <= n; i += 4) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(values + i));
    const unsigned mask =
        static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi32(v, same))) ^ 0xffffu;
    if (mask != 0) return i + static_cast<std::size_t>(std::countr_zero(mask) / 4);
  }
#endif
  while (i < n && values[i] == value) ++i;
  return i;
}

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_RANGE_SCAN_H_
