#include "tools/bench/png_codec.h"

#include <png.h>

#include <array>
#include <csetjmp>
#include <cstring>

namespace linemap::bench {
namespace {

constexpr std::uint8_t kGreyOf[3] = {254, 0, 205};  // indexed by Cell: free, occupied, unknown

struct WriteState {
  std::string out;
  std::string error;
};

void WriteBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* state = static_cast<WriteState*>(png_get_io_ptr(png));
  state->out.append(reinterpret_cast<const char*>(data), length);
}

void Flush(png_structp) {}

void OnError(png_structp png, png_const_charp message) {
  auto* text = static_cast<std::string*>(png_get_error_ptr(png));
  if (text) *text = message;
  png_longjmp(png, 1);
}

void OnWarning(png_structp, png_const_charp) {}

// One image row (top first) in the layout's sample format.
void PackRow(const Grid& grid, int image_row, PngLayout layout, std::vector<png_byte>* row) {
  const int grid_row = grid.height() - 1 - image_row;
  const Cell* cells = grid.cells().data() + grid.Index(0, grid_row);
  const int width = grid.width();
  if (layout == PngLayout::kGrey8) {
    for (int c = 0; c < width; ++c) (*row)[c] = kGreyOf[static_cast<int>(cells[c])];
  } else if (layout == PngLayout::kPalette8) {
    for (int c = 0; c < width; ++c) (*row)[c] = static_cast<png_byte>(cells[c]);
  } else {
    std::fill(row->begin(), row->end(), 0);
    for (int c = 0; c < width; ++c) {
      (*row)[c >> 2] |= static_cast<png_byte>(static_cast<int>(cells[c]) << (6 - 2 * (c & 3)));
    }
  }
}

// libpng's setjmp error handling lives in its own function without C++
// objects whose destructors a longjmp would skip.
bool WritePng(png_structp png, png_infop info, const Grid& grid, PngLayout layout, int level,
              std::vector<png_byte>* row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_compression_level(png, level);
  const bool palette = layout != PngLayout::kGrey8;
  const int depth = layout == PngLayout::kPalette2 ? 2 : 8;
  png_set_IHDR(png, info, static_cast<png_uint_32>(grid.width()),
               static_cast<png_uint_32>(grid.height()), depth,
               palette ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (palette) {
    std::array<png_color, 3> colours;
    for (int i = 0; i < 3; ++i) colours[i] = {kGreyOf[i], kGreyOf[i], kGreyOf[i]};
    png_set_PLTE(png, info, colours.data(), 3);
  }
  png_write_info(png, info);
  for (int r = 0; r < grid.height(); ++r) {
    PackRow(grid, r, layout, row);
    png_write_row(png, row->data());
  }
  png_write_end(png, info);
  return true;
}

struct ReadState {
  std::span<const std::uint8_t> data;
  std::size_t offset = 0;
};

void ReadBytes(png_structp png, png_bytep out, png_size_t length) {
  auto* state = static_cast<ReadState*>(png_get_io_ptr(png));
  if (state->data.size() - state->offset < length) png_error(png, "truncated PNG");
  std::memcpy(out, state->data.data() + state->offset, length);
  state->offset += length;
}

bool ReadPng(png_structp png, png_infop info, Grid* grid, std::vector<png_byte>* row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  const int colour = png_get_color_type(png, info);
  if (png_get_bit_depth(png, info) > 8 ||
      (colour != PNG_COLOR_TYPE_GRAY && colour != PNG_COLOR_TYPE_PALETTE) || width > (1u << 20) ||
      height > (1u << 20)) {
    png_error(png, "not an 8-bit-or-less grey or palette PNG");
  }
  // One byte per pixel (small depths unpacked), and a table from that byte
  // to the cell: a palette PNG's indices are looked up in its palette's
  // grey values, not expanded to RGB and converted back to grey by libpng
  // (which made every decode of the bench's smallest layout, 2-bit palette,
  // about 1.4x slower than the straightforward reading).
  const auto cell_of_grey = [](int v) {
    return v == 254 ? Cell::kFree : v == 0 ? Cell::kOccupied : Cell::kUnknown;
  };
  std::array<Cell, 256> cell_of;
  cell_of.fill(Cell::kUnknown);
  if (colour == PNG_COLOR_TYPE_PALETTE) {
    png_set_packing(png);
    png_colorp palette = nullptr;
    int entries = 0;
    if (png_get_PLTE(png, info, &palette, &entries) != PNG_INFO_PLTE) png_error(png, "no palette");
    for (int i = 0; i < entries && i < 256; ++i) {
      if (palette[i].red != palette[i].green || palette[i].red != palette[i].blue) {
        png_error(png, "a palette colour that is not grey");
      }
      cell_of[static_cast<std::size_t>(i)] = cell_of_grey(palette[i].red);
    }
  } else {
    png_set_expand_gray_1_2_4_to_8(png);
    for (int v = 0; v < 256; ++v) cell_of[static_cast<std::size_t>(v)] = cell_of_grey(v);
  }
  png_read_update_info(png, info);
  row->resize(png_get_rowbytes(png, info));
  *grid = Grid(static_cast<int>(width), static_cast<int>(height));
  for (png_uint_32 r = 0; r < height; ++r) {
    png_read_row(png, row->data(), nullptr);
    Cell* cells = grid->mutable_cells().data() + grid->Index(0, static_cast<int>(height - 1 - r));
    for (png_uint_32 c = 0; c < width; ++c) cells[c] = cell_of[(*row)[c]];
  }
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

const char* PngLayoutName(PngLayout layout) {
  switch (layout) {
    case PngLayout::kGrey8:
      return "grey8";
    case PngLayout::kPalette8:
      return "palette8";
    case PngLayout::kPalette2:
      return "palette2";
  }
  return "?";
}

StatusOr<std::string> EncodeTrinaryPng(const Grid& grid, PngLayout layout, int zlib_level) {
  if (grid.empty()) return InvalidArgumentError("PNG: the map has no cells");
  if (zlib_level < 0 || zlib_level > 9) return InvalidArgumentError("PNG: zlib level not in 0..9");
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, OnError, OnWarning);
  if (!png) return InternalError("PNG: out of memory");
  png_infop info = png_create_info_struct(png);
  WriteState state;
  png_set_write_fn(png, &state, WriteBytes, Flush);
  const std::size_t row_bytes = layout == PngLayout::kPalette2
                                    ? (static_cast<std::size_t>(grid.width()) + 3) / 4
                                    : static_cast<std::size_t>(grid.width());
  std::vector<png_byte> row(row_bytes);
  const bool ok = info && WritePng(png, info, grid, layout, zlib_level, &row);
  png_destroy_write_struct(&png, &info);
  if (!ok) return InternalError("PNG: libpng failed: " + error);
  return std::move(state.out);
}

StatusOr<Grid> DecodeTrinaryPng(std::span<const std::uint8_t> bytes) {
  std::string error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, OnError, OnWarning);
  if (!png) return InternalError("PNG: out of memory");
  png_infop info = png_create_info_struct(png);
  ReadState state{bytes, 0};
  png_set_read_fn(png, &state, ReadBytes);
  Grid grid;
  std::vector<png_byte> row;
  const bool ok = info && ReadPng(png, info, &grid, &row);
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) return CorruptError("PNG: " + error);
  return grid;
}

}  // namespace linemap::bench
