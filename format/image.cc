#include "format/image.h"

#include <png.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "format/file_io.h"

namespace linemap {
namespace {

constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t{4} << 30;

Status CheckDimensions(std::uint64_t width, std::uint64_t height, const std::string& name,
                       std::uint64_t max_cells) {
  if (width == 0 || height == 0) {
    return CorruptError(name + ": image has zero width or height");
  }
  if (width > 0x7fffffff || height > 0x7fffffff || width * height > max_cells) {
    return ResourceExhaustedError(name + ": image of " + std::to_string(width) + " x " +
                                  std::to_string(height) + " cells exceeds the limit of " +
                                  std::to_string(max_cells) + " cells");
  }
  return Status::Ok();
}

// A tokenizer for the PNM header: whitespace-separated decimal numbers with
// '#' comments running to the end of the line.
class PnmHeaderReader {
 public:
  explicit PnmHeaderReader(std::span<const std::uint8_t> bytes) : bytes_(bytes), pos_(2) {}

  bool ReadNumber(std::uint64_t* value) {
    SkipSpaceAndComments();
    if (pos_ >= bytes_.size() || !std::isdigit(bytes_[pos_])) return false;
    std::uint64_t v = 0;
    while (pos_ < bytes_.size() && std::isdigit(bytes_[pos_])) {
      v = v * 10 + (bytes_[pos_] - '0');
      if (v > 0xffffffffull) return false;
      ++pos_;
    }
    *value = v;
    return true;
  }
  // After maxval exactly one whitespace byte separates the header from the
  // raster (netpbm's rule).
  bool SkipSingleWhitespace() {
    if (pos_ >= bytes_.size() || !std::isspace(bytes_[pos_])) return false;
    ++pos_;
    return true;
  }
  std::size_t position() const { return pos_; }

 private:
  void SkipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      if (std::isspace(bytes_[pos_])) {
        ++pos_;
      } else if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else {
        break;
      }
    }
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t pos_;
};

std::uint16_t ScaleToQuantum(std::uint64_t v, std::uint64_t maxval) {
  if (maxval == 65535) return static_cast<std::uint16_t>(v);
  if (maxval == 255) return static_cast<std::uint16_t>(v * 257);
  return static_cast<std::uint16_t>((v * kQuantumMax + maxval / 2) / maxval);
}

struct PngReadState {
  std::span<const std::uint8_t> bytes;
  std::size_t pos = 0;
  std::string error;
};

void PngRead(png_structp png, png_bytep out, png_size_t length) {
  auto* state = static_cast<PngReadState*>(png_get_io_ptr(png));
  if (state->bytes.size() - state->pos < length) {
    png_error(png, "file is truncated");
  }
  std::memcpy(out, state->bytes.data() + state->pos, length);
  state->pos += length;
}

void PngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngReadState*>(png_get_error_ptr(png));
  state->error = message;
  png_longjmp(png, 1);
}

void PngWarning(png_structp, png_const_charp) {}

}  // namespace

StatusOr<RawImage> DecodePgm(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '2')) {
    return CorruptError(name + ": not a PGM image (expected P5 or P2)");
  }
  const bool ascii = bytes[1] == '2';
  PnmHeaderReader header(bytes);
  std::uint64_t width = 0, height = 0, maxval = 0;
  if (!header.ReadNumber(&width) || !header.ReadNumber(&height) || !header.ReadNumber(&maxval)) {
    return CorruptError(name + ": malformed PGM header");
  }
  if (maxval == 0 || maxval > 65535) {
    return CorruptError(name + ": PGM maxval " + std::to_string(maxval) + " is outside 1..65535");
  }
  LINEMAP_RETURN_IF_ERROR(CheckDimensions(width, height, name, max_cells));
  if (!header.SkipSingleWhitespace()) return CorruptError(name + ": malformed PGM header");
  const std::uint64_t cells = width * height;
  const std::size_t bytes_per_sample = maxval > 255 ? 2 : 1;
  std::size_t pos = header.position();
  // Checked before the raster is allocated: a header may claim any size. An
  // ASCII sample takes at least one digit and one separator.
  if (ascii && bytes.size() - pos < 2 * cells - 1) {
    return CorruptError(name + ": PGM raster is truncated (" + std::to_string(bytes.size() - pos) +
                        " bytes for " + std::to_string(cells) + " ASCII pixels)");
  }
  if (!ascii && bytes.size() - pos < cells * bytes_per_sample) {
    return CorruptError(name + ": PGM raster is truncated (" + std::to_string(bytes.size() - pos) +
                        " bytes for " + std::to_string(cells) + " pixels)");
  }
  RawImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.channels = 1;
  image.samples.resize(cells);
  if (!ascii) {
    for (std::uint64_t i = 0; i < cells; ++i) {
      std::uint64_t v = bytes[pos++];
      if (bytes_per_sample == 2) v = (v << 8) | bytes[pos++];
      if (v > maxval) return CorruptError(name + ": PGM sample exceeds maxval");
      image.samples[i] = ScaleToQuantum(v, maxval);
    }
    return image;
  }
  // The ASCII raster continues with the same tokenizer.
  for (std::uint64_t i = 0; i < cells; ++i) {
    std::uint64_t v = 0;
    if (!header.ReadNumber(&v)) return CorruptError(name + ": PGM raster is truncated");
    if (v > maxval) return CorruptError(name + ": PGM sample exceeds maxval");
    image.samples[i] = ScaleToQuantum(v, maxval);
  }
  return image;
}

