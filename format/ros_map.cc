// ROS map_server YAML + image reading and writing (include/linemap/map_io.h).
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "format/image.h"
#include "format/pixel_classifier.h"
#include "linemap/map_io.h"

namespace linemap {
namespace {

constexpr std::uint64_t kMaxYamlBytes = 1 << 20;

std::string Quoted(const std::string& path) { return "'" + path + "'"; }

bool IsYamlPath(const std::string& path) {
  return HasExtension(path, ".yaml") || HasExtension(path, ".yml");
}

std::string DirectoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return "";
  return path.substr(0, slash + 1);
}

std::string StemOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = base.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);
}

// The shortest decimal text that reads back as the same double.
std::string FormatDouble(double v) {
  std::array<char, 64> buf;
  const auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  std::string s(buf.data(), result.ptr);
  // Keep it a YAML float rather than an int where it has no fraction.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

Status CheckThresholds(const MapMetadata& meta, const std::string& where) {
  auto in_unit = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; };
  if (!in_unit(meta.occupied_thresh)) {
    return InvalidArgumentError(where + ": occupied_thresh must be within 0..1");
  }
  if (!in_unit(meta.free_thresh)) {
    return InvalidArgumentError(where + ": free_thresh must be within 0..1");
  }
  return Status::Ok();
}

Status CheckResolution(double resolution, const std::string& where) {
  if (!std::isfinite(resolution) || resolution <= 0.0) {
    return InvalidArgumentError(where + ": resolution must be a positive number of metres, not " +
                                FormatDouble(resolution));
  }
  return Status::Ok();
}

StatusOr<MapMode> ParseMode(const std::string& text, const std::string& where) {
  if (std::optional<MapMode> mode = MapModeFromName(text)) return *mode;
  return InvalidArgumentError(where + ": mode '" + text + "' is not trinary, scale or raw");
}

template <typename T>
StatusOr<T> ReadScalar(const YAML::Node& doc, const char* key, const std::string& where) {
  try {
    return doc[key].as<T>();
  } catch (const YAML::Exception&) {
    return InvalidArgumentError(where + ": key '" + key + "' has the wrong type");
  }
}

// The YAML's origin [x, y, yaw]. Required, as map_server requires it (like
// image and resolution): a map taken at 0,0,0 instead would lie in the wrong
// place without a word.
StatusOr<Pose2D> ReadOrigin(const YAML::Node& doc, const std::string& where) {
  if (!doc["origin"])
    return InvalidArgumentError(
        where + ": has no 'origin' key (map_server needs one too: add origin: [x, y, yaw])");
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> origin,
                           ReadScalar<std::vector<double>>(doc, "origin", where));
  if (origin.size() != 3) {
    return InvalidArgumentError(where + ": 'origin' must have 3 elements [x, y, yaw], not " +
                                std::to_string(origin.size()));
  }
  for (double v : origin) {
    if (!std::isfinite(v)) return InvalidArgumentError(where + ": 'origin' is not finite");
  }
  return Pose2D{origin[0], origin[1], origin[2]};
}

struct YamlMap {
  std::string image_path;
  MapMetadata meta;
};

