// The .lmap encoder (spec/format.md section "Encoding (informative)").
//
// Lossy layers, in decoding order:
//   FREE  the free cells, with free specks under kMinFreeRegionCells cells
//         dropped and enclosed non-free holes under kMaxHoleCells cells
//         filled; cells that later layers make occupied are "don't care".
//   SEGS  wall segments on the integer lattice (the extractor's lines).
//   OCCP  occupied cells the segments miss, minus isolated occupied specks
//         (at most kSpeckBudget of the occupied cells).
// Lossless mode adds RESD, the exact grid coded against the lossy one.
#include <algorithm>
#include <cstdio>
#include <string>

#include "codec/codec/chunk_coding.h"
#include "codec/codec/interim_lines.h"
#include "codec/codec/plane_coder.h"
#include "codec/codec/raster.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

// Free 4-connected regions smaller than this are dropped (cells).
constexpr std::size_t kMinFreeRegionCells = 3;
// Enclosed holes in the free space up to this size are filled (cells).
constexpr std::size_t kMaxHoleCells = 8;
// Largest share of occupied cells that may be dropped as isolated specks.
constexpr double kSpeckBudget = 0.01;
// Shortest axis run the interim extractor keeps (cells).
constexpr int kMinRunCells = 8;

// 4-connected components of cells where `member` is true; calls
// visit(cells, touches_border) for each.
template <typename Member, typename Visit>
void ForEachComponent(int width, int height, Member&& member, Visit&& visit) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(width) * height, 0);
  std::vector<std::size_t> stack;
  std::vector<std::size_t> cells;
  for (std::size_t start = 0; start < seen.size(); ++start) {
    if (seen[start] || !member(start)) continue;
    cells.clear();
    bool border = false;
    seen[start] = 1;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      cells.push_back(i);
      const int c = static_cast<int>(i % width);
      const int r = static_cast<int>(i / width);
      if (c == 0 || r == 0 || c == width - 1 || r == height - 1) border = true;
      auto push = [&](std::size_t j) {
        if (!seen[j] && member(j)) {
          seen[j] = 1;
          stack.push_back(j);
        }
      };
      if (c > 0) push(i - 1);
      if (c + 1 < width) push(i + 1);
      if (r > 0) push(i - width);
      if (r + 1 < height) push(i + width);
    }
    visit(cells, border);
  }
}

// Occupied cells to reproduce: all but isolated specks, within the budget.
std::vector<std::uint8_t> OccupiedTarget(const Grid& grid) {
  const int w = grid.width();
  const int h = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  std::vector<std::uint8_t> target(cells.size(), 0);
  std::size_t occupied = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    target[i] = cells[i] == Cell::kOccupied;
    occupied += target[i];
  }
  std::size_t budget = static_cast<std::size_t>(kSpeckBudget * static_cast<double>(occupied));
  for (int r = 0; r < h && budget > 0; ++r) {
    for (int c = 0; c < w && budget > 0; ++c) {
      if (!target[grid.Index(c, r)]) continue;
      bool alone = true;
      for (int dr = -1; dr <= 1 && alone; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if ((dr || dc) && grid.Contains(c + dc, r + dr) &&
              cells[grid.Index(c + dc, r + dr)] == Cell::kOccupied) {
            alone = false;
            break;
          }
        }
      }
      if (alone) {
        target[grid.Index(c, r)] = 0;
        --budget;
      }
    }
  }
  return target;
}

std::vector<FreeTarget> FreeTargetOf(const Grid& grid, const std::vector<std::uint8_t>& occupied) {
  const int w = grid.width();
  const int h = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  std::vector<FreeTarget> target(cells.size(), FreeTarget::kNotFree);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (occupied[i]) {
      target[i] = FreeTarget::kDontCare;
    } else if (cells[i] == Cell::kFree) {
      target[i] = FreeTarget::kFree;
    }
  }
  ForEachComponent(
      w, h, [&](std::size_t i) { return cells[i] == Cell::kFree; },
      [&](const std::vector<std::size_t>& comp, bool) {
        if (comp.size() >= kMinFreeRegionCells) return;
        for (std::size_t i : comp) target[i] = FreeTarget::kNotFree;
      });
  ForEachComponent(
      w, h, [&](std::size_t i) { return target[i] == FreeTarget::kNotFree; },
      [&](const std::vector<std::size_t>& comp, bool border) {
        if (border || comp.size() > kMaxHoleCells) return;
        for (std::size_t i : comp) target[i] = FreeTarget::kFree;
      });
  return target;
}

std::vector<std::pair<std::string, std::string>> MetadataOf(const EncodeOptions& options) {
  std::vector<std::pair<std::string, std::string>> entries;
  entries.emplace_back("creator", options.creator);
  if (!options.time.empty()) entries.emplace_back("time", options.time);
  if (!options.frame_id.empty()) entries.emplace_back("frame_id", options.frame_id);
  if (options.robot_pose) {
    char text[96];
    std::snprintf(text, sizeof(text), "%.17g %.17g %.17g", options.robot_pose->x,
                  options.robot_pose->y, options.robot_pose->yaw);
    entries.emplace_back("robot_pose", text);
  }
  return entries;
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> EncodeLmap(const Grid& grid, const EncodeOptions& options) {
  const int w = grid.width();
  const int h = grid.height();
  if (w < 0 || h < 0 || grid.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    return InvalidArgumentError("grid dimensions do not match its cells");
  }
  if (!(grid.meta.resolution > 0) || grid.meta.resolution > 1e300) {
    return InvalidArgumentError("grid resolution must be a positive number");
  }
  ContainerWriter writer;
  HeaderFields header{w, h, grid.meta, options.lossless};
  writer.AddChunk(kHeaderChunk, WriteHeader(header));
  writer.AddChunk(kMetadataChunk, WrapPayload(WriteMetadata(MetadataOf(options)), true));

  std::vector<Cell> canvas(grid.size(), Cell::kUnknown);
  const std::vector<std::uint8_t> occupied = OccupiedTarget(grid);

  std::vector<std::uint8_t> decided;
  writer.AddChunk(
      kFreeChunk,
      WrapPayload(EncodeFreePlane(FreeTargetOf(grid, occupied), canvas, w, h, &decided), false));
  for (std::size_t i = 0; i < canvas.size(); ++i) {
    if (decided[i]) canvas[i] = Cell::kFree;
  }

  std::vector<LatticeSegment> segments = InterimAxisRunSegments(occupied, w, h, kMinRunCells);
  CanonicalizeSegments(&segments);
  if (!segments.empty()) {
    writer.AddChunk(kSegmentChunk, WrapPayload(WriteSegments(segments), true));
    for (const LatticeSegment& s : segments) {
      RasterizeSegment(s.a, s.b, [&](int c, int r) { canvas[grid.Index(c, r)] = Cell::kOccupied; });
    }
  }

  writer.AddChunk(kOccupiedChunk, WrapPayload(EncodeOccupiedPlane(occupied, canvas, w, h), false));
  for (std::size_t i = 0; i < canvas.size(); ++i) {
    if (occupied[i]) canvas[i] = Cell::kOccupied;
  }
  if (options.lossless) {
    writer.AddChunk(kResidualChunk,
                    WrapPayload(EncodeResidualPlane(grid.cells(), canvas, w, h), false));
  }
  return writer.Finish();
}

Status SaveLmap(const std::string& path, const Grid& grid, const EncodeOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, EncodeLmap(grid, options));
  return WriteFileAtomic(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace linemap
