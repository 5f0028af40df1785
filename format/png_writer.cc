#include "format/png_writer.h"

#include <png.h>

namespace linemap {
namespace {

void AppendData(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}
void NoFlush(png_structp) {}

// `rows` are packed rows at the given bit depth and colour type.
StatusOr<std::vector<std::uint8_t>> WritePng(int width, int height, int bit_depth, int color_type,
                                             const std::vector<std::vector<std::uint8_t>>& rows,
                                             const std::vector<std::uint8_t>* levels) {
  std::vector<std::uint8_t> out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return InternalError("png_create_write_struct failed");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return InternalError("libpng failed to write the reference PNG");
  }
  png_set_write_fn(png, &out, AppendData, NoFlush);
  png_set_compression_level(png, 9);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
               bit_depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette;
  if (levels != nullptr) {
    for (std::uint8_t v : *levels) palette.push_back(png_color{v, v, v});
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  }
  png_write_info(png, info);
  for (const std::vector<std::uint8_t>& row : rows) {
    png_write_row(png, const_cast<png_bytep>(row.data()));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> EncodeGreyPng(int width, int height,
                                                  const std::vector<std::uint8_t>& grey) {
  std::vector<std::vector<std::uint8_t>> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    rows[y].assign(grey.begin() + static_cast<std::ptrdiff_t>(y) * width,
                   grey.begin() + static_cast<std::ptrdiff_t>(y + 1) * width);
  }
  return WritePng(width, height, 8, PNG_COLOR_TYPE_GRAY, rows, nullptr);
}

StatusOr<std::vector<std::uint8_t>> EncodePalettePng(int width, int height,
                                                     const std::vector<std::uint8_t>& index,
                                                     const std::vector<std::uint8_t>& levels) {
  std::vector<std::vector<std::uint8_t>> rows(static_cast<std::size_t>(height));
  const std::size_t row_bytes = (static_cast<std::size_t>(width) * 2 + 7) / 8;
  for (int y = 0; y < height; ++y) {
    rows[y].assign(row_bytes, 0);
    for (int x = 0; x < width; ++x) {
      const std::uint8_t v = index[static_cast<std::size_t>(y) * width + x] & 3;
      rows[y][x / 4] |= static_cast<std::uint8_t>(v << (6 - 2 * (x % 4)));
    }
  }
  return WritePng(width, height, 2, PNG_COLOR_TYPE_PALETTE, rows, &levels);
}

}  // namespace linemap
