#include "tools/bench/image_anchors.h"

#include <cctype>

#include "format/file_io.h"
#include "format/image.h"
#include "linemap/map_io.h"
#include "tools/bench/subprocess.h"

namespace linemap::bench {
namespace {

// Encoded and decoded images are at most a few bytes per cell; a larger file
// means a broken program, not a map.
constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 34;

std::vector<std::string> Substitute(const std::vector<std::string>& argv, const std::string& in,
                                    const std::string& out) {
  std::vector<std::string> filled;
  for (const std::string& arg : argv)
    filled.push_back(arg == "{in}" ? in : arg == "{out}" ? out : arg);
  return filled;
}

// Runs one of the codec's programs; every failure names the codec.
StatusOr<double> RunCodecProgram(const ImageCodec& codec, const std::vector<std::string>& argv) {
  if (argv.empty()) return InvalidArgumentError(codec.label + ": no command");
  if (!ToolAvailable(argv[0])) {
    return NotFoundError(codec.label + ": " + argv[0] + " not found in PATH (Debian package " +
                         codec.package + ")");
  }
  StatusOr<SubprocessRun> run = RunSubprocessTimed(argv);
  if (!run.ok()) return Status(run.status().code(), codec.label + ": " + run.status().message());
  if (run->exit_code != 0) {
    return IoError(codec.label + ": " + argv[0] + " failed with exit code " +
                   std::to_string(run->exit_code));
  }
  return run->cpu_ms;
}

StatusOr<std::string> ReadScratch(const std::string& path) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, kMaxFileBytes, Limit::kNone));
  return std::string(bytes.begin(), bytes.end());
}

// Reads the next netpbm header number at `*pos`, skipping white space and
// '#' comments; -1 when there is none.
long NextHeaderNumber(const std::string& bytes, std::size_t* pos) {
  while (*pos < bytes.size()) {
    const char c = bytes[*pos];
    if (c == '#') {
      while (*pos < bytes.size() && bytes[*pos] != '\n') ++*pos;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++*pos;
    } else {
      break;
    }
  }
  long value = -1;
  while (*pos < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[*pos]))) {
    value = (value < 0 ? 0 : value * 10) + (bytes[*pos] - '0');
    if (value > (1L << 30)) return -1;
    ++*pos;
  }
  return value;
}

}  // namespace

std::vector<std::uint8_t> MapSaverGrey(const Grid& grid) {
  std::vector<std::uint8_t> grey(grid.size());
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      const Cell cell = grid.at(c, r);
      grey[grid.Index(c, grid.height() - 1 - r)] = cell == Cell::kFree       ? kPgmFree
                                                   : cell == Cell::kOccupied ? kPgmOccupied
                                                                             : kPgmUnknown;
    }
  }
  return grey;
}

std::string MapSaverPgm(const Grid& grid) {
  return EncodePgm(grid.width(), grid.height(), MapSaverGrey(grid));
}

ImageCodec JpegXlCodec(const JxlOptions& options) {
  return {"JPEG XL",
          "libjxl-tools",
          {options.encoder, "{in}", "{out}", "-d", "0", "-e", std::to_string(options.effort), "-E",
           std::to_string(options.prev_channels), "-I", std::to_string(options.iterations_percent),
           "-g", std::to_string(options.group_size_shift)},
          "map.jxl",
          {options.decoder, "{in}", "{out}"},
          "back.pgm"};
}

ImageCodec WebpCodec(const WebpOptions& options) {
  return {"WebP",
          "webp",
          {options.encoder, "-quiet", "-lossless", "-z", std::to_string(options.method), "{in}",
           "-o", "{out}"},
          "map.webp",
          {options.decoder, "-quiet", "{in}", "-ppm", "-o", "{out}"},
          "back.ppm"};
}

StatusOr<AnchorFile> EncodeImageAnchor(const Grid& grid, const ImageCodec& codec) {
  LINEMAP_ASSIGN_OR_RETURN(ScratchDir dir, ScratchDir::Create("anchor"));
  LINEMAP_ASSIGN_OR_RETURN(const std::string in,
                           dir.WriteScratchFile("map.pgm", MapSaverPgm(grid)));
  const std::string out = dir.path() + "/" + codec.encoded_name;
  AnchorFile file;
  LINEMAP_ASSIGN_OR_RETURN(file.encode_cpu_ms,
                           RunCodecProgram(codec, Substitute(codec.encode, in, out)));
  LINEMAP_ASSIGN_OR_RETURN(file.bytes, ReadScratch(out));
  return file;
}

StatusOr<double> DecodeAndCheckImageAnchor(const Grid& grid, const ImageCodec& codec,
                                           const std::string& encoded) {
  LINEMAP_ASSIGN_OR_RETURN(ScratchDir dir, ScratchDir::Create("anchor"));
  LINEMAP_ASSIGN_OR_RETURN(const std::string in, dir.WriteScratchFile(codec.encoded_name, encoded));
  const std::string out = dir.path() + "/" + codec.decoded_name;
  LINEMAP_ASSIGN_OR_RETURN(const double cpu_ms,
                           RunCodecProgram(codec, Substitute(codec.decode, in, out)));
  LINEMAP_ASSIGN_OR_RETURN(const std::string decoded, ReadScratch(out));
  int width = 0, height = 0;
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> grey,
                           ReadNetpbmGrey(decoded, codec.label + " decode", &width, &height));
  if (width != grid.width() || height != grid.height()) {
    return CorruptError(codec.label + ": decoded " + std::to_string(width) + " x " +
                        std::to_string(height) + " pixels, the map is " +
                        std::to_string(grid.width()) + " x " + std::to_string(grid.height()));
  }
  const std::vector<std::uint8_t> expected = MapSaverGrey(grid);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (grey[i] != expected[i]) {
      return CorruptError(codec.label + ": not lossless: image pixel (" +
                          std::to_string(i % width) + ", " + std::to_string(i / width) +
                          ") decodes to " + std::to_string(grey[i]) + ", not " +
                          std::to_string(expected[i]));
    }
  }
  return cpu_ms;
}

StatusOr<std::vector<std::uint8_t>> ReadNetpbmGrey(const std::string& bytes,
                                                   const std::string& name, int* width,
                                                   int* height) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '6')) {
    return CorruptError(name + ": not a binary PGM (P5) or PPM (P6)");
  }
  const std::size_t channels = bytes[1] == '5' ? 1 : 3;
  std::size_t pos = 2;
  const long w = NextHeaderNumber(bytes, &pos);
  const long h = NextHeaderNumber(bytes, &pos);
  const long maxval = NextHeaderNumber(bytes, &pos);
  if (w <= 0 || h <= 0 || maxval != 255 || pos >= bytes.size()) {
    return CorruptError(name + ": bad header (want width, height and maxval 255)");
  }
  ++pos;  // the single white-space byte before the pixels
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if ((bytes.size() - pos) / channels < pixels) {
    return CorruptError(name + ": " + std::to_string(w) + " x " + std::to_string(h) +
                        " pixels announced, fewer bytes follow");
  }
  std::vector<std::uint8_t> grey(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const char* p = bytes.data() + pos + i * channels;
    if (channels == 3 && (p[0] != p[1] || p[0] != p[2])) {
      return CorruptError(name + ": pixel " + std::to_string(i) + " is not grey");
    }
    grey[i] = static_cast<std::uint8_t>(p[0]);
  }
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  return grey;
}

}  // namespace linemap::bench
