// Hint bytes of a tile (spec/format.md section 6.2).
#include "codec/layers/layer_hints.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "codec/layers/raster.h"

namespace linemap {
namespace {

// Bucket side of the item index (cells, as a shift): small enough that a
// 1024-cell tile looks at few items it does not meet, large enough that a
// room's box spans few buckets.
constexpr int kBucketShift = 8;
// Buckets an item may be listed in (see MakeBuckets).
constexpr int kMaxBucketsPerItem = 4;

bool Overlaps(const BoundingBox& box, CellRect t) {
  return box.max_col >= t.x0 && box.min_col < t.x1 && box.max_row >= t.y0 && box.min_row < t.y1;
}

// ORs `bits` into the `Word`-sized bytes at p (a Word of `bits` bytes:
// `word_bits`).
template <typename Word>
void OrWord(std::uint8_t* p, Word word_bits) {
  Word w;
  std::memcpy(&w, p, sizeof(w));
  w |= word_bits;
  std::memcpy(p, &w, sizeof(w));
}

// ORs `bits` into n bytes, eight at a time: a room's fill spans whole tile
// rows, and GCC at -O2 keeps a byte loop of unknown length scalar (half of
// DrawOutline's time on a median map was that loop). The tail is not a
// byte loop either: the last 8 bytes are ORed as one word, overlapping the
// words before it, and a span under 8 bytes as two words of 4 (or 2) that
// meet or overlap; ORing a byte twice leaves it as ORing it once. The rows
// of small rooms are short spans, and the byte loop of their tails took
// two fifths of the spans' time (7 % of DrawOutline's on the median maps).
// `bits` is a value, not read through the outline, which might alias the
// bytes.
void OrSpan(std::uint8_t* p, int n, std::uint8_t bits) {
  if (n >= 8) {
    const std::uint64_t word_bits = 0x0101010101010101u * bits;
    for (int i = 0; i < n - 8; i += 8) OrWord(p + i, word_bits);
    OrWord(p + n - 8, word_bits);
  } else if (n >= 4) {
    const std::uint32_t word_bits = 0x01010101u * bits;
    OrWord(p, word_bits);
    OrWord(p + n - 4, word_bits);
  } else if (n >= 2) {
    const auto word_bits = static_cast<std::uint16_t>(0x0101u * bits);
    OrWord(p, word_bits);
    OrWord(p + n - 2, word_bits);
  } else if (n == 1) {
    *p |= bits;
  }
}

bool Inside(int c, int r, CellRect t) { return c >= t.x0 && c < t.x1 && r >= t.y0 && r < t.y1; }

// The rasterisation of a -> b (RasterizeSegment, raster.h): step i in
// [0, n] covers (a.col + floor((2 i dx + n) / 2n), a.row + floor((2 i dy +
// n) / 2n)). Along the major axis (the one with |delta| == n) the cell moves
// exactly one per step, which lets a tile find its cells and crossings
// without walking the rest of the edge; along the other the floor is
// stepped with a remainder rather than divided out per cell.
class EdgeRaster {
 public:
  EdgeRaster(CellIndex a, CellIndex b)
      : a_(a),
        dx_(std::int64_t{b.col} - a.col),
        dy_(std::int64_t{b.row} - a.row),
        n_(std::max(std::llabs(dx_), std::llabs(dy_))) {}
  std::int64_t n() const { return n_; }

