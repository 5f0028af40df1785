#include "tools/bench/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "format/file_io.h"
#include "tools/bench/measure.h"
#include "tools/bench/png_codec.h"

namespace linemap::bench {
namespace {

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// SVG y of a point at grid row `row` (cell units, row 0 at the bottom).
double SvgY(const Grid& grid, double row) { return grid.height() - 0.5 - row; }
double SvgX(double col) { return col + 0.5; }

std::string ChainPoints(const Grid& grid, const std::vector<CellIndex>& chain) {
  std::string points;
  for (const CellIndex& cell : chain) {
    points += Num(SvgX(cell.col)) + "," + Num(SvgY(grid, cell.row)) + " ";
  }
  return points;
}

struct PlotMethod {
  const char* label;
  const char* size_figure;
  const char* colour;
};

const std::vector<PlotMethod>& PlotMethods() {
  static const std::vector<PlotMethod> methods = {
      {"PNG 2-bit", key::kPng2Bytes, "#7f7f7f"},
      {"zstd -19", key::kZstdBytes, "#1f77b4"},
      {"xz -9e", key::kXzBytes, "#9467bd"},
      {"JBIG1", key::kJbigBytes, "#8c564b"},
      {"WebP", key::kWebpBytes, "#e377c2"},
      {"JPEG XL", key::kJxlBytes, "#17becf"},
      {".lmap 2.0 (default)", key::kLmapBytes, "#2ca02c"},
      {".lmap 2.0 --raster-only", key::kLmapRasterBytes, "#bcbd22"},
      {".lmap 2.3 --compact", key::kLmapCompactBytes, "#98df8a"},
      {".lmap 2.3 --compact --raster-only", key::kLmapRasterCompactBytes, "#dbdb8d"},
  };
  return methods;
}

}  // namespace

std::string Base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string MapOverlaySvg(const Grid& grid, const std::vector<LineSegment>& segments,
                          const Segmentation* segmentation, const std::string& title) {
  const double w = grid.width(), h = grid.height();
  const double scale =
      std::min(1.0, 1200.0 / std::max(w, h)) * std::max(1.0, 600.0 / std::max(w, h));
  const double stroke = std::max(0.6, std::max(w, h) / 900.0);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + Num(w) + " " +
                    Num(h) + "\" width=\"" + Num(w * scale) + "\" height=\"" + Num(h * scale) +
                    "\">\n<title>" + Escape(title) + "</title>\n";
  StatusOr<std::string> png = EncodeTrinaryPng(grid, PngLayout::kPalette2, 9);
  if (png.ok()) {
    svg += "<image x=\"0\" y=\"0\" width=\"" + Num(w) + "\" height=\"" + Num(h) +
           "\" opacity=\"0.45\" style=\"image-rendering:pixelated\" "
           "href=\"data:image/png;base64," +
           Base64(*png) + "\"/>\n";
  }
  if (segmentation) {
    svg += "<g fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"" + Num(stroke) +
           "\" stroke-linejoin=\"round\">\n";
    for (const RoomBorder& room : segmentation->rooms) {
      svg += "<polygon points=\"" + ChainPoints(grid, room.chain) + "\"/>\n";
    }
    svg += "</g>\n<g fill=\"#2ca02c\" fill-opacity=\"0.3\" stroke=\"#2ca02c\" stroke-width=\"" +
           Num(stroke * 0.7) + "\">\n";
    for (const FurnitureBlob& blob : segmentation->blobs) {
      svg += "<polygon points=\"" + ChainPoints(grid, blob.outline) + "\"/>\n";
    }
    svg += "</g>\n";
  }
  svg += "<g stroke=\"#d62728\" stroke-width=\"" + Num(stroke) + "\" stroke-linecap=\"round\">\n";
  for (const LineSegment& s : segments) {
    svg += "<line x1=\"" + Num(SvgX(s.x1)) + "\" y1=\"" + Num(SvgY(grid, s.y1)) + "\" x2=\"" +
           Num(SvgX(s.x2)) + "\" y2=\"" + Num(SvgY(grid, s.y2)) + "\"/>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

Status WriteMapOverlaySvg(const std::string& dir, const Grid& grid, const MapResult& result) {
  std::string file = result.name;
  for (std::size_t at = file.find('/'); at != std::string::npos; at = file.find('/', at + 2)) {
    file.replace(at, 1, "__");
  }
  // The default .lmap 2.0 file's own layers; when they could not be read,
  // RM-Line's segments and the segmentation's room borders and furniture.
  Segmentation segmentation;
  std::vector<LineSegment> segments;
  std::string source;
  Status status = Status::Ok();
  if (result.lmap_geometry) {
    segments = result.lmap_geometry->segments;
    for (const auto& chain : result.lmap_geometry->room_chains) {
      segmentation.rooms.push_back({chain});
    }
    for (const auto& outline : result.lmap_geometry->blob_outlines) {
      FurnitureBlob blob;
      blob.outline = outline;
      segmentation.blobs.push_back(std::move(blob));
    }
    source = ".lmap 2.0 layers";
  } else {
    segments = result.rmline_segments;
    StatusOr<Segmentation> segmented = SegmentMap(grid);
    if (segmented.ok()) {
      segmentation = std::move(*segmented);
    } else {
      status = segmented.status();
    }
    source = "RM-Line + SegmentMap";
  }
  const std::string title =
      result.name + " (" + source + "): walls red, room borders blue, furniture green";
  LINEMAP_RETURN_IF_ERROR(WriteFileAtomic(dir + "/" + file + ".svg",
                                          MapOverlaySvg(grid, segments, &segmentation, title)));
  return status;
}

std::string SummaryPlotSvg(const std::vector<MapResult>& results) {
  // A column per method, a dot per map; log-scale y axis: size / PNG-9.
  struct Point {
    double ratio;
    std::size_t method;
  };
  const std::vector<PlotMethod>& methods = PlotMethods();
  std::vector<Point> points;
  double lo = 1.0, hi = 1.0;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (const MapResult& result : results) {
      const std::optional<double> ratio = result.RatioToPng9(methods[m].size_figure);
      if (!ratio || *ratio <= 0) continue;
      points.push_back({*ratio, m});
      lo = std::min(lo, *ratio);
      hi = std::max(hi, *ratio);
    }
  }
  const double top = 30, bottom = 380, left = 70, column = 60;
  // Below `bottom`: the columns' rotated labels.
  const std::string height = "500";
  const double right = left + column * static_cast<double>(methods.size());
  const double log_lo = std::floor(std::log10(lo) * 4) / 4;
  const double log_hi = std::max(log_lo + 0.5, std::ceil(std::log10(hi) * 4) / 4);
  auto py = [&](double r) {
    return bottom - (bottom - top) * (std::log10(r) - log_lo) / (log_hi - log_lo);
  };
  auto column_x = [&](std::size_t m) { return left + column * (static_cast<double>(m) + 0.5); };
  auto px = [&](const Point& p) {
    // Spread the maps of a column a little so the dots stay visible.
    const double jitter = std::fmod(p.ratio * 7919.0, 1.0) - 0.5;
    return column_x(p.method) + jitter * column * 0.5;
  };
  // Room right of the plot for the legend's longest line ("<method>:
  // median 0.123", about 40 characters at 6.5 px).
  const std::string width = Num(right + 300);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + width + " " +
                    height + "\" width=\"" + width + "\" height=\"" + height +
                    "\" font-family=\"sans-serif\" font-size=\"12\">\n"
                    "<title>Size ratio to PNG-9, per map and method</title>\n"
                    "<rect x=\"0\" y=\"0\" width=\"" +
                    width + "\" height=\"" + height + "\" fill=\"white\"/>\n<g stroke=\"#ddd\">\n";
  for (double e = log_lo; e <= log_hi + 1e-9; e += 0.25) {
    const double r = std::pow(10.0, e);
    const std::string y = Num(py(r));
    const bool one = std::fabs(e) < 1e-9;
    svg += "<line x1=\"" + Num(left) + "\" x2=\"" + Num(right) + "\" y1=\"" + y + "\" y2=\"" + y +
           "\"" + (one ? " stroke=\"#888\"" : "") + "/>\n";
    char label[32];
    std::snprintf(label, sizeof label, "%.2g", r);
    svg += "<text x=\"" + Num(left - 6) + "\" y=\"" + Num(py(r) + 4) +
           "\" text-anchor=\"end\" stroke=\"none\" fill=\"#333\">" + label + "</text>\n";
  }
  svg += "</g>\n";
  for (std::size_t m = 0; m < methods.size(); ++m) {
    svg += "<text transform=\"translate(" + Num(column_x(m) + 4) + "," + Num(bottom + 8) +
           ") rotate(-35)\" text-anchor=\"end\" font-size=\"11\">" + Escape(methods[m].label) +
           "</text>\n";
  }
  svg += "<text x=\"" + Num((left + right) / 2) + "\" y=\"" + Num(top - 10) +
         "\" text-anchor=\"middle\">exact methods</text>\n<text transform=\"translate(18," +
         Num((top + bottom) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">size / PNG-9 (log scale; below 1 = smaller)"
         "</text>\n";
  for (const Point& p : points) {
    svg += "<circle cx=\"" + Num(px(p)) + "\" cy=\"" + Num(py(p.ratio)) + "\" r=\"3\" fill=\"" +
           methods[p.method].colour + "\" fill-opacity=\"0.55\"/>\n";
  }
  double legend_y = top + 10;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> ratios;
    for (const Point& p : points) {
      if (p.method == m) ratios.push_back(p.ratio);
    }
    std::string label = methods[m].label;
    if (ratios.empty()) {
      label += ": not measured";
    } else {
      const double median = Median(ratios);
      svg += "<rect x=\"" + Num(column_x(m) - 6) + "\" y=\"" + Num(py(median) - 6) +
             "\" width=\"12\" height=\"12\" fill=\"" + methods[m].colour +
             "\" stroke=\"black\"/>\n";
      char text[64];
      std::snprintf(text, sizeof text, ": median %.3f", median);
      label += text;
    }
    svg += "<rect x=\"" + Num(right + 30) + "\" y=\"" + Num(legend_y - 9) +
           "\" width=\"10\" height=\"10\" fill=\"" + methods[m].colour + "\"/>\n<text x=\"" +
           Num(right + 45) + "\" y=\"" + Num(legend_y) + "\">" + Escape(label) + "</text>\n";
    legend_y += 18;
  }
  svg += "<text x=\"" + Num(right + 30) + "\" y=\"" + Num(legend_y + 8) +
         "\" fill=\"#555\">dots: maps; squares: medians</text>\n</svg>\n";
  return svg;
}

}  // namespace linemap::bench