StatusOr<YamlMap> ParseMapYaml(const std::string& yaml_path) {
  const std::string where = Quoted(yaml_path);
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(yaml_path, kMaxYamlBytes, Limit::kNone));
  YAML::Node doc;
  try {
    doc = YAML::Load(std::string(bytes.begin(), bytes.end()));
  } catch (const YAML::Exception& e) {
    return InvalidArgumentError(where + ": not valid YAML (line " +
                                std::to_string(e.mark.line + 1) + ")");
  }
  if (!doc.IsMap())
    return InvalidArgumentError(where + ": not a map YAML (expected key: value pairs)");

  YamlMap out;
  if (!doc["image"]) return InvalidArgumentError(where + ": has no 'image' key");
  LINEMAP_ASSIGN_OR_RETURN(std::string image, ReadScalar<std::string>(doc, "image", where));
  if (image.empty()) return InvalidArgumentError(where + ": 'image' is empty");
  out.image_path = image[0] == '/' ? image : DirectoryOf(yaml_path) + image;

  if (!doc["resolution"]) return InvalidArgumentError(where + ": has no 'resolution' key");
  LINEMAP_ASSIGN_OR_RETURN(out.meta.resolution, ReadScalar<double>(doc, "resolution", where));
  LINEMAP_RETURN_IF_ERROR(CheckResolution(out.meta.resolution, where));

  LINEMAP_ASSIGN_OR_RETURN(out.meta.origin, ReadOrigin(doc, where));
  if (doc["negate"]) {
    // nav2 reads negate as an int and falls back to a bool.
    StatusOr<int> as_int = ReadScalar<int>(doc, "negate", where);
    if (as_int.ok()) {
      out.meta.negate = *as_int != 0;
    } else {
      LINEMAP_ASSIGN_OR_RETURN(out.meta.negate, ReadScalar<bool>(doc, "negate", where));
    }
  }
  if (doc["occupied_thresh"]) {
    LINEMAP_ASSIGN_OR_RETURN(out.meta.occupied_thresh,
                             ReadScalar<double>(doc, "occupied_thresh", where));
  }
  if (doc["free_thresh"]) {
    LINEMAP_ASSIGN_OR_RETURN(out.meta.free_thresh, ReadScalar<double>(doc, "free_thresh", where));
  }
  if (doc["mode"]) {
    LINEMAP_ASSIGN_OR_RETURN(std::string mode, ReadScalar<std::string>(doc, "mode", where));
    LINEMAP_ASSIGN_OR_RETURN(out.meta.mode, ParseMode(mode, where));
  }
  LINEMAP_RETURN_IF_ERROR(CheckThresholds(out.meta, where));
  return out;
}

// The caller's values over the YAML's (or the defaults of a bare image),
// checked as a YAML's are. A threshold the caller sets must also leave the
// free one below the occupied one; a YAML's own pair is taken as it is, as
// map_server takes it.
Status ApplyOverrides(const MapLoadOptions& options, const std::string& where, MapMetadata* meta) {
  if (options.resolution) meta->resolution = *options.resolution;
  if (options.origin) meta->origin = *options.origin;
  if (options.negate) meta->negate = *options.negate;
  if (options.occupied_thresh) meta->occupied_thresh = *options.occupied_thresh;
  if (options.free_thresh) meta->free_thresh = *options.free_thresh;
  if (options.mode) meta->mode = *options.mode;
  LINEMAP_RETURN_IF_ERROR(CheckResolution(meta->resolution, where));
  LINEMAP_RETURN_IF_ERROR(CheckThresholds(*meta, where));
  if ((options.occupied_thresh || options.free_thresh) &&
      !(meta->free_thresh < meta->occupied_thresh)) {
    return InvalidArgumentError(where + ": free threshold " + FormatDouble(meta->free_thresh) +
                                " must be below the occupied threshold " +
                                FormatDouble(meta->occupied_thresh));
  }
  return Status::Ok();
}

// True when map_saver's three grey values read back as their own states
// under `meta`.
bool HoldsMapSaverValues(const MapMetadata& meta) {
  return ClassifyGrey8(kPgmFree, meta) == Cell::kFree &&
         ClassifyGrey8(kPgmOccupied, meta) == Cell::kOccupied &&
         ClassifyGrey8(kPgmUnknown, meta) == Cell::kUnknown;
}

// The metadata written beside a map_saver PGM: always trinary without
// negate (the pixel values are fixed), keeping the grid's thresholds when
// they read 0 / 254 / 205 back correctly and map_saver's 0.65 / 0.196
// otherwise (nav2's own depot.yaml has free_thresh 0.25, under which 205
// would read as free).
MapMetadata SavedMetadata(const MapMetadata& source) {
  MapMetadata meta = source;
  meta.mode = MapMode::kTrinary;
  meta.negate = false;
  if (!HoldsMapSaverValues(meta)) {
    meta.occupied_thresh = kDefaultOccupiedThresh;
    meta.free_thresh = kDefaultFreeThresh;
  }
  return meta;
}

// True for a name YAML reads back as the same text without quotes: letters,
// digits and "._-", not starting with '-' (map_saver's names stay as they
// were, unquoted). The name always ends in ".pgm", so it never reads as a
// number, a bool or null.
bool IsPlainYamlName(const std::string& name) {
  if (name.empty() || name[0] == '-') return false;
  for (const char ch : name) {
    const bool plain = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                       (ch >= '0' && ch <= '9') || ch == '.' || ch == '_' || ch == '-';
    if (!plain) return false;
  }
  return true;
}