  // Marks the cells of steps [0, last] (n > 0) inside `t` in the tile's
  // hint bytes (row r at out + (r - t.y0) * stride): clears the bits
  // `clear`, then sets `set`. Along the major axis the steps are clipped
  // to the tile; the minor coordinate lies between the ends' (each step
  // rounds a point of the segment), so an edge whose ends' minor
  // coordinates are inside the tile needs no test per cell (no edge of a
  // map of one tile does), and an edge along an axis has no minor steps at
  // all (most sides of rooms and furniture). The cell's offset is stepped
  // along with the cell, and the minor coordinate's carry is added rather
  // than branched on: on a slanted edge it comes at no regular step. (A
  // callback per cell testing both coordinates against the tile was a
  // fifth of DrawOutline's time on the median maps.)
  void MarkInside(std::int64_t last, CellRect t, std::uint8_t* out, std::ptrdiff_t stride,
                  std::uint8_t clear, std::uint8_t set) const {
    const bool steep = std::llabs(dy_) == n_;
    const std::int64_t start = steep ? a_.row : a_.col;
    const bool up = steep ? dy_ > 0 : dx_ > 0;
    const std::int64_t lo = steep ? t.y0 : t.x0;
    const std::int64_t hi = steep ? t.y1 : t.x1;
    std::int64_t i0 = up ? lo - start : start - hi + 1;
    std::int64_t i1 = up ? hi - start : start - lo + 1;
    i0 = std::max<std::int64_t>(i0, 0);
    i1 = std::min<std::int64_t>(i1, last + 1);
    if (i0 >= i1) return;
    const std::int64_t minor_start = steep ? a_.col : a_.row;
    const std::int64_t minor_delta = steep ? dx_ : dy_;
    const std::int64_t minor_lo = steep ? t.x0 : t.y0;
    const std::int64_t minor_hi = steep ? t.x1 : t.y1;
    const bool all_inside = std::min(minor_start, minor_start + minor_delta) >= minor_lo &&
                            std::max(minor_start, minor_start + minor_delta) < minor_hi;
    MinorStepper minor_step(i0, 2 * minor_delta, n_);
    std::int64_t minor = minor_start + minor_step.q;
    const std::int64_t major = up ? start + i0 : start - i0;
    const std::int64_t c = steep ? minor : major, r = steep ? major : minor;
    std::ptrdiff_t at = (r - t.y0) * stride + (c - t.x0);
    const std::ptrdiff_t major_unit = (steep ? stride : 1) * (up ? 1 : -1);
    const std::ptrdiff_t minor_unit = steep ? 1 : stride;
    const auto keep = static_cast<std::uint8_t>(~clear);
    if (minor_delta == 0) {
      // Along an axis: the minor coordinate stays, inside the tile or not.
      if (!all_inside) return;
      for (std::int64_t i = i0; i < i1; ++i, at += major_unit) {
        out[at] = static_cast<std::uint8_t>((out[at] & keep) | set);
      }
      return;
    }
    std::int64_t rem = minor_step.rem;
    const std::int64_t step = minor_step.step, two_n = minor_step.two_n;
    for (std::int64_t i = i0; i < i1; ++i) {
      if (all_inside || (minor >= minor_lo && minor < minor_hi)) {
        out[at] = static_cast<std::uint8_t>((out[at] & keep) | set);
      }
      rem += step;
      const std::int64_t carry = (rem >= two_n ? 1 : 0) - (rem < 0 ? 1 : 0);
      rem -= carry * two_n;
      minor += carry;
      at += major_unit + carry * minor_unit;
    }
  }

  // Calls emit(r, c) for each step of the edge between rows r and r + 1
  // with r in [lo, hi] (dy != 0): c is the column of the step's cell on row
  // r, as FillChain (raster.h) takes it. Columns are stepped along, as in
  // VisitInside.
  template <typename Emit>
  void VisitCrossings(int lo, int hi, Emit&& emit) const {
    if (std::llabs(dy_) == n_) {
      // Steep: one row per step. Going up, the step from row r starts at
      // cell r - a.row; going down, the step to row r ends at a.row - r.
      // Either way the cell's index rises by one per row visited.
      const std::int64_t i0 = dy_ > 0 ? lo - a_.row : a_.row - hi;
      const std::int64_t count = hi - lo + 1;
      MinorStepper col(i0, 2 * dx_, n_);
      for (std::int64_t k = 0; k < count; ++k, col.Next()) {
        const int r = static_cast<int>(dy_ > 0 ? lo + k : hi - k);
        emit(r, static_cast<int>(a_.col + col.q));
      }
      return;
    }
    // Shallow: one column per step, the row changing on some steps; walked
    // cell by cell, with the row stepped along.
    const std::int64_t sx = dx_ > 0 ? 1 : -1;
    MinorStepper row_step(0, 2 * dy_, n_);  // step 0 is a itself
    int row = a_.row;
    for (std::int64_t i = 0; i < n_; ++i) {
      row_step.Next();
      const int next = static_cast<int>(a_.row + row_step.q);
      if (next != row) {
        // Up: the cell on row r is this one (i); down: the next (i + 1).
        const int r = std::min(row, next);
        if (r >= lo && r <= hi) {
          emit(r, static_cast<int>(a_.col + sx * (next > row ? i : i + 1)));
        }
        row = next;
      }
    }
  }

