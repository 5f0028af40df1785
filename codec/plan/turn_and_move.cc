// Stage 4 of the trajectory planner: turn-and-move generation (Kosteley et
// al., section 3.2 D, the node-queue algorithm after Figure 9; Table 1 stage
// 9 "neighbourhood template" and stage 10 "trajectory scenario generation").
//
// From each node taken from the queue, straight moves are tried along every
// ray of the neighbourhood template (external cycle: the turning angle;
// internal cycle: the distance along the ray). A ray walks through the
// trajectory region M_tb; where it leaves the region (a virgin cell), meets
// a lower Lee index than the node's, or reaches D_max, the last cell is a
// candidate end point. Candidates with exactly five virgin 8-neighbours
// (the region's convex corners) go to Node_Opt; the one with the highest
// Lee index (then the shorter move; exact mirror-image ties are all kept) is
// Node_Max. Cells that the straight move of some ray passes over without
// ending there form the passability matrix: a candidate in it is not
// terminal and is not queued. A ray that meets the goal ends the node's
// expansion (the "end of path" flag).
//
// Additions to the paper:
//  - the exact segment of every move is checked cell by cell against the
//    safe zone, and the passability matrix is marked along that segment
//    (the ray's rounded staircase is not the segment and would hide corners);
//  - the queue is cut by max_extra_nodes, max_expansions, max_trajectories
//    and a per-cell visit limit, so that wide regions cannot explode;
//  - two shortest paths of the region (backtracked bottom-up and top-down)
//    are straightened greedily and always added as alternatives: they are
//    the only trajectories when the queue finds nothing (possible with a
//    large D_min), so a reachable goal always yields a trajectory;
//  - so is the Euclidean-shortest 8-connected path (octile A*): the wave
//    counts steps, and a route with more steps can be shorter in metres;
//  - every trajectory is tightened: waypoints that a direct safe move
//    (<= D_max) can skip are dropped, and inner waypoints slide to shorten
//    their two moves;
//  - ranking: fewest moves, then shortest, with trajectories more than
//    max_length_excess longer than the shortest found ranked last.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <queue>
#include <set>
#include <utility>
#include <vector>

#include "linemap/plan.h"

namespace linemap {
namespace {

// How often one cell may start a node at its best depth: bounds the copies
// of the same continuation that equal-length alternatives create.
constexpr int kMaxVisitsPerCell = 4;
// Largest D_max in cells the template accepts (memory ~ 2 pi D^2 offsets).
constexpr double kMaxTemplateRadius = 500.0;

double Length(int dx, int dy) { return std::sqrt(static_cast<double>(dx) * dx + dy * dy); }

struct Node {
  CellIndex cell;
  int parent = -1;
  int moves = 0;
  double length = 0.0;
};

struct Candidate {
  CellIndex cell;
  std::int32_t wave = -1;
  double length = 0.0;
};

// Per-call scratch arrays; "stamps" let one node's passability matrix and
// unique-node map be cleared in O(1).
struct Scratch {
  std::vector<std::uint32_t> passed;
  std::vector<std::uint32_t> unique;
  std::vector<std::int32_t> best_moves;
  std::vector<std::uint8_t> visits;
  std::uint32_t stamp = 0;
};

class Generator {
 public:
  Generator(const SafeZone& zone, const LeeWave& wave, const TrajectoryRegion& region,
            const MoveTemplate& moves, CellIndex start, CellIndex goal,
            const GenerationOptions& options)
      : zone_(zone),
        wave_(wave),
        region_(region),
        moves_(moves),
        start_(start),
        goal_(goal),
        options_(options) {
    const std::size_t n = zone.safe.size();
    scratch_.passed.assign(n, 0);
    scratch_.unique.assign(n, 0);
    scratch_.best_moves.assign(n, -1);
    scratch_.visits.assign(n, 0);
  }

  std::vector<CellTrajectory> Run();

