// LAYR (spec/format.md section 5.6, version 2.2): the three vector layers
// in sections. The grid is cut into squares of S cells a side; each item
// (wall, room, object) belongs to one section, and each section's items are
// one range-coded stream of their own with fresh models, listed in a table
// with the box that holds all of their points. A window is drawn from the
// layers of the sections whose box meets its tiles, so on a 282-Mcell map a
// viewer decodes a room without decoding the 180,000 walls of the others.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_SECTIONS_H_
#define LINEMAP_CODEC_LAYERS_LAYER_SECTIONS_H_

#include <cstdint>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "linemap/codec.h"
#include "linemap/status.h"
#include "linemap/vector_layers.h"

namespace linemap {

// The least and greatest section side a file may give (cells).
inline constexpr std::int64_t kMinSectionSide = 16;
inline constexpr std::int64_t kMaxSectionSide = (std::int64_t{1} << 31) - 1;

// The section (row-major number) an item with these points belongs to: the
// one holding the lower corner of their box (spec 5.6 leaves the choice to
// the encoder; EncodeLayerSections and ArrangeLayersInSections agree on this
// one). `points` must not be empty.
std::int64_t SectionOfPoints(const std::vector<CellIndex>& points, int width, int side);

// The LAYR body of layers already grouped by section, in section order
// (ArrangeLayersInSections, section_order.h, with the same side).
std::vector<std::uint8_t> EncodeLayerSections(const std::vector<WallPolyline>& walls,
                                              const std::vector<RoomOutline>& rooms,
                                              const std::vector<FurnitureObject>& furniture,
                                              int width, int height, int side);

// A LAYR body's table, read and checked once against the grid, the limits
// and the bytes (spec 5.6): the sections that hold items, in order.
struct LayerSection {
  std::uint64_t index = 0;             // in the section grid, row-major
  int c0 = 0, r0 = 0, c1 = 0, r1 = 0;  // the box of its points, inclusive
  std::uint32_t walls = 0, rooms = 0, objects = 0;
  std::uint64_t first_wall = 0;     // walls in the sections before it
  std::uint64_t first_object = 0;   // objects in the sections before it
  std::uint64_t stream_offset = 0;  // in the body
  std::uint64_t stream_bytes = 0;
};
struct LayerSectionTable {
  std::int64_t side = 0;
  std::uint64_t walls = 0;  // over all sections
  std::vector<LayerSection> sections;
};
// Corrupt: a side outside 16..2^31-1, a table or stream past the body's end,
// streams that do not fill it, a box outside the grid, a count above
// 2^32 - 1 or more than 2^32 rooms or objects (ids are 32-bit); resource
// exhausted: counts above the limits (summed over the sections).
StatusOr<LayerSectionTable> ReadLayerSectionTable(const std::vector<std::uint8_t>& body, int width,
                                                  int height, const DecodeLimits& limits);

// The layers of the sections of `table` (read from `body`) whose box meets
// `region` (a rectangle of cells; what a window's tiles need), or of every
// section when `region` is null. Points, vertices and chain cells count
// against the limits, and room ids must increase, over the sections read
// together. Errors: corrupt (a malformed stream, a point outside its
// section's box, room ids not increasing), resource exhausted.
struct DecodedLayers {
  std::vector<WallPolyline> walls;
  // Of each of `walls`, its index among the walls of all the sections in
  // file order (the wall's number in a whole read): a region's walls are
  // not numbered from 0.
  std::vector<std::uint64_t> wall_indices;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
};
StatusOr<DecodedLayers> DecodeLayerSections(const std::vector<std::uint8_t>& body,
                                            const LayerSectionTable& table, int width, int height,
                                            const DecodeLimits& limits, bool expand_chains,
                                            const CellRect* region);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_LAYER_SECTIONS_H_
