// Furniture standing against walls (SegmentationMethod::kRooms, step 5b).
// A cabinet or a shelf against a wall is, in the occupancy grid, one piece
// with the wall: the free space does not enclose it, so the enclosed-
// obstacle test of step 1 cannot see it. It shows as a compact bump of the
// wall into a room: in every grid line across the bump (rows for a bump on
// a top or bottom wall, columns for one on a left or right wall) the run of
// blocked cells is short and has the same room on both ends, while in the
// wall behind it the run is long (it goes on along the wall). The bump is
// the connected set of such short-run cells; it is cut from the wall along
// the wall's face, the first grid line whose run is long. It is furniture
// when it is deep and wide enough to be more than wall noise or a wall's
// end (a stub beside a wide opening is no wider than a wall is thick),
// small enough to be a piece of furniture rather than a room's notch, the
// wall goes on behind it past both of its sides (a piece of wall between
// two door openings does not), and most of its cells that face the room
// are occupied (the scan saw it; a bump of unknown cells is a scan hole).
// Scan noise is allowed for: a free pocket that noise closed off beside a
// cabinet stands for any room at a run's end, a line that a noise cell
// joined to a side wall is bridged from the lines on either side, and the
// room in front of the bump is looked for up to two lines out.
//
// Runs are taken along the grid's axes, so bumps are found on walls that
// run along the grid's rows or columns (maps are usually drawn so); a
// cabinet in a room's corner (its run goes on into the side wall) or against
// a slanted wall is not found.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <utility>

#include "codec/segment/byte_scan.h"
#include "codec/segment/segment_internal.h"

namespace linemap::segment_internal {
namespace {

// Size limits of a bump in cells: depth across the wall's face, width along
// it.
struct BumpRule {
  int min_depth = 0;
  int max_depth = 0;
  int min_width = 0;
  int max_width = 0;
};

BumpRule MakeBumpRule(const SegmentationOptions& options, double res) {
  BumpRule rule;
  rule.min_depth =
      std::max(1, static_cast<int>(std::lround(options.wall_furniture_min_depth_m / res)));
  rule.max_depth = static_cast<int>(std::lround(options.wall_furniture_max_depth_m / res));
  // Wider than a wall is thick: a wall's end beside a wide opening is a bump
  // of the wall's thickness.
  rule.min_width = static_cast<int>(std::floor(options.wall_max_thickness_m / res)) + 1;
  rule.max_width = static_cast<int>(std::lround(options.wall_furniture_max_width_m / res));
  return rule;
}

// The map seen along one axis: runs go along a line (a row or a column),
// `lines` of `length` cells. Horizontal runs (rows) find bumps on top and
// bottom walls; vertical runs (columns) on left and right walls.
struct Axis {
  bool rows = true;
  int lines = 0;   // rows (or columns)
  int length = 0;  // cells per line
};

// A cell of a bump: its index and its column and row (kept, so that the
// flood and Accept divide by the width for no cell).
struct BumpCell {
  std::size_t index;
  int col, row;
};

// The first index >= `col` of `marks[0, end)` that is non-zero, or `end`.
// Most cells in a row's span of marks are unmarked (the span of a column
// axis reaches from the leftmost to the rightmost marked column), so four
// marks are tested at a time (eight measured slower: more stretches end
// inside a block).
int FirstNonZeroMark(const std::int32_t* marks, int col, int end) {
  while (col + 4 <= end) {
    std::uint64_t lo, hi;
    std::memcpy(&lo, marks + col, 8);
    std::memcpy(&hi, marks + col + 2, 8);
    if (lo | hi) break;
    col += 4;
  }
  while (col < end && !marks[col]) ++col;
  return col;
}

// The first index >= `col` of `flags[0, w)` that is zero, or `w` (flags
// hold 0 or 1): the end of a run of blocked cells, eight cells at a time
// (a wall along a row is a long run).
int FirstZeroFlag(const std::uint8_t* flags, int col, int w) {
  constexpr std::uint64_t kAllOnes = 0x0101010101010101ULL;
  while (col + 8 <= w) {
    std::uint64_t chunk;
    std::memcpy(&chunk, flags + col, 8);
    if (chunk != kAllOnes) break;
    col += 8;
  }
  while (col < w && flags[col]) ++col;
  return col;
}

class BumpFinder {
 public:
  BumpFinder(const Grid& grid, const std::vector<std::int32_t>& room_of_cell, const BumpRule& rule,
             WallFurnitureScratch scratch)
      : grid_(grid),
        room_of_(room_of_cell),
        rule_(rule),
        blocked_(std::make_unique_for_overwrite<std::uint8_t[]>(grid.size())),
        claimed_(grid.size(), 0),
        mark_(std::move(scratch.mark_storage)),
        seen_(std::move(scratch.flag_storage)),
        span_lo_(grid.height(), grid.width()),
        span_hi_(grid.height(), 0) {
    mark_.assign(grid.size(), 0);
    seen_.assign(grid.size(), 0);
    // `&`, not `&&`: without the branch the loop over the whole map is
    // vectorised.
    const Cell* cells = grid.cells().data();
    const std::int32_t* rooms = room_of_cell.data();
    std::uint8_t* blocked = blocked_.get();
    for (std::size_t i = 0; i < grid.size(); ++i) {
      blocked[i] = (rooms[i] == 0) & (cells[i] != Cell::kFree);
    }
  }

