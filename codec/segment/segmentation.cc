// SegmentMap(): the rooms of a grid, each run through the paper's stages
// (Kosteley et al., section 3.2 A-C; stage numbers as in its Table 1), and
// the polygon fill used to measure what a room chain encloses.
#include "linemap/segmentation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "codec/segment/segment_internal.h"

namespace linemap {
namespace {

double MsSince(double start) { return segment_internal::ThreadCpuMs() - start; }

Status ValidateRoomOptions(const SegmentationOptions& options) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(options.min_door_width_m) || !positive(options.max_door_width_m) ||
      options.min_door_width_m > options.max_door_width_m) {
    return InvalidArgumentError(
        "door widths must be positive, min_door_width_m <= max_door_width_m");
  }
  for (const double v :
       {options.door_constriction_m, options.min_room_area_m2, options.max_room_area_m2,
        options.max_furniture_area_m2, options.wall_min_length_m, options.wall_max_thickness_m,
        options.furniture_group_m, options.corridor_min_elongation,
        options.wall_furniture_min_depth_m, options.wall_furniture_max_depth_m,
        options.wall_furniture_max_width_m}) {
    if (!std::isfinite(v) || v < 0) {
      return InvalidArgumentError("segmentation lengths and areas must be finite and >= 0");
    }
  }
  return Status::Ok();
}

Status ValidateOptions(const SegmentationOptions& options) {
  if (options.method == SegmentationMethod::kRooms) return ValidateRoomOptions(options);
  for (const auto* list : {&options.border_dilate, &options.border_erode}) {
    for (const StructuringElement& element : *list) {
      if (!element.Valid()) {
        return InvalidArgumentError("structuring elements need odd width and height");
      }
    }
  }
  if (options.furniture_closing && !options.furniture_closing->Valid()) {
    return InvalidArgumentError("furniture_closing needs odd width and height");
  }
  if (options.max_cut_rows < 0) return InvalidArgumentError("max_cut_rows must be >= 0");
  return Status::Ok();
}

int HalfExtent(const std::vector<StructuringElement>& elements) {
  int sum = 0;
  for (const StructuringElement& element : elements) {
    sum += std::max(element.width, element.height) / 2;
  }
  return sum;
}

// The free component holding the robot (the nearest free cell within 3
// cells when its own cell is not free).
StatusOr<std::int32_t> RobotRoom(const Grid& grid, const Labeling& free_labels, CellPoint robot,
                                 CellIndex* cell) {
  // The cell whose square [c - 0.5, c + 0.5) holds the point, as the edge map
  // and the line extractor round (a point on the map's lower edge is in).
  const double col_f = std::floor(robot.col + 0.5);
  const double row_f = std::floor(robot.row + 0.5);
  const auto where = [&] {
    double x = 0, y = 0;
    grid.CellToWorld(robot.col, robot.row, &x, &y);
    char text[96];
    std::snprintf(text, sizeof(text), "robot position %.3f,%.3f m", x, y);
    return std::string(text);
  };
  if (!(col_f >= 0 && row_f >= 0 && col_f < grid.width() && row_f < grid.height())) {
    return InvalidArgumentError(where() + " is outside the map");
  }
  const int col = static_cast<int>(col_f);
  const int row = static_cast<int>(row_f);
  for (int radius = 0; radius <= 3; ++radius) {
    for (int dr = -radius; dr <= radius; ++dr) {
      for (int dc = -radius; dc <= radius; ++dc) {
        if (std::max(std::abs(dr), std::abs(dc)) != radius) continue;
        const std::int32_t label = free_labels.get(col + dc, row + dr);
        if (label > 0) {
          *cell = {col + dc, row + dr};
          return label;
        }
      }
    }
  }
  return InvalidArgumentError(where() + " is not in free space (nor within 3 cells of it)");
}

std::vector<std::int32_t> RoomLabels(const Labeling& free_labels, std::size_t min_cells) {
  std::vector<std::int32_t> labels;
  for (std::size_t k = 0; k < free_labels.components.size(); ++k) {
    if (free_labels.components[k].cell_count >= min_cells) {
      labels.push_back(static_cast<std::int32_t>(k + 1));
    }
  }
  if (labels.empty() && !free_labels.components.empty()) {
    labels.push_back(1);
    for (std::size_t k = 1; k < free_labels.components.size(); ++k) {
      if (free_labels.components[k].cell_count > free_labels.components[labels[0] - 1].cell_count) {
        labels[0] = static_cast<std::int32_t>(k + 1);
      }
    }
  }
  std::stable_sort(labels.begin(), labels.end(), [&](std::int32_t a, std::int32_t b) {
    return free_labels.components[a - 1].cell_count > free_labels.components[b - 1].cell_count;
  });
  return labels;
}

std::size_t CountEnclosedFree(const segment_internal::RoomLayout& layout,
                              const std::vector<CellIndex>& local_chain) {
  const BinaryMask fill = FillChainPolygon(local_chain, layout.free.width, layout.free.height);
  std::size_t count = 0;
  for (std::size_t i = 0; i < fill.bits.size(); ++i) count += fill.bits[i] && layout.free.bits[i];
  return count;
}

}  // namespace

