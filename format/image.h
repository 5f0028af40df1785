// Decoding and encoding of the map images map_server reads: PGM (P2, P5; 8 or
// 16 bit) and PNG (grey, grey+alpha, RGB, RGBA, palette, 1/2/4/8/16 bit),
// whole or one row at a time (a 20,768 x 13,612 map is 282 MB of PGM and
// 564 MB of 16-bit samples; read by rows, loading it holds one row).
#ifndef LINEMAP_FORMAT_IMAGE_H_
#define LINEMAP_FORMAT_IMAGE_H_

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "linemap/status.h"

namespace linemap {

// An image as GraphicsMagick's 16-bit build sees it: every sample is a
// quantum in 0..65535 (an 8-bit sample v becomes v * 257), rows top first.
struct RawImage {
  int width = 0;
  int height = 0;
  int channels = 0;                    // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  std::vector<std::uint16_t> samples;  // width * height * channels

  bool has_alpha() const { return channels == 2 || channels == 4; }
  const std::uint16_t* pixel(int x, int y) const {
    return samples.data() + (static_cast<std::size_t>(y) * width + x) * channels;
  }
};

inline constexpr std::uint32_t kQuantumMax = 65535;

// A map image read one row at a time, top row first. Every file defect
// (truncation, a sample above maxval, a bad PNG) is reported by ReadRow, as
// an error naming the file, when the row holding it is read.
class ImageRowReader {
 public:
  virtual ~ImageRowReader() = default;

  int width() const { return width_; }
  int height() const { return height_; }
  int channels() const { return channels_; }  // as RawImage::channels
  bool has_alpha() const { return channels_ == 2 || channels_ == 4; }

  // Reads the next row into `row`: width() * channels() quanta laid out as
  // a row of RawImage::samples. Called at most height() times.
  virtual Status ReadRow(std::uint16_t* row) = 0;

 protected:
  int width_ = 0;
  int height_ = 0;
  int channels_ = 0;
};

// Opens the image file `path` for reading by rows, choosing the decoder by
// the file's magic bytes, not its name. The header is read and checked
// here: images with more than `max_cells` pixels are refused before any
// buffer is allocated, and, for a regular file, a PGM raster shorter than
// its header claims is refused at once. Memory held: one row of samples and
// a 256 KiB read buffer, except for interlaced (Adam7) PNGs, whose rows
// come out only after the last pass: those are decoded whole here (their
// 8/16-bit raster, 1..8 bytes per pixel).
StatusOr<std::unique_ptr<ImageRowReader>> OpenImageRows(const std::string& path,
                                                        std::uint64_t max_cells);

// `name` is used in error messages only. Images with more than `max_cells`
// pixels are refused before any pixel buffer is allocated.
StatusOr<RawImage> DecodePgm(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells);
StatusOr<RawImage> DecodePng(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells);
// Chooses the decoder by the file's magic bytes, not its name.
StatusOr<RawImage> ReadImageFile(const std::string& path, std::uint64_t max_cells);

// The header of a binary 8-bit PGM (P5) of width x height pixels; the
// pixel bytes (rows top first) follow it.
std::string PgmHeader(int width, int height);

// A binary 8-bit PGM (P5) of `grey` (width * height bytes, rows top first).
std::string EncodePgm(int width, int height, std::span<const std::uint8_t> grey);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_IMAGE_H_
