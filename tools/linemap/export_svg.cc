#include "tools/linemap/export_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string_view>

#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

constexpr double kMarginPx = 16;
constexpr double kFooterPx = 44;
constexpr double kMinCanvasWidthPx = 600;

struct LayerStyle {
  const char* colour;
  const char* label;
  double fill_opacity;  // closed layers only
};

LayerStyle StyleOf(const std::string& layer) {
  if (layer == "wall") return {"#e8262a", "walls", 0};
  if (layer == "room_border") return {"#1f6fd1", "room borders", 0.08};
  return {"#18a038", "furniture", 0.2};
}

std::string Px(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", v);
  // -0.004 (or -0.0: the rotation of a map without yaw) prints "-0.00".
  if (std::string_view(text) == "-0.00") return "0.00";
  return text;
}

// Map-frame metres to SVG pixels: x right, y down (north up).
struct Frame {
  double min_x = 0, max_y = 0, scale = 1;  // scale: px per metre
  double X(double x) const { return kMarginPx + (x - min_x) * scale; }
  double Y(double y) const { return kMarginPx + (max_y - y) * scale; }
};

// The round scale-bar length (1, 2 or 5 times a power of ten metres) at
// most `metres`.
double RoundMetres(double metres) {
  const double power = std::pow(10.0, std::floor(std::log10(metres)));
  for (double step : {5.0, 2.0, 1.0}) {
    if (step * power <= metres) return step * power;
  }
  return power;
}

std::string LayerGroup(const ExportLayer& layer, const Frame& f, double cell_px) {
  const LayerStyle style = StyleOf(layer.name);
  // Lines half a cell wide, so that the wall cells under them still show,
  // but at least a pixel on big maps drawn at less than a pixel per cell.
  const double width = std::clamp(cell_px * 0.5, 1.0, 2.5);
  std::string out = "<g id=\"" + layer.name + "\" stroke=\"" + style.colour + "\" stroke-width=\"" +
                    Px(width) + "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" fill=\"" +
                    (layer.closed ? style.colour : "none") + "\" fill-opacity=\"" +
                    Px(style.fill_opacity) + "\">\n";
  for (const LayerFeature& feature : layer.features) {
    std::string points;
    for (const WorldPoint& p : feature.points) {
      points += (points.empty() ? "" : " ") + Px(f.X(p.x)) + "," + Px(f.Y(p.y));
    }
    if (points.empty()) continue;
    // A one-point feature still shows: a round cap draws a dot.
    if (feature.points.size() == 1) points += " " + points;
    out += std::string("<") + (layer.closed ? "polygon" : "polyline") + " points=\"" + points +
           "\"/>\n";
  }
  return out + "</g>\n";
}

// The map's rectangle in pixels, as SVG attributes: its lower-left corner
// is the map origin, and the map's yaw turns it about that corner
// (counter-clockwise in the map frame, so clockwise in SVG's y-down pixels).
std::string MapBox(const Grid& grid, const Frame& f) {
  const double res = grid.meta.resolution;
  const double ox = f.X(grid.meta.origin.x);
  const double oy = f.Y(grid.meta.origin.y);
  const double w = grid.width() * res * f.scale;
  const double h = grid.height() * res * f.scale;
  const std::string rotate = "rotate(" + Px(-grid.meta.origin.yaw * 180 / std::numbers::pi) + " " +
                             Px(ox) + " " + Px(oy) + ")";
  return "x=\"" + Px(ox) + "\" y=\"" + Px(oy - h) + "\" width=\"" + Px(w) + "\" height=\"" + Px(h) +
         "\" transform=\"" + rotate + "\"";
}

std::string MapImage(const Grid& grid, const Frame& f, const std::vector<std::uint8_t>& png) {
  const std::string box = MapBox(grid, f);
  return "<image " + box +
         " preserveAspectRatio=\"none\" image-rendering=\"optimizeSpeed\" "
         "style=\"image-rendering:pixelated\" href=\"data:image/png;base64," +
         Base64(png) + "\"/>\n<rect " + box +
         " fill=\"none\" stroke=\"#999\" stroke-width=\"1\"/>\n";
}

// Text width estimate: about 7.5 px per character of 13 px sans-serif.
double TextWidth(const std::string& text, double u) {
  return 7.5 * u * static_cast<double>(text.size());
}

// The footer's sizes scale with `u` (1 for a map drawn 1000 px long), so
// that its text keeps its size against the map when a viewer fits the
// picture to the screen. The scale bar is about a fifth of the map's width.
struct ScaleBarSize {
  double metres = 0;
  std::string label;
  double width_px = 0;  // bar and label
};

ScaleBarSize ScaleBarFor(const Frame& f, double map_width_px, double u) {
  ScaleBarSize s;
  s.metres = RoundMetres(map_width_px / 5 / f.scale);
  char label[32];
  std::snprintf(label, sizeof(label), "%g m", s.metres);
  s.label = label;
  s.width_px = s.metres * f.scale + 8 * u + TextWidth(s.label, u);
  return s;
}

std::string ScaleBar(const Frame& f, const ScaleBarSize& bar, double top, double u) {
  const double len = bar.metres * f.scale;
  const double x0 = kMarginPx, y = top + 24 * u;
  const std::string& label = bar.label;
  return "<g id=\"scale_bar\" stroke=\"#000\" stroke-width=\"" + Px(2 * u) + "\">\n<path d=\"M" +
         Px(x0) + "," + Px(y - 6 * u) + " V" + Px(y) + " H" + Px(x0 + len) + " V" + Px(y - 6 * u) +
         "\" fill=\"none\"/>\n<text x=\"" + Px(x0 + len + 8 * u) + "\" y=\"" + Px(y + 4 * u) +
         "\" stroke=\"none\" fill=\"#000\">" + label + "</text>\n</g>\n";
}