namespace {

// What the libpng pass produces; lives in the caller's frame so that a
// png_longjmp out of libpng skips no destructor.
struct PngRaster {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int channels = 0;
  int bit_depth = 0;
  std::vector<std::uint8_t> bytes;
  std::vector<png_bytep> rows;
  Status status;
};

// All libpng calls. This frame holds no object with a destructor across a
// libpng call: errors longjmp back to the setjmp below.
bool ReadPngRaster(png_structp png, png_infop info, const std::string& name,
                   std::uint64_t max_cells, PngRaster* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
  png_read_info(png, info);
  out->width = png_get_image_width(png, info);
  out->height = png_get_image_height(png, info);
  out->status = CheckDimensions(out->width, out->height, name, max_cells);
  if (!out->status.ok()) return true;
  const int color_type = png_get_color_type(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (bit_depth == 16) png_set_swap(png);  // native little-endian 16-bit samples
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  out->channels = png_get_channels(png, info);
  out->bit_depth = png_get_bit_depth(png, info);
  const std::size_t rowbytes = png_get_rowbytes(png, info);
  out->bytes.resize(rowbytes * out->height);
  out->rows.resize(out->height);
  for (png_uint_32 y = 0; y < out->height; ++y) out->rows[y] = out->bytes.data() + y * rowbytes;
  png_read_image(png, out->rows.data());
  return true;
}

}  // namespace

StatusOr<RawImage> DecodePng(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells) {
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) {
    return CorruptError(name + ": not a PNG image");
  }
  PngReadState state{bytes, 0, {}};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, PngError, PngWarning);
  if (png == nullptr) return InternalError("libpng could not start");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return InternalError("libpng could not start");
  }
  png_set_read_fn(png, &state, PngRead);
  PngRaster raster;
  const bool read = ReadPngRaster(png, info, name, max_cells, &raster);
  png_destroy_read_struct(&png, &info, nullptr);
  if (!read) return CorruptError(name + ": bad PNG: " + state.error);
  if (!raster.status.ok()) return raster.status;

  RawImage image;
  image.width = static_cast<int>(raster.width);
  image.height = static_cast<int>(raster.height);
  image.channels = raster.channels;
  const std::size_t samples_per_row = static_cast<std::size_t>(raster.width) * raster.channels;
  image.samples.resize(samples_per_row * raster.height);
  std::size_t k = 0;
  for (png_uint_32 y = 0; y < raster.height; ++y) {
    const std::uint8_t* row = raster.rows[y];
    for (std::size_t i = 0; i < samples_per_row; ++i) {
      if (raster.bit_depth == 16) {
        std::uint16_t v;
        std::memcpy(&v, row + 2 * i, 2);
        image.samples[k++] = v;
      } else {
        image.samples[k++] = static_cast<std::uint16_t>(row[i] * 257);
      }
    }
  }
  return image;
}

namespace {

// True when `prefix` (the first bytes of a file) can start a PNG or a PGM.
bool LooksLikeMapImage(const std::uint8_t* prefix, std::size_t size) {
  if (size >= 8 && png_sig_cmp(prefix, 0, 8) == 0) return true;
  return size >= 2 && prefix[0] == 'P' && (prefix[1] == '5' || prefix[1] == '2');
}

// The first up to 8 bytes of `path` (fewer if it is shorter or cannot be
// read: ReadFileBytes then says why).
std::size_t ReadSignature(const std::string& path, std::uint8_t (&prefix)[8]) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return 0;
  const std::size_t size = std::fread(prefix, 1, sizeof(prefix), file);
  std::fclose(file);
  return size;
}

}  // namespace

StatusOr<RawImage> ReadImageFile(const std::string& path, std::uint64_t max_cells) {
  const std::string name = "'" + path + "'";
  // A file that is no image (or an endless stream such as /dev/zero) is
  // refused on its first bytes, not after reading gigabytes of it.
  std::uint8_t prefix[8];
  const std::size_t prefix_size = ReadSignature(path, prefix);
  if (prefix_size >= 2 && !LooksLikeMapImage(prefix, prefix_size)) {
    return CorruptError(name + ": not a map image (PGM P2/P5 or PNG expected)");
  }
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, kMaxImageFileBytes));
  if (bytes.empty()) return CorruptError(name + ": file is empty, not a map image");
  if (bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0) {
    return DecodePng(bytes, name, max_cells);
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '2')) {
    return DecodePgm(bytes, name, max_cells);
  }
  return CorruptError(name + ": not a map image (PGM P2/P5 or PNG expected)");
}

std::string PgmHeader(int width, int height) {
  return "P5\n# CREATOR: linemap\n" + std::to_string(width) + " " + std::to_string(height) +
         "\n255\n";
}

std::string EncodePgm(int width, int height, std::span<const std::uint8_t> grey) {
  std::string out = PgmHeader(width, height);
  out.append(reinterpret_cast<const char*>(grey.data()), grey.size());
  return out;
}

}  // namespace linemap
