// Reading and writing ROS map_server maps: a YAML file plus a PGM or PNG image.
//
// Pixel classification follows nav2_map_server's map_io.cpp (loadMapFromFile)
// exactly, as GraphicsMagick (16-bit quanta) sees the image:
//   shade = mean of the channels / 65535, with channels (R, G, B) and, in
//           trinary mode when the image has alpha, also the alpha value
//           (so a transparent pixel pulls the shade towards black);
//           grey images have R = G = B; 8-bit samples v become v * 257.
//   occ   = negate ? shade : 1 - shade
//   trinary: occ > occupied_thresh -> occupied; else occ < free_thresh -> free;
//            else unknown.
//   scale:   alpha != opaque -> unknown; then as trinary, and the values in
//            between keep the level rint((occ - free) / (occ_t - free) * 100),
//            which a trinary grid stores as unknown.
//   raw:     v = round(shade * 255); 0 -> free, 100 -> occupied, 1..99 -> unknown
//            (a trinary grid cannot hold the levels), above 100 -> unknown.
// Both comparisons are strict, as in nav2's code: a value equal to a
// threshold is unknown.
#ifndef LINEMAP_MAP_IO_H_
#define LINEMAP_MAP_IO_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// How far a saved file is pushed towards the disk before the save returns.
// Either way the file is written under a temporary name and renamed into
// place, so a program that dies mid-save never leaves a partial file.
enum class Durability {
  // fsync the file and its directory: the new file survives a power cut
  // right after the save (the default; about 1-2 ms per save).
  kSynced,
  // Rename only: a power cut within the kernel's writeback delay (seconds)
  // may lose the new file. For batch conversions on a workstation.
  kUnsynced,
};

struct MapLoadOptions {
  // Refuse images with more cells than this before allocating them.
  std::uint64_t max_cells = std::uint64_t{1} << 30;
  // Used when the map is a bare image without YAML, and to override the
  // YAML's values when set.
  std::optional<double> resolution;
  std::optional<Pose2D> origin;
  std::optional<bool> negate;
  std::optional<double> occupied_thresh;
  std::optional<double> free_thresh;
  std::optional<MapMode> mode;
};

// Loads `path`: a map YAML (.yaml / .yml) naming its image (image,
// resolution and origin are required, as map_server requires them), or a
// bare PGM / PNG image that gets the defaults (0.05 m, origin 0, thresholds
// 0.65 / 0.196, trinary, no negate) unless overridden by `options`.
StatusOr<Grid> LoadRosMap(const std::string& path, const MapLoadOptions& options = {});

// The image file LoadRosMap(path) reads: for a map YAML the image it names
// (a relative name taken from the YAML's folder), for anything else `path`
// itself. Fails as LoadRosMap does on a YAML it cannot parse.
StatusOr<std::string> RosMapImagePath(const std::string& path);

// Classifies an image file with the given metadata (no YAML involved).
StatusOr<Grid> LoadMapImage(const std::string& image_path, const MapMetadata& meta,
                            std::uint64_t max_cells = std::uint64_t{1} << 30);

class ImageRowReader;

// A map file opened to be read one row of cells at a time, top row first
// (grid row height() - 1 first, as its image stores it), for callers that
// never hold the whole grid (SaveRosMapAsLmap in codec.h). It opens as
// LoadRosMap(path, options) loads, with the same errors, and classifies each
// row as LoadRosMap does; it holds one row of samples and the image
// decoder's buffers.
class MapRowReader {
 public:
  static StatusOr<std::unique_ptr<MapRowReader>> Open(const std::string& path,
                                                      const MapLoadOptions& options = {});
  // The image file `image_path` with the given metadata (no YAML involved).
  static StatusOr<std::unique_ptr<MapRowReader>> OpenImage(
      const std::string& image_path, const MapMetadata& meta,
      std::uint64_t max_cells = std::uint64_t{1} << 30);
  ~MapRowReader();

