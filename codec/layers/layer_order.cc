// Greedy nearest-neighbour order of the layer items (layer_order.h).
#include "codec/layers/layer_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "codec/layers/layer_coding.h"

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

// What a start offset of (dc, dr) costs, roughly, in bits: coded integers
// take about 2 log2 of their magnitude. A table for the common short jumps
// (log2 is much of the tour's time), made once; the tour keeps a pointer
// to it so that the cost inlines into its loops.
constexpr int kLog2Table = 4096;
const double* Log2OnePlusTable() {
  static const std::vector<double> table = [] {
    std::vector<double> t(kLog2Table);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = std::log2(1.0 + static_cast<double>(i));
    return t;
  }();
  return table.data();
}

// Improves the nearest-neighbour tour by 2-opt moves: reversing a run of
// walls (each wall reversed too) changes only the two jumps at its ends;
// and by moving one wall between two others near one of its ends (Or-opt:
// WALL 41,201 -> 41,021 bytes on the same maps).
// Moves are sought among each end's kNeighbours nearest wall ends (within
// kReach cells), so a pass costs about n kNeighbours, and at most
// kMaxPasses passes run. The nearest-neighbour tour leaves long jumps where
// it ran out of near walls; on the 25 maps of ../shared/maps these moves
// cut WALL from 41,988 to 41,201 bytes (16 neighbours; 8 gave 41,246, a
// reach of 128 cells and 20 passes 41,181, all without kMaxRun). 8
// neighbours and 4 passes: the default files of the 25 maps 30 bytes
// larger in all (183,748 against 183,718) for 10 % less encode time
// (16 and 8 passes took 7 % of encoding cs_lg); 2 passes another 83 bytes
// for 2 % less.
constexpr int kNeighbours = 8;
constexpr int kReach = 64;
constexpr int kNearBucket = 16;  // cells: the buckets NearEnds reads (any size finds the same)
constexpr int kMaxPasses = 4;
// Longest run reversed, in walls: a reversal costs its length, and on a
// map of 184,000 walls unbounded runs cost a second and a half.
constexpr std::size_t kMaxRun = 1000;

// Each wall end's near ends (WallTour::NearEnds) in one array: end e's are
// ends[first[e], first[e + 1]).
struct NearLists {
  struct Range {
    const std::size_t* b;
    const std::size_t* e;
    const std::size_t* begin() const { return b; }
    const std::size_t* end() const { return e; }
  };
  Range Of(std::size_t end) const {
    return {ends.data() + first[end], ends.data() + first[end + 1]};
  }
  std::vector<std::size_t> ends;
  std::vector<std::size_t> first;
};

class WallTour {
 public:
  explicit WallTour(std::vector<WallPolyline>* walls) : walls_(*walls) {
    const std::size_t n = walls_.size();
    ends_.reserve(2 * n);
    for (const WallPolyline& wall : walls_) {
      ends_.push_back(wall.points.front());
      ends_.push_back(wall.points.back());
    }
    tour_.resize(n);
    reversed_.assign(n, 0);
    pos_.resize(n);
    for (std::size_t k = 0; k < n; ++k) tour_[k] = pos_[k] = k;
  }

  void Improve() {
    const std::size_t n = walls_.size();
    if (n < 3) return;
    const NearLists near = NearEnds();
    for (int pass = 0; pass < kMaxPasses; ++pass) {
      bool improved = false;
      for (std::size_t i = 0; i < n; ++i) {
        // Reversing [i, j]: jumps out(i-1) -> in(i) and out(j) -> in(j+1)
        // become out(i-1) -> out(j) and in(i) -> in(j+1).
        for (const int side : {0, 1}) {
          // Side 0 looks for in(j+1) near in(i), side 1 for out(j) near
          // out(i-1) (before the first wall is (0, 0), no wall's end).
          if (side == 1 && i == 0) continue;
          for (std::size_t e : near.Of(side == 0 ? InEnd(i) : OutEnd(i - 1))) {
            const std::size_t k = pos_[e / 2];
            std::size_t j;
            if (side == 1) {
              // e must be out(j), j >= i: the new jump out(i-1) -> out(j).
              if (k < i || OutEnd(k) != e) continue;
              j = k;
            } else {
              // e must be in(j+1), j + 1 > i: the new jump in(i) -> in(j+1).
              if (k <= i || InEnd(k) != e) continue;
              j = k - 1;
            }
            if (j - i < kMaxRun && Gain(i, j) > 1e-9) {
              Reverse(i, j);
              improved = true;
            }
          }
        }
        if (MoveOne(i, near)) improved = true;
      }
      if (!improved) break;
    }
  }

