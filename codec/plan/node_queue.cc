// Stage 4 of the trajectory planner, its core: the node queue (Kosteley et
// al., section 3.2 D, the node-queue algorithm after Figure 9; Table 1 stage
// 10 "trajectory scenario generation").
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
// Where linemap departs from the paper here (exact segments, the cuts of the
// queue) is listed at the top of codec/plan/turn_and_move.cc.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "codec/plan/turn_and_move_internal.h"
#include "linemap/plan.h"

namespace linemap::plan_internal {
namespace {

// How often one cell may start a node at its best depth: bounds the copies
// of the same continuation that equal-length alternatives create.
constexpr int kMaxVisitsPerCell = 4;

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

}  // namespace

std::vector<CellTrajectory> RunNodeQueue(const SafeZone& zone, const LeeWave& wave,
                                         const TrajectoryRegion& region, const MoveTemplate& moves,
                                         CellIndex start, CellIndex goal,
                                         const GenerationOptions& options) {
  return Generator(zone, wave, region, moves, start, goal, options).Run();
}

}  // namespace linemap::plan_internal
