// bench_tiles: sizes and speed of the .lmap 2.0 tile cell coder
// (codec/cells/tile_coder.h) on the maps of ../shared/maps, against the 1.0
// lossless planes (OCCP + FREE over an empty canvas, as the 1.0 encoder
// coded them without segments) and libpng level 9.
//
//   bench_tiles [--maps DIR] [--tile N] [--sizes] [--no-hints] [--only SUBSTR]
//               [--dump-pgm DIR] [--jxl FILE] [--file-layers]
//               [--compare [--time]]
//
// --dump-pgm writes each map as a trinary PGM (map_saver's grey levels) for
// running other codecs on it; --jxl reads "flat_name bytes" lines (e.g.
// `cjxl -d 0 -e 9 -E 3 -I 100 -g 3` sizes of those PGMs) and adds columns.
//
// Per map: cells; PNG-9 bytes (the smallest of libpng's 8-bit grey, 8-bit
// palette and 2-bit palette at level 9, as `linemap bench` takes it) and
// libpng's decode CPU ns per cell; the 1.0 planes' bytes; the tile coder's
// bytes for TileModel kTemplate (tile, hinted), kMixed (mix, hmix) and
// kMixedAllCells (mall, hmall), without and with hints (BuildLayerHints),
// and their ratios to PNG-9; encode and decode CPU ns per cell (dec: no
// hints, hdec: hints, hmdec: kMixed with hints, madec: kMixedAllCells
// without hints) and decode time over libpng's. --sizes adds the kTemplate
// bytes with 256 x 256 and 512 x 512 tiles. hlay, hl/h, hl/png, hldec,
// hld/hd: TileModel::kLayerContext with hints (bytes, over kTemplate's with
// hints, over PNG-9; decode ns, over kTemplate's with hints).
// --file-layers takes the hints from the layers a default 2.x file stores
// (ExtractVectorLayers drawn by LayerIndex, what CELL is coded against)
// instead of BuildLayerHints. --compare prints one line per map instead:
// map, T(uning)/H(eld-out), cells, hinted kTemplate bytes, kLayerContext
// bytes, their ratio, (with --time) both decode ns per cell and their
// ratio, then the bytes of the CELL encoder's choice per tile
// (EncodeCellTile: the smallest of three models) and their ratio to
// kTemplate's. Tuning maps and
// held-out maps are listed and summarised (medians) separately: the coder's
// parameters were chosen on the tuning maps only. Every coding is decoded and compared
// with the map (exit 1 if one differs).
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "codec/cells/cell_tiles.h"
#include "codec/cells/plane_coder.h"
#include "codec/cells/tile_coder.h"
#include "codec/cells/tile_hints.h"
#include "codec/layers/layer_extraction.h"
#include "codec/layers/layer_hints.h"
#include "linemap/map_io.h"
#include "tools/bench/png_codec.h"
#include "tools/bench/tuning_split.h"

namespace linemap {
namespace {

double CpuNow() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Least CPU seconds of `fn` over 5 runs (3 above 1 Mcell): the machine is
// shared, and the least time is the one least disturbed by other programs.
template <typename Fn>
double MinSeconds(std::size_t cells, Fn&& fn) {
  const int runs = cells > 1000000 ? 3 : 5;
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const double start = CpuNow();
    fn();
    t.push_back(CpuNow() - start);
  }
  std::sort(t.begin(), t.end());
  return t.front();
}

std::vector<CellRect> Tiles(int width, int height, int tile) {
  std::vector<CellRect> out;
  for (int y = 0; y < height; y += tile) {
    for (int x = 0; x < width; x += tile) {
      out.push_back(CellRect{x, y, std::min(x + tile, width), std::min(y + tile, height)});
    }
  }
  return out;
}

std::vector<std::vector<std::uint8_t>> EncodeAll(const Grid& g, const std::uint8_t* hints, int tile,
                                                 TileModel model = TileModel::kTemplate) {
  std::vector<std::vector<std::uint8_t>> out;
  for (const CellRect& t : Tiles(g.width(), g.height(), tile)) {
    out.push_back(EncodeTileCells(g.cells().data(), hints, g.width(), g.height(), t, model));
  }
  return out;
}

std::size_t TotalBytes(const std::vector<std::vector<std::uint8_t>>& tiles) {
  std::size_t n = 0;
  for (const auto& t : tiles) n += t.size();
  return n;
}

// Decodes every tile into `out`; false on any error.
bool DecodeAll(const std::vector<std::vector<std::uint8_t>>& data, const std::uint8_t* hints,
               int width, int height, int tile, std::vector<Cell>* out) {
  const std::vector<CellRect> tiles = Tiles(width, height, tile);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (!DecodeTileCells(data[i].data(), data[i].size(), hints, width, height, tiles[i],
                         out->data())
             .ok()) {
      return false;
    }
  }
  return true;
}