 private:
  std::size_t At(CellIndex c) const {
    return static_cast<std::size_t>(c.row) * zone_.width + c.col;
  }
  void Expand(int node_index);
  // Walks one ray; returns true when it reached the goal.
  bool WalkRay(const Node& node, const TemplateRay& ray);
  // Ends a ray: the move to its farthest safe cell up to index `last`
  // marks the passability matrix and offers a Node_Opt / Node_Max candidate.
  void Consider(const Node& node, const TemplateRay& ray, int last);
  void MarkPassed(CellIndex from, CellIndex to);
  void Enqueue(int parent, CellIndex cell);
  bool BeyondCut(int moves) const {
    return best_moves_ >= 0 && moves > best_moves_ + options_.max_extra_nodes;
  }

  const SafeZone& zone_;
  const LeeWave& wave_;
  const TrajectoryRegion& region_;
  const MoveTemplate& moves_;
  CellIndex start_, goal_;
  GenerationOptions options_;
  Scratch scratch_;
  std::vector<Node> nodes_;  // the queue: nodes_[head_..] are waiting
  std::vector<int> ends_;    // the "end of path" list
  int best_moves_ = -1;
  // Node_Max and Node_Opt of the node being expanded.
  std::vector<Candidate> node_max_;
  std::vector<Candidate> node_opt_;
};

void Generator::Enqueue(int parent, CellIndex cell) {
  const Node& from = nodes_[parent];
  Node child{cell, parent, from.moves + 1,
             from.length + Length(cell.col - from.cell.col, cell.row - from.cell.row)};
  if (BeyondCut(child.moves)) return;
  if (cell == goal_) {
    if (ends_.size() >= options_.max_trajectories) return;
    if (best_moves_ < 0) best_moves_ = child.moves;
    nodes_.push_back(child);
    ends_.push_back(static_cast<int>(nodes_.size()) - 1);
    return;
  }
  std::int32_t& best = scratch_.best_moves[At(cell)];
  std::uint8_t& visits = scratch_.visits[At(cell)];
  if (best >= 0 && child.moves > best) return;  // reached before with fewer moves
  if (best == child.moves && visits >= kMaxVisitsPerCell) return;
  if (best != child.moves) visits = 0;
  best = child.moves;
  ++visits;
  nodes_.push_back(child);
}

void Generator::MarkPassed(CellIndex from, CellIndex to) {
  // Walks the major axis one cell at a time; the minor coordinate is
  // minor_delta * i / n, kept as twice its value split into quotient and
  // remainder (2 * |minor| * i = q * n + r) so no division is needed.
  const int dx = to.col - from.col, dy = to.row - from.row;
  const bool x_major = std::abs(dx) >= std::abs(dy);
  const int n = x_major ? std::abs(dx) : std::abs(dy);
  const int minor = x_major ? std::abs(dy) : std::abs(dx);
  const int major_step = (x_major ? dx : dy) < 0 ? -1 : 1;
  const int minor_step = (x_major ? dy : dx) < 0 ? -1 : 1;
  long long q = 0, r = 0;
  for (int i = 1; i < n; ++i) {
    r += 2LL * minor;
    while (r >= n) {
      r -= n;
      ++q;
    }
    // Exactly half-way between two cells (2x odd): the line only grazes
    // them, neither is passed through.
    if (r == 0 && q % 2 == 1) continue;
    const int m = static_cast<int>((q + 1) / 2);  // round(q / 2 + r / 2n)
    const int major_offset = major_step * i, minor_offset = minor_step * m;
    const CellIndex cell = x_major ? CellIndex{from.col + major_offset, from.row + minor_offset}
                                   : CellIndex{from.col + minor_offset, from.row + major_offset};
    scratch_.passed[At(cell)] = scratch_.stamp;
  }
}

void Generator::Consider(const Node& node, const TemplateRay& ray, int last) {
  // The farthest cell of the ray (up to `last`) whose exact segment is safe:
  // the ray's rounded cells are in the region, but the segment to a cell
  // may clip a corner outside the safe zone.
  for (; last >= 0; --last) {
    const CellIndex cell{node.cell.col + ray.cells[last].dx, node.cell.row + ray.cells[last].dy};
    if (SegmentIsSafe(zone_, node.cell, cell)) break;
  }
  if (last < 0) return;
  const CellIndex cell{node.cell.col + ray.cells[last].dx, node.cell.row + ray.cells[last].dy};
  // The passability matrix: the cells this move passes over are not terminal.
  MarkPassed(node.cell, cell);
  if (ray.lengths[last] < options_.d_min_cells) return;
  if (scratch_.unique[At(cell)] == scratch_.stamp) return;
  const Candidate candidate{cell, wave_.At(cell.col, cell.row), ray.lengths[last]};
  if (region_.virgin_neighbours[At(cell)] == 5) {
    node_opt_.push_back(candidate);
    scratch_.unique[At(cell)] = scratch_.stamp;
  }
  // Node_Max: the highest Lee index, then the shortest move. Exact ties
  // (mirror-image moves) are all kept, so equal alternatives survive.
  const Candidate& best = node_max_.empty() ? candidate : node_max_.front();
  const bool higher = candidate.wave > best.wave ||
                      (candidate.wave == best.wave && candidate.length < best.length - 1e-9);
  const bool tie = candidate.wave == best.wave && std::abs(candidate.length - best.length) <= 1e-9;
  if (higher) node_max_.clear();
  if (higher || tie) {
    node_max_.push_back(candidate);
    scratch_.unique[At(cell)] = scratch_.stamp;
  }
}

bool Generator::WalkRay(const Node& node, const TemplateRay& ray) {
  const std::int32_t node_wave = wave_.At(node.cell.col, node.cell.row);
  const int count = static_cast<int>(ray.cells.size());
  for (int k = 0; k < count; ++k) {
    const CellIndex cell{node.cell.col + ray.cells[k].dx, node.cell.row + ray.cells[k].dy};
    if (!region_.In(cell.col, cell.row) || wave_.At(cell.col, cell.row) < node_wave) {
      Consider(node, ray, k - 1);  // virgin area or going back: the previous cell ends the move
      return false;
    }
    if (cell == goal_) {
      if (SegmentIsSafe(zone_, node.cell, cell)) return true;
      Consider(node, ray, k - 1);
      return false;
    }
    if (k + 1 == count) {  // D_max reached
      Consider(node, ray, k);
      return false;
    }
  }
  return false;
}

void Generator::Expand(int node_index) {
  const Node node = nodes_[node_index];
  ++scratch_.stamp;
  node_max_.clear();
  node_opt_.clear();
  for (const TemplateRay& ray : moves_.rays) {
    if (WalkRay(node, ray)) {  // end of path: only the goal is queued
      Enqueue(node_index, goal_);
      return;
    }
  }
  std::vector<Candidate> children = node_opt_;
  children.insert(children.end(), node_max_.begin(), node_max_.end());
  std::set<std::size_t> queued;
  for (const Candidate& c : children) {
    if (scratch_.passed[At(c.cell)] == scratch_.stamp) continue;  // not terminal
    if (!queued.insert(At(c.cell)).second) continue;
    Enqueue(node_index, c.cell);
  }
}

std::vector<CellIndex> Waypoints(const std::vector<Node>& nodes, int end) {
  std::vector<CellIndex> cells;
  for (int i = end; i >= 0; i = nodes[i].parent) cells.push_back(nodes[i].cell);
  std::reverse(cells.begin(), cells.end());
  return cells;
}

std::vector<CellTrajectory> Generator::Run() {
  nodes_.push_back(Node{start_, -1, 0, 0.0});
  scratch_.best_moves[At(start_)] = 0;
  std::size_t expansions = 0;
  for (std::size_t head = 0; head < nodes_.size(); ++head) {
    const Node& node = nodes_[head];
    if (node.cell == goal_ || BeyondCut(node.moves + 1)) continue;
    if (++expansions > options_.max_expansions) break;
    Expand(static_cast<int>(head));
  }
  std::vector<CellTrajectory> found;
  std::set<std::vector<std::pair<int, int>>> seen;
  for (int end : ends_) {
    CellTrajectory t;
    t.waypoints = Waypoints(nodes_, end);
    t.length_cells = nodes_[end].length;
    std::vector<std::pair<int, int>> key;
    for (const CellIndex& c : t.waypoints) key.emplace_back(c.col, c.row);
    if (seen.insert(key).second) found.push_back(std::move(t));
  }
  return found;
}

// A cell path (start first, consecutive cells 8-adjacent) straightened
// greedily: from each waypoint, the farthest path cell reachable by a safe
// straight move no longer than D_max, before the first one that is not.
CellTrajectory StraightenPath(const SafeZone& zone, const std::vector<CellIndex>& path,
                              double d_max_cells) {
  CellTrajectory t;
  t.straightened = true;
  t.waypoints.push_back(path.front());
  const auto fits = [&](std::size_t i, std::size_t j) {
    return Length(path[j].col - path[i].col, path[j].row - path[i].row) <= d_max_cells + 1e-9 &&
           SegmentIsSafe(zone, path[i], path[j]);
  };
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && fits(i, j + 1)) ++j;
    t.length_cells += Length(path[j].col - path[i].col, path[j].row - path[i].row);
    t.waypoints.push_back(path[j]);
    i = j;
  }
  return t;
}

