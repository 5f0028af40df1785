// Wall segments joined into polylines (layer_extraction.h).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "codec/layers/layer_coding.h"
#include "codec/layers/layer_extraction.h"
#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/layer_order.h"

namespace linemap {
namespace layer_extraction_internal {

std::vector<WallPolyline> JoinSegmentsUnordered(const std::vector<LatticeSegment>& segments) {
  const auto key = [](CellIndex c) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.row)) << 32) |
           static_cast<std::uint32_t>(c.col);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> at_end;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    at_end[key(segments[i].a)].push_back(i);
    if (!(segments[i].a == segments[i].b)) at_end[key(segments[i].b)].push_back(i);
  }
  std::vector<bool> used(segments.size(), false);
  // The other end of an unused segment at `p`, marking it used.
  const auto next_from = [&](CellIndex p, CellIndex* out) {
    for (std::size_t i : at_end[key(p)]) {
      if (used[i]) continue;
      used[i] = true;
      *out = segments[i].a == p ? segments[i].b : segments[i].a;
      return true;
    }
    return false;
  };
  std::vector<WallPolyline> walls;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    std::vector<CellIndex> forward = {segments[i].a, segments[i].b};
    CellIndex q;
    while (next_from(forward.back(), &q)) forward.push_back(q);
    std::vector<CellIndex> backward;
    while (next_from(backward.empty() ? forward.front() : backward.back(), &q)) {
      backward.push_back(q);
    }
    std::reverse(backward.begin(), backward.end());
    backward.insert(backward.end(), forward.begin(), forward.end());
    walls.push_back({std::move(backward)});
  }
  return walls;
}

}  // namespace layer_extraction_internal

namespace {

using layer_extraction_internal::JoinSegmentsUnordered;

}  // namespace

std::vector<WallPolyline> JoinSegments(const std::vector<LatticeSegment>& segments) {
  std::vector<WallPolyline> walls = JoinSegmentsUnordered(segments);
  CanonicalizeWalls(&walls);
  return walls;
}

}  // namespace linemap