std::size_t PlanesBytes(const Grid& g) {
  std::vector<Cell> canvas(g.size(), Cell::kUnknown);
  std::vector<std::uint8_t> occ(g.size()), free(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    occ[i] = g.cells()[i] == Cell::kOccupied;
    free[i] = g.cells()[i] == Cell::kFree;
  }
  std::size_t n = EncodeOccupiedPlane(occ, canvas, g.width(), g.height()).size();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (occ[i]) canvas[i] = Cell::kOccupied;
  }
  return n + EncodeFreePlane(free, canvas, g.width(), g.height()).size();
}

// Bytes and CPU ns per cell of one way of coding a map.
struct Coded {
  double bytes = 0, enc_ns = 0, dec_ns = 0;
};

struct Row {
  std::string name;
  bool tuning = false;
  double cells = 0, png = 0, png_dec_ns = 0, planes = 0, t256 = 0, t512 = 0, jxl = 0;
  Coded plain, hinted, mixed, mixed_hinted;  // template / mixed model, without / with hints
  Coded smallest, smallest_hinted;           // kMixedAllCells without / with hints
  Coded layered;                             // kLayerContext with hints
  Coded mixed_layered;                       // kMixedLayerAllCells with hints
};

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Column {
  const char* title;
  const char* format;  // printf format of one value, width included
  double (*value)(const Row&);
};