 private:
  CellIndex a_;
  std::int64_t dx_, dy_, n_;
};

}  // namespace

LayerIndex::LayerIndex(const std::vector<WallPolyline>& walls,
                       const std::vector<RoomOutline>& rooms,
                       const std::vector<FurnitureObject>& furniture) {
  // Reserved exactly: grown by doubling, the segments alone would peak at
  // three times their size on a large map.
  std::size_t segments = 0;
  for (const WallPolyline& wall : walls)
    segments += wall.points.empty() ? 0 : wall.points.size() - 1;
  segments_.reserve(segments);
  outlines_.reserve(rooms.size() + furniture.size());
  for (const WallPolyline& wall : walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      segments_.push_back({&wall.points[i - 1]});
    }
  }
  for (const RoomOutline& room : rooms) {
    AddOutline(room.polygon, kHintRoomInside, kHintRoomBorder, kHintRoomInside);
  }
  for (const FurnitureObject& object : furniture) {
    AddOutline(object.polygon, kHintFurniture, kHintFurniture, 0);
  }
  bool first = true;
  const auto extend = [&](const BoundingBox& box) {
    extent_ = first ? box
                    : BoundingBox{std::min(extent_.min_col, box.min_col),
                                  std::min(extent_.min_row, box.min_row),
                                  std::max(extent_.max_col, box.max_col),
                                  std::max(extent_.max_row, box.max_row)};
    first = false;
  };
  for (const Segment& s : segments_) extend(s.box());
  for (const Outline& o : outlines_) extend(o.box());
}

bool LayerIndex::Covers(CellRect t) const {
  return extent_.min_col >= t.x0 && extent_.max_col < t.x1 && extent_.min_row >= t.y0 &&
         extent_.max_row < t.y1;
}

template <typename Item, typename Draw>
void LayerIndex::ForItemsMeeting(const std::vector<Item>& list, const Buckets& buckets, CellRect t,
                                 Draw&& draw) const {
  if (Covers(t)) {
    for (std::uint32_t i = 0; i < list.size(); ++i) {
      if (Overlaps(list[i].box(), t)) draw(i);
    }
    return;
  }
  for (std::uint32_t i : ItemsNear(buckets, t)) {
    if (Overlaps(list[i].box(), t)) draw(i);
  }
}

void LayerIndex::AddOutline(const std::vector<CellIndex>& polygon, std::uint8_t fill_bits,
                            std::uint8_t chain_bits, std::uint8_t clear_on_chain) {
  if (polygon.empty()) return;
  outlines_.push_back({&polygon, BoxOfCells(polygon), fill_bits, chain_bits, clear_on_chain});
}

BoundingBox LayerIndex::Segment::box() const {
  return {std::min(ends[0].col, ends[1].col), std::min(ends[0].row, ends[1].row),
          std::max(ends[0].col, ends[1].col), std::max(ends[0].row, ends[1].row)};
}

template <typename Item>
LayerIndex::Buckets LayerIndex::MakeBuckets(const std::vector<Item>& list) {
  Buckets b;
  for (const Item& item : list) {
    b.cols = std::max(b.cols, (std::max(item.box().max_col, 0) >> kBucketShift) + 1);
    b.rows = std::max(b.rows, (std::max(item.box().max_row, 0) >> kBucketShift) + 1);
  }
  b.starts.assign(static_cast<std::size_t>(b.cols) * b.rows + 1, 0);
  // An item listed in at most kMaxBucketsPerItem buckets, a wider one in
  // `wide` (every tile looks at those): the index stays within a few bytes
  // per item whatever a file's boxes span (long diagonal walls, corridors).
  const auto wide = [](const BoundingBox& box) {
    const std::int64_t w =
        (std::max(box.max_col, 0) >> kBucketShift) - (std::max(box.min_col, 0) >> kBucketShift) + 1;
    const std::int64_t h =
        (std::max(box.max_row, 0) >> kBucketShift) - (std::max(box.min_row, 0) >> kBucketShift) + 1;
    return w * h > kMaxBucketsPerItem;
  };
  // Two passes over the boxes' buckets: count, then place.
  const auto for_buckets = [&](const BoundingBox& box, auto&& f) {
    const int bx0 = std::max(box.min_col, 0) >> kBucketShift;
    const int bx1 = std::max(box.max_col, 0) >> kBucketShift;
    const int by0 = std::max(box.min_row, 0) >> kBucketShift;
    const int by1 = std::max(box.max_row, 0) >> kBucketShift;
    for (int by = by0; by <= by1; ++by) {
      for (int bx = bx0; bx <= bx1; ++bx) f(static_cast<std::size_t>(by) * b.cols + bx);
    }
  };
  for (std::size_t i = 0; i < list.size(); ++i) {
    const BoundingBox box = list[i].box();
    if (wide(box)) {
      b.wide.push_back(static_cast<std::uint32_t>(i));
    } else {
      for_buckets(box, [&](std::size_t k) { ++b.starts[k + 1]; });
    }
  }
  for (std::size_t k = 1; k < b.starts.size(); ++k) b.starts[k] += b.starts[k - 1];
  b.items.resize(b.starts.back());
  std::vector<std::uint32_t> fill(b.starts.begin(), b.starts.end() - 1);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const BoundingBox box = list[i].box();
    if (wide(box)) continue;
    for_buckets(box, [&](std::size_t k) { b.items[fill[k]++] = static_cast<std::uint32_t>(i); });
  }
  return b;
}