  // Moves the wall at position i, either way round, between two walls next
  // to one of its ends where that saves more than taking it out costs.
  bool MoveOne(std::size_t i, const NearLists& near) {
    const std::size_t n = tour_.size();
    const std::size_t w = tour_[i];
    const double removed =
        JumpCost(Before(i), In(i)) +
        (i + 1 < n ? JumpCost(Out(i), In(i + 1)) - JumpCost(Before(i), In(i + 1)) : 0.0);
    double best = 1e-9;
    std::size_t best_k = 0;  // insert before the wall now at best_k (n: at the end)
    int best_rev = 0;
    for (const int end : {0, 1}) {
      const std::size_t e = 2 * w + static_cast<std::size_t>(end);
      const CellIndex here = EndPoint(e), there = EndPoint(e ^ 1);
      for (std::size_t f : near.Of(e)) {
        const std::size_t k = pos_[f / 2];
        if (k == i) continue;
        // f = Out(k): insert after k, entering at e. f = In(k): insert
        // before k, leaving at e.
        std::size_t at;
        CellIndex in, out;
        if (OutEnd(k) == f) {
          at = k + 1;
          in = here;
          out = there;
        } else {
          at = k;
          in = there;
          out = here;
        }
        if (at == i || at == i + 1) continue;
        const std::size_t lo = std::min(at, i), hi = std::max(at, i);
        if (hi - lo >= kMaxRun) continue;
        const CellIndex before = at == 0 ? CellIndex{0, 0} : Out(at - 1);
        double added = JumpCost(before, in);
        if (at < n) added += JumpCost(out, In(at)) - JumpCost(before, In(at));
        const double gain = removed - added;
        if (gain > best) {
          best = gain;
          best_k = at;
          // Entering at the wall's back end means it runs reversed.
          best_rev = (in == EndPoint(2 * w + 1) && !(in == EndPoint(2 * w))) ? 1 : 0;
        }
      }
    }
    if (best <= 1e-9) return false;
    const std::uint8_t rev = static_cast<std::uint8_t>(best_rev);
    if (best_k > i) {
      std::rotate(tour_.begin() + i, tour_.begin() + i + 1, tour_.begin() + best_k);
      std::rotate(reversed_.begin() + i, reversed_.begin() + i + 1, reversed_.begin() + best_k);
      reversed_[best_k - 1] = rev;
      for (std::size_t k = i; k < best_k; ++k) pos_[tour_[k]] = k;
    } else {
      std::rotate(tour_.begin() + best_k, tour_.begin() + i, tour_.begin() + i + 1);
      std::rotate(reversed_.begin() + best_k, reversed_.begin() + i, reversed_.begin() + i + 1);
      reversed_[best_k] = rev;
      for (std::size_t k = best_k; k <= i; ++k) pos_[tour_[k]] = k;
    }
    return true;
  }

  std::vector<WallPolyline> Take() {
    std::vector<WallPolyline> out;
    out.reserve(walls_.size());
    for (std::size_t k = 0; k < tour_.size(); ++k) {
      WallPolyline wall = std::move(walls_[tour_[k]]);
      if (reversed_[k]) std::reverse(wall.points.begin(), wall.points.end());
      out.push_back(std::move(wall));
    }
    return out;
  }

 private:
  // Ends are numbered 2 w (the front of wall w as given) and 2 w + 1 (its back).
  CellIndex EndPoint(std::size_t e) const { return ends_[e]; }
  double Log2OnePlus(int d) const {
    return d < kLog2Table ? log2_[d] : std::log2(1.0 + static_cast<double>(d));
  }
  double JumpCost(CellIndex p, CellIndex q) const {
    return Log2OnePlus(std::abs(p.col - q.col)) + Log2OnePlus(std::abs(p.row - q.row));
  }
  std::size_t InEnd(std::size_t k) const { return 2 * tour_[k] + (reversed_[k] ? 1 : 0); }
  std::size_t OutEnd(std::size_t k) const { return 2 * tour_[k] + (reversed_[k] ? 0 : 1); }
  CellIndex In(std::size_t k) const { return EndPoint(InEnd(k)); }
  CellIndex Out(std::size_t k) const { return EndPoint(OutEnd(k)); }
  CellIndex Before(std::size_t i) const { return i == 0 ? CellIndex{0, 0} : Out(i - 1); }

  double Gain(std::size_t i, std::size_t j) const {
    double gain = JumpCost(Before(i), In(i)) - JumpCost(Before(i), Out(j));
    if (j + 1 < tour_.size()) gain += JumpCost(Out(j), In(j + 1)) - JumpCost(In(i), In(j + 1));
    return gain;
  }

  void Reverse(std::size_t i, std::size_t j) {
    std::reverse(tour_.begin() + i, tour_.begin() + j + 1);
    std::reverse(reversed_.begin() + i, reversed_.begin() + j + 1);
    for (std::size_t k = i; k <= j; ++k) {
      reversed_[k] ^= 1;
      pos_[tour_[k]] = k;
    }
  }