// The printed columns: sizes in bytes, times in CPU ns per cell.
const Column kColumns[] = {
    {"cells", " %9.0f", [](const Row& r) { return r.cells; }},
    {"png9", " %7.0f", [](const Row& r) { return r.png; }},
    {"v1pl", " %7.0f", [](const Row& r) { return r.planes; }},
    {"tile", " %7.0f", [](const Row& r) { return r.plain.bytes; }},
    {"hinted", " %7.0f", [](const Row& r) { return r.hinted.bytes; }},
    {"mix", " %7.0f", [](const Row& r) { return r.mixed.bytes; }},
    {"hmix", " %7.0f", [](const Row& r) { return r.mixed_hinted.bytes; }},
    {"mall", " %7.0f", [](const Row& r) { return r.smallest.bytes; }},
    {"hmall", " %7.0f", [](const Row& r) { return r.smallest_hinted.bytes; }},
    {"t/png", " %6.3f", [](const Row& r) { return r.plain.bytes / r.png; }},
    {"ma/png", " %6.3f", [](const Row& r) { return r.smallest.bytes / r.png; }},
    {"h/png", " %6.3f", [](const Row& r) { return r.hinted.bytes / r.png; }},
    {"hm/png", " %6.3f", [](const Row& r) { return r.mixed_hinted.bytes / r.png; }},
    {"hma/png", " %7.3f", [](const Row& r) { return r.smallest_hinted.bytes / r.png; }},
    {"pngdec", " %6.2f", [](const Row& r) { return r.png_dec_ns; }},
    {"enc", " %6.2f", [](const Row& r) { return r.plain.enc_ns; }},
    {"dec", " %6.2f", [](const Row& r) { return r.plain.dec_ns; }},
    {"hdec", " %6.2f", [](const Row& r) { return r.hinted.dec_ns; }},
    {"hmdec", " %6.2f", [](const Row& r) { return r.mixed_hinted.dec_ns; }},
    {"madec", " %6.2f", [](const Row& r) { return r.smallest.dec_ns; }},
    {"d/png", " %6.3f", [](const Row& r) { return r.plain.dec_ns / r.png_dec_ns; }},
    {"hd/png", " %6.3f", [](const Row& r) { return r.hinted.dec_ns / r.png_dec_ns; }},
    {"hmd/png", " %7.3f", [](const Row& r) { return r.mixed_hinted.dec_ns / r.png_dec_ns; }},
    {"hlay", " %7.0f", [](const Row& r) { return r.layered.bytes; }},
    {"hl/h", " %6.3f", [](const Row& r) { return r.layered.bytes / r.hinted.bytes; }},
    {"hl/png", " %6.3f", [](const Row& r) { return r.layered.bytes / r.png; }},
    {"hldec", " %6.2f", [](const Row& r) { return r.layered.dec_ns; }},
    {"hld/hd", " %6.3f", [](const Row& r) { return r.layered.dec_ns / r.hinted.dec_ns; }},
    {"hmlay", " %7.0f", [](const Row& r) { return r.mixed_layered.bytes; }},
    {"hml/hma", " %7.3f",
     [](const Row& r) { return r.mixed_layered.bytes / r.smallest_hinted.bytes; }},
    {"hml/hl", " %6.3f", [](const Row& r) { return r.mixed_layered.bytes / r.layered.bytes; }},
    {"hmldec", " %6.2f", [](const Row& r) { return r.mixed_layered.dec_ns; }},
};
const Column kSizeColumns[] = {
    {"t256", " %7.0f", [](const Row& r) { return r.t256; }},
    {"t512", " %7.0f", [](const Row& r) { return r.t512; }},
};
const Column kJxlColumns[] = {
    {"jxl", " %7.0f", [](const Row& r) { return r.jxl; }},
    {"t/jxl", " %6.3f", [](const Row& r) { return r.plain.bytes / r.jxl; }},
    {"h/jxl", " %6.3f", [](const Row& r) { return r.hinted.bytes / r.jxl; }},
    {"m/jxl", " %6.3f", [](const Row& r) { return r.mixed.bytes / r.jxl; }},
    {"hm/jxl", " %6.3f", [](const Row& r) { return r.mixed_hinted.bytes / r.jxl; }},
    {"ma/jxl", " %6.3f", [](const Row& r) { return r.smallest.bytes / r.jxl; }},
};

void PrintRows(const std::vector<Row>& rows, bool tuning, bool sizes, bool jxl) {
  std::vector<Column> cols(std::begin(kColumns), std::end(kColumns));
  if (sizes) cols.insert(cols.end(), std::begin(kSizeColumns), std::end(kSizeColumns));
  if (jxl) cols.insert(cols.end(), std::begin(kJxlColumns), std::end(kJxlColumns));
  std::printf("\n%s maps\n%-44s", tuning ? "TUNING" : "HELD-OUT", "map");
  for (const Column& c : cols) {
    const int width = std::atoi(c.format + 2);
    std::printf(" %*s", width, c.title);
  }
  std::printf("\n");
  std::vector<std::vector<double>> values(cols.size());
  for (const Row& r : rows) {
    if (r.tuning != tuning) continue;
    std::printf("%-44s", r.name.c_str());
    for (std::size_t k = 0; k < cols.size(); ++k) {
      values[k].push_back(cols[k].value(r));
      std::printf(cols[k].format, values[k].back());
    }
    std::printf("\n");
  }
  std::printf("%-44s", "median");
  for (std::size_t k = 0; k < cols.size(); ++k) std::printf(cols[k].format, Median(values[k]));
  std::printf("\n");
}