// The Euclidean-shortest 8-connected path (octile costs: 1 and sqrt 2; A*
// with the octile heuristic; SafeZone::CanStep steps), or an empty path. The
// Lee wave counts a diagonal step as 1, so the region's paths are shortest
// in steps, and around obstacles a route with more steps can be shorter in
// metres; this one covers that case.
// Paths longer than `max_length` cells (octile) are not searched.
std::vector<CellIndex> OctileShortestPath(const SafeZone& zone, CellIndex start, CellIndex goal,
                                          double max_length) {
  const int w = zone.width;
  const auto at = [w](int c, int r) { return static_cast<std::size_t>(r) * w + c; };
  const auto heuristic = [&](int c, int r) {
    const double dx = std::abs(c - goal.col), dy = std::abs(r - goal.row);
    return std::max(dx, dy) + (std::numbers::sqrt2 - 1) * std::min(dx, dy);
  };
  std::vector<double> cost(zone.safe.size(), std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> parent(zone.safe.size(), -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  cost[at(start.col, start.row)] = 0;
  open.push({heuristic(start.col, start.row), at(start.col, start.row)});
  const std::size_t target = at(goal.col, goal.row);
  while (!open.empty()) {
    const auto [key, i] = open.top();
    open.pop();
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    if (key > cost[i] + heuristic(c, r) + 1e-9) continue;  // stale entry
    if (i == target || key > max_length) break;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !zone.CanStep(c, r, dx, dy)) continue;
        const std::size_t j = at(c + dx, r + dy);
        const double next = cost[i] + ((dx && dy) ? std::numbers::sqrt2 : 1.0);
        if (next < cost[j] - 1e-12) {
          cost[j] = next;
          parent[j] = static_cast<std::int32_t>(i);
          open.push({next + heuristic(c + dx, r + dy), j});
        }
      }
    }
  }
  std::vector<CellIndex> path;
  if (!(cost[target] <= max_length)) return path;
  for (std::int64_t i = static_cast<std::int64_t>(target); i >= 0; i = parent[i]) {
    path.push_back({static_cast<int>(i % w), static_cast<int>(i / w)});
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// One shortest path of the region (goal back to start by index steps; at a
// choice, the first neighbour in row order, bottom-up or top-down as asked,
// so the two calls give mirror-image paths in symmetric rooms), then
// straightened (StraightenPath).
CellTrajectory Straightened(const SafeZone& zone, const LeeWave& wave,
                            const TrajectoryRegion& region, CellIndex goal, bool top_down,
                            double d_max_cells) {
  std::vector<CellIndex> path = {goal};
  const int first_dy = top_down ? 1 : -1;
  while (wave.At(path.back().col, path.back().row) > 0) {
    const CellIndex cell = path.back();
    const std::int32_t lower = wave.At(cell.col, cell.row) - 1;
    CellIndex next = cell;
    for (int k = 0; k < 9 && next == cell; ++k) {
      const int dy = first_dy * (k / 3 - 1), dx = k % 3 - 1;
      if (region.In(cell.col + dx, cell.row + dy) &&
          wave.At(cell.col + dx, cell.row + dy) == lower &&
          zone.CanStep(cell.col, cell.row, dx, dy)) {
        next = {cell.col + dx, cell.row + dy};
      }
    }
    if (next == cell) return {};  // cannot happen for a region built from this wave
    path.push_back(next);
  }
  std::reverse(path.begin(), path.end());
  return StraightenPath(zone, path, d_max_cells);
}

// Drops waypoints that a direct safe move no longer than D_max can skip
// (farthest first). The queue's moves end where rays leave the region, so a
// later move can often start earlier: this only removes turns.
CellTrajectory Shortcut(const SafeZone& zone, const CellTrajectory& in, double d_max_cells) {
  const std::vector<CellIndex>& w = in.waypoints;
  CellTrajectory out;
  out.straightened = in.straightened;
  out.waypoints.push_back(w.front());
  std::size_t i = 0;
  while (i + 1 < w.size()) {
    std::size_t j = w.size() - 1;
    for (; j > i + 1; --j) {
      const double length = Length(w[j].col - w[i].col, w[j].row - w[i].row);
      if (length <= d_max_cells + 1e-9 && SegmentIsSafe(zone, w[i], w[j])) break;
    }
    out.length_cells += Length(w[j].col - w[i].col, w[j].row - w[i].row);
    out.waypoints.push_back(w[j]);
    i = j;
  }
  return out;
}

double PathLength(const std::vector<CellIndex>& w) {
  double length = 0.0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    length += Length(w[i].col - w[i - 1].col, w[i].row - w[i - 1].row);
  }
  return length;
}