std::vector<std::uint32_t> LayerIndex::ItemsNear(const Buckets& b, CellRect t) {
  std::vector<std::uint32_t> items;
  if (b.cols == 0 || t.x1 <= t.x0 || t.y1 <= t.y0) return items;
  const int bx0 = std::max(t.x0, 0) >> kBucketShift;
  const int by0 = std::max(t.y0, 0) >> kBucketShift;
  const int bx1 = std::min((t.x1 - 1) >> kBucketShift, b.cols - 1);
  const int by1 = std::min((t.y1 - 1) >> kBucketShift, b.rows - 1);
  if (t.x1 <= 0 || t.y1 <= 0 || bx0 > bx1 || by0 > by1) return items;
  for (int by = by0; by <= by1; ++by) {
    for (int bx = bx0; bx <= bx1; ++bx) {
      const std::size_t k = static_cast<std::size_t>(by) * b.cols + bx;
      items.insert(items.end(), b.items.begin() + b.starts[k], b.items.begin() + b.starts[k + 1]);
    }
  }
  items.insert(items.end(), b.wide.begin(), b.wide.end());
  if (bx0 != bx1 || by0 != by1 || !b.wide.empty()) {
    std::sort(items.begin(), items.end());
    items.erase(std::unique(items.begin(), items.end()), items.end());
  }
  return items;
}