  int width() const;
  int height() const;
  const MapMetadata& meta() const { return meta_; }
  // Whether the file opened is the image itself (no map YAML): its errors
  // name it already.
  bool is_bare_image() const { return bare_image_; }
  // Fills `cells` (width() of them) with the next row; at most height()
  // calls. A defect of the image (truncated, a sample above its maximum)
  // fails naming the file.
  Status ReadRow(Cell* cells);

 private:
  MapRowReader(std::unique_ptr<ImageRowReader> image, const MapMetadata& meta);

  std::unique_ptr<ImageRowReader> image_;
  MapMetadata meta_;
  std::vector<std::uint16_t> samples_;
  // A grey pixel's cell depends on its one sample only, and maps are long
  // runs of equal samples: each new sample is classified once.
  std::uint16_t last_sample_ = 0;
  Cell last_cell_ = Cell::kUnknown;
  bool bare_image_ = true;
};

// Writes `yaml_path` and an image next to it (same stem, .pgm), as nav2's
// map_saver does in trinary mode: 0 occupied, 254 free, 205 unknown, and a
// YAML (mode trinary, negate 0) that loads back to the same grid. The YAML
// keeps the grid's resolution and origin in full precision, and its
// thresholds when they read 0 / 254 / 205 back correctly; otherwise it gets
// map_saver's 0.65 / 0.196 (a source with negate 1, or nav2's depot.yaml with
// free_thresh 0.25, under which 205 reads as free). Both files are written
// under temporary names and flushed before either is renamed into place, so
// a failure leaves existing files untouched.
Status SaveRosMap(const std::string& yaml_path, const Grid& grid,
                  Durability durability = Durability::kSynced);

// A ROS map saved piece by piece, for maps too large to hold twice (a
// 20,768 x 13,612 map is 282 MB as a grid and again as a PGM): the files
// SaveRosMap writes, built from rectangles of cells given in any order, with
// memory that does not grow with the map (a 1 MiB conversion buffer). The
// PGM and YAML are written under temporary names and renamed into place by
// Commit(), as SaveRosMap does; a writer destroyed without Commit() leaves
// existing files untouched and no temporary behind.
class RosMapWriter {
 public:
  // Starts writing `yaml_path` (must end in .yaml or .yml) and its image
  // SavedImagePath(yaml_path) for a width x height map (both >= 1) with
  // metadata `meta` (written as SaveRosMap writes a grid's). Refuses, before
  // creating anything, outputs that are directories or read-only files.
  static StatusOr<RosMapWriter> Open(const std::string& yaml_path, int width, int height,
                                     const MapMetadata& meta,
                                     Durability durability = Durability::kSynced);

  RosMapWriter(RosMapWriter&&) noexcept;
  RosMapWriter& operator=(RosMapWriter&&) noexcept;
  ~RosMapWriter();

  // Writes the cells of columns [col0, col0 + cols) and grid rows
  // [row0, row0 + rows) (row 0 at the origin), given as a rows x cols array
  // in grid-row order (row0 first). The rectangle must lie inside the map;
  // every cell is to be written exactly once, in any order.
  Status WriteCells(int col0, int row0, int cols, int rows, const Cell* cells);
  // Renames both files into place once every cell has been written (else
  // fails, leaving the old files).
  Status Commit();

 private:
  struct Impl;
  explicit RosMapWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// What a map saved to files holds, for callers that never had the grid in
// memory (DecodeLmapToRosMap in codec.h).
struct MapFileSummary {
  int width = 0;
  int height = 0;
  MapMetadata meta;   // the grid's, as the YAML describes it
  CellCounts counts;  // cells written in each state
};

// The image SaveRosMap() writes beside `yaml_path`: same directory and stem,
// ending in .pgm ("maps/office.yaml" -> "maps/office.pgm").
std::string SavedImagePath(const std::string& yaml_path);

// The trinary PGM pixel values map_saver writes.
inline constexpr std::uint8_t kPgmOccupied = 0;
inline constexpr std::uint8_t kPgmFree = 254;
inline constexpr std::uint8_t kPgmUnknown = 205;

}  // namespace linemap

#endif  // LINEMAP_MAP_IO_H_
