// Lossless image codecs as size anchors for .lmap: JPEG XL (libjxl's `cjxl`)
// and WebP lossless (libwebp's `cwebp`), each run as a subprocess on the
// trinary map written the way ROS map_saver writes it (8-bit grey PGM:
// occupied 0, free 254, unknown 205). The matching decoder (`djxl`, `dwebp`)
// turns every file back into pixels, which are checked against the map, so a
// size only counts when the codec really was lossless.
#ifndef LINEMAP_TOOLS_BENCH_IMAGE_ANCHORS_H_
#define LINEMAP_TOOLS_BENCH_IMAGE_ANCHORS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::bench {

// The grey of every cell as map_saver writes it, image row 0 = top (grid
// row height-1): width * height bytes.
std::vector<std::uint8_t> MapSaverGrey(const Grid& grid);
// The same as a binary PGM (P5, maxval 255).
std::string MapSaverPgm(const Grid& grid);

// A command-line image codec. In the argument lists "{in}" and "{out}" stand
// for the input and output paths (both in a scratch folder).
struct ImageCodec {
  std::string label;                // in messages and tables: "JPEG XL", "WebP"
  std::string package;              // the Debian package with the programs
  std::vector<std::string> encode;  // reads the PGM {in}, writes {out}
  std::string encoded_name;         // {out} of encode: "map.jxl"
  std::vector<std::string> decode;  // reads the encoded {in}, writes a PGM or PPM {out}
  std::string decoded_name;         // {out} of decode: "back.pgm"
};

struct JxlOptions {
  std::string encoder = "cjxl";
  std::string decoder = "djxl";
  int effort = 9;  // -e: 1..9 in cjxl 0.7; 9 = slowest, smallest
  // -E: previous channels the MA tree may look at; a grey map has one
  // channel, so 3 only asks for the most cjxl allows.
  int prev_channels = 3;
  int iterations_percent = 100;  // -I: share of pixels that train the MA tree
  int group_size_shift = 3;      // -g: groups of 128 << shift pixels a side (3 = 1024)
};

struct WebpOptions {
  std::string encoder = "cwebp";
  std::string decoder = "dwebp";
  int method = 9;  // -z: lossless preset 0..9; 9 = slowest, smallest
};

// cjxl -d 0 (mathematically lossless) with the options; djxl to a PGM.
ImageCodec JpegXlCodec(const JxlOptions& options = {});
// cwebp -lossless -z METHOD; dwebp to a PPM (its PGM output is YUV, not grey).
ImageCodec WebpCodec(const WebpOptions& options = {});

struct AnchorFile {
  std::string bytes;         // the encoded file
  double encode_cpu_ms = 0;  // the encoder's CPU time, one run (SubprocessRun)
};

// Encodes MapSaverPgm(grid). kNotFound naming the program and its package
// when the encoder is not installed; kIoError when it fails.
StatusOr<AnchorFile> EncodeImageAnchor(const Grid& grid, const ImageCodec& codec);

// Decodes `encoded` (a file from EncodeImageAnchor) and checks every pixel
// against MapSaverGrey(grid); returns the decoder's CPU time in ms, one run.
// kCorrupt naming the first differing pixel when the decode is not exact.
StatusOr<double> DecodeAndCheckImageAnchor(const Grid& grid, const ImageCodec& codec,
                                           const std::string& encoded);

// The grey of an 8-bit binary PGM (P5) or PPM (P6, every pixel grey: R = G =
// B), rows top first; kCorrupt on anything else. `name` is for messages.
StatusOr<std::vector<std::uint8_t>> ReadNetpbmGrey(const std::string& bytes,
                                                   const std::string& name, int* width,
                                                   int* height);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_IMAGE_ANCHORS_H_
