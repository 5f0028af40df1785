// LAYR (spec/format.md section 5.6, version 2.2): the three vector layers
// in sections. The grid is cut into squares of S cells a side; each item
// (wall, room, object) belongs to one section, and each section's items are
// one range-coded stream of their own with fresh models, listed in a table
// with the box that holds all of their points. A window is drawn from the
// layers of the sections whose box meets its tiles, so on a 282-Mcell map a
// viewer decodes a room without decoding the 180,000 walls of the others.
#ifndef LINEMAP_CODEC_CODEC_LAYER_SECTIONS_H_
#define LINEMAP_CODEC_CODEC_LAYER_SECTIONS_H_

#include <cstdint>
#include <vector>

#include "codec/codec/tile_coder.h"
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

// The layers of a LAYR body: of every section when `region` is null, else of
// the sections whose box meets `region` (a rectangle of cells; what a
// window's tiles need). Errors: corrupt (malformed table or stream, a point
// outside its section's box, room ids not increasing), resource exhausted
// (counts above the limits).
struct DecodedLayers {
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
};
StatusOr<DecodedLayers> DecodeLayerSections(const std::vector<std::uint8_t>& body, int width,
                                            int height, const DecodeLimits& limits,
                                            bool expand_chains, const CellRect* region);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_LAYER_SECTIONS_H_