// `name` as a YAML scalar that yaml-cpp (and so nav2's map_server) reads back
// byte for byte, whatever the file name holds: plain when it can be, else
// single-quoted ('' for '), else, when it holds ASCII control characters
// (which a single-quoted scalar cannot carry: line breaks fold), double-quoted
// with \xNN escapes. Bytes from 0x80 up are written as they are.
std::string YamlScalar(const std::string& name) {
  if (IsPlainYamlName(name)) return name;
  const auto is_control = [](char ch) {
    const unsigned char c = static_cast<unsigned char>(ch);
    return c < 0x20 || c == 0x7f;
  };
  std::string out;
  if (std::none_of(name.begin(), name.end(), is_control)) {
    out = "'";
    for (const char c : name) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
  }
  out = "\"";
  for (const char c : name) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (is_control(c)) {
      static const char kHex[] = "0123456789ABCDEF";
      const unsigned char u = static_cast<unsigned char>(c);
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string YamlText(const std::string& image_name, const MapMetadata& meta) {
  std::string y;
  y += "image: " + YamlScalar(image_name) + "\n";
  y += std::string("mode: ") + MapModeName(meta.mode) + "\n";
  y += "resolution: " + FormatDouble(meta.resolution) + "\n";
  y += "origin: [" + FormatDouble(meta.origin.x) + ", " + FormatDouble(meta.origin.y) + ", " +
       FormatDouble(meta.origin.yaw) + "]\n";
  y += std::string("negate: ") + (meta.negate ? "1" : "0") + "\n";
  y += "occupied_thresh: " + FormatDouble(meta.occupied_thresh) + "\n";
  y += "free_thresh: " + FormatDouble(meta.free_thresh) + "\n";
  return y;
}

}  // namespace

MapRowReader::MapRowReader(std::unique_ptr<ImageRowReader> image, const MapMetadata& meta)
    : image_(std::move(image)),
      meta_(meta),
      samples_(static_cast<std::size_t>(image_->width()) * image_->channels()),
      last_cell_(ClassifyPixel(&last_sample_, 1, meta)) {}

MapRowReader::~MapRowReader() = default;

int MapRowReader::width() const { return image_->width(); }
int MapRowReader::height() const { return image_->height(); }

StatusOr<std::unique_ptr<MapRowReader>> MapRowReader::OpenImage(const std::string& image_path,
                                                                const MapMetadata& meta,
                                                                std::uint64_t max_cells) {
  LINEMAP_RETURN_IF_ERROR(CheckResolution(meta.resolution, Quoted(image_path)));
  LINEMAP_RETURN_IF_ERROR(CheckThresholds(meta, Quoted(image_path)));
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<ImageRowReader> image,
                           OpenImageRows(image_path, max_cells));
  return std::unique_ptr<MapRowReader>(new MapRowReader(std::move(image), meta));
}

StatusOr<std::unique_ptr<MapRowReader>> MapRowReader::Open(const std::string& path,
                                                           const MapLoadOptions& options) {
  if (path.empty()) return InvalidArgumentError("empty map file name");
  if (IsDirectory(path)) return InvalidArgumentError(Quoted(path) + " is a directory, not a map");
  if (!IsYamlPath(path)) {
    MapMetadata meta;
    LINEMAP_RETURN_IF_ERROR(ApplyOverrides(options, Quoted(path), &meta));
    return OpenImage(path, meta, options.max_cells);
  }
  LINEMAP_ASSIGN_OR_RETURN(YamlMap yaml, ParseMapYaml(path));
  LINEMAP_RETURN_IF_ERROR(ApplyOverrides(options, Quoted(path), &yaml.meta));
  StatusOr<std::unique_ptr<MapRowReader>> reader =
      OpenImage(yaml.image_path, yaml.meta, options.max_cells);
  if (!reader.ok() && reader.status().code() == StatusCode::kNotFound) {
    return NotFoundError(Quoted(path) + " names image " + Quoted(yaml.image_path) +
                         ", which does not exist");
  }
  if (!reader.ok()) return reader.status().WithContext(Quoted(path));
  (*reader)->bare_image_ = false;
  return reader;
}