  void Find(bool rows, std::vector<WallPiece>* out);

 private:
  std::size_t Index(const Axis& axis, int line, int k) const {
    return axis.rows ? grid_.Index(k, line) : grid_.Index(line, k);
  }
  bool Blocked(std::size_t i) const { return blocked_[i] != 0; }
  // The room at the end of a run: its id, -1 for a free cell in no room
  // (any room), 0 for none.
  std::int32_t EndRoom(std::size_t i) const {
    if (room_of_[i] > 0) return room_of_[i];
    return grid_.cells()[i] == Cell::kFree ? -1 : 0;
  }
  void MarkRun(const Axis& axis, int line, int begin, int end);
  void MarkShortRuns(const Axis& axis);
  void MarkColumnRuns(const Axis& axis);
  void ColumnStep(const Axis& axis, std::uint8_t blocked, std::uint8_t blocked_above, int c, int r,
                  std::vector<int>* start);
  bool BridgeLine(int r, int dc, int dr);
  bool Marked(int r) const { return span_lo_[r] < span_hi_[r]; }
  void Extend(int r, int lo, int hi) {
    span_lo_[r] = std::min(span_lo_[r], lo);
    span_hi_[r] = std::max(span_hi_[r], hi);
  }
  // Pushes neighbour n of a bump's cell when it joins the bump. Most
  // neighbours are unmarked, so the mark is read first.
  void Visit(const BumpCell& n, std::int32_t room, std::vector<BumpCell>* stack) {
    if (mark_[n.index] != room || seen_[n.index] || claimed_[n.index]) return;
    seen_[n.index] = 1;
    stack->push_back(n);
  }
  void FloodBump(BumpCell seed, std::int32_t room, std::vector<BumpCell>* cells,
                 std::vector<BumpCell>* stack);
  bool Accept(const Axis& axis, std::int32_t room, const std::vector<BumpCell>& cells,
              WallPiece* piece) const;

