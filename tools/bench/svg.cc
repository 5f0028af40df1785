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

// The smallest of 1, 2, 5 x 10^k (k >= 0) that splits [0, `span`] into at
// most `ticks` steps.
double TickStep(double span, int ticks) {
  if (!std::isfinite(span) || span <= 0) return 1.0;
  for (double scale = 1;; scale *= 10) {
    for (double step : {1.0, 2.0, 5.0}) {
      if (span / (step * scale) <= ticks) return step * scale;
    }
  }
}

std::string TickLabel(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

struct PlotMethod {
  const char* label;
  const char* size_figure;
  const char* displ_figure;  // nullptr: lossless, DisPL 0
  const char* colour;
};

const std::vector<PlotMethod>& PlotMethods() {
  static const std::vector<PlotMethod> methods = {
      {"PNG 2-bit", key::kPng2Bytes, nullptr, "#7f7f7f"},
      {"zstd -19", key::kZstdBytes, nullptr, "#1f77b4"},
      {"xz -9e", key::kXzBytes, nullptr, "#9467bd"},
      {"JBIG1", key::kJbigBytes, nullptr, "#8c564b"},
      {"WebP", key::kWebpBytes, nullptr, "#e377c2"},
      {"JPEG XL", key::kJxlBytes, nullptr, "#17becf"},
      {".lmap 2.0 (default)", key::kLmapBytes, nullptr, "#2ca02c"},
      {".lmap 2.0 --raster-only", key::kLmapRasterBytes, nullptr, "#bcbd22"},
      {".lmap 2.3 --compact", key::kLmapCompactBytes, nullptr, "#98df8a"},
      {".lmap 2.3 --compact --raster-only", key::kLmapRasterCompactBytes, nullptr, "#dbdb8d"},
      {".lmap 1.0 --lossy", key::kLmapLossyBytes, key::kEvalDisplCm, "#d62728"},
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
  // Left panel: lossless methods (DisPL 0), one column each. Right panel:
  // lossy methods against DisPL_ave. Shared log-scale y axis: size / PNG-9.
  struct Point {
    double displ, ratio;
    std::size_t method;
  };
  const std::vector<PlotMethod>& methods = PlotMethods();
  std::vector<Point> points;
  double max_displ = 1.0, lo = 1.0, hi = 1.0;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (const MapResult& result : results) {
      const std::optional<double> ratio = result.RatioToPng9(methods[m].size_figure);
      std::optional<double> displ = 0.0;
      if (methods[m].displ_figure) displ = result.Get(methods[m].displ_figure);
      if (!ratio || !displ || *ratio <= 0) continue;
      points.push_back({*displ, *ratio, m});
      max_displ = std::max(max_displ, *displ);
      lo = std::min(lo, *ratio);
      hi = std::max(hi, *ratio);
    }
  }
  std::size_t lossless = 0;
  for (const PlotMethod& method : methods) lossless += method.displ_figure ? 0 : 1;
  const double top = 30, bottom = 380, left = 70, column = 60;
  // Below `bottom`: the DisPL axis and the lossless columns' rotated labels.
  const std::string height = "500";
  const double lossless_right = left + column * static_cast<double>(lossless);
  const double lossy_left = lossless_right + 40, lossy_right = lossy_left + 330;
  const double log_lo = std::floor(std::log10(lo) * 4) / 4;
  const double log_hi = std::max(log_lo + 0.5, std::ceil(std::log10(hi) * 4) / 4);
  // DisPL ticks 1, 2 or 5 x 10^k cm apart, at most 10 of them: a lossy file
  // far off on one map (hundreds of cm) must not draw a tick per cm.
  const double x_step = TickStep(max_displ, 10);
  const double x_max = std::ceil(max_displ / x_step) * x_step;
  auto py = [&](double r) {
    return bottom - (bottom - top) * (std::log10(r) - log_lo) / (log_hi - log_lo);
  };
  auto px = [&](const Point& p) {
    if (!methods[p.method].displ_figure) {
      // Spread the maps of a column a little so the dots stay visible.
      const double jitter = std::fmod(p.ratio * 7919.0, 1.0) - 0.5;
      return left + column * (static_cast<double>(p.method) + 0.5) + jitter * column * 0.5;
    }
    return lossy_left + (lossy_right - lossy_left) * p.displ / x_max;
  };
  // Room right of the panels for the legend's longest line ("<method>:
  // median 0.123", about 40 characters at 6.5 px).
  const std::string width = Num(lossy_right + 300);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + width + " " +
                    height + "\" width=\"" + width + "\" height=\"" + height +
                    "\" font-family=\"sans-serif\" font-size=\"12\">\n"
                    "<title>Size ratio to PNG-9 vs DisPL_ave, per map and method</title>\n"
                    "<rect x=\"0\" y=\"0\" width=\"" +
                    width + "\" height=\"" + height + "\" fill=\"white\"/>\n<g stroke=\"#ddd\">\n";
  for (double e = log_lo; e <= log_hi + 1e-9; e += 0.25) {
    const double r = std::pow(10.0, e);
    const std::string y = Num(py(r));
    const bool one = std::fabs(e) < 1e-9;
    svg += "<line x1=\"" + Num(left) + "\" x2=\"" + Num(lossy_right) + "\" y1=\"" + y + "\" y2=\"" +
           y + "\"" + (one ? " stroke=\"#888\"" : "") + "/>\n";
    char label[32];
    std::snprintf(label, sizeof label, "%.2g", r);
    svg += "<text x=\"" + Num(left - 6) + "\" y=\"" + Num(py(r) + 4) +
           "\" text-anchor=\"end\" stroke=\"none\" fill=\"#333\">" + label + "</text>\n";
  }
  const int x_ticks = static_cast<int>(std::lround(x_max / x_step));
  for (int tick = 0; tick <= x_ticks; ++tick) {
    const double d = tick * x_step;
    const double x = lossy_left + (lossy_right - lossy_left) * d / x_max;
    svg += "<line y1=\"" + Num(top) + "\" y2=\"" + Num(bottom) + "\" x1=\"" + Num(x) + "\" x2=\"" +
           Num(x) + "\"/>\n<text x=\"" + Num(x) + "\" y=\"" + Num(bottom + 16) +
           "\" text-anchor=\"middle\" stroke=\"none\" fill=\"#333\">" + TickLabel(d) + "</text>\n";
  }
  svg += "</g>\n";
  std::size_t column_index = 0;
  for (const PlotMethod& method : methods) {
    if (method.displ_figure) continue;
    const double x = left + column * (static_cast<double>(column_index++) + 0.5);
    svg += "<text transform=\"translate(" + Num(x + 4) + "," + Num(bottom + 8) +
           ") rotate(-35)\" text-anchor=\"end\" font-size=\"11\">" + Escape(method.label) +
           "</text>\n";
  }
  svg += "<text x=\"" + Num((left + lossless_right) / 2) + "\" y=\"" + Num(top - 10) +
         "\" text-anchor=\"middle\">lossless (DisPL 0)</text>\n<text x=\"" +
         Num((lossy_left + lossy_right) / 2) + "\" y=\"" + Num(top - 10) +
         "\" text-anchor=\"middle\">lossy</text>\n<text x=\"" +
         Num((lossy_left + lossy_right) / 2) + "\" y=\"" + Num(bottom + 34) +
         "\" text-anchor=\"middle\">DisPL_ave (cm)</text>\n<text transform=\"translate(18," +
         Num((top + bottom) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">size / PNG-9 (log scale; below 1 = smaller)"
         "</text>\n";
  for (const Point& p : points) {
    svg += "<circle cx=\"" + Num(px(p)) + "\" cy=\"" + Num(py(p.ratio)) + "\" r=\"3\" fill=\"" +
           methods[p.method].colour + "\" fill-opacity=\"0.55\"/>\n";
  }
  double legend_y = top + 10;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> ratios, displs;
    for (const Point& p : points) {
      if (p.method != m) continue;
      ratios.push_back(p.ratio);
      displs.push_back(p.displ);
    }
    std::string label = methods[m].label;
    if (ratios.empty()) {
      label += ": not measured";
    } else {
      const Point median{Median(displs), Median(ratios), m};
      const double x =
          methods[m].displ_figure ? px(median) : left + column * (static_cast<double>(m) + 0.5);
      svg += "<rect x=\"" + Num(x - 6) + "\" y=\"" + Num(py(median.ratio) - 6) +
             "\" width=\"12\" height=\"12\" fill=\"" + methods[m].colour +
             "\" stroke=\"black\"/>\n";
      char text[64];
      std::snprintf(text, sizeof text, ": median %.3f", median.ratio);
      label += text;
    }
    svg += "<rect x=\"" + Num(lossy_right + 30) + "\" y=\"" + Num(legend_y - 9) +
           "\" width=\"10\" height=\"10\" fill=\"" + methods[m].colour + "\"/>\n<text x=\"" +
           Num(lossy_right + 45) + "\" y=\"" + Num(legend_y) + "\">" + Escape(label) + "</text>\n";
    legend_y += 18;
  }
  svg += "<text x=\"" + Num(lossy_right + 30) + "\" y=\"" + Num(legend_y + 8) +
         "\" fill=\"#555\">dots: maps; squares: medians</text>\n</svg>\n";
  return svg;
}

}  // namespace linemap::bench
