#include "tools/bench/jbig.h"

#include "format/file_io.h"
#include "tools/bench/subprocess.h"

namespace linemap::bench {

std::string PbmPlane(const Grid& grid, BitPlane plane) {
  const auto in_plane = [plane](Cell cell) {
    return plane == BitPlane::kOccupied ? cell == Cell::kOccupied : cell != Cell::kFree;
  };
  const std::size_t row_bytes = (static_cast<std::size_t>(grid.width()) + 7) / 8;
  std::string pbm =
      "P4\n" + std::to_string(grid.width()) + " " + std::to_string(grid.height()) + "\n";
  const std::size_t header = pbm.size();
  pbm.resize(header + row_bytes * static_cast<std::size_t>(grid.height()), '\0');
  for (int image_row = 0; image_row < grid.height(); ++image_row) {
    const int row = grid.height() - 1 - image_row;
    char* out = pbm.data() + header + row_bytes * static_cast<std::size_t>(image_row);
    for (int col = 0; col < grid.width(); ++col) {
      if (in_plane(grid.at(col, row))) out[col >> 3] |= static_cast<char>(0x80 >> (col & 7));
    }
  }
  return pbm;
}

StatusOr<std::string> JbigEncodePbm(const std::string& pbm, const JbigOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(ScratchDir dir, ScratchDir::Create("jbig"));
  LINEMAP_ASSIGN_OR_RETURN(const std::string in, dir.WriteScratchFile("plane.pbm", pbm));
  const std::string out = dir.path() + "/plane.jbg";
  std::vector<std::string> argv = {options.encoder};
  if (options.sequential) argv.push_back("-q");
  argv.push_back(in);
  argv.push_back(out);
  LINEMAP_ASSIGN_OR_RETURN(int code, RunSubprocess(argv));
  if (code != 0) {
    return IoError(options.encoder + " failed with exit code " + std::to_string(code));
  }
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(out, std::uint64_t{1} << 32));
  return std::string(bytes.begin(), bytes.end());
}

StatusOr<JbigSizes> JbigTwoPlaneSizes(const Grid& grid, const JbigOptions& options) {
  JbigSizes sizes;
  LINEMAP_ASSIGN_OR_RETURN(std::string not_free_jbg,
                           JbigEncodePbm(PbmPlane(grid, BitPlane::kNotFree), options));
  LINEMAP_ASSIGN_OR_RETURN(std::string occupied_jbg,
                           JbigEncodePbm(PbmPlane(grid, BitPlane::kOccupied), options));
  sizes.not_free_plane = not_free_jbg.size();
  sizes.occupied_plane = occupied_jbg.size();
  return sizes;
}

}  // namespace linemap::bench