// Pulls the trajectory taut: each inner waypoint moves to a neighbouring
// cell (steps of 8, 4, 2, 1 cells) whenever that shortens its two moves and
// both stay safe, no longer than D_max and no shorter than D_min (unless
// already shorter). The queue's waypoints sit on the region's corners, which
// for an 8-connected wave lie off the Euclidean shortest line.
void Slide(const SafeZone& zone, double d_min, double d_max, std::vector<CellIndex>* w) {
  static constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  static constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  const auto fits = [&](CellIndex a, CellIndex b, double old_length) {
    const double length = Length(b.col - a.col, b.row - a.row);
    return length <= d_max + 1e-9 && (length >= d_min || length >= old_length) &&
           SegmentIsSafe(zone, a, b);
  };
  constexpr int kMaxRounds = 64;
  for (int step : {8, 4, 2, 1}) {
    for (int round = 0; round < kMaxRounds; ++round) {
      bool moved = false;
      for (std::size_t i = 1; i + 1 < w->size(); ++i) {
        const CellIndex prev = (*w)[i - 1], next = (*w)[i + 1];
        CellIndex& at = (*w)[i];
        const double before = Length(at.col - prev.col, at.row - prev.row);
        const double after = Length(next.col - at.col, next.row - at.row);
        for (int d = 0; d < 8; ++d) {
          const CellIndex p{at.col + step * kDx[d], at.row + step * kDy[d]};
          if (!zone.IsSafe(p.col, p.row) || p == prev || p == next) continue;
          const double total = Length(p.col - prev.col, p.row - prev.row) +
                               Length(next.col - p.col, next.row - p.row);
          if (total < before + after - 1e-9 && fits(prev, p, before) && fits(p, next, after)) {
            at = p;
            moved = true;
            break;
          }
        }
      }
      if (!moved) break;
    }
  }
}

