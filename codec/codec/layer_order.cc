// Greedy nearest-neighbour order of the layer items (layer_order.h).
#include "codec/codec/layer_order.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace linemap {
namespace {

// Candidate points in square buckets of kBucket cells; a query scans rings
// of buckets around the current point until no farther ring can hold a
// nearer point, and after kMaxRings falls back to scanning every point.
constexpr int kBucket = 32;
constexpr int kMaxRings = 48;

struct Candidate {
  CellIndex p;
  int item;
  bool is_last;  // walls: the item's last point (a reversal makes it the start)
  int vertex;    // polygons: the vertex index (a rotation makes it the start)
};

class NearestIndex {
 public:
  explicit NearestIndex(std::vector<Candidate> points) : points_(std::move(points)) {
    for (const Candidate& c : points_) {
      max_col_ = std::max(max_col_, c.p.col);
      max_row_ = std::max(max_row_, c.p.row);
    }
    bx_ = max_col_ / kBucket + 1;
    by_ = max_row_ / kBucket + 1;
    start_.assign(static_cast<std::size_t>(bx_) * by_ + 1, 0);
    for (const Candidate& c : points_) ++start_[Bucket(c.p) + 1];
    for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    order_.resize(points_.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points_.size(); ++i) order_[fill[Bucket(points_[i].p)]++] = i;
  }

  // The nearest candidate of an item not yet taken (-1 when none is left).
  int Nearest(CellIndex at, const std::vector<bool>& taken) const {
    int best = -1;
    long best_d = 0;
    const auto consider = [&](std::size_t i) {
      const Candidate& c = points_[i];
      if (taken[c.item]) return;
      const long d = std::labs(long{c.p.col} - at.col) + std::labs(long{c.p.row} - at.row);
      if (best < 0 || d < best_d || (d == best_d && Before(i, static_cast<std::size_t>(best)))) {
        best = static_cast<int>(i);
        best_d = d;
      }
    };
    const int cx = std::clamp(at.col / kBucket, 0, bx_ - 1);
    const int cy = std::clamp(at.row / kBucket, 0, by_ - 1);
    for (int ring = 0; ring <= std::max(bx_, by_); ++ring) {
      // Points in ring r are at least (r - 1) * kBucket + 1 away.
      if (best >= 0 && best_d <= static_cast<long>(ring - 1) * kBucket) break;
      if (ring > kMaxRings) {
        for (std::size_t i = 0; i < points_.size(); ++i) consider(i);
        break;
      }
      for (int y = cy - ring; y <= cy + ring; ++y) {
        if (y < 0 || y >= by_) continue;
        const bool edge_row = y == cy - ring || y == cy + ring;
        for (int x = cx - ring; x <= cx + ring; x += edge_row ? 1 : 2 * ring) {
          if (x >= 0 && x < bx_) {
            const std::size_t b = static_cast<std::size_t>(y) * bx_ + x;
            for (std::size_t k = start_[b]; k < start_[b + 1]; ++k) consider(order_[k]);
          }
          if (ring == 0) break;
        }
      }
    }
    return best;
  }
  const Candidate& at(int i) const { return points_[static_cast<std::size_t>(i)]; }

 private:
  std::size_t Bucket(CellIndex p) const {
    return static_cast<std::size_t>(p.row / kBucket) * bx_ + p.col / kBucket;
  }
  // Ties: the lower item, then its first point before its last.
  bool Before(std::size_t a, std::size_t b) const {
    const Candidate& x = points_[a];
    const Candidate& y = points_[b];
    if (x.item != y.item) return x.item < y.item;
    return x.is_last != y.is_last ? !x.is_last : x.vertex < y.vertex;
  }
  std::vector<Candidate> points_;
  std::vector<std::size_t> order_;  // point indices grouped by bucket
  std::vector<std::size_t> start_;  // bucket b holds order_[start_[b], start_[b+1])
  int max_col_ = 0, max_row_ = 0, bx_ = 1, by_ = 1;
};

}  // namespace

void OrderWallsForCoding(std::vector<WallPolyline>* walls) {
  std::vector<Candidate> points;
  for (std::size_t i = 0; i < walls->size(); ++i) {
    const std::vector<CellIndex>& p = (*walls)[i].points;
    points.push_back({p.front(), static_cast<int>(i), false, 0});
    points.push_back({p.back(), static_cast<int>(i), true, 0});
  }
  const NearestIndex index(std::move(points));
  std::vector<bool> taken(walls->size(), false);
  std::vector<WallPolyline> ordered;
  ordered.reserve(walls->size());
  CellIndex at{0, 0};
  for (int k = index.Nearest(at, taken); k >= 0; k = index.Nearest(at, taken)) {
    const Candidate& c = index.at(k);
    taken[c.item] = true;
    WallPolyline wall = std::move((*walls)[c.item]);
    if (c.is_last) std::reverse(wall.points.begin(), wall.points.end());
    at = wall.points.back();
    ordered.push_back(std::move(wall));
  }
  *walls = std::move(ordered);
}

void OrderFurnitureForCoding(std::vector<FurnitureObject>* furniture) {
  std::vector<Candidate> points;
  for (std::size_t i = 0; i < furniture->size(); ++i) {
    const std::vector<CellIndex>& polygon = (*furniture)[i].polygon;
    for (std::size_t v = 0; v < polygon.size(); ++v) {
      points.push_back({polygon[v], static_cast<int>(i), false, static_cast<int>(v)});
    }
  }
  const NearestIndex index(std::move(points));
  std::vector<bool> taken(furniture->size(), false);
  std::vector<FurnitureObject> ordered;
  ordered.reserve(furniture->size());
  CellIndex at{0, 0};
  for (int k = index.Nearest(at, taken); k >= 0; k = index.Nearest(at, taken)) {
    const Candidate& c = index.at(k);
    taken[c.item] = true;
    FurnitureObject object = std::move((*furniture)[c.item]);
    // Start the polygon at the nearest vertex; it ends next to it.
    std::rotate(object.polygon.begin(), object.polygon.begin() + c.vertex, object.polygon.end());
    object.outline = ChainOfPolygon(object.polygon);
    object.id = static_cast<std::uint32_t>(ordered.size());
    at = object.polygon.back();
    ordered.push_back(std::move(object));
  }
  *furniture = std::move(ordered);
}

}  // namespace linemap
