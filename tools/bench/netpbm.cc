#include "tools/bench/netpbm.h"

#include <filesystem>
#include <string>
#include <system_error>

#include "tools/bench/image_anchors.h"
#include "tools/bench/subprocess.h"

namespace linemap::bench {

StatusOr<std::uint64_t> PnmtopngBytes(const Grid& grid) {
  LINEMAP_ASSIGN_OR_RETURN(ScratchDir dir, ScratchDir::Create("pnmtopng"));
  LINEMAP_ASSIGN_OR_RETURN(const std::string pgm,
                           dir.WriteScratchFile("map.pgm", MapSaverPgm(grid)));
  const std::string png = dir.path() + "/map.png";
  // pnmtopng writes to stdout: run it through sh only for the redirection,
  // with both paths from mkdtemp (no user text in the command).
  LINEMAP_ASSIGN_OR_RETURN(
      const int code,
      RunSubprocess({"sh", "-c", "pnmtopng -compression 9 '" + pgm + "' > '" + png + "'"}));
  if (code != 0) return IoError("pnmtopng: exit code " + std::to_string(code));
  std::error_code ec;
  const auto size = std::filesystem::file_size(png, ec);
  if (ec) return IoError("pnmtopng: no output: " + ec.message());
  return static_cast<std::uint64_t>(size);
}

}  // namespace linemap::bench
