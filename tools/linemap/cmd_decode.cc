// linemap decode IN.lmap -o OUT.yaml: writes OUT.yaml and OUT.pgm as nav2's
// map_saver does (trinary).
#include <cstdio>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

// Refuses outputs that would replace the input file (only possible when an
// .lmap is named *.yaml or *.pgm; by device and inode, so links count too).
Status CheckOutput(const std::string& out, const std::string& in) {
  if (IsDirectory(out)) return InvalidArgumentError("'" + out + "' is a directory");
  for (const std::string& written : {out, SavedImagePath(out)}) {
    if (IsSameFile(written, in)) {
      return InvalidArgumentError("output '" + written + "' is the input file '" + in +
                                  "'; give another output name");
    }
  }
  return Status::Ok();
}

std::vector<OptionSpec> DecodeOptions() {
  std::vector<OptionSpec> options = {
      {"-o", "OUT.yaml", "output YAML; the PGM goes beside it"},
      {"--no-sync", "",
       "skip flushing the files to disk (fsync); they are still replaced atomically, but a "
       "power cut right after may lose them"}};
  for (OptionSpec& o : DecodeLimitOptionSpecs()) options.push_back(std::move(o));
  return options;
}
}  // namespace

const CommandSpec kDecodeSpec = {
    "decode",
    "IN.lmap -o OUT.yaml",
    "decode an .lmap file into a ROS map (YAML + PGM)",
    "Writes OUT.yaml and OUT.pgm (0 occupied, 254 free, 205 unknown) as nav2's\n"
    "map_saver does, so nav2's map_server loads the result.",
    DecodeOptions(),
    1,
    1,
};

int RunDecode(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kDecodeSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::optional<std::string> out = parsed->Get("-o");
  if (!out) return ReportError("decode", InvalidArgumentError("missing -o OUT.yaml"));
  const Status output_ok = CheckOutput(*out, parsed->positional[0]);
  if (!output_ok.ok()) return ReportError("decode", output_ok);
  StatusOr<DecodeLimits> limits = DecodeLimitsFrom(*parsed);
  if (!limits.ok()) return ReportError("decode", limits.status());
  StatusOr<Grid> grid = LoadLmap(parsed->positional[0], *limits);
  if (!grid.ok()) return ReportError("decode", grid.status());
  Status saved = SaveRosMap(*out, *grid,
                            parsed->Has("--no-sync") ? Durability::kUnsynced : Durability::kSynced);
  if (!saved.ok()) return ReportError("decode", saved);
  const CellCounts counts = grid->Count();
  std::printf("wrote %s and its .pgm: %d x %d cells, %zu free, %zu occupied, %zu unknown\n",
              out->c_str(), grid->width(), grid->height(), counts.free, counts.occupied,
              counts.unknown);
  return kExitOk;
}

}  // namespace linemap::cli