Status MapRowReader::ReadRow(Cell* cells) {
  LINEMAP_RETURN_IF_ERROR(image_->ReadRow(samples_.data()));
  const int width = image_->width();
  const int channels = image_->channels();
  if (channels != 1) {
    for (int x = 0; x < width; ++x) {
      cells[x] =
          ClassifyPixel(samples_.data() + static_cast<std::size_t>(x) * channels, channels, meta_);
    }
    return Status::Ok();
  }
  for (int x = 0; x < width; ++x) {
    if (samples_[x] != last_sample_) {
      last_sample_ = samples_[x];
      last_cell_ = ClassifyPixel(&last_sample_, 1, meta_);
    }
    cells[x] = last_cell_;
  }
  return Status::Ok();
}

namespace {

// Loading holds the grid and one row of samples, never the image (2 bytes
// per pixel per channel as quanta).
StatusOr<Grid> ReadAllRows(MapRowReader* reader) {
  Grid grid(reader->width(), reader->height());
  grid.meta = reader->meta();
  // Image row 0 is the top of the map.
  for (int row = reader->height() - 1; row >= 0; --row) {
    LINEMAP_RETURN_IF_ERROR(reader->ReadRow(grid.mutable_cells().data() + grid.Index(0, row)));
  }
  return grid;
}

}  // namespace

StatusOr<Grid> LoadMapImage(const std::string& image_path, const MapMetadata& meta,
                            std::uint64_t max_cells) {
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<MapRowReader> reader,
                           MapRowReader::OpenImage(image_path, meta, max_cells));
  return ReadAllRows(reader.get());
}

StatusOr<Grid> LoadRosMap(const std::string& path, const MapLoadOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<MapRowReader> reader, MapRowReader::Open(path, options));
  StatusOr<Grid> grid = ReadAllRows(reader.get());
  if (!grid.ok() && IsYamlPath(path)) return grid.status().WithContext(Quoted(path));
  return grid;
}

StatusOr<std::string> RosMapImagePath(const std::string& path) {
  if (!IsYamlPath(path)) return path;
  LINEMAP_ASSIGN_OR_RETURN(YamlMap yaml, ParseMapYaml(path));
  return yaml.image_path;
}

std::string SavedImagePath(const std::string& yaml_path) {
  return DirectoryOf(yaml_path) + StemOf(yaml_path) + ".pgm";
}

// The PGM bytes of rectangles of cells, gathered in a fixed buffer and
// written where they belong in the file (rows of a full-width rectangle lie
// one after the other in the PGM, top row first).
struct RosMapWriter::Impl {
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

  Impl(AtomicFileWriter pgm_writer, AtomicFileWriter yaml_writer)
      : pgm(std::move(pgm_writer)), yaml(std::move(yaml_writer)) {}

  AtomicFileWriter pgm;
  AtomicFileWriter yaml;
  std::string yaml_text;
  int width = 0;
  int height = 0;
  std::uint64_t header_bytes = 0;
  std::uint64_t cells_written = 0;
  std::string buffer;  // grey bytes of the run at buffer_offset
  std::uint64_t buffer_offset = 0;

  Status Flush() {
    if (buffer.empty()) return Status::Ok();
    const Status written = pgm.WriteAt(buffer_offset, buffer);
    buffer.clear();
    return written;
  }

  // The grey bytes of `n` cells at PGM byte `offset`.
  Status Put(std::uint64_t offset, const Cell* cells, std::size_t n) {
    static constexpr char kGrey[3] = {static_cast<char>(kPgmFree), static_cast<char>(kPgmOccupied),
                                      static_cast<char>(kPgmUnknown)};  // by Cell value
    while (n > 0) {
      const bool continues = !buffer.empty() && buffer_offset + buffer.size() == offset;
      if (!continues || buffer.size() == kBufferBytes) {
        LINEMAP_RETURN_IF_ERROR(Flush());
        buffer_offset = offset;
      }
      const std::size_t k = std::min(n, kBufferBytes - buffer.size());
      const std::size_t start = buffer.size();
      buffer.resize(start + k);
      for (std::size_t i = 0; i < k; ++i) buffer[start + i] = kGrey[static_cast<int>(cells[i])];
      cells += k;
      offset += k;
      n -= k;
    }
    return Status::Ok();
  }
};

