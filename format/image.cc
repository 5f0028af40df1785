#include "format/image.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>
#include <utility>

#include "format/file_io.h"

namespace linemap {
namespace {

// Read buffer of a file-backed image: large enough that a 282 MB PGM takes
// about a thousand reads, small beside the grid it fills.
constexpr std::size_t kReadBufferBytes = std::size_t{256} << 10;

Status CheckDimensions(std::uint64_t width, std::uint64_t height, const std::string& name,
                       std::uint64_t max_cells) {
  if (width == 0 || height == 0) {
    return CorruptError(name + ": image has zero width or height");
  }
  // A grid's sides are ints: no max_cells makes a wider image loadable.
  if (width > 0x7fffffff || height > 0x7fffffff) {
    return UnsupportedError(name + ": image of " + std::to_string(width) + " x " +
                            std::to_string(height) + " cells has a side above 2^31 - 1");
  }
  if (width * height > max_cells) {
    return OverLimitError(Limit::kCells, name + ": image of " + std::to_string(width) + " x " +
                                             std::to_string(height) +
                                             " cells exceeds the limit of " +
                                             std::to_string(max_cells) + " cells");
  }
  return Status::Ok();
}

// The bytes of an image, from memory or from a file read in pieces through
// a fixed buffer. Reads past the end (or after a read error) give fewer
// bytes; status() then tells a read error from the end of the data.
class ByteSource {
 public:
  explicit ByteSource(std::span<const std::uint8_t> bytes)
      : data_(bytes.data()), end_(bytes.size()), known_size_(bytes.size()) {}
  explicit ByteSource(InputFile file) : file_(std::move(file)), buffer_(kReadBufferBytes) {
    if (file_->is_regular()) known_size_ = file_->size();
    data_ = buffer_.data();
  }

  // Bytes left when the size is known up front (memory, a regular file);
  // nullopt for a pipe or a device.
  std::optional<std::uint64_t> remaining() const {
    if (!known_size_) return std::nullopt;
    const std::uint64_t consumed = offset_ + pos_;
    return *known_size_ > consumed ? *known_size_ - consumed : 0;
  }
  // The next byte, or -1 at the end of the data.
  int Peek() {
    if (pos_ == end_ && !Refill()) return -1;
    return data_[pos_];
  }
  int Get() {
    const int c = Peek();
    if (c >= 0) ++pos_;
    return c;
  }
  // Up to `size` bytes into `out`; fewer only at the end of the data.
  std::size_t Read(std::uint8_t* out, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
      if (pos_ == end_ && !Refill()) break;
      const std::size_t n = std::min(size - done, end_ - pos_);
      std::memcpy(out + done, data_ + pos_, n);
      pos_ += n;
      done += n;
    }
    return done;
  }
  // Copies up to `size` of the next bytes into `out` without consuming
  // them; fewer only when the data is shorter (or, from a pipe, when its
  // first read gave fewer).
  std::size_t PeekPrefix(std::uint8_t* out, std::size_t size) {
    if (pos_ == end_) Refill();
    const std::size_t n = std::min(size, end_ - pos_);
    std::memcpy(out, data_ + pos_, n);
    return n;
  }
  const Status& status() const { return status_; }

 private:
  bool Refill() {
    if (!file_ || !status_.ok()) return false;
    StatusOr<std::size_t> n = file_->Read(buffer_.data(), buffer_.size());
    if (!n.ok()) {
      status_ = n.status();
      return false;
    }
    offset_ += end_;
    pos_ = 0;
    end_ = *n;
    return end_ > 0;
  }

  std::optional<InputFile> file_;
  std::vector<std::uint8_t> buffer_;
  const std::uint8_t* data_ = nullptr;
  std::size_t pos_ = 0;       // in data_
  std::size_t end_ = 0;       // bytes in data_
  std::uint64_t offset_ = 0;  // of data_[0] in the whole
  std::optional<std::uint64_t> known_size_;
  Status status_;
};

// Reads the PNM header's and the ASCII raster's whitespace-separated
// decimal numbers, with '#' comments running to the end of the line.
bool ReadPnmNumber(ByteSource* in, std::uint64_t* value) {
  for (int c = in->Peek(); c >= 0; c = in->Peek()) {
    if (std::isspace(c)) {
      in->Get();
    } else if (c == '#') {
      while (c >= 0 && c != '\n' && c != '\r') {
        in->Get();
        c = in->Peek();
      }
    } else {
      break;
    }
  }
  int c = in->Peek();
  if (c < 0 || !std::isdigit(c)) return false;
  std::uint64_t v = 0;
  while (c >= 0 && std::isdigit(c)) {
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
    if (v > 0xffffffffull) return false;
    in->Get();
    c = in->Peek();
  }
  *value = v;
  return true;
}

std::uint16_t ScaleToQuantum(std::uint64_t v, std::uint64_t maxval) {
  if (maxval == 65535) return static_cast<std::uint16_t>(v);
  if (maxval == 255) return static_cast<std::uint16_t>(v * 257);
  return static_cast<std::uint16_t>((v * kQuantumMax + maxval / 2) / maxval);
}

class PgmRowReader : public ImageRowReader {
 public:
  // `source` must start with "P5" or "P2".
  static StatusOr<std::unique_ptr<ImageRowReader>> Open(std::unique_ptr<ByteSource> source,
                                                        const std::string& name,
                                                        std::uint64_t max_cells);
  Status ReadRow(std::uint16_t* row) override;