// --compare's values per map: cells, bytes of kTemplate and kLayerContext
// with hints and their ratio, decode ns of both and their ratio, the bytes
// of the smaller of the two per tile and their ratio to kTemplate's.
constexpr int kCompareValues = 9;

void PrintCompareValues(const double* v) {
  std::printf(" %9.0f %7.0f %7.0f %6.3f %6.2f %6.2f %6.3f %7.0f %6.3f\n", v[0], v[1], v[2], v[3],
              v[4], v[5], v[6], v[7], v[8]);
}

// "nav2/depot.yaml" -> "nav2__depot".
std::string FlatName(std::string path) {
  path = path.substr(0, path.rfind('.'));
  std::string out;
  for (char c : path) out += c == '/' ? std::string("__") : std::string(1, c);
  return out;
}

// The trinary map as map_saver writes it (254 free, 0 occupied, 205
// unknown; top image row first), for running other codecs on it.
void DumpPgm(const Grid& g, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return;
  std::fprintf(f, "P5\n%d %d\n255\n", g.width(), g.height());
  static const unsigned char kGrey[3] = {254, 0, 205};
  std::vector<unsigned char> row(static_cast<std::size_t>(g.width()));
  for (int y = g.height() - 1; y >= 0; --y) {
    for (int x = 0; x < g.width(); ++x) row[x] = kGrey[static_cast<int>(g.at(x, y))];
    std::fwrite(row.data(), 1, row.size(), f);
  }
  std::fclose(f);
}

// The JPEG XL size of `name` from a file of "name bytes" lines (made by
// running cjxl on the --dump-pgm files), 0 when absent.
double JxlBytes(const std::string& file, const std::string& name) {
  std::FILE* f = std::fopen(file.c_str(), "r");
  if (f == nullptr) return 0;
  char key[512];
  double bytes = 0, found = 0;
  while (std::fscanf(f, "%511s %lf%*[^\n]", key, &bytes) == 2) {
    if (name == key) found = bytes;
  }
  std::fclose(f);
  return found;
}

// The hints a default .lmap 2.x file's tiles are coded against: the
// layers the encoder extracts and stores, drawn by LayerIndex (spec 6.2).
StatusOr<std::vector<std::uint8_t>> FileLayerHints(const Grid& g) {
  LINEMAP_ASSIGN_OR_RETURN(VectorLayers layers, ExtractVectorLayers(g, EncodeOptions{}));
  const LayerIndex index(layers.walls, layers.rooms, layers.furniture);
  return index.TileHints(CellRect{0, 0, g.width(), g.height()});
}

// Encodes and decodes `g` in tiles, timing both; false when the decode
// fails or differs from `g`.
bool Measure(const Grid& g, const std::uint8_t* hints, int tile, TileModel model, Coded* out,
             bool timed = true) {
  const double cells = static_cast<double>(g.size());
  std::vector<std::vector<std::uint8_t>> data;
  if (!timed) {
    data = EncodeAll(g, hints, tile, model);
    out->bytes = static_cast<double>(TotalBytes(data));
    std::vector<Cell> decoded(g.size(), Cell::kFree);
    return DecodeAll(data, hints, g.width(), g.height(), tile, &decoded) && decoded == g.cells();
  }
  out->enc_ns =
      1e9 / cells * MinSeconds(g.size(), [&] { data = EncodeAll(g, hints, tile, model); });
  out->bytes = static_cast<double>(TotalBytes(data));
  std::vector<Cell> decoded(g.size(), Cell::kFree);
  bool ok = true;
  out->dec_ns = 1e9 / cells * MinSeconds(g.size(), [&] {
                  ok = ok && DecodeAll(data, hints, g.width(), g.height(), tile, &decoded);
                });
  return ok && decoded == g.cells();
}

