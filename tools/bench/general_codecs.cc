#include "tools/bench/general_codecs.h"

#include <lzma.h>
#include <zstd.h>

namespace linemap::bench {

std::span<const std::uint8_t> RawCells(const Grid& grid) {
  static_assert(sizeof(Cell) == 1);
  return {reinterpret_cast<const std::uint8_t*>(grid.cells().data()), grid.size()};
}

StatusOr<std::string> ZstdCompress(std::span<const std::uint8_t> data, int level) {
  std::string out(ZSTD_compressBound(data.size()), '\0');
  const std::size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), level);
  if (ZSTD_isError(n)) return InternalError(std::string("zstd: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

StatusOr<std::string> XzCompress(std::span<const std::uint8_t> data, int preset, bool extreme) {
  if (preset < 0 || preset > 9) return InvalidArgumentError("xz: preset must be in 0..9");
  std::string out(lzma_stream_buffer_bound(data.size()), '\0');
  std::size_t written = 0;
  const std::uint32_t flags =
      static_cast<std::uint32_t>(preset) | (extreme ? LZMA_PRESET_EXTREME : 0);
  const lzma_ret ret =
      lzma_easy_buffer_encode(flags, LZMA_CHECK_CRC64, nullptr, data.data(), data.size(),
                              reinterpret_cast<std::uint8_t*>(out.data()), &written, out.size());
  if (ret != LZMA_OK) return InternalError("xz: liblzma error " + std::to_string(ret));
  out.resize(written);
  return out;
}

}  // namespace linemap::bench