 private:
  PgmRowReader(std::unique_ptr<ByteSource> source, std::string name)
      : source_(std::move(source)), name_(std::move(name)) {}
  Status Truncated() const {
    if (!source_->status().ok()) return source_->status();
    return CorruptError(name_ + ": PGM raster is truncated");
  }

  std::unique_ptr<ByteSource> source_;
  std::string name_;
  bool ascii_ = false;
  std::uint64_t maxval_ = 0;
  std::size_t bytes_per_sample_ = 1;
  std::vector<std::uint8_t> raw_row_;  // binary rows as stored
};

StatusOr<std::unique_ptr<ImageRowReader>> PgmRowReader::Open(std::unique_ptr<ByteSource> source,
                                                             const std::string& name,
                                                             std::uint64_t max_cells) {
  std::unique_ptr<PgmRowReader> reader(new PgmRowReader(std::move(source), name));
  ByteSource& in = *reader->source_;
  const int magic0 = in.Get(), magic1 = in.Get();
  if (magic0 != 'P' || (magic1 != '5' && magic1 != '2')) {
    return CorruptError(name + ": not a PGM image (expected P5 or P2)");
  }
  reader->ascii_ = magic1 == '2';
  std::uint64_t width = 0, height = 0, maxval = 0;
  if (!ReadPnmNumber(&in, &width) || !ReadPnmNumber(&in, &height) || !ReadPnmNumber(&in, &maxval)) {
    if (!in.status().ok()) return in.status();
    return CorruptError(name + ": malformed PGM header");
  }
  if (maxval == 0 || maxval > 65535) {
    return CorruptError(name + ": PGM maxval " + std::to_string(maxval) + " is outside 1..65535");
  }
  LINEMAP_RETURN_IF_ERROR(CheckDimensions(width, height, name, max_cells));
  // After maxval exactly one whitespace byte separates the header from the
  // raster (netpbm's rule).
  const int separator = in.Get();
  if (separator < 0 || !std::isspace(separator)) {
    return CorruptError(name + ": malformed PGM header");
  }
  const std::uint64_t cells = width * height;
  reader->maxval_ = maxval;
  reader->bytes_per_sample_ = maxval > 255 ? 2 : 1;
  // Checked before any row is allocated or read, when the size is known: a
  // header may claim any size. An ASCII sample takes at least one digit and
  // one separator.
  if (const std::optional<std::uint64_t> left = in.remaining()) {
    const bool short_ascii = reader->ascii_ && *left < 2 * cells - 1;
    const bool short_binary = !reader->ascii_ && *left < cells * reader->bytes_per_sample_;
    if (short_ascii || short_binary) {
      return CorruptError(name + ": PGM raster is truncated (" + std::to_string(*left) +
                          " bytes for " + std::to_string(cells) +
                          (reader->ascii_ ? " ASCII pixels)" : " pixels)"));
    }
  }
  reader->width_ = static_cast<int>(width);
  reader->height_ = static_cast<int>(height);
  reader->channels_ = 1;
  if (!reader->ascii_) reader->raw_row_.resize(width * reader->bytes_per_sample_);
  return std::unique_ptr<ImageRowReader>(std::move(reader));
}

Status PgmRowReader::ReadRow(std::uint16_t* row) {
  const std::size_t width = static_cast<std::size_t>(width_);
  if (ascii_) {
    for (std::size_t x = 0; x < width; ++x) {
      std::uint64_t v = 0;
      if (!ReadPnmNumber(source_.get(), &v)) return Truncated();
      if (v > maxval_) return CorruptError(name_ + ": PGM sample exceeds maxval");
      row[x] = ScaleToQuantum(v, maxval_);
    }
    return Status::Ok();
  }
  if (source_->Read(raw_row_.data(), raw_row_.size()) != raw_row_.size()) return Truncated();
  const std::uint8_t* p = raw_row_.data();
  if (bytes_per_sample_ == 2) {
    for (std::size_t x = 0; x < width; ++x, p += 2) {
      const std::uint64_t v = (std::uint64_t{p[0]} << 8) | p[1];
      if (v > maxval_) return CorruptError(name_ + ": PGM sample exceeds maxval");
      row[x] = ScaleToQuantum(v, maxval_);
    }
    return Status::Ok();
  }
  if (maxval_ == 255) {  // the common map_saver case: no sample can exceed it
    for (std::size_t x = 0; x < width; ++x) row[x] = static_cast<std::uint16_t>(p[x] * 257);
    return Status::Ok();
  }
  for (std::size_t x = 0; x < width; ++x) {
    if (p[x] > maxval_) return CorruptError(name_ + ": PGM sample exceeds maxval");
    row[x] = ScaleToQuantum(p[x], maxval_);
  }
  return Status::Ok();
}

// libpng's input and error reporting. Lives in the reader, whose address
// libpng keeps.
struct PngIo {
  ByteSource* source = nullptr;
  std::string error;
};

void PngRead(png_structp png, png_bytep out, png_size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (io->source->Read(out, length) != length) {
    png_error(png, io->source->status().ok() ? "file is truncated" : "read error");
  }
}

void PngError(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  io->error = message;
  png_longjmp(png, 1);
}

void PngWarning(png_structp, png_const_charp) {}

// The image's form after the transforms the reader asks libpng for.
struct PngShape {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int channels = 0;
  int bit_depth = 0;
  std::size_t rowbytes = 0;
  int passes = 1;
};

// The libpng calls. These frames hold no object with a destructor across a
// libpng call: errors longjmp back to their setjmp.
bool PngReadHeader(png_structp png, png_infop info, PngShape* shape) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
  png_read_info(png, info);
  shape->width = png_get_image_width(png, info);
  shape->height = png_get_image_height(png, info);
  return true;
}

