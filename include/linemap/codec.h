// The .lmap codec: encode a trinary occupancy grid into the chunked file
// format of spec/format.md and decode it back, bit-exactly and without
// floating point in the decoding path.
//
// A 2.x file (the default: version 2.2; 2.3 with compact cells or within a
// tolerance) decodes to the input cell for cell and carries
// the map's vector layers: walls as polylines, one border chain per room,
// furniture outlines; the cells are coded in tiles against what the layers
// draw. Within a tolerance (EncodeOptions::tolerance_cells) the file is
// smaller and every guarantee of the tolerance is checked on its decode.
// Version 1.0 files (the former lossy mode) are no longer written but keep
// decoding.
#ifndef LINEMAP_CODEC_H_
#define LINEMAP_CODEC_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/map_io.h"
#include "linemap/segmentation.h"
#include "linemap/status.h"
#include "linemap/vector_layers.h"

namespace linemap {

struct EncodeOptions {
  // Largest distance, in cells (Chebyshev), by which the decoded map may
  // differ from the input; 0 (the default) is an exact file, 1..4 a file of
  // the map simplified within that distance with every guarantee of
  // linemap/tolerance.h checked on what it decodes to (obstacles and
  // free space within T both ways, no leaks, plans agree); other values are
  // refused (invalid argument). Within a tolerance the walls are straight,
  // fitted within T cells, and leave the scan specks and lone pieces
  // shorter than 2T + 1 cells to the cells; room
  // outlines are simplified within T + 1 cells (2 when exact). Where the
  // simplified cells would not be smaller than the exact ones (an all-free
  // map, a clean plan) the exact file is written: never larger, and marked
  // lossless.
  int tolerance_cells = 0;
  // For a grid that is itself a map simplified within this many cells (one
  // decoded from a file saved within a tolerance, which names its T): its
  // exact file is marked so (header lossless flag clear, metadata key
  // `tolerance`), since its cells are not the robot's own map and only the
  // guarantees within that T hold against it. 0 (the default): the grid is
  // the robot's map. At most 2^31 - 1; with tolerance_cells above 0 the
  // guarantees would not add up, and the save is refused (invalid
  // argument): simplify the original map instead.
  int simplified_within_cells = 0;
  // Largest map (cells) saved within a tolerance; 0: no limit. The
  // tolerance checks hold the whole grid and some of its distance maps,
  // about 25 bytes a cell at their peak (a 6000 x 6000 map at T = 1: 0.83
  // GB and about 80 s of CPU), so a larger map is refused with
  // kResourceExhausted before any of them is made. The default, 2^26 cells
  // (about 1.7 GB), keeps a robot's save from exhausting its memory; an
  // exact save of any size needs about 1 byte a cell.
  std::uint64_t max_tolerance_cells = std::uint64_t{1} << 26;
  // Store the vector layers (walls, rooms, furniture) besides the cells
  // (default true); false writes the cells only (with `compact` too, the
  // smallest exact file).
  bool vector_layers = true;
  // Side of the square tiles the cells are coded in (cells, 16..65536; 0,
  // the default, picks it: 1024 up to 4096 cells a side, 512 beyond): each
  // tile decodes on its own, so a window decodes only the tiles it meets,
  // and tiles are coded on several threads. Smaller tiles make windows
  // cheaper and files a little larger.
  int tile_size_cells = 0;
  // Side of the square sections the vector layers are stored in (cells;
  // 0, the default, picks it: one section up to 4096 cells a side, sections
  // of 2048 beyond; else at least 16). A window decodes only the layers of
  // the sections that reach its tiles; each section costs a few bytes and
  // starts its models afresh.
  int layer_section_cells = 0;
  // Threads the encoder may use (the calling one included); 0 = one per
  // core (the default). 2.x files code their tiles in parallel and extract
  // the walls beside the rooms, on maps over 4096 cells a side the layers
  // of two 2048-cell blocks at a time (each holds some 55 MB meanwhile);
  // within a tolerance the short plans' searches are shared out, and each
  // sampled start's two whole-map searches run side by side. The bytes are
  // the same for any number.
  int max_threads = 0;
  // Line extractor for the wall segments.
  LineMethod method = LineMethod::kLinemap;
  // linemap extractor tolerance in cells, at least 0.5 (default 1.0; raised
  // to tolerance_cells within a tolerance); see lines.h.
  double epsilon_cells = 1.0;
  // The wall layer: false (the default) follows the pixel steps of slanted
  // walls and both faces of two-cell walls, so that the walls' DisPL_ave
  // (the RM-Line paper's measure) stays below RM-Line's own on every map of
  // ../shared/maps; true draws one segment per straight wall
  // (StraightWalls()), 1.4 % smaller files over those maps (up to 14 % on
  // clean plans with slanted walls) at up to twice the DisPL_ave. Files
  // saved within a tolerance (tolerance_cells >= 1) always draw straight
  // walls: they are for bandwidth.
  bool straight_walls = false;
  // Code the exact cells for size rather than decode speed: each tile also
  // tries the two codings that code every cell of a changed row with mixed
  // predictions (spec/tile_coding.md models 3 and 12) and keeps the
  // smallest. Over ../shared/maps the files are a median 4.5 % smaller
  // (8.5 % without layers), decode in about 4x the time (up to 9-11x per map;
  // milliseconds for a building) and encode in about 1.3x. Files are
  // version 2.3. (Cells saved within a tolerance are always coded that way.)
  bool compact = false;
  // Robot position in map-frame metres, stored in the metadata
  // (`robot_pose`). The layers are the whole map's whatever the pose: seeded
  // from it, the line extractor fitted the robot's free space and left the
  // others' walls to short covering pieces (nav2 depot: 889 walls at a
  // DisPL_ave of 4.4 cm against 320 at 0.46), and rooms are split at
  // doorways over the whole map anyway.
  std::optional<Pose2D> robot_pose;
  // Called on the calling thread with the share of the work done (0 to 1),
  // at least once, with 1, when the file is complete; an exact file of a
  // map over 4096 cells a side reports after each row of 2048-cell blocks
  // (about 0.7 s apart on the 282-Mcell office map), a save within a
  // tolerance after each round of its checks (an estimate: the rounds a map
  // needs are not known ahead; tsc takes 13 at T = 1). Empty: no reports.
  // `linemap encode` draws it as a progress bar when stderr is a terminal.
  std::function<void(double)> progress;
  // Metadata text, each entry stored only when non-empty (the "meta" chunk
  // is left out when all are): a tiny map's file stays smaller than its PNG,
  // and without `time` encoding the same map twice gives the same bytes.
  std::string creator;
  std::string time;
  std::string frame_id;
};

// Caller-set bounds on what a file may make the decoder allocate or do.
// The defaults read the largest maps nav2 users have reported (20,768 x
// 13,612 cells) with their layers. Layer items cost memory out of
// proportion to their bytes: a layer's range-coded stream reads zeros past
// its end and zeros decode as the smallest item (a one-vertex room or
// object; a wall of two points a column on from the last one's end), so a
// file of some 60 bytes may hold as many items as the limits (and, for
// walls, the grid's width) allow. Within the defaults that is 2^24 walls (about 1.1 GB
// and 9 s to read here) or 2^20 rooms and as many furniture objects (some
// 150 MB each); lower max_segments and max_objects for untrusted files.
struct DecodeLimits {
  std::uint64_t max_file_bytes = std::uint64_t{1} << 31;      // load() only
  std::uint64_t max_cells = std::uint64_t{1} << 30;           // width * height
  std::uint64_t max_chunk_bytes = std::uint64_t{1} << 30;     // one chunk's payload
  std::uint64_t max_inflated_bytes = std::uint64_t{1} << 28;  // one inflated payload
  std::uint64_t max_segments = std::uint64_t{1} << 24;        // wall segments per chunk
  // Cells of one room or furniture chain, and of all the rooms' chains (and
  // apart, of all the objects'): a chain is expanded cell by cell.
  std::uint64_t max_chain_length = std::uint64_t{1} << 26;
  // Rooms per file, and furniture objects per file (apart). A generated
  // 4096 x 4096 office map has 1,175 rooms and 2,354 objects; the
  // 282-Mcell one some 17 times as many.
  std::uint64_t max_objects = std::uint64_t{1} << 20;
  // Threads the decoder may use for the tiles of a 2.0 file (the calling
  // one included); 0 = one per core. The result is the same for any number.
  int max_threads = 0;
  bool operator==(const DecodeLimits&) const = default;
};

// An integer-lattice segment between two cell centres (the stored form).
struct LatticeSegment {
  CellIndex a;
  CellIndex b;
  bool operator==(const LatticeSegment&) const = default;
};

// Everything a file holds, for `info` and `export`.
struct LmapChunkInfo {
  std::string type;
  std::size_t payload_bytes = 0;
  std::string coder;  // "header", "raw", "deflate", "range"
};

struct LmapContents {
  int major = 0;
  int minor = 0;
  bool lossless = false;
  Grid grid;  // the decoded grid, metadata included
  // Version 2.x layers.
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
  // Version 1.0 layers.
  std::vector<LatticeSegment> segments;
  std::vector<std::vector<CellIndex>> room_chains;
  std::vector<std::vector<CellIndex>> blob_outlines;
  std::vector<std::pair<std::string, std::string>> metadata;  // key, value
  std::vector<LmapChunkInfo> chunks;
};

// The metadata key (spec/format.md 4.3) under which the encoder records the
// tolerance a file's map was simplified within: T in cells, in decimal, in
// every file that is not exact (as the CLI's --tolerance and the Python
// module's `tolerance`). The guarantees of linemap/tolerance.h that
// a planner may rely on depend on T, so the file says it itself.
inline constexpr char kToleranceMetadataKey[] = "tolerance";
// The T a file simplified within a tolerance names: of a file of version
// 2.x whose header's lossless flag is clear, the last `tolerance` entry of
// its metadata, a whole number from 1 to 2^31 - 1 in plain decimal. nullopt
// for an exact file (the key means nothing there), a 1.0 file, a file
// written before the key existed or by another encoder, or a value that is
// no such number (metadata is informational: it never rejects a file).
std::optional<int> ToleranceCellsOf(
    int major, bool lossless, const std::vector<std::pair<std::string, std::string>>& metadata);

StatusOr<std::vector<std::uint8_t>> EncodeLmap(const Grid& grid, const EncodeOptions& options = {});
StatusOr<Grid> DecodeLmap(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits = {});
StatusOr<LmapContents> DecodeLmapContents(const std::vector<std::uint8_t>& bytes,
                                          const DecodeLimits& limits = {});

// A window of cells [col0, col1) x [row0, row1) (grid rows, row 0 at the
// origin).
struct CellWindow {
  int col0 = 0;
  int row0 = 0;
  int col1 = 0;
  int row1 = 0;
};

// The window of a width x height map in `meta`'s frame that a box [x0, x1]
// x [y0, y1] of map-frame metres covers: the cells whose centres lie in the
// box, centres on its edges included (within 1e-9 cell, more at large
// coordinates: a few units in their last place, so that an edge typed in
// decimal on a centre keeps it, also at a UTM origin). With a yaw in the origin the
// box's corners are taken into the grid and the window is the cell
// rectangle around them. (CellHoldingPoint, linemap/grid.h, takes a point
// on a cell's edge by the same slack.) Invalid argument when the box is
// inverted or not finite, holds no centre, or its window reaches past the
// map (not clipped: what is served or written is what was asked for, or
// nothing); the message starts with `label` and the box, gives the cells
// the box covers (in full, or to 4 digits past 1e15) and states the map's
// extent.
// `linemap decode --window` and lmap_server's ~window both take this rule.
StatusOr<CellWindow> CellWindowOfMetres(const MapMetadata& meta, int width, int height, double x0,
                                        double y0, double x1, double y1,
                                        const std::string& label = "window");

// The cells of `window` (non-empty, inside the map; else invalid argument)
// as a grid whose origin is the window's lower-left corner in the map frame.
// A 2.0 file decodes only the tiles the window meets, each only up to the
// window's last row, and the layer sections that reach them; a 1.0 file is
// decoded whole and cropped. Every chunk's CRC is checked, but the parts of
// a file a window does not decode are not: a file altered by design (CRCs
// recomputed) past a window may decode there and fail as a whole.
StatusOr<Grid> DecodeLmapRegion(const std::vector<std::uint8_t>& bytes, const CellWindow& window,
                                const DecodeLimits& limits = {});
StatusOr<Grid> LoadLmapRegion(const std::string& path, const CellWindow& window,
                              const DecodeLimits& limits = {});

// Decodes the .lmap file `lmap_path` into the ROS map SaveRosMap writes
// (`yaml_path` and the PGM beside it), atomically, without holding the grid:
// a 2.x file is decoded a band of tile rows at a time from the top of the
// map (at most 24 Mi cells per band, column groups on wider maps) and each
// band goes straight to the PGM. Memory: the file's bytes and the vector
// layers of one band of LAYR sections (their polygons and walls), plus the
// band and one tile per thread, whatever the map's size (a 20,768 x 13,612
// map peaks at 31 MB without layers, 48 MB with them). A 1.0 file is decoded whole
// (its planes have no tiles) and saved. Returns the map's size, metadata
// and cell counts.
StatusOr<MapFileSummary> DecodeLmapToRosMap(const std::string& lmap_path,
                                            const std::string& yaml_path,
                                            const DecodeLimits& limits = {},
                                            Durability durability = Durability::kSynced);

// save(): opens the output (a missing directory, a read-only file or a
// directory there is reported before any work), encodes, then writes
// atomically (temporary file, fsync, rename), so a crash or a full disk never
// leaves a broken file where a good one was.
Status SaveLmap(const std::string& path, const Grid& grid, const EncodeOptions& options = {});

// What SaveRosMapAsLmap saved: the map's size (cells) and the file's bytes.
struct LmapSaveSummary {
  int width = 0;
  int height = 0;
  std::uint64_t bytes = 0;
};

// Saves the ROS map at `map_path` (a map YAML or a bare PGM / PNG image,
// read as LoadRosMap(map_path, load) reads it) as `lmap_path`: the bytes
// EncodeLmap writes for that grid, written atomically (as SaveLmap, with
// `durability`; the output is opened before the map is read). An exact file
// (tolerance 0) of a map over 4096 cells a side (more than one layer
// section) is coded as the image is read, a row of 2048-cell layer blocks at
// a time, so the grid is never held whole: the 20,768 x 13,612-cell office map (282 Mcells) saves
// with a peak of 0.8-0.9 bytes per cell, where loading its grid alone takes 1. Other files are
// coded from the loaded grid. Errors name the map file or its image, or the
// output (checked first).
StatusOr<LmapSaveSummary> SaveRosMapAsLmap(const std::string& map_path,
                                           const std::string& lmap_path,
                                           const EncodeOptions& options = {},
                                           const MapLoadOptions& load = {},
                                           Durability durability = Durability::kSynced);
StatusOr<Grid> LoadLmap(const std::string& path, const DecodeLimits& limits = {});
StatusOr<LmapContents> LoadLmapContents(const std::string& path, const DecodeLimits& limits = {});

// True when `bytes` start with the .lmap signature.
bool LooksLikeLmap(const std::vector<std::uint8_t>& bytes);

// Whether a map argument is read as an .lmap file, as the CLI, the ROS nodes
// and the Python module read theirs: its name ends in .lmap (a renamed image
// is then refused as a bad .lmap rather than read as an image), or the file
// starts with the .lmap signature.
bool IsLmapPath(const std::string& path);

// Quality measures of a decoded grid against the original.
struct GridComparison {
  bool same_geometry = false;  // width, height, resolution, origin
  std::size_t cells = 0;
  std::size_t cells_equal = 0;
  double obstacle_recall_1 = 1.0;     // original occupied with a decoded occupied within 1 cell
  double obstacle_precision_1 = 1.0;  // decoded occupied with an original occupied within 1 cell
  double free_iou = 1.0;
  // Free regions of >= kLeakRegionCells cells (4-connected in the original)
  // that the decoded free space joins: sum over decoded components of
  // (original regions touched - 1).
  std::size_t leaks = 0;
  std::size_t unknown_turned_free = 0;
  double unknown_turned_free_share = 0;  // of the original free cells
};
inline constexpr std::size_t kLeakRegionCells = 50;

// Part of the full library (linemap::linemap), not of the decoder alone.
GridComparison CompareGrids(const Grid& original, const Grid& decoded);

}  // namespace linemap

#endif  // LINEMAP_CODEC_H_
