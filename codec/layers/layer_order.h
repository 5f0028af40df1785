// The order in which a file lists its walls and furniture: each item's start
// is coded as an offset from where the previous one ended, so the encoder
// walks the map greedily from item to nearest item (a nearest-neighbour
// tour over the items' ends). On indoor maps the next wall usually starts a
// door's width from where the last one ended: a few bits instead of a
// column and row anywhere in the map. Decoders do not depend on the order.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_ORDER_H_
#define LINEMAP_CODEC_LAYERS_LAYER_ORDER_H_

#include <vector>

#include "linemap/vector_layers.h"

namespace linemap {

// Reorders the walls from the point (0, 0) on: next the wall with the end
// nearest (L1) the previous wall's last point, reversed when that is its
// last point. Ties go to the lower index in the input, so the result is
// deterministic. Then 2-opt moves (a run of walls reversed, each wall
// reversed too) shorten the tour's jumps, in coded bits.
void OrderWallsForCoding(std::vector<WallPolyline>* walls);

// Reorders the objects from (0, 0) on: next the object with the polygon
// vertex nearest the previous polygon's last vertex, its polygon rotated to
// start there (its outline recomputed); ids follow the new order.
void OrderFurnitureForCoding(std::vector<FurnitureObject>* furniture);

// Drops zero-length steps and polylines left with fewer than two points
// (DropRepeatedWallPoints), then orders and orients the rest for coding
// (OrderWallsForCoding): the form EncodeWalls takes.
void CanonicalizeWalls(std::vector<WallPolyline>* walls);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_LAYER_ORDER_H_