bool PngSetTransforms(png_structp png, png_infop info, PngShape* shape) {
  if (setjmp(png_jmpbuf(png))) return false;
  const int color_type = png_get_color_type(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (bit_depth == 16) png_set_swap(png);  // native little-endian 16-bit samples
  shape->passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  shape->channels = png_get_channels(png, info);
  shape->bit_depth = png_get_bit_depth(png, info);
  shape->rowbytes = png_get_rowbytes(png, info);
  return true;
}

bool PngReadOneRow(png_structp png, png_bytep row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_row(png, row, nullptr);
  return true;
}

bool PngReadAllRows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  return true;
}

class PngRowReader : public ImageRowReader {
 public:
  static StatusOr<std::unique_ptr<ImageRowReader>> Open(std::unique_ptr<ByteSource> source,
                                                        const std::string& name,
                                                        std::uint64_t max_cells);
  ~PngRowReader() override {
    if (png_ != nullptr)
      png_destroy_read_struct(&png_, info_ != nullptr ? &info_ : nullptr, nullptr);
  }
  Status ReadRow(std::uint16_t* row) override;

 private:
  PngRowReader(std::unique_ptr<ByteSource> source, std::string name)
      : source_(std::move(source)), name_(std::move(name)) {
    io_.source = source_.get();
  }
  Status Bad() const {
    if (!source_->status().ok()) return source_->status();
    return CorruptError(name_ + ": bad PNG: " + io_.error);
  }

  std::unique_ptr<ByteSource> source_;
  std::string name_;
  PngIo io_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  PngShape shape_;
  std::vector<std::uint8_t> raster_;  // one row, or all rows when interlaced
  png_uint_32 next_row_ = 0;
};

StatusOr<std::unique_ptr<ImageRowReader>> PngRowReader::Open(std::unique_ptr<ByteSource> source,
                                                             const std::string& name,
                                                             std::uint64_t max_cells) {
  std::uint8_t signature[8];
  if (source->Read(signature, 8) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
    if (!source->status().ok()) return source->status();
    return CorruptError(name + ": not a PNG image");
  }
  std::unique_ptr<PngRowReader> reader(new PngRowReader(std::move(source), name));
  reader->png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader->io_, PngError, PngWarning);
  if (reader->png_ == nullptr) return InternalError("libpng could not start");
  reader->info_ = png_create_info_struct(reader->png_);
  if (reader->info_ == nullptr) return InternalError("libpng could not start");
  png_set_read_fn(reader->png_, &reader->io_, PngRead);
  png_set_sig_bytes(reader->png_, 8);
  PngShape& shape = reader->shape_;
  if (!PngReadHeader(reader->png_, reader->info_, &shape)) return reader->Bad();
  LINEMAP_RETURN_IF_ERROR(CheckDimensions(shape.width, shape.height, name, max_cells));
  if (!PngSetTransforms(reader->png_, reader->info_, &shape)) return reader->Bad();
  reader->width_ = static_cast<int>(shape.width);
  reader->height_ = static_cast<int>(shape.height);
  reader->channels_ = shape.channels;
  if (shape.passes == 1) {
    reader->raster_.resize(shape.rowbytes);
    return std::unique_ptr<ImageRowReader>(std::move(reader));
  }
  // Adam7: a row is complete only after the last pass.
  reader->raster_.resize(shape.rowbytes * shape.height);
  std::vector<png_bytep> rows(shape.height);
  for (png_uint_32 y = 0; y < shape.height; ++y)
    rows[y] = reader->raster_.data() + y * shape.rowbytes;
  if (!PngReadAllRows(reader->png_, rows.data())) return reader->Bad();
  return std::unique_ptr<ImageRowReader>(std::move(reader));
}