RosMapWriter::RosMapWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RosMapWriter::RosMapWriter(RosMapWriter&&) noexcept = default;
RosMapWriter& RosMapWriter::operator=(RosMapWriter&&) noexcept = default;
RosMapWriter::~RosMapWriter() = default;

StatusOr<RosMapWriter> RosMapWriter::Open(const std::string& yaml_path, int width, int height,
                                          const MapMetadata& meta, Durability durability) {
  if (!IsYamlPath(yaml_path)) {
    return InvalidArgumentError(Quoted(yaml_path) + ": output map name must end in .yaml or .yml");
  }
  if (width <= 0 || height <= 0) {
    return InvalidArgumentError(Quoted(yaml_path) + ": cannot save an empty grid");
  }
  LINEMAP_ASSIGN_OR_RETURN(AtomicFileWriter pgm,
                           AtomicFileWriter::Open(SavedImagePath(yaml_path), durability));
  LINEMAP_ASSIGN_OR_RETURN(AtomicFileWriter yaml, AtomicFileWriter::Open(yaml_path, durability));
  auto impl = std::make_unique<Impl>(std::move(pgm), std::move(yaml));
  impl->yaml_text = YamlText(StemOf(yaml_path) + ".pgm", SavedMetadata(meta));
  impl->width = width;
  impl->height = height;
  const std::string header = PgmHeader(width, height);
  impl->header_bytes = header.size();
  LINEMAP_RETURN_IF_ERROR(impl->pgm.Append(header));
  impl->buffer.reserve(Impl::kBufferBytes);
  return RosMapWriter(std::move(impl));
}

Status RosMapWriter::WriteCells(int col0, int row0, int cols, int rows, const Cell* cells) {
  Impl& m = *impl_;
  if (col0 < 0 || row0 < 0 || cols <= 0 || rows <= 0 || cols > m.width - col0 ||
      rows > m.height - row0) {
    return InvalidArgumentError("cells [" + std::to_string(col0) + ", +" + std::to_string(cols) +
                                ") x [" + std::to_string(row0) + ", +" + std::to_string(rows) +
                                ") are empty or not inside the " + std::to_string(m.width) + " x " +
                                std::to_string(m.height) + " map of " + Quoted(m.yaml.path()));
  }
  // Top row first: the PGM runs top down, grid rows bottom up.
  for (int r = row0 + rows - 1; r >= row0; --r) {
    const std::uint64_t image_row = static_cast<std::uint64_t>(m.height - 1 - r);
    const std::uint64_t offset =
        m.header_bytes + image_row * static_cast<std::uint64_t>(m.width) + col0;
    LINEMAP_RETURN_IF_ERROR(m.Put(offset, cells + static_cast<std::size_t>(r - row0) * cols, cols));
  }
  LINEMAP_RETURN_IF_ERROR(m.Flush());
  m.cells_written += static_cast<std::uint64_t>(cols) * rows;
  return Status::Ok();
}

Status RosMapWriter::Commit() {
  Impl& m = *impl_;
  const std::uint64_t cells = static_cast<std::uint64_t>(m.width) * m.height;
  if (m.cells_written != cells) {
    return InternalError(Quoted(m.yaml.path()) + ": " + std::to_string(m.cells_written) + " of " +
                         std::to_string(cells) + " cells written; not saving");
  }
  LINEMAP_RETURN_IF_ERROR(m.yaml.Append(m.yaml_text));
  return CommitFilesAtomic({&m.pgm, &m.yaml});
}

Status SaveRosMap(const std::string& yaml_path, const Grid& grid, Durability durability) {
  LINEMAP_ASSIGN_OR_RETURN(
      RosMapWriter writer,
      RosMapWriter::Open(yaml_path, grid.width(), grid.height(), grid.meta, durability));
  // Bands of about 1 MiB: the image is never held whole beside the grid.
  const int band_rows = static_cast<int>(
      std::max<std::size_t>(1, (std::size_t{1} << 20) / static_cast<std::size_t>(grid.width())));
  // From the top of the map down, so the PGM is written front to back.
  for (int row1 = grid.height(); row1 > 0; row1 -= band_rows) {
    const int row0 = std::max(0, row1 - band_rows);
    LINEMAP_RETURN_IF_ERROR(writer.WriteCells(0, row0, grid.width(), row1 - row0,
                                              grid.cells().data() + grid.Index(0, row0)));
  }
  return writer.Commit();
}

}  // namespace linemap