void LayerIndex::DrawOutline(const Outline& outline, CellRect t, std::uint8_t* out,
                             std::ptrdiff_t stride, Scratch* scratch) {
  const std::vector<CellIndex>& polygon = *outline.polygon;
  const auto at = [&](int c, int r) -> std::uint8_t& {
    return out[(r - t.y0) * stride + (c - t.x0)];
  };
  const auto mark_chain = [&](int c, int r) {
    std::uint8_t& h = at(c, r);
    h = static_cast<std::uint8_t>((h & ~outline.clear_on_chain) | outline.chain_bits);
  };
  const std::size_t k = polygon.size();
  if (k == 1) {
    // A one-cell chain: no crossings, no fill.
    if (Inside(polygon[0].col, polygon[0].row, t)) mark_chain(polygon[0].col, polygon[0].row);
    return;
  }
  // Fill (8.2): on each row, the cells in [x0, x1), [x2, x3), ... of the
  // sorted crossings, i.e. those with an odd number of crossings at or left
  // of them. Crossings left of the tile only flip the parity a row starts
  // with (`flip` holds the flips as differences along the rows, so an edge
  // wholly left of the tile costs two writes); those right of it change
  // nothing inside.
  const int r0 = std::max(t.y0, outline.box().min_row);
  const int r1 = std::min(t.y1, outline.box().max_row);  // crossing rows stop below the top
  if (r0 < r1) {
    const std::size_t rows = static_cast<std::size_t>(r1 - r0);
    std::vector<std::uint8_t>& flip = scratch->flip;
    flip.assign(rows + 1, 0);
    std::vector<std::pair<int, int>>& crossings = scratch->crossings;  // (row, column)
    crossings.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const CellIndex a = polygon[i], b = polygon[(i + 1) % k];
      if (a.row == b.row) continue;  // no crossings (and a == b: no steps)
      const int lo = std::max(std::min(a.row, b.row), r0);
      const int hi = std::min(std::max(a.row, b.row) - 1, r1 - 1);
      if (lo > hi) continue;
      if (std::max(a.col, b.col) < t.x0) {
        flip[lo - r0] ^= 1;
        flip[hi + 1 - r0] ^= 1;
        continue;
      }
      if (std::min(a.col, b.col) >= t.x1) continue;
      if (a.col == b.col) {
        // A vertical edge (most room sides) crosses every row in its own
        // column, here inside the tile: no division per row.
        for (int r = lo; r <= hi; ++r) crossings.emplace_back(r, a.col);
        continue;
      }
      const EdgeRaster edge(a, b);
      edge.VisitCrossings(lo, hi, [&](int r, int c) {
        if (c < t.x0) {
          flip[r - r0] ^= 1;
          flip[r + 1 - r0] ^= 1;
        } else if (c < t.x1) {
          crossings.emplace_back(r, c);
        }
      });
    }
    // The crossings by row (a counting sort: a room over a whole tile has
    // two on each of its rows), then by column within each row.
    std::vector<std::uint32_t>& starts = scratch->starts;
    starts.assign(rows + 1, 0);
    for (const auto& [r, c] : crossings) ++starts[r - r0 + 1];
    for (std::size_t i = 1; i <= rows; ++i) starts[i] += starts[i - 1];
    std::vector<int>& cols = scratch->cols;
    cols.resize(crossings.size());
    {
      std::vector<std::uint32_t>& next = scratch->next;
      next.assign(starts.begin(), starts.end() - 1);
      for (const auto& [r, c] : crossings) cols[next[r - r0]++] = c;
    }
    const std::uint8_t fill_bits = outline.fill_bits;
    unsigned parity = 0;
    for (int r = r0; r < r1; ++r) {
      parity ^= flip[r - r0];
      int* begin = cols.data() + starts[r - r0];
      int* end = cols.data() + starts[r - r0 + 1];
      // Most rows of a room have two crossings: one compare orders them,
      // cheaper than a call of std::sort per row.
      if (end - begin == 2) {
        if (begin[0] > begin[1]) std::swap(begin[0], begin[1]);
      } else if (end - begin > 2) {
        std::sort(begin, end);
      }
      unsigned inside = parity;
      int from = t.x0;
      std::uint8_t* row = &at(t.x0, r) - t.x0;
      for (const int* p = begin; p != end; ++p) {
        if (inside) OrSpan(row + from, *p - from, fill_bits);
        from = *p;
        inside ^= 1;
      }
      if (inside) OrSpan(row + from, t.x1 - from, fill_bits);
    }
  }
  // The chain's cells: each edge's rasterisation but its last cell.
  for (std::size_t i = 0; i < k; ++i) {
    const CellIndex a = polygon[i], b = polygon[(i + 1) % k];
    if (a == b) continue;
    if (std::max(a.col, b.col) < t.x0 || std::min(a.col, b.col) >= t.x1 ||
        std::max(a.row, b.row) < t.y0 || std::min(a.row, b.row) >= t.y1) {
      continue;
    }
    const EdgeRaster edge(a, b);
    edge.MarkInside(edge.n() - 1, t, out, stride, outline.clear_on_chain, outline.chain_bits);
  }
}

void LayerIndex::DrawTileHints(CellRect t, std::uint8_t* out, std::ptrdiff_t stride) const {
  const int tw = t.x1 - t.x0;
  for (int r = t.y0; r < t.y1; ++r) std::memset(out + (r - t.y0) * stride, 0, tw);
  if (!Covers(t)) {
    std::call_once(buckets_once_, [this] {
      segment_buckets_ = MakeBuckets(segments_);
      outline_buckets_ = MakeBuckets(outlines_);
    });
  }
  Scratch scratch;
  ForItemsMeeting(outlines_, outline_buckets_, t,
                  [&](std::uint32_t i) { DrawOutline(outlines_[i], t, out, stride, &scratch); });
  ForItemsMeeting(segments_, segment_buckets_, t, [&](std::uint32_t i) {
    const Segment& s = segments_[i];
    const CellIndex a = s.a(), b = s.b();
    if (a == b) {
      // Inside: its box overlaps the tile.
      out[(a.row - t.y0) * stride + (a.col - t.x0)] |= kHintWall;
      return;
    }
    const EdgeRaster edge(a, b);
    edge.MarkInside(edge.n(), t, out, stride, 0, kHintWall);
  });
}

std::vector<std::uint8_t> LayerIndex::TileHints(CellRect t) const {
  const int tw = t.x1 - t.x0;
  std::vector<std::uint8_t> hints(static_cast<std::size_t>(tw) * (t.y1 - t.y0));
  if (!hints.empty()) DrawTileHints(t, hints.data(), tw);
  return hints;
}

}  // namespace linemap
