// `linemap export OUT.svg`: the vector layers drawn over the decoded map.
#ifndef LINEMAP_TOOLS_LINEMAP_EXPORT_SVG_H_
#define LINEMAP_TOOLS_LINEMAP_EXPORT_SVG_H_

#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"
#include "tools/linemap/export_layers.h"

namespace linemap::cli {

// An SVG, north (map +y) up: the grid as an embedded PNG in map_saver's grey
// levels, the layers over it in distinct colours (walls red, room borders
// blue, furniture green), a scale bar of a round number of metres and a
// legend with each layer's count.
StatusOr<std::string> LayersToSvg(const std::vector<ExportLayer>& layers, const Grid& grid);

// RFC 4648 base64 (with padding), for the data URI of the embedded PNG.
std::string Base64(const std::vector<std::uint8_t>& bytes);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_EXPORT_SVG_H_
