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

// The side the encoder writes: `requested` when positive (the caller
// checked it is at least kMinSectionSide), else one section for a map of at
// most `block_side` cells a side (a window of a small map decodes fast
// enough with all of its layers; one stream codes smallest) and sections of
// `block_side` cells beyond, the blocks the layers of large maps are
// extracted in, so that no item crosses a section.
int LayerSectionSide(int width, int height, int requested, int block_side);

// The layers as one LAYR body lists them, so that the hints the cells are
// coded against (drawn in file order, spec 6.2) are the decoder's: items
// grouped by section in row-major order (an item's section is the one
// holding the lower corner of its points' box); with more than one section,
// walls and objects ordered for coding within each section; room ids
// renumbered 1, 2, ... in file order when the grouping left them out of
// increasing order (the objects' room ids follow); object ids their place
// in the list.
void ArrangeLayersInSections(int width, int height, int side, std::vector<WallPolyline>* walls,
                             std::vector<RoomOutline>* rooms,
                             std::vector<FurnitureObject>* furniture);

// The LAYR body of layers already arranged (ArrangeLayersInSections with
// the same side).
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