CellTrajectory Tighten(const SafeZone& zone, const CellTrajectory& in, double d_min, double d_max) {
  CellTrajectory t = Shortcut(zone, in, d_max);
  Slide(zone, d_min, d_max, &t.waypoints);
  t = Shortcut(zone, t, d_max);
  t.length_cells = PathLength(t.waypoints);
  return t;
}

// One ray of the first octant (0..45 degrees): the distinct rounded cells
// at steps of half a cell (each coordinate moves by at most 0.5 per step,
// so consecutive cells are 8-adjacent), up to the radius.
TemplateRay OctantRay(double angle_rad, double radius) {
  TemplateRay ray;
  ray.angle_rad = angle_rad;
  const double cx = std::cos(angle_rad), cy = std::sin(angle_rad);
  const double limit = radius * radius + 1e-6;
  const int steps = static_cast<int>(2.0 * radius) + 1;
  ray.cells.reserve(steps);
  ray.lengths.reserve(steps);
  for (int k = 1; k <= steps; ++k) {
    const double t = 0.5 * k;
    const int dx = static_cast<int>(std::lround(t * cx));
    const int dy = static_cast<int>(std::lround(t * cy));
    if ((dx == 0 && dy == 0) ||
        static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > limit) {
      continue;
    }
    if (!ray.cells.empty() && ray.cells.back() == CellOffset{dx, dy}) continue;
    ray.cells.push_back({dx, dy});
    ray.lengths.push_back(static_cast<float>(Length(dx, dy)));
  }
  return ray;
}

