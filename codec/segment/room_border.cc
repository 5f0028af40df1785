// Room-border closure (Kosteley et al., section 3.2 C).
//  Stage 1: M_H dilated (5x5 full, then the 3x3 cross) = D, D eroded twice
//           (5x5 full) = E, heavy border = D \ E.
//  Stage 3: 8-connected components of the heavy border; the mid-line rule:
//           two or more entries into a component along the horizontal
//           mid-line of its box make it a room border.
//  Stage 4: the component is opened on a cut row: the first run of its cells
//           from the left is the "-2" line, its component neighbours in the
//           row below are the "-3" line. A Lee wave (breadth-first, "line"
//           data structure) starts from the neighbours above the -2 line
//           (value 1) and stops at the first cell next to the -3 line (the
//           minimum-distance "end of path" cell). The backward pass walks
//           down the distances, preferring a step next to room space ("-4"),
//           and the chain is closed through the -3 and -2 lines.
// The room's component is the one holding D's outer boundary; the mid-line
// rule is only counted (see segmentation.h for why).
// Acceptance: the polygon through the chain holds the robot (point in
// polygon) or, without one, at least half of the room's free cells;
// otherwise the next cut row around the mid-line is tried, and at last the
// outer contour of D is used.
// linemap's addition: with protect_room_interior, the room's own interior
// (M_H eroded by the 3x3 cross) is kept out of the band.
#include <algorithm>
#include <deque>

#include "codec/segment/segment_internal.h"

