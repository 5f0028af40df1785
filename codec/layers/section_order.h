// How the encoder lays the vector layers out in LAYR's sections
// (spec/format.md 5.6 and 9): the section side it picks and the order of the
// items. Encoder only: decoding does not need it.
#ifndef LINEMAP_CODEC_LAYERS_SECTION_ORDER_H_
#define LINEMAP_CODEC_LAYERS_SECTION_ORDER_H_

#include <vector>

#include "codec/layers/layer_extraction.h"
#include "linemap/vector_layers.h"

namespace linemap {

// Maps of at most this many cells a side keep their layers in one section
// (a window of such a map decodes fast enough with all of its layers; one
// stream codes smallest).
inline constexpr int kOneSectionCells = 2 * kLayerBlockCells;
// The side of the sections of larger maps (cells): the blocks their layers
// are extracted in, so that no item crosses a section. A window reads the
// layers of the sections its tiles reach, and decoding them was the larger
// part of a 1 % window's time with sections of 4096: on a generated
// 8192 x 8192 office map sections of 2048 decode that window in 5.9 ms
// rather than 9.8 (the whole map: 155 ms), for files 0.8 % larger (models
// start afresh in each section; 1,458,314 against 1,446,317 bytes on the
// 282-Mcell office map).
inline constexpr int kSectionCells = kLayerBlockCells;

// The side the encoder writes: `requested` when positive (the caller
// checked it is at least kMinSectionSide), else one section for a map of at
// most kOneSectionCells a side and sections of kSectionCells beyond.
int LayerSectionSide(int width, int height, int requested);

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

// The two steps of ArrangeLayersInSections. The first groups and orders the
// items of a list by section; its result for a row of sections depends on
// that row's items alone, so a map coded a band of section rows at a time
// (lmap/row_encoder.h) orders each band on its own. The second numbers them:
// room ids 1, 2, ... in list order when `renumber_rooms` or when they do
// not increase, object ids their place in the list.
void OrderItemsInSections(int width, int height, int side, std::vector<WallPolyline>* walls,
                          std::vector<RoomOutline>* rooms, std::vector<FurnitureObject>* furniture);
void NumberItemsInOrder(bool renumber_rooms, std::vector<RoomOutline>* rooms,
                        std::vector<FurnitureObject>* furniture);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_SECTION_ORDER_H_