int Run(int argc, char** argv) {
  std::string dir = "/work/shared/maps";
  int tile = 1024;
  bool sizes = false, hints_on = true, compare = false, timed = false, file_layers = false;
  std::string only, dump, jxl_file;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--maps" && i + 1 < argc) {
      dir = argv[++i];
    } else if (a == "--tile" && i + 1 < argc) {
      tile = std::atoi(argv[++i]);
    } else if (a == "--sizes") {
      sizes = true;
    } else if (a == "--compare") {
      compare = true;
    } else if (a == "--time") {
      timed = true;
    } else if (a == "--file-layers") {
      file_layers = true;
    } else if (a == "--no-hints") {
      hints_on = false;
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (a == "--jxl" && i + 1 < argc) {
      jxl_file = argv[++i];
    } else if (a == "--dump-pgm" && i + 1 < argc) {
      dump = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: bench_tiles [--maps DIR] [--tile N] [--sizes] [--no-hints] "
                   "[--only SUBSTR] [--dump-pgm DIR] [--jxl FILE] [--file-layers] "
                   "[--compare [--time]]\n");
      return 2;
    }
  }
  if (tile < 1) {
    std::fprintf(stderr, "bench_tiles: --tile must be >= 1\n");
    return 2;
  }
  std::vector<Row> rows;
  std::vector<double> compared[2][kCompareValues];  // tuning, held-out
  if (compare) {
    std::printf("%-44s %s %9s %7s %7s %6s %6s %6s %6s %7s %6s\n", "map", "T/H", "cells", "hinted",
                "hlay", "hl/h", "hdec", "hldec", "ld/hd", "cell", "cell/h");
  }
  for (const bench::SplitMap& m : bench::kTuningSplit) {
    if (!only.empty() && std::string(m.path).find(only) == std::string::npos) continue;
    const std::string path = dir + "/" + m.path;
    StatusOr<Grid> loaded = LoadRosMap(path);
    if (!loaded.ok()) {
      std::fprintf(stderr, "bench_tiles: %s: %s\n", path.c_str(),
                   loaded.status().ToString().c_str());
      return 1;
    }
    const Grid& g = *loaded;
    if (!dump.empty()) DumpPgm(g, dump + "/" + FlatName(m.path) + ".pgm");
    Row r;
    r.name = m.path;
    r.tuning = m.tuning;
    r.cells = static_cast<double>(g.size());
    if (compare) {
      StatusOr<std::vector<std::uint8_t>> built =
          file_layers ? FileLayerHints(g) : BuildLayerHints(g);
      if (!built.ok()) return 1;
      const std::uint8_t* compare_hints = hints_on ? built->data() : nullptr;
      Coded a, b;
      const bool ok = Measure(g, compare_hints, tile, TileModel::kTemplate, &a, timed) &&
                      Measure(g, compare_hints, tile, TileModel::kLayerContext, &b, timed);
      // What the CELL encoder writes (EncodeCellTile: the smallest model).
      double best = 0;
      for (const CellRect& t : Tiles(g.width(), g.height(), tile)) {
        std::vector<std::uint8_t> tile_hints;
        for (int y = t.y0; y < t.y1; ++y) {
          for (int x = t.x0; x < t.x1; ++x) {
            tile_hints.push_back(compare_hints ? compare_hints[g.Index(x, y)] : 0);
          }
        }
        best += static_cast<double>(
            EncodeCellTile(TileCells(g, t), tile_hints, t.x1 - t.x0, t.y1 - t.y0).size());
      }
      const double values[kCompareValues] = {r.cells,
                                             a.bytes,
                                             b.bytes,
                                             b.bytes / a.bytes,
                                             a.dec_ns,
                                             b.dec_ns,
                                             a.dec_ns > 0 ? b.dec_ns / a.dec_ns : 0,
                                             best,
                                             best / a.bytes};
      std::printf("%-44s %s", m.path, m.tuning ? "T" : "H");
      PrintCompareValues(values);
      for (int k = 0; k < kCompareValues; ++k) compared[m.tuning ? 0 : 1][k].push_back(values[k]);
      std::fflush(stdout);
      if (!ok) return 1;
      continue;
    }
    std::string best_png;
    for (bench::PngLayout layout :
         {bench::PngLayout::kGrey8, bench::PngLayout::kPalette8, bench::PngLayout::kPalette2}) {
      StatusOr<std::string> png = bench::EncodeTrinaryPng(g, layout, 9);
      if (png.ok() && (best_png.empty() || png->size() < best_png.size())) best_png = *png;
    }
    r.png = static_cast<double>(best_png.size());
    const std::span<const std::uint8_t> png_bytes(
        reinterpret_cast<const std::uint8_t*>(best_png.data()), best_png.size());
    r.png_dec_ns =
        1e9 / r.cells * MinSeconds(g.size(), [&] { (void)bench::DecodeTrinaryPng(png_bytes); });
    r.planes = static_cast<double>(PlanesBytes(g));

    std::vector<std::uint8_t> hints;
    if (hints_on) {
      StatusOr<std::vector<std::uint8_t>> built =
          file_layers ? FileLayerHints(g) : BuildLayerHints(g);
      if (!built.ok()) {
        std::fprintf(stderr, "bench_tiles: %s: hints: %s\n", m.path,
                     built.status().ToString().c_str());
        return 1;
      }
      hints = std::move(*built);
    }
    const std::uint8_t* hint_ptr = hints_on ? hints.data() : nullptr;
    bool ok = Measure(g, nullptr, tile, TileModel::kTemplate, &r.plain) &&
              Measure(g, nullptr, tile, TileModel::kMixed, &r.mixed) &&
              Measure(g, nullptr, tile, TileModel::kMixedAllCells, &r.smallest);
    if (hints_on) {
      ok = ok && Measure(g, hint_ptr, tile, TileModel::kTemplate, &r.hinted) &&
           Measure(g, hint_ptr, tile, TileModel::kMixed, &r.mixed_hinted) &&
           Measure(g, hint_ptr, tile, TileModel::kMixedAllCells, &r.smallest_hinted) &&
           Measure(g, hint_ptr, tile, TileModel::kLayerContext, &r.layered) &&
           Measure(g, hint_ptr, tile, TileModel::kMixedLayerAllCells, &r.mixed_layered);
    }
    if (!ok) {
      std::fprintf(stderr, "bench_tiles: %s: round trip FAILED\n", m.path);
      return 1;
    }
    if (sizes) {
      r.t256 = static_cast<double>(TotalBytes(EncodeAll(g, nullptr, 256)));
      r.t512 = static_cast<double>(TotalBytes(EncodeAll(g, nullptr, 512)));
    }
    if (!jxl_file.empty()) r.jxl = JxlBytes(jxl_file, FlatName(m.path));
    rows.push_back(r);
    std::fprintf(stderr, "%s done\n", m.path);
  }
  if (compare) {
    for (int set = 0; set < 2; ++set) {
      double medians[kCompareValues];
      for (int k = 0; k < kCompareValues; ++k) medians[k] = Median(compared[set][k]);
      std::printf("%-44s %s", set == 0 ? "median (tuning)" : "median (held-out)", set ? "H" : "T");
      PrintCompareValues(medians);
    }
    return 0;
  }
  std::printf(
      "tile %d; bytes; ns = CPU ns per cell (least of 5 runs, 3 above 1 Mcell)\n"
      "tile/hinted: TileModel::kTemplate without/with hints; mix/hmix: TileModel::kMixed; "
      "mall/hmall: TileModel::kMixedAllCells; hlay: kLayerContext; hmlay: kMixedLayerAllCells\n",
      tile);
  PrintRows(rows, true, sizes, !jxl_file.empty());
  PrintRows(rows, false, sizes, !jxl_file.empty());
  return 0;
}

}  // namespace
}  // namespace linemap

int main(int argc, char** argv) { return linemap::Run(argc, argv); }