  const Grid& grid_;
  const std::vector<std::int32_t>& room_of_;
  BumpRule rule_;
  // Blocked: no room cell and not free (wall, unknown, obstacles too large
  // or too wall-like for furniture). Every byte is set in the constructor,
  // so the array is not zeroed first.
  std::unique_ptr<std::uint8_t[]> blocked_;
  std::vector<std::uint8_t> claimed_;  // cells of bumps already accepted
  std::vector<std::int32_t> mark_;     // room at both ends of the short run through the cell
  std::vector<std::uint8_t> seen_;     // cells of components looked at
  // Per row, the columns [span_lo_, span_hi_) that hold its marks (empty
  // when span_lo_ >= span_hi_): the passes after the marking look only
  // there, not at the rest of a map (walls, unknown, open floor).
  std::vector<int> span_lo_;
  std::vector<int> span_hi_;
};

// A run [begin, end) of blocked cells along the axis in one line: marked
// when it is short and bounded on both ends by cells of one room. A free
// cell in no room (a pocket that noise closed off, e.g. in the gap between
// a cabinet and a side wall) stands for any room.
void BumpFinder::MarkRun(const Axis& axis, int line, int begin, int end) {
  if (begin == 0 || end == axis.length || end - begin > rule_.max_width) return;
  const std::int32_t a = EndRoom(Index(axis, line, begin - 1));
  const std::int32_t b = EndRoom(Index(axis, line, end));
  if (a == 0 || b == 0 || (a > 0 && b > 0 && a != b) || (a < 0 && b < 0)) return;
  const std::int32_t room = std::max(a, b);
  for (int j = begin; j < end; ++j) mark_[Index(axis, line, j)] = room;
  if (axis.rows) {
    Extend(line, begin, end);
  } else {
    for (int r = begin; r < end; ++r) Extend(r, line, line + 1);
  }
}

void BumpFinder::MarkShortRuns(const Axis& axis) {
  const int w = grid_.width(), h = grid_.height();
  // Clear what the other axis marked.
  for (int r = 0; r < h; ++r) {
    if (!Marked(r)) continue;
    const std::size_t row = static_cast<std::size_t>(r) * w;
    std::fill(mark_.begin() + row + span_lo_[r], mark_.begin() + row + span_hi_[r], 0);
    std::fill(seen_.begin() + row + span_lo_[r], seen_.begin() + row + span_hi_[r], 0);
    span_lo_[r] = w;
    span_hi_[r] = 0;
  }
  // Both axes are scanned in raster order (columns keep their open run's
  // start), so the map is read in memory order.
  if (axis.rows) {
    for (int r = 0; r < h; ++r) {
      const std::uint8_t* row = blocked_.get() + static_cast<std::size_t>(r) * w;
      int c = FirstNonZeroByte(row, 0, w);
      while (c < w) {
        const int begin = c;
        c = FirstZeroFlag(row, c, w);
        MarkRun(axis, r, begin, c);
        c = FirstNonZeroByte(row, c, w);
      }
    }
  } else {
    MarkColumnRuns(axis);
  }
  // A noise cell in the gap between a cabinet and a side wall joins one
  // line of the cabinet to the side wall, and that line's run goes on: its
  // cells between two marked lines (of one room) are marked all the same.
  const int dc = axis.rows ? 0 : 1, dr = axis.rows ? 1 : 0;
  for (int r = dr; r + dr < h; ++r) {
    if (!Marked(r - dr) || !Marked(r + dr)) continue;
    BridgeLine(r, dc, dr);
  }
}

// The noise bridges of one row (MarkShortRuns): its unmarked blocked cells
// between two cells of one room's marks, the row's neighbours across the
// runs (`dc`, `dr`: one cell along the other axis). Only the columns
// where both neighbours lie in their rows' spans of marks are looked at;
// the row is read through plain pointers, a tight loop. Returns whether it
// marked any cell.
bool BumpFinder::BridgeLine(int r, int dc, int dr) {
  const int w = grid_.width();
  const std::size_t row = grid_.Index(0, r);
  const std::ptrdiff_t before = -static_cast<std::ptrdiff_t>(dr) * w - dc;
  const std::ptrdiff_t after = static_cast<std::ptrdiff_t>(dr) * w + dc;
  // The cell before c is in row r - dr at column c - dc, the one after in
  // row r + dr at column c + dc. A mark made here in the same row (dr = 0)
  // lies inside the row's span, so the range does not move under the loop.
  const int lo = std::max({dc, span_lo_[r - dr] + dc, span_lo_[r + dr] - dc});
  const int hi = std::min({w - dc, span_hi_[r - dr] + dc, span_hi_[r + dr] - dc});
  std::int32_t* marks = mark_.data() + row;
  const std::uint8_t* blocked = blocked_.get() + row;
  int first = w, last = -1;
  for (int c = lo; c < hi; ++c) {
    // Most cells have no mark before them: skip to the next that has one
    // (the marks are read as they are now, so a mark made here in the same
    // row is seen as by the test below).
    c = FirstNonZeroMark(marks + before, c, hi);
    if (c == hi) break;
    if (marks[c] || !blocked[c]) continue;
    const std::int32_t room = marks[c + before];
    if (room && room == marks[c + after]) {
      marks[c] = room;
      first = std::min(first, c);
      last = c;
    }
  }
  if (last < 0) return false;
  Extend(r, first, last + 1);
  return true;
}

// The column runs of MarkShortRuns: a run of a column starts where its
// cell turns blocked from the row above and ends where it turns free, so
// only the cells that differ from the row above need a look. Rows are
// compared eight cells at a time (blocked_ holds 0 or 1), and most words of
// a map equal the row above.
void BumpFinder::MarkColumnRuns(const Axis& axis) {
  const int w = grid_.width(), h = grid_.height();
  std::vector<int> start(w, -1);
  const std::vector<std::uint8_t> none(static_cast<std::size_t>(w), 0);
  const std::uint8_t* above = none.data();
  for (int r = 0; r <= h; ++r) {
    const std::uint8_t* row =
        r < h ? blocked_.get() + static_cast<std::size_t>(r) * w : none.data();
    int c = 0;
    for (; c + 8 <= w; c += 8) {
      std::uint64_t a, b;
      std::memcpy(&a, above + c, 8);
      std::memcpy(&b, row + c, 8);
      if (a == b) continue;
      for (int k = c; k < c + 8; ++k) ColumnStep(axis, row[k], above[k], k, r, &start);
    }
    for (; c < w; ++c) ColumnStep(axis, row[c], above[c], c, r, &start);
    above = row;
  }
}

// Column c at row r: a run starts where the cell turns blocked and the
// open run ends where it turns free.
void BumpFinder::ColumnStep(const Axis& axis, std::uint8_t blocked, std::uint8_t blocked_above,
                            int c, int r, std::vector<int>* start) {
  if (blocked == blocked_above) return;
  if (blocked) {
    (*start)[c] = r;
  } else {
    MarkRun(axis, c, (*start)[c], r);
    (*start)[c] = -1;
  }
}

// `cells`: one 4-connected set of cells marked with `room`.
bool BumpFinder::Accept(const Axis& axis, std::int32_t room, const std::vector<BumpCell>& cells,
                        WallPiece* piece) const {
  const int w = grid_.width();
  BoundingBox box{w, grid_.height(), -1, -1};
  for (const auto& [i, c, r] : cells) {
    box.min_col = std::min(box.min_col, c);
    box.max_col = std::max(box.max_col, c);
    box.min_row = std::min(box.min_row, r);
    box.max_row = std::max(box.max_row, r);
  }
  // Along the runs (the wall's face) and across them (out of the wall).
  const int lo_line = axis.rows ? box.min_row : box.min_col;
  const int hi_line = axis.rows ? box.max_row : box.max_col;
  const int lo_k = axis.rows ? box.min_col : box.min_row;
  const int hi_k = axis.rows ? box.max_col : box.max_row;
  const int depth = hi_line - lo_line + 1;
  const int width = hi_k - lo_k + 1;
  if (depth < rule_.min_depth || depth > rule_.max_depth || width > rule_.max_width) return false;
  // The typical width (median over the lines): a noise cell beside a wall's
  // end widens one line, not the end.
  std::vector<int> per_line(depth, 0);
  for (const auto& [i, c, r] : cells) {
    ++per_line[(axis.rows ? r : c) - lo_line];
  }
  std::nth_element(per_line.begin(), per_line.begin() + depth / 2, per_line.end());
  if (per_line[depth / 2] < rule_.min_width) return false;
  // The lines just outside the bump: on one side the wall (blocked cells
  // with long runs), on the other the room it stands in.
  if (lo_line == 0 || hi_line == axis.lines - 1) return false;
  // The room is looked for up to two lines out: noise may have joined the
  // bump's front line to a side wall (that line is then left out).
  int wall_lo = 0, wall_hi = 0, room_lo = 0, room_hi = 0;
  for (int k = lo_k; k <= hi_k; ++k) {
    const std::size_t lo = Index(axis, lo_line - 1, k);
    const std::size_t hi = Index(axis, hi_line + 1, k);
    wall_lo += Blocked(lo) && mark_[lo] == 0;
    wall_hi += Blocked(hi) && mark_[hi] == 0;
    room_lo +=
        room_of_[lo] == room || (lo_line >= 2 && room_of_[Index(axis, lo_line - 2, k)] == room);
    room_hi += room_of_[hi] == room ||
               (hi_line + 2 < axis.lines && room_of_[Index(axis, hi_line + 2, k)] == room);
  }
  const bool on_lo_wall = 2 * wall_lo >= width && 2 * room_hi >= width;
  const bool on_hi_wall = 2 * wall_hi >= width && 2 * room_lo >= width;
  if (on_lo_wall == on_hi_wall) return false;
  // The wall goes on behind the bump for min_depth cells past each of its
  // sides (in the line behind the bump or, where noise merged the bump's
  // last line with the wall, the line behind that): a piece of wall between
  // two door openings ends where the openings cross the wall (give or take
  // a noise cell at a jamb), and is no bump.
  const int step = on_lo_wall ? -1 : 1;
  const int base = on_lo_wall ? lo_line - 1 : hi_line + 1;
  for (int j = 1; j <= rule_.min_depth; ++j) {
    for (const int k : {lo_k - j, hi_k + j}) {
      if (k < 0 || k >= axis.length) return false;
      bool wall = false;
      for (const int line : {base, base + step}) {
        if (line < 0 || line >= axis.lines) continue;
        const std::size_t i = Index(axis, line, k);
        wall = wall || (Blocked(i) && mark_[i] == 0);
      }
      if (!wall) return false;
    }
  }
  piece->room = room;
  piece->box = box;
  Labeling local;
  local.width = box.max_col - box.min_col + 1;
  local.height = box.max_row - box.min_row + 1;
  local.labels.assign(static_cast<std::size_t>(local.width) * local.height, 0);
  for (const auto& [i, c, r] : cells) {
    local.labels[static_cast<std::size_t>(r - box.min_row) * local.width + (c - box.min_col)] = 1;
    if (grid_.cells()[i] == Cell::kOccupied) piece->occupied.push_back({c, r});
  }
  // Furniture is seen by the scan: most of the bump's cells that face the
  // room are occupied (a bump of unknown cells is a hole in the scan).
  std::size_t facing = 0, facing_occupied = 0;
  for (const auto& [i, c, r] : cells) {
    bool faces = false;
    for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      faces = faces ||
              (grid_.Contains(c + dc, r + dr) && room_of_[grid_.Index(c + dc, r + dr)] == room);
    }
    facing += faces;
    facing_occupied += faces && grid_.cells()[i] == Cell::kOccupied;
  }
  if (facing_occupied == 0 || 2 * facing_occupied < facing) return false;
  ComponentStats stats;
  stats.cell_count = cells.size();
  stats.box = {0, 0, local.width - 1, local.height - 1};
  // The trace starts at the first cell in raster order.
  const auto first = std::find(local.labels.begin(), local.labels.end(), 1);
  const int offset = static_cast<int>(first - local.labels.begin());
  stats.first_cell = {offset % local.width, offset / local.width};
  local.components.push_back(stats);
  for (const CellIndex& cell : TraceOuterContour(local, 1)) {
    piece->outline.push_back({cell.col + box.min_col, cell.row + box.min_row});
  }
  std::sort(piece->occupied.begin(), piece->occupied.end(),
            [](const CellIndex& a, const CellIndex& b) {
              return a.row != b.row ? a.row < b.row : a.col < b.col;
            });
  return true;
}

// The 4-connected set of cells marked with `room` that holds `seed` (not
// yet seen or claimed) into *cells, marking them seen.
void BumpFinder::FloodBump(BumpCell seed, std::int32_t room, std::vector<BumpCell>* cells,
                           std::vector<BumpCell>* stack) {
  const int w = grid_.width(), h = grid_.height();
  cells->clear();
  stack->assign(1, seed);
  seen_[seed.index] = 1;
  while (!stack->empty()) {
    const auto [i, c, r] = stack->back();
    stack->pop_back();
    cells->push_back({i, c, r});
    if (c + 1 < w) Visit({i + 1, c + 1, r}, room, stack);
    if (c > 0) Visit({i - 1, c - 1, r}, room, stack);
    if (r + 1 < h) Visit({i + w, c, r + 1}, room, stack);
    if (r > 0) Visit({i - w, c, r - 1}, room, stack);
  }
}

void BumpFinder::Find(bool rows, std::vector<WallPiece>* out) {
  const Axis axis{rows, rows ? grid_.height() : grid_.width(),
                  rows ? grid_.width() : grid_.height()};
  MarkShortRuns(axis);
  const int h = grid_.height();
  std::vector<BumpCell> cells, stack;
  for (int r0 = 0; r0 < h; ++r0) {
    const std::size_t row = grid_.Index(0, r0);
    const std::int32_t* marks = mark_.data() + row;
    const int end = span_hi_[r0];
    for (int c0 = FirstNonZeroMark(marks, span_lo_[r0], end); c0 < end;
         c0 = FirstNonZeroMark(marks, c0 + 1, end)) {
      const std::size_t seed = row + c0;
      if (seen_[seed] || claimed_[seed]) continue;
      const std::int32_t room = marks[c0];
      FloodBump({seed, c0, r0}, room, &cells, &stack);
      WallPiece piece;
      if (!Accept(axis, room, cells, &piece)) continue;
      for (const BumpCell& cell : cells) claimed_[cell.index] = 1;
      out->push_back(std::move(piece));
    }
  }
}

}  // namespace

std::vector<WallPiece> FindWallFurniture(const Grid& grid,
                                         const std::vector<std::int32_t>& room_of_cell,
                                         const SegmentationOptions& options,
                                         WallFurnitureScratch scratch) {
  std::vector<WallPiece> pieces;
  if (grid.empty() || options.wall_furniture_max_depth_m <= 0 ||
      options.wall_furniture_max_width_m <= 0) {
    return pieces;
  }
  BumpFinder finder(grid, room_of_cell, MakeBumpRule(options, grid.meta.resolution),
                    std::move(scratch));
  finder.Find(/*rows=*/true, &pieces);
  finder.Find(/*rows=*/false, &pieces);
  return pieces;
}

}  // namespace linemap::segment_internal