  // Each end's kNeighbours nearest ends of other walls within kReach (L1;
  // ties to the lower end number).
  NearLists NearEnds() const {
    const std::size_t m = 2 * walls_.size();
    int max_col = 0, max_row = 0;
    for (std::size_t e = 0; e < m; ++e) {
      max_col = std::max(max_col, EndPoint(e).col);
      max_row = std::max(max_row, EndPoint(e).row);
    }
    // Ends in square buckets of kNearBucket cells, in one array (bucket b
    // holds in_bucket[start[b], start[b + 1]), by increasing end). Buckets
    // much smaller than kReach, so that the search below can stop after
    // the few nearest. Which ends are found does not depend on the buckets.
    const int bx = max_col / kNearBucket + 1, by = max_row / kNearBucket + 1;
    const auto bucket_of = [&](CellIndex p) {
      return static_cast<std::size_t>(p.row / kNearBucket) * bx + p.col / kNearBucket;
    };
    std::vector<std::size_t> start(static_cast<std::size_t>(bx) * by + 1, 0);
    for (std::size_t e = 0; e < m; ++e) ++start[bucket_of(EndPoint(e)) + 1];
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    std::vector<std::size_t> in_bucket(m);
    {
      std::vector<std::size_t> fill(start.begin(), start.end() - 1);
      for (std::size_t e = 0; e < m; ++e) in_bucket[fill[bucket_of(EndPoint(e))]++] = e;
    }
    NearLists near;
    near.first.reserve(m + 1);
    near.first.push_back(0);
    // The kNeighbours least (distance, end) pairs so far, in increasing
    // order: kept by insertion rather than collecting every end within
    // kReach and sorting (on the fetch maps a dense cluster of wall ends
    // puts hundreds within reach of each end). Buckets are read ring by
    // ring around the end's own bucket and skipped when no cell of theirs
    // can beat the worst kept pair, so the search mostly reads the nearest
    // few buckets; the pairs kept are the same as a full scan's.
    std::pair<long, std::size_t> best[kNeighbours];
    const int rings = kReach / kNearBucket + 1;
    for (std::size_t e = 0; e < m; ++e) {
      const CellIndex p = EndPoint(e);
      int kept = 0;
      const auto offer = [&](long d, std::size_t f) {
        const std::pair<long, std::size_t> item{d, f};
        if (kept == kNeighbours && !(item < best[kept - 1])) return;
        int k = kept < kNeighbours ? kept++ : kept - 1;
        for (; k > 0 && item < best[k - 1]; --k) best[k] = best[k - 1];
        best[k] = item;
      };
      // L1 distance from p to the nearest cell of bucket (x, y).
      const auto bucket_distance = [&](int x, int y) {
        const int lo_c = x * kNearBucket, lo_r = y * kNearBucket;
        const int dc = std::max({0, lo_c - p.col, p.col - (lo_c + kNearBucket - 1)});
        const int dr = std::max({0, lo_r - p.row, p.row - (lo_r + kNearBucket - 1)});
        return static_cast<long>(dc) + dr;
      };
      const auto scan = [&](int x, int y) {
        if (x < 0 || x >= bx || y < 0 || y >= by) return;
        const long reach = kept == kNeighbours ? best[kept - 1].first : kReach;
        if (bucket_distance(x, y) > reach) return;
        const std::size_t b = static_cast<std::size_t>(y) * bx + x;
        for (std::size_t k = start[b]; k < start[b + 1]; ++k) {
          const std::size_t f = in_bucket[k];
          if (f / 2 == e / 2) continue;
          const CellIndex q = EndPoint(f);
          const long d = std::labs(long{p.col} - q.col) + std::labs(long{p.row} - q.row);
          if (d <= kReach) offer(d, f);
        }
      };
      const int cx = p.col / kNearBucket, cy = p.row / kNearBucket;
      for (int ring = 0; ring <= rings; ++ring) {
        // Every cell of ring `ring` is at least (ring - 1) kNearBucket + 1 away.
        if (kept == kNeighbours &&
            best[kept - 1].first < static_cast<long>(ring - 1) * kNearBucket + 1) {
          break;
        }
        if (ring == 0) {
          scan(cx, cy);
          continue;
        }
        for (int x = cx - ring; x <= cx + ring; ++x) {
          scan(x, cy - ring);
          scan(x, cy + ring);
        }
        for (int y = cy - ring + 1; y <= cy + ring - 1; ++y) {
          scan(cx - ring, y);
          scan(cx + ring, y);
        }
      }
      for (int k = 0; k < kept; ++k) near.ends.push_back(best[k].second);
      near.first.push_back(near.ends.size());
    }
    return near;
  }

  std::vector<WallPolyline>& walls_;
  const double* log2_ = Log2OnePlusTable();
  std::vector<CellIndex> ends_;         // by end (EndPoint): read far more often than the walls
  std::vector<std::size_t> tour_;       // wall at each position
  std::vector<std::uint8_t> reversed_;  // whether the wall at a position runs back to front
  std::vector<std::size_t> pos_;        // position of each wall
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
  WallTour tour(&ordered);
  tour.Improve();
  ordered = tour.Take();
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

void CanonicalizeWalls(std::vector<WallPolyline>* walls) {
  DropRepeatedWallPoints(walls);
  OrderWallsForCoding(walls);
}

}  // namespace linemap
