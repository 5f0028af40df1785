// Steps 5 and 6 of linemap's extractor: prune covered groups, leave specks
// to the furniture layer.
#include "codec/lines/prune_and_specks.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "codec/lines/edge_cells.h"
#include "codec/lines/segment_index.h"

namespace linemap::lines_internal {
namespace {

// The segments of the live groups, and the group of each.
struct LiveSegments {
  std::vector<LineSegment> segments;
  std::vector<std::uint32_t> group_of;
};
LiveSegments CollectLiveSegments(const std::vector<Group>& groups) {
  LiveSegments live;
  for (std::uint32_t id = 0; id < groups.size(); ++id) {
    if (!groups[id].alive) continue;
    live.segments.push_back(groups[id].segment);
    live.group_of.push_back(id);
  }
  return live;
}

// True when `cells` are whole 8-connected components of the edge map: no
// edge cell outside them touches one of them.
bool HoldsWholeComponents(const EdgeMap& edges, const std::vector<CellXY>& cells) {
  for (const CellXY& c : cells) {
    for (int k = 0; k < 8; ++k) {
      const int col = c.col + kDcol[k], row = c.row + kDrow[k];
      if (col < 0 || row < 0 || col >= edges.width || row >= edges.height) continue;
      if (!edges.is_edge[static_cast<std::size_t>(row) * edges.width + col]) continue;
      const bool inside = std::any_of(cells.begin(), cells.end(), [&](const CellXY& other) {
        return other.col == col && other.row == row;
      });
      if (!inside) return false;
    }
  }
  return true;
}

}  // namespace

void PruneCoveredGroups(std::vector<Group>* groups, int width, int height, double epsilon,
                        double max_added_cost) {
  const LiveSegments live = CollectLiveSegments(*groups);
  const std::vector<LineSegment>& segments = live.segments;
  const std::vector<std::uint32_t>& group_of = live.group_of;
  SegmentIndex index(&segments, width, height);
  std::vector<std::uint8_t> skip(segments.size(), 0);
  // Smallest first, ties in segment order: (cells, segment) pairs sorted.
  std::vector<std::pair<std::size_t, std::uint32_t>> by_size(segments.size());
  for (std::uint32_t s = 0; s < segments.size(); ++s) {
    by_size[s] = {(*groups)[group_of[s]].cells.size(), s};
  }
  std::sort(by_size.begin(), by_size.end());
  std::vector<std::uint32_t> order(segments.size());
  for (std::size_t i = 0; i < by_size.size(); ++i) order[i] = by_size[i].second;
  std::vector<std::uint32_t> targets;
  std::vector<double> distances;
  for (std::uint32_t s : order) {
    Group& group = (*groups)[group_of[s]];
    skip[s] = 1;
    targets.clear();
    distances.clear();
    bool covered = true;
    double added_cost = -group.cost;
    for (const CellXY& c : group.cells) {
      std::uint32_t nearest = 0;
      const double d = index.NearestDistance(c.col, c.row, &skip, &nearest);
      added_cost += d;
      if (d > epsilon || added_cost > max_added_cost) {
        covered = false;
        break;
      }
      targets.push_back(nearest);
      distances.push_back(d);
    }
    if (!covered || added_cost > max_added_cost) {
      skip[s] = 0;
      continue;
    }
    for (std::size_t i = 0; i < targets.size(); ++i) {
      Group& target = (*groups)[group_of[targets[i]]];
      target.cells.push_back(group.cells[i]);
      target.cost += distances[i];
    }
    group.alive = false;
    group.cells.clear();
  }
}

std::vector<std::uint32_t> LeaveSpecksToFurniture(const EdgeMap& edges, std::vector<Group>* groups,
                                                  std::size_t max_cells, double min_gap,
                                                  double max_added, double budget,
                                                  double* total_cost) {
  std::vector<std::uint32_t> handed_over;
  if (max_cells == 0) return handed_over;
  const int width = edges.width, height = edges.height;
  const LiveSegments live = CollectLiveSegments(*groups);
  const std::vector<LineSegment>& segments = live.segments;
  const std::vector<std::uint32_t>& group_of = live.group_of;
  SegmentIndex index(&segments, width, height);
  std::vector<std::uint8_t> gone(segments.size(), 0);
  // What leaving segment s's cells to the furniture layer adds to the
  // summed distance; infinity when another segment is within min_gap.
  auto added_cost = [&](std::uint32_t s) {
    const Group& group = (*groups)[group_of[s]];
    gone[s] = 1;
    double added = -group.cost;
    for (const CellXY& c : group.cells) {
      const double d = index.NearestDistance(c.col, c.row, &gone);
      if (d < min_gap) {
        added = std::numeric_limits<double>::infinity();
        break;
      }
      added += d;
    }
    gone[s] = 0;
    return added;
  };
  std::vector<std::pair<double, std::uint32_t>> specks;  // (added cost, segment)
  for (std::uint32_t s = 0; s < segments.size(); ++s) {
    const Group& group = (*groups)[group_of[s]];
    if (group.cells.size() > max_cells || !HoldsWholeComponents(edges, group.cells)) continue;
    const double added = added_cost(s);
    if (added <= max_added) specks.push_back({added, s});
  }
  std::stable_sort(specks.begin(), specks.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [first_cost, s] : specks) {
    const double added = added_cost(s);  // higher if a nearer speck went
    if (!(added <= max_added) || *total_cost + added > budget) continue;
    *total_cost += added;
    gone[s] = 1;
    Group& group = (*groups)[group_of[s]];
    for (const CellXY& c : group.cells) {
      handed_over.push_back(static_cast<std::uint32_t>(c.row) * static_cast<std::uint32_t>(width) +
                            static_cast<std::uint32_t>(c.col));
    }
    group.alive = false;
    group.cells = {};
  }
  return handed_over;
}

}  // namespace linemap::lines_internal