// The octant's symmetry that maps first-octant offsets to octant `octant`
// (counter-clockwise from +x); odd octants mirror the angle within it.
CellOffset ToOctant(CellOffset o, int octant) {
  switch (octant) {
    case 0:
      return {o.dx, o.dy};
    case 1:
      return {o.dy, o.dx};
    case 2:
      return {-o.dy, o.dx};
    case 3:
      return {-o.dx, o.dy};
    case 4:
      return {-o.dx, -o.dy};
    case 5:
      return {-o.dy, -o.dx};
    case 6:
      return {o.dy, -o.dx};
    default:
      return {o.dx, -o.dy};
  }
}

}  // namespace

MoveTemplate MoveTemplate::Build(double d_max_cells) {
  MoveTemplate moves;
  moves.d_max_cells = std::clamp(d_max_cells, 1.0, kMaxTemplateRadius);
  const double radius = moves.d_max_cells;
  // Angular step <= 1 / D_max: neighbouring rays are <= 1 cell apart at D_max.
  const int per_octant =
      std::max(1, static_cast<int>(std::ceil(2.0 * std::numbers::pi * radius / 8.0)));
  const int ray_count = 8 * per_octant;
  const double step = 2.0 * std::numbers::pi / ray_count;
  // Rays of the first octant, 0..45 degrees inclusive; the others are its
  // mirror images, which keeps the template exactly symmetric and is 8 times
  // cheaper than rounding every ray.
  std::vector<TemplateRay> base;
  for (int j = 0; j <= per_octant; ++j) base.push_back(OctantRay(step * j, radius));
  moves.rays.reserve(ray_count);
  for (int i = 0; i < ray_count; ++i) {
    const int octant = i / per_octant, j = i % per_octant;
    const TemplateRay& from = base[octant % 2 == 0 ? j : per_octant - j];
    TemplateRay ray;
    ray.angle_rad = step * i;
    ray.lengths = from.lengths;
    ray.cells.reserve(from.cells.size());
    for (const CellOffset& o : from.cells) ray.cells.push_back(ToOctant(o, octant));
    moves.cell_count += ray.cells.size();
    moves.rays.push_back(std::move(ray));
  }
  return moves;
}

namespace {

// Visits the supercover cells of the segment in order; stops early when
// `visit` returns false. Returns false iff it stopped early.
template <typename Visit>
bool WalkSegment(CellIndex from, CellIndex to, Visit visit) {
  const int nx = std::abs(to.col - from.col), ny = std::abs(to.row - from.row);
  const int sx = to.col > from.col ? 1 : -1, sy = to.row > from.row ? 1 : -1;
  CellIndex at = from;
  if (!visit(at)) return false;
  int ix = 0, iy = 0;
  while (ix < nx || iy < ny) {
    // Which cell border the segment crosses next: compare (ix + 0.5) / nx
    // with (iy + 0.5) / ny without division.
    const long long side =
        static_cast<long long>(1 + 2 * ix) * ny - static_cast<long long>(1 + 2 * iy) * nx;
    if (side == 0) {  // through a corner: both side cells are touched
      if (!visit(CellIndex{at.col + sx, at.row}) || !visit(CellIndex{at.col, at.row + sy})) {
        return false;
      }
      at.col += sx;
      at.row += sy;
      ++ix;
      ++iy;
    } else if (side < 0) {
      at.col += sx;
      ++ix;
    } else {
      at.row += sy;
      ++iy;
    }
    if (!visit(at)) return false;
  }
  return true;
}

}  // namespace

