// nav_msgs/OccupancyGrid <-> Grid (include/linemap/occupancy_grid.h).
#include "linemap/occupancy_grid.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <system_error>

namespace linemap {

double YawFromQuaternion(const Quaternion& q) {
  // The z-axis rotation of the ZYX Euler decomposition (tf2::getYaw); for a
  // planar quaternion (x = y = 0) it is 2 * atan2(z, w), exactly.
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

Quaternion QuaternionFromYaw(double yaw) {
  Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

double ResolutionFromFloat32(float resolution) {
  char text[64];
  const std::to_chars_result written = std::to_chars(text, text + sizeof(text), resolution);
  double value = resolution;
  if (written.ec == std::errc()) std::from_chars(text, written.ptr, value);
  return value;
}

namespace {

// The thresholds in whole percent, as map_saver rounds them
// (std::rint(thresh * 100.0)): compared as doubles, 0.29 * 100 is
// 28.999999999999996 and a cell of 29 would not be free.
struct PercentThresholds {
  double free;
  double occupied;
};
PercentThresholds InPercent(const OccupancyThresholds& thresholds) {
  return {std::rint(thresholds.free * 100.0), std::rint(thresholds.occupied * 100.0)};
}

// map_saver's rule for one int8 value (see the header).
Cell CellFromOccupancy(std::int8_t value, const PercentThresholds& percent) {
  if (value < 0 || value > 100) return Cell::kUnknown;
  if (value <= percent.free) return Cell::kFree;
  if (value >= percent.occupied) return Cell::kOccupied;
  return Cell::kUnknown;
}

std::int8_t OccupancyFromCell(Cell cell) {
  switch (cell) {
    case Cell::kFree:
      return 0;
    case Cell::kOccupied:
      return 100;
    case Cell::kUnknown:
      break;
  }
  return -1;
}

}  // namespace

Status CheckOccupancyThresholds(const OccupancyThresholds& thresholds) {
  const PercentThresholds percent = InPercent(thresholds);
  if (!(thresholds.free >= 0.0 && thresholds.occupied <= 1.0 && percent.free < percent.occupied)) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "thresholds must satisfy 0 <= free < occupied <= 1 in whole percents; free "
                  "%g (%.0f %%), occupied %g (%.0f %%)",
                  thresholds.free, percent.free, thresholds.occupied, percent.occupied);
    return InvalidArgumentError(text);
  }
  return Status::Ok();
}

StatusOr<Grid> GridFromOccupancyGrid(const OccupancyGridMessage& message,
                                     const OccupancyThresholds& thresholds,
                                     std::uint64_t max_cells) {
  const std::uint64_t cells = std::uint64_t{message.width} * message.height;
  if (message.width > 0x7fffffffu || message.height > 0x7fffffffu) {
    return InvalidArgumentError("occupancy grid: width or height above 2^31-1");
  }
  if (cells > max_cells) {
    return OverLimitError(Limit::kCells, "occupancy grid: " + std::to_string(message.width) +
                                             " x " + std::to_string(message.height) +
                                             " cells exceed the limit of " +
                                             std::to_string(max_cells));
  }
  if (message.data.size() != cells) {
    return InvalidArgumentError("occupancy grid: data holds " +
                                std::to_string(message.data.size()) +
                                " values, width x height is " + std::to_string(cells));
  }
  if (!(message.resolution > 0.0f) || !std::isfinite(message.resolution)) {
    return InvalidArgumentError("occupancy grid: resolution must be positive and finite");
  }
  LINEMAP_RETURN_IF_ERROR(CheckOccupancyThresholds(thresholds).WithContext("occupancy grid"));
  const PercentThresholds percent = InPercent(thresholds);
  const Quaternion& q = message.origin_orientation;
  if (!std::isfinite(message.origin_x) || !std::isfinite(message.origin_y) || !std::isfinite(q.x) ||
      !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w)) {
    return InvalidArgumentError("occupancy grid: origin is not finite");
  }
  Grid grid(static_cast<int>(message.width), static_cast<int>(message.height));
  std::vector<Cell>& out = grid.mutable_cells();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = CellFromOccupancy(message.data[i], percent);
  }
  grid.meta.resolution = ResolutionFromFloat32(message.resolution);
  grid.meta.origin = {message.origin_x, message.origin_y, YawFromQuaternion(q)};
  return grid;
}

OccupancyGridMessage OccupancyGridFromGrid(const Grid& grid, const std::string& frame_id) {
  OccupancyGridMessage message;
  message.frame_id = frame_id;
  message.width = static_cast<std::uint32_t>(grid.width());
  message.height = static_cast<std::uint32_t>(grid.height());
  message.resolution = static_cast<float>(grid.meta.resolution);
  message.origin_x = grid.meta.origin.x;
  message.origin_y = grid.meta.origin.y;
  message.origin_orientation = QuaternionFromYaw(grid.meta.origin.yaw);
  message.data.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    message.data[i] = OccupancyFromCell(grid.cells()[i]);
  }
  return message;
}

}  // namespace linemap
