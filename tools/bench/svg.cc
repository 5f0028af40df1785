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
  const char* displ_figure;  // nullptr: lossless, DisPL 0
  const char* colour;
};

const std::vector<PlotMethod>& PlotMethods() {
  static const std::vector<PlotMethod> methods = {
      {"PNG 2-bit", key::kPng2Bytes, nullptr, "#7f7f7f"},
      {"zstd -19", key::kZstdBytes, nullptr, "#1f77b4"},
      {"xz -9", key::kXzBytes, nullptr, "#9467bd"},
      {"JBIG1", key::kJbigBytes, nullptr, "#8c564b"},
      {".lmap lossless", key::kLmapLosslessBytes, nullptr, "#2ca02c"},
      {".lmap lossy", key::kLmapLossyBytes, key::kEvalDisplCm, "#d62728"},
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
  StatusOr<Segmentation> segmentation = SegmentMap(grid);
  std::string file = result.name;
  for (std::size_t at = file.find('/'); at != std::string::npos; at = file.find('/', at + 2)) {
    file.replace(at, 1, "__");
  }
  const std::string title =
      result.name + ": RM-Line segments (red), room borders (blue), " + "furniture (green)";
  LINEMAP_RETURN_IF_ERROR(
      WriteFileAtomic(dir + "/" + file + ".svg",
                      MapOverlaySvg(grid, result.rmline_segments,
                                    segmentation.ok() ? &*segmentation : nullptr, title)));
  if (!segmentation.ok()) return segmentation.status();
  return Status::Ok();
}

std::string SummaryPlotSvg(const std::vector<MapResult>& results) {
  struct Point {
    double displ, ratio;
    const PlotMethod* method;
  };
  std::vector<Point> points;
  double max_displ = 1.0, lo = 1.0, hi = 1.0;
  for (const PlotMethod& method : PlotMethods()) {
    for (const MapResult& result : results) {
      const std::optional<double> ratio = result.RatioToPng9(method.size_figure);
      std::optional<double> displ = 0.0;
      if (method.displ_figure) displ = result.Get(method.displ_figure);
      if (!ratio || !displ || *ratio <= 0) continue;
      points.push_back({*displ, *ratio, &method});
      max_displ = std::max(max_displ, *displ);
      lo = std::min(lo, *ratio);
      hi = std::max(hi, *ratio);
    }
  }
  const double left = 70, right = 640, top = 30, bottom = 390;
  const double log_lo = std::floor(std::log10(lo) * 2) / 2,
               log_hi = std::ceil(std::log10(hi) * 2) / 2;
  const double x_max = std::ceil(max_displ);
  auto px = [&](double d) { return left + (right - left) * d / x_max; };
  auto py = [&](double r) {
    return bottom - (bottom - top) * (std::log10(r) - log_lo) / std::max(0.5, log_hi - log_lo);
  };
  std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 820 440\" width=\"820\" "
      "height=\"440\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<title>Size ratio to PNG-9 vs DisPL_ave</title>\n"
      "<rect x=\"0\" y=\"0\" width=\"820\" height=\"440\" fill=\"white\"/>\n";
  svg += "<g stroke=\"#ccc\">\n";
  for (double e = log_lo; e <= log_hi + 1e-9; e += 0.5) {
    const double r = std::pow(10.0, e);
    svg += "<line x1=\"" + Num(left) + "\" x2=\"" + Num(right) + "\" y1=\"" + Num(py(r)) +
           "\" y2=\"" + Num(py(r)) + "\"/>\n";
    char label[32];
    std::snprintf(label, sizeof label, "%g", std::round(r * 1000) / 1000);
    svg += "<text x=\"" + Num(left - 6) + "\" y=\"" + Num(py(r) + 4) +
           "\" text-anchor=\"end\" stroke=\"none\" fill=\"#333\">" + label + "</text>\n";
  }
  for (int d = 0; d <= static_cast<int>(x_max); ++d) {
    svg += "<line y1=\"" + Num(top) + "\" y2=\"" + Num(bottom) + "\" x1=\"" + Num(px(d)) +
           "\" x2=\"" + Num(px(d)) + "\"/>\n<text x=\"" + Num(px(d)) + "\" y=\"" +
           Num(bottom + 16) + "\" text-anchor=\"middle\" stroke=\"none\" fill=\"#333\">" +
           std::to_string(d) + "</text>\n";
  }
  svg += "</g>\n<text x=\"" + Num((left + right) / 2) + "\" y=\"" + Num(bottom + 34) +
         "\" text-anchor=\"middle\">DisPL_ave (cm); lossless methods at 0</text>\n"
         "<text transform=\"translate(18," +
         Num((top + bottom) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">size / PNG-9 (log scale)</text>\n";
  for (const Point& p : points) {
    svg += "<circle cx=\"" + Num(px(p.displ)) + "\" cy=\"" + Num(py(p.ratio)) +
           "\" r=\"3\" fill=\"" + p.method->colour + "\" fill-opacity=\"0.45\"/>\n";
  }
  double legend_y = top + 10;
  for (const PlotMethod& method : PlotMethods()) {
    std::vector<double> ratios, displs;
    for (const Point& p : points) {
      if (p.method != &method) continue;
      ratios.push_back(p.ratio);
      displs.push_back(p.displ);
    }
    std::string label = method.label;
    if (ratios.empty()) {
      label += " (not measured)";
    } else {
      const double r = Median(ratios), d = Median(displs);
      svg += "<rect x=\"" + Num(px(d) - 6) + "\" y=\"" + Num(py(r) - 6) +
             "\" width=\"12\" height=\"12\" fill=\"" + method.colour + "\" stroke=\"black\"/>\n";
      char median[64];
      std::snprintf(median, sizeof median, " (median %.3f)", r);
      label += median;
    }
    svg += "<rect x=\"655\" y=\"" + Num(legend_y - 9) + "\" width=\"10\" height=\"10\" fill=\"" +
           method.colour + "\"/>\n<text x=\"670\" y=\"" + Num(legend_y) + "\">" + Escape(label) +
           "</text>\n";
    legend_y += 18;
  }
  svg += "<text x=\"655\" y=\"" + Num(legend_y + 8) +
         "\" fill=\"#555\">dots: maps; squares: medians</text>\n</svg>\n";
  return svg;
}

}  // namespace linemap::bench