std::vector<CellIndex> SegmentCells(CellIndex from, CellIndex to) {
  std::vector<CellIndex> cells;
  WalkSegment(from, to, [&](CellIndex c) {
    cells.push_back(c);
    return true;
  });
  return cells;
}

bool SegmentIsSafe(const SafeZone& zone, CellIndex from, CellIndex to) {
  return WalkSegment(from, to, [&](CellIndex c) { return zone.IsSafe(c.col, c.row); });
}

std::vector<CellTrajectory> GenerateTrajectories(const SafeZone& zone, const LeeWave& wave,
                                                 const TrajectoryRegion& region,
                                                 const MoveTemplate& moves, CellIndex start,
                                                 CellIndex goal, const GenerationOptions& options) {
  if (wave.goal_index < 0 || !region.In(goal.col, goal.row)) return {};
  if (start == goal) return {CellTrajectory{{start}, 0.0, false}};
  std::vector<CellTrajectory> found =
      Generator(zone, wave, region, moves, start, goal, options).Run();
  // Two more alternatives, always: shortest paths of the region, straightened.
  // It is the only one when the queue found nothing, and often the shortest.
  for (bool top_down : {false, true}) {
    CellTrajectory straightened =
        Straightened(zone, wave, region, goal, top_down, moves.d_max_cells);
    if (!straightened.waypoints.empty()) found.push_back(std::move(straightened));
  }
  std::set<std::vector<std::pair<int, int>>> seen;
  std::vector<CellTrajectory> shortened;
  double shortest = std::numeric_limits<double>::infinity();
  const auto add_tightened = [&](const CellTrajectory& t) {
    CellTrajectory s = Tighten(zone, t, options.d_min_cells, moves.d_max_cells);
    std::vector<std::pair<int, int>> key;
    for (const CellIndex& c : s.waypoints) key.emplace_back(c.col, c.row);
    if (!seen.insert(key).second) return;
    shortest = std::min(shortest, s.length_cells);
    shortened.push_back(std::move(s));
  };
  for (const CellTrajectory& t : found) add_tightened(t);
  // The octile path, when a shorter trajectory may exist (the best is not
  // already the straight line). A safe polyline of length E has a
  // 4-connected cell path of length <= sqrt 2 * E, and octile lengths are at
  // most 4-connected ones, so octile paths longer than sqrt 2 times the
  // shortest so far cannot lead to a shorter trajectory and are not searched.
  constexpr double kOctileExcess = std::numbers::sqrt2;
  const double direct = Length(goal.col - start.col, goal.row - start.row);
  if (shortest > direct * (1.0 + options.max_length_excess)) {
    const std::vector<CellIndex> octile =
        OctileShortestPath(zone, start, goal, kOctileExcess * shortest);
    if (octile.size() >= 2) add_tightened(StraightenPath(zone, octile, moves.d_max_cells));
  }
  found = std::move(shortened);
  const double too_long = shortest * (1.0 + options.max_length_excess) + 1e-9;
  std::stable_sort(
      found.begin(), found.end(), [&](const CellTrajectory& a, const CellTrajectory& b) {
        const bool a_long = a.length_cells > too_long, b_long = b.length_cells > too_long;
        if (a_long != b_long) return b_long;
        if (a.waypoints.size() != b.waypoints.size())
          return a.waypoints.size() < b.waypoints.size();
        return a.length_cells < b.length_cells;
      });
  return found;
}

}  // namespace linemap