Status PngRowReader::ReadRow(std::uint16_t* row) {
  if (next_row_ >= shape_.height) return InternalError(name_ + ": read past the last row");
  const std::uint8_t* bytes = raster_.data();
  if (shape_.passes == 1) {
    if (!PngReadOneRow(png_, raster_.data())) return Bad();
  } else {
    bytes += next_row_ * shape_.rowbytes;
  }
  ++next_row_;
  const std::size_t samples = static_cast<std::size_t>(shape_.width) * shape_.channels;
  if (shape_.bit_depth == 16) {
    std::memcpy(row, bytes, samples * 2);
  } else {
    for (std::size_t i = 0; i < samples; ++i) row[i] = static_cast<std::uint16_t>(bytes[i] * 257);
  }
  return Status::Ok();
}

bool IsPngSignature(const std::uint8_t* prefix, std::size_t size) {
  return size >= 8 && png_sig_cmp(prefix, 0, 8) == 0;
}

bool IsPgmSignature(const std::uint8_t* prefix, std::size_t size) {
  return size >= 2 && prefix[0] == 'P' && (prefix[1] == '5' || prefix[1] == '2');
}

// All rows of `reader` as one RawImage.
StatusOr<RawImage> ReadAllRows(ImageRowReader& reader) {
  RawImage image;
  image.width = reader.width();
  image.height = reader.height();
  image.channels = reader.channels();
  const std::size_t row_samples = static_cast<std::size_t>(image.width) * image.channels;
  image.samples.resize(row_samples * image.height);
  for (int y = 0; y < image.height; ++y) {
    LINEMAP_RETURN_IF_ERROR(reader.ReadRow(image.samples.data() + y * row_samples));
  }
  return image;
}

}  // namespace

StatusOr<RawImage> DecodePgm(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells) {
  if (!IsPgmSignature(bytes.data(), bytes.size())) {
    return CorruptError(name + ": not a PGM image (expected P5 or P2)");
  }
  LINEMAP_ASSIGN_OR_RETURN(
      std::unique_ptr<ImageRowReader> reader,
      PgmRowReader::Open(std::make_unique<ByteSource>(bytes), name, max_cells));
  return ReadAllRows(*reader);
}

StatusOr<RawImage> DecodePng(std::span<const std::uint8_t> bytes, const std::string& name,
                             std::uint64_t max_cells) {
  LINEMAP_ASSIGN_OR_RETURN(
      std::unique_ptr<ImageRowReader> reader,
      PngRowReader::Open(std::make_unique<ByteSource>(bytes), name, max_cells));
  return ReadAllRows(*reader);
}

StatusOr<std::unique_ptr<ImageRowReader>> OpenImageRows(const std::string& path,
                                                        std::uint64_t max_cells) {
  const std::string name = "'" + path + "'";
  LINEMAP_ASSIGN_OR_RETURN(InputFile file, InputFile::Open(path));
  auto source = std::make_unique<ByteSource>(std::move(file));
  // A file that is no image (or an endless stream such as /dev/zero) is
  // refused on its first bytes.
  std::uint8_t prefix[8];
  const std::size_t prefix_size = source->PeekPrefix(prefix, sizeof(prefix));
  LINEMAP_RETURN_IF_ERROR(source->status());
  if (IsPngSignature(prefix, prefix_size)) {
    return PngRowReader::Open(std::move(source), name, max_cells);
  }
  if (IsPgmSignature(prefix, prefix_size)) {
    return PgmRowReader::Open(std::move(source), name, max_cells);
  }
  if (prefix_size == 0) return CorruptError(name + ": file is empty, not a map image");
  return CorruptError(name + ": not a map image (PGM P2/P5 or PNG expected)");
}

StatusOr<RawImage> ReadImageFile(const std::string& path, std::uint64_t max_cells) {
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<ImageRowReader> reader, OpenImageRows(path, max_cells));
  return ReadAllRows(*reader);
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