std::string LegendLabel(const ExportLayer& layer) {
  return std::string(StyleOf(layer.name).label) + " (" + std::to_string(layer.features.size()) +
         ")";
}

// Each entry: a 22 px swatch, its label and a gap; then the north arrow.
double LegendEntryWidth(const ExportLayer& layer, double u) {
  return 48 * u + TextWidth(LegendLabel(layer), u);
}

double LegendWidth(const std::vector<ExportLayer>& layers, double u) {
  double total = 40 * u;
  for (const ExportLayer& layer : layers) total += LegendEntryWidth(layer, u);
  return total;
}

std::string Legend(const std::vector<ExportLayer>& layers, double left, double top, double u) {
  double x = left;
  const double y = top + 24 * u;
  std::string out = "<g id=\"legend\">\n";
  for (std::size_t i = 0; i < layers.size(); ++i) {
    out += "<line x1=\"" + Px(x) + "\" y1=\"" + Px(y) + "\" x2=\"" + Px(x + 22 * u) + "\" y2=\"" +
           Px(y) + "\" stroke=\"" + StyleOf(layers[i].name).colour + "\" stroke-width=\"" +
           Px(3 * u) + "\"/>\n<text x=\"" + Px(x + 28 * u) + "\" y=\"" + Px(y + 4 * u) + "\">" +
           LegendLabel(layers[i]) + "</text>\n";
    x += LegendEntryWidth(layers[i], u);
  }
  // North: the map frame's +y axis points up the page.
  out += "<path d=\"M" + Px(x + 10 * u) + "," + Px(y + 8 * u) + " V" + Px(y - 10 * u) + " M" +
         Px(x + 5 * u) + "," + Px(y - 4 * u) + " L" + Px(x + 10 * u) + "," + Px(y - 10 * u) + " L" +
         Px(x + 15 * u) + "," + Px(y - 4 * u) + "\" stroke=\"#000\" stroke-width=\"" + Px(1.5 * u) +
         "\" fill=\"none\"/>\n<text x=\"" + Px(x + 19 * u) + "\" y=\"" + Px(y + 4 * u) +
         "\">N</text>\n";
  return out + "</g>\n";
}

}  // namespace

std::string Base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    if (n > 1) v |= std::uint32_t{bytes[i + 1]} << 8;
    if (n > 2) v |= bytes[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += n > 1 ? kAlphabet[(v >> 6) & 63] : '=';
    out += n > 2 ? kAlphabet[v & 63] : '=';
  }
  return out;
}

StatusOr<std::string> LayersToSvg(const std::vector<ExportLayer>& layers, const Grid& grid) {
  // The map's extent in metres: the corners of its outer cells (a yaw turns
  // the rectangle).
  const auto [min_x, min_y, max_x, max_y] = MapBoundsMetres(grid.meta, grid.width(), grid.height());
  // About one pixel per cell, between 800 and 2000 pixels along the longer
  // side, so that small maps are not tiny and big ones stay viewable.
  const double long_metres = std::max(max_x - min_x, max_y - min_y);
  const double long_px =
      std::clamp(static_cast<double>(std::max(grid.width(), grid.height())), 800.0, 2000.0);
  Frame f{min_x, max_y, long_px / long_metres};
  const double map_w = (max_x - min_x) * f.scale;
  const double map_h = (max_y - min_y) * f.scale;
  const double u = std::clamp(long_px / 1000, 1.0, 2.0);
  const double canvas_w = std::max(map_w + 2 * kMarginPx, kMinCanvasWidthPx * u);
  // The legend goes right of the scale bar, or below it on narrow maps.
  const ScaleBarSize bar = ScaleBarFor(f, map_w, u);
  const double legend_w = LegendWidth(layers, u);
  const bool two_rows = kMarginPx + bar.width_px + 24 * u > canvas_w - kMarginPx - legend_w;
  const double canvas_h = map_h + 2 * kMarginPx + (kFooterPx + (two_rows ? 28 : 0)) * u;
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> png, TrinaryPng(grid));

  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Px(canvas_w) +
                    "\" height=\"" + Px(canvas_h) + "\" viewBox=\"0 0 " + Px(canvas_w) + " " +
                    Px(canvas_h) + "\" font-family=\"sans-serif\" font-size=\"" + Px(13 * u) +
                    "\">\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  out += MapImage(grid, f, png);
  const double cell_px = grid.meta.resolution * f.scale;
  // The layers are clipped to the map's rectangle: those of a window reach
  // past it (its items are whole), and would run into the margin and footer.
  out += "<clipPath id=\"map_area\"><rect " + MapBox(grid, f) + "/></clipPath>\n";
  out += "<g clip-path=\"url(#map_area)\">\n";
  // Rooms under furniture under walls, so that the thin wall lines stay on top.
  for (const char* name : {"room_border", "furniture", "wall"}) {
    for (const ExportLayer& layer : layers) {
      if (layer.name == name) out += LayerGroup(layer, f, cell_px);
    }
  }
  out += "</g>\n";
  const double footer_top = map_h + 2 * kMarginPx;
  out += ScaleBar(f, bar, footer_top, u);
  out += two_rows ? Legend(layers, kMarginPx, footer_top + 28 * u, u)
                  : Legend(layers, canvas_w - kMarginPx - legend_w, footer_top, u);
  return out + "</svg>\n";
}

}  // namespace linemap::cli