namespace linemap::segment_internal {
namespace {

double MsSince(double start) { return ThreadCpuMs() - start; }

constexpr int kDc[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kDr[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

// The Lee closure of one component, reusing its scratch arrays between cut
// rows (only touched cells are reset).
class LeeCloser {
 public:
  LeeCloser(const Labeling& labels, std::int32_t label, const BinaryMask& interior,
            const BinaryMask& room_space)
      : labels_(labels),
        label_(label),
        interior_(interior),
        room_space_(room_space),
        dist_(labels.labels.size(), 0),
        mark_(labels.labels.size(), 0) {}

  // The closed chain for cut row `row`, or empty when the row does not cut
  // the component from outside to room space.
  std::vector<CellIndex> Close(int row) {
    std::vector<CellIndex> chain;
    if (OpenAt(row)) chain = WaveAndWalkBack();
    Reset();
    return chain;
  }

 private:
  static constexpr std::int8_t kMinus2 = 2;  // the paper's "-2" line
  static constexpr std::int8_t kMinus3 = 3;  // the paper's "-3" line

  std::size_t Index(int col, int row) const {
    return static_cast<std::size_t>(row) * labels_.width + col;
  }
  bool Mine(int col, int row) const { return labels_.get(col, row) == label_; }
  bool Marked(int col, int row, std::int8_t mark) const {
    return Mine(col, row) && mark_[Index(col, row)] == mark;
  }
  void SetMark(int col, int row, std::int8_t mark) {
    mark_[Index(col, row)] = mark;
    touched_.push_back({col, row});
  }

  bool OpenAt(int row) {
    const BoundingBox& box = labels_.components[label_ - 1].box;
    int c0 = box.min_col;
    while (c0 <= box.max_col && !Mine(c0, row)) ++c0;
    if (c0 > box.max_col) return false;
    int c1 = c0;
    while (Mine(c1 + 1, row)) ++c1;
    if (!interior_.get(c1 + 1, row)) return false;  // must switch into room space
    for (int c = c0; c <= c1; ++c) SetMark(c, row, kMinus2);
    bool any_below = false;
    for (int c = c0 - 1; c <= c1 + 1; ++c) {
      if (Mine(c, row - 1)) {
        SetMark(c, row - 1, kMinus3);
        any_below = true;
      }
    }
    starts_.clear();
    for (int c = c0 - 1; c <= c1 + 1; ++c) {
      if (Mine(c, row + 1)) starts_.push_back({c, row + 1});
    }
    return any_below && !starts_.empty();
  }

  bool NextToMark(CellIndex cell, std::int8_t mark, CellIndex* which) const {
    for (int k = 0; k < 8; ++k) {
      if (Marked(cell.col + kDc[k], cell.row + kDr[k], mark)) {
        *which = {cell.col + kDc[k], cell.row + kDr[k]};
        return true;
      }
    }
    return false;
  }

  bool NextToRoomSpace(CellIndex cell) const {
    for (int k = 0; k < 8; ++k) {
      if (room_space_.get(cell.col + kDc[k], cell.row + kDr[k])) return true;
    }
    return false;
  }

  std::vector<CellIndex> WaveAndWalkBack() {
    std::deque<CellIndex> line;
    for (const CellIndex& s : starts_) {
      dist_[Index(s.col, s.row)] = 1;
      visited_.push_back(s);
      line.push_back(s);
    }
    CellIndex end{}, end_mark{};
    bool found = false;
    while (!line.empty() && !found) {
      const CellIndex cur = line.front();
      line.pop_front();
      if (NextToMark(cur, kMinus3, &end_mark)) {
        end = cur;
        found = true;
        break;
      }
      const std::int32_t d = dist_[Index(cur.col, cur.row)];
      for (int k = 0; k < 8; ++k) {
        const CellIndex n{cur.col + kDc[k], cur.row + kDr[k]};
        if (!Mine(n.col, n.row)) continue;
        const std::size_t i = Index(n.col, n.row);
        if (mark_[i] || dist_[i]) continue;
        dist_[i] = d + 1;
        visited_.push_back(n);
        line.push_back(n);
      }
    }
    if (!found) return {};
    // Backward pass from the end to a start cell (value 1).
    std::vector<CellIndex> path{end};
    CellIndex cur = end;
    while (dist_[Index(cur.col, cur.row)] > 1) {
      const std::int32_t want = dist_[Index(cur.col, cur.row)] - 1;
      CellIndex first{}, preferred{};
      bool have_first = false, have_preferred = false;
      for (int k = 0; k < 8; ++k) {
        const CellIndex n{cur.col + kDc[k], cur.row + kDr[k]};
        if (!Mine(n.col, n.row) || dist_[Index(n.col, n.row)] != want) continue;
        if (!have_first) first = n;
        have_first = true;
        if (!have_preferred && NextToRoomSpace(n)) {
          preferred = n;
          have_preferred = true;
        }
      }
      if (!have_first) return {};
      const CellIndex chosen = have_preferred ? preferred : first;
      path.push_back(chosen);
      cur = chosen;
    }
    std::reverse(path.begin(), path.end());  // start ... end
    AppendCutWalk(end_mark, path.front(), &path);
    return path;
  }

  // Walks from `from` (a -3 cell next to the end) through the -3 and -2
  // lines to a -2 cell next to `start`, appending the cells.
  void AppendCutWalk(CellIndex from, CellIndex start, std::vector<CellIndex>* chain) {
    auto on_cut = [&](int c, int r) { return Marked(c, r, kMinus2) || Marked(c, r, kMinus3); };
    auto next_to_start = [&](CellIndex c) {
      return Marked(c.col, c.row, kMinus2) && std::abs(c.col - start.col) <= 1 &&
             std::abs(c.row - start.row) <= 1;
    };
    std::vector<CellIndex> seen{from};
    std::vector<int> parent{-1};
    for (std::size_t head = 0; head < seen.size(); ++head) {
      const CellIndex cur = seen[head];
      if (next_to_start(cur)) {
        std::vector<CellIndex> walk;
        for (int i = static_cast<int>(head); i >= 0; i = parent[i]) walk.push_back(seen[i]);
        chain->insert(chain->end(), walk.rbegin(), walk.rend());
        return;
      }
      for (int k = 0; k < 8; ++k) {
        const int c = cur.col + kDc[k], r = cur.row + kDr[k];
        if (!on_cut(c, r)) continue;
        const CellIndex n{c, r};
        if (std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
        seen.push_back(n);
        parent.push_back(static_cast<int>(head));
      }
    }
    chain->clear();  // cannot happen: the -2 line touches every start cell
  }

  void Reset() {
    for (const CellIndex& c : touched_) mark_[Index(c.col, c.row)] = 0;
    for (const CellIndex& c : visited_) dist_[Index(c.col, c.row)] = 0;
    touched_.clear();
    visited_.clear();
  }

  const Labeling& labels_;
  std::int32_t label_;
  const BinaryMask& interior_;
  const BinaryMask& room_space_;
  std::vector<std::int32_t> dist_;
  std::vector<std::int8_t> mark_;
  std::vector<CellIndex> touched_;
  std::vector<CellIndex> visited_;
  std::vector<CellIndex> starts_;
};

// Point in polygon (the paper's proposal for telling the room border from
// other border components): the chain must hold the robot when its cell is
// off the heavy border, and otherwise at least half of the room's free cells.
bool HoldsTheRoom(const std::vector<CellIndex>& chain, const RoomLayout& layout,
                  const BinaryMask& interior) {
  if (chain.size() < 4) return false;
  if (layout.robot && interior.get(layout.robot->col, layout.robot->row)) {
    return PolygonContains(chain, layout.robot->col, layout.robot->row);
  }
  const BinaryMask fill = FillChainPolygon(chain, layout.free.width, layout.free.height);
  std::size_t enclosed = 0;
  for (std::size_t i = 0; i < fill.bits.size(); ++i)
    enclosed += fill.bits[i] && layout.free.bits[i];
  return 2 * enclosed >= layout.free_cells;
}

std::vector<CellIndex> FallbackContour(const BinaryMask& dilated) {
  const Labeling labels = LabelComponents(dilated, Connectivity::kEight);
  if (labels.components.empty()) return {};
  return TraceOuterContour(labels, 1);
}

}  // namespace

HeavyBorder ComputeHeavyBorder(const RoomLayout& layout,
                               const std::vector<StructuringElement>& dilate,
                               const std::vector<StructuringElement>& erode,
                               bool protect_room_interior) {
  HeavyBorder border;
  border.dilated = DilateAll(layout.room, dilate);
  // D and E are computed on the whole crop, which reaches past the grid, so a
  // room that touches the map edge is not eaten into by the erosion; only
  // the band's cells inside the grid can carry the chain.
  border.eroded = ErodeAll(border.dilated, erode);
  if (protect_room_interior) {
    border.eroded = Union(border.eroded, Erode(layout.room, StructuringElement::Cross3()));
  }
  border.band = Intersect(Subtract(border.dilated, border.eroded), layout.in_grid);
  border.dilated = Intersect(border.dilated, layout.in_grid);
  return border;
}

int MidLineEntries(const Labeling& labels, std::int32_t label) {
  const BoundingBox& box = labels.components[label - 1].box;
  const int row = (box.min_row + box.max_row) / 2;
  int entries = 0;
  for (int col = box.min_col; col <= box.max_col; ++col) {
    if (labels.at(col, row) == label && labels.get(col - 1, row) != label) ++entries;
  }
  return entries;
}

bool PolygonContains(const std::vector<CellIndex>& chain, double col, double row) {
  bool inside = false;
  const std::size_t n = chain.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const CellIndex& a = chain[i];
    const CellIndex& b = chain[j];
    if ((a.row > row) == (b.row > row)) continue;
    const double x = a.col + (row - a.row) * (b.col - a.col) / static_cast<double>(b.row - a.row);
    if (col < x) inside = !inside;
  }
  return inside;
}

BorderClosure CloseRoomBorder(const RoomLayout& layout, const HeavyBorder& border,
                              int max_cut_rows) {
  BorderClosure closure;
  auto start = ThreadCpuMs();
  const Labeling labels = LabelComponents(border.band, Connectivity::kEight);
  closure.border_components = static_cast<int>(labels.components.size());
  for (std::size_t k = 0; k < labels.components.size(); ++k) {
    if (MidLineEntries(labels, static_cast<std::int32_t>(k + 1)) >= 2) ++closure.ring_components;
  }
  closure.border_ms = MsSince(start);
  start = ThreadCpuMs();
  // The outer border is the component of D's first cell (D's outer boundary
  // is in the band and 8-connected).
  std::int32_t outer = 0;
  for (std::size_t i = 0; i < border.dilated.bits.size() && !outer; ++i) {
    if (border.dilated.bits[i]) outer = labels.labels[i];
  }
  if (outer > 0) {
    const BinaryMask room_space = Intersect(border.eroded, layout.room);
    LeeCloser closer(labels, outer, border.eroded, room_space);
    const BoundingBox& box = labels.components[outer - 1].box;
    const int mid = (box.min_row + box.max_row) / 2;
    for (int attempt = 0; attempt < 2 * max_cut_rows + 1; ++attempt) {
      const int offset = (attempt + 1) / 2 * (attempt % 2 ? 1 : -1);
      const int row = mid + offset;
      if (row <= box.min_row || row >= box.max_row) continue;
      std::vector<CellIndex> chain = closer.Close(row);
      if (HoldsTheRoom(chain, layout, border.eroded)) {
        closure.chain = std::move(chain);
        closure.closed_by_lee = true;
        break;
      }
    }
  }
  if (!closure.closed_by_lee) closure.chain = FallbackContour(border.dilated);
  closure.lee_ms = MsSince(start);
  return closure;
}

}  // namespace linemap::segment_internal