namespace segment_internal {
double ThreadCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec * 1e3 + now.tv_nsec * 1e-6;
}
}  // namespace segment_internal

BinaryMask FillChainPolygon(const std::vector<CellIndex>& chain, int width, int height) {
  BinaryMask fill(width, height);
  const std::size_t n = chain.size();
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(std::max(height, 0)));
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const CellIndex& a = chain[i];
    const CellIndex& b = chain[j];
    if (a.row == b.row) continue;
    // Rows y with (a.row > y) != (b.row > y): y in [min, max).
    const int lo = std::max(std::min(a.row, b.row), 0);
    const int hi = std::min(std::max(a.row, b.row), height);
    for (int y = lo; y < hi; ++y) {
      crossings[y].push_back(a.col +
                             (y - a.row) * (b.col - a.col) / static_cast<double>(b.row - a.row));
    }
  }
  for (int y = 0; y < height; ++y) {
    std::vector<double>& xs = crossings[y];
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int c0 = std::max(static_cast<int>(std::ceil(xs[k])), 0);
      const int c1 = std::min(static_cast<int>(std::floor(xs[k + 1])), width - 1);
      for (int c = c0; c <= c1; ++c) fill.set(c, y, true);
    }
  }
  for (const CellIndex& cell : chain) {
    if (fill.Contains(cell.col, cell.row)) fill.set(cell.col, cell.row, true);
  }
  return fill;
}

StatusOr<Segmentation> SegmentMap(const Grid& grid, const SegmentationOptions& options) {
  LINEMAP_RETURN_IF_ERROR(ValidateOptions(options));
  Segmentation result;
  if (options.method == SegmentationMethod::kRooms) {
    if (!(grid.meta.resolution > 0) || !std::isfinite(grid.meta.resolution)) {
      return InvalidArgumentError("map resolution must be positive to segment rooms");
    }
    const double start = segment_internal::ThreadCpuMs();
    segment_internal::BuildRooms(
        grid, options, segment_internal::FloodRooms(grid, options, &result.timings), &result);
    result.timings.total_ms = MsSince(start);
    return result;
  }
  const auto total_start = segment_internal::ThreadCpuMs();
  auto start = segment_internal::ThreadCpuMs();
  BinaryMask free(grid.width(), grid.height());
  for (std::size_t i = 0; i < grid.size(); ++i) free.bits[i] = grid.cells()[i] == Cell::kFree;
  const Labeling free_labels = LabelComponents(free, Connectivity::kFour);
  std::vector<std::int32_t> room_labels;
  std::optional<CellIndex> robot_cell;
  if (options.robot && !grid.empty()) {
    CellIndex cell;
    LINEMAP_ASSIGN_OR_RETURN(const std::int32_t label,
                             RobotRoom(grid, free_labels, *options.robot, &cell));
    room_labels.push_back(label);
    robot_cell = cell;
  } else {
    room_labels = RoomLabels(free_labels, options.min_room_cells);
  }
  result.timings.room_layout_ms += MsSince(start);

  const int margin = HalfExtent(options.border_dilate) + 2;
  std::vector<std::uint8_t> claimed(grid.size(), 0);
  for (const std::int32_t label : room_labels) {
    start = segment_internal::ThreadCpuMs();
    const segment_internal::RoomLayout layout =
        segment_internal::BuildRoomLayout(grid, free_labels, label, margin, robot_cell);
    result.timings.room_layout_ms += MsSince(start);

    start = segment_internal::ThreadCpuMs();
    const segment_internal::HeavyBorder border = segment_internal::ComputeHeavyBorder(
        layout, options.border_dilate, options.border_erode, options.protect_room_interior);
    result.timings.morphology_ms += MsSince(start);

    start = segment_internal::ThreadCpuMs();
    std::vector<FurnitureBlob> blobs =
        segment_internal::ExtractBlobs(grid, layout, options.furniture_closing, &claimed);
    result.timings.furniture_ms += MsSince(start);
    for (FurnitureBlob& blob : blobs) result.blobs.push_back(std::move(blob));

    segment_internal::BorderClosure closure =
        segment_internal::CloseRoomBorder(layout, border, options.max_cut_rows);
    result.timings.border_ms += closure.border_ms;
    result.timings.lee_ms += closure.lee_ms;

    RoomBorder room;
    room.free_cells = layout.free_cells;
    room.enclosed_free_cells = CountEnclosedFree(layout, closure.chain);
    room.closed_by_lee = closure.closed_by_lee;
    room.border_components = closure.border_components;
    room.ring_components = closure.ring_components;
    room.chain.reserve(closure.chain.size());
    for (const CellIndex& cell : closure.chain) {
      room.chain.push_back({cell.col + layout.col0, cell.row + layout.row0});
    }
    result.rooms.push_back(std::move(room));
  }
  result.timings.total_ms = MsSince(total_start);
  return result;
}

}  // namespace linemap
