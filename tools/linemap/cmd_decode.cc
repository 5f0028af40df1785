// linemap decode IN.lmap -o OUT.yaml [--window X0,Y0,X1,Y1 | --window-cells
// C0,R0,C1,R1 | --room-at X,Y] [--threads N]: writes OUT.yaml and OUT.pgm as
// nav2's map_saver does (trinary), of the whole map, one window of it, or
// the window of one room.
#include <cstdio>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/decode_window.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

// Refuses outputs that are no map YAML or would replace the input file (only
// possible when an .lmap is named *.yaml or *.pgm; by device and inode, so
// links count too).
// Before any decoding, which takes long on a huge map: SaveRosMap refuses
// the name and the save an output it cannot write, but only once the map or
// a window has been decoded.
Status CheckOutput(const std::string& out, const std::string& in) {
  if (IsDirectory(out)) return InvalidArgumentError("'" + out + "' is a directory");
  LINEMAP_RETURN_IF_ERROR(CheckOutputExtension(out, {".yaml", ".yml"}, "a map YAML"));
  for (const std::string& written : {out, SavedImagePath(out)}) {
    if (IsSameFile(written, in)) {
      return InvalidArgumentError("output '" + written + "' is the input file '" + in +
                                  "'; give another output name");
    }
  }
  for (const std::string& written : {out, SavedImagePath(out)}) {
    LINEMAP_RETURN_IF_ERROR(CheckOutputWritable(written));
  }
  return Status::Ok();
}

StatusOr<MapFileSummary> SaveWindow(const std::string& in, const CellWindow& window,
                                    const std::string& out, const DecodeLimits& limits,
                                    Durability durability) {
  LINEMAP_ASSIGN_OR_RETURN(Grid grid, LoadLmapRegion(in, window, limits));
  LINEMAP_RETURN_IF_ERROR(SaveRosMap(out, grid, durability));
  return MapFileSummary{grid.width(), grid.height(), grid.meta, grid.Count()};
}

// --room-at: the room holding the point and the cells of its box into
// `out`, from one read of the file (a map saved over it meanwhile cannot
// mix two maps' frames); sets *window to the box and *text to the room's id
// and kind. A point outside every room's border asks for a room that is not
// there: invalid argument (exit 2), nothing written.
StatusOr<MapFileSummary> SaveRoom(const std::string& in, const ParsedArgs& args,
                                  const std::string& out, const DecodeLimits& limits,
                                  Durability durability, std::string* text,
                                  std::optional<CellWindow>* window) {
  StatusOr<std::vector<std::uint8_t>> bytes = ReadFileBytes(in, limits.max_file_bytes);
  if (!bytes.ok()) return bytes.status();
  StatusOr<LmapHeader> header = DecodeLmapHeader(*bytes, limits);
  if (!header.ok()) return header.status().WithContext("'" + in + "'");
  LINEMAP_ASSIGN_OR_RETURN(const CellIndex cell, RoomCellFromArgs(args, *header, in));
  StatusOr<std::optional<LmapRoom>> room = DecodeLmapRoomAt(*bytes, cell, limits);
  if (!room.ok()) return room.status().WithContext("'" + in + "'");
  if (!room->has_value()) {
    return InvalidArgumentError(
        "no room of '" + in + "' encloses cell (" + std::to_string(cell.col) + ", " +
        std::to_string(cell.row) +
        ") (it lies outside every room's border, or the file has no rooms)");
  }
  const LmapRoom& found = **room;
  LINEMAP_RETURN_IF_ERROR(SaveRosMap(out, found.grid, durability));
  *text = ", room " + std::to_string(found.room.id) + " (" + RoomKindName(found.room.kind) + ")";
  *window = found.window;
  return MapFileSummary{found.grid.width(), found.grid.height(), found.grid.meta,
                        found.grid.Count()};
}

std::vector<OptionSpec> DecodeOptions() {
  std::vector<OptionSpec> options = {
      {"-o", "OUT.yaml", "output YAML; the PGM goes beside it"},
      {"--window", "X0,Y0,X1,Y1",
       "decode only the cells whose centres lie in the box [X0, X1] x [Y0, Y1] (map-frame metres, "
       "edges included)"},
      {"--window-cells", "C0,R0,C1,R1",
       "decode only columns C0..C1-1 and rows R0..R1-1 (grid rows, row 0 at the origin)"},
      {"--room-at", "X,Y",
       "decode only the room at the point X,Y (map-frame metres): the cells of the box of the "
       "smallest room border enclosing it"},
      {"--no-sync", "",
       "skip flushing the files to disk (fsync); they are still replaced atomically, but a "
       "power cut right after may lose them"}};
  for (OptionSpec& o : DecodeLimitOptionSpecs()) options.push_back(std::move(o));
  return options;
}
}  // namespace

const CommandSpec kDecodeSpec = {
    "decode",
    "IN.lmap -o OUT.yaml [--window X0,Y0,X1,Y1 | --window-cells C0,R0,C1,R1 | --room-at X,Y] "
    "[--threads N]",
    "decode an .lmap file into a ROS map (YAML + PGM)",
    "Writes OUT.yaml and OUT.pgm (0 occupied, 254 free, 205 unknown) as nav2's\n"
    "map_saver does, so nav2's map_server loads the result.\n"
    "With --window or --window-cells only that rectangle of cells is decoded\n"
    "(a 2.0 file decodes only the tiles it meets) and written, with the YAML\n"
    "origin at the window's lower-left corner, so it lies where it lay in the\n"
    "whole map. --window X0,Y0,X1,Y1 takes the cells whose centres lie in the\n"
    "box, on its edges too; the centre of cell (col, row) is the origin plus\n"
    "((col + 0.5) x resolution, (row + 0.5) x resolution) turned by the\n"
    "origin's yaw. When the yaw is not 0, the box's corners are taken into the\n"
    "grid and the window is the cell rectangle around them. --window-cells is\n"
    "half-open: C0 <= col < C1, R0 <= row < R1. A window that is empty or\n"
    "reaches past the map's border is refused (exit 2).\n"
    "--room-at X,Y decodes the window of one room, as a viewer shows it when\n"
    "the user picks a point: of the rooms whose border encloses the cell\n"
    "holding the point, the smallest (rooms nest: a corridor's border runs\n"
    "around the rooms off it), and the box of its border. Only the\n"
    "layer sections around the point and the tiles of the box are read (a room\n"
    "of a 282-Mcell map in milliseconds). A point off the map or outside every\n"
    "room's border (unknown space; a file without rooms) is refused (exit 2).\n"
    "Without a window a 2.0 file is decoded band by band straight into the\n"
    "PGM, so memory does not grow with the map's cells.",
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
  const Status limits_apply = CheckLayerLimitsApplyTo({parsed->positional[0]}, *parsed);
  if (!limits_apply.ok()) return ReportError("decode", limits_apply);
  StatusOr<DecodeLimits> limits = DecodeLimitsFrom(*parsed);
  if (!limits.ok()) return ReportError("decode", limits.status());
  const std::string& in = parsed->positional[0];
  StatusOr<std::optional<CellWindow>> window = WindowFromArgs(*parsed, in, *limits);
  if (!window.ok()) return ReportError("decode", window.status());
  const Durability durability =
      parsed->Has("--no-sync") ? Durability::kUnsynced : Durability::kSynced;
  // A window or a room is decoded into memory (it is the small part asked
  // for); the whole map goes to the files band by band, never held whole.
  std::string room_text;
  StatusOr<MapFileSummary> written =
      parsed->Get("--room-at")
          ? SaveRoom(in, *parsed, *out, *limits, durability, &room_text, &*window)
      : *window ? SaveWindow(in, **window, *out, *limits, durability)
                : DecodeLmapToRosMap(in, *out, *limits, durability);
  if (!written.ok()) return ReportError("decode", written.status());
  std::string where = room_text;
  if (*window) {
    const CellWindow& w = **window;
    where += " (columns " + std::to_string(w.col0) + ".." + std::to_string(w.col1 - 1) + ", rows " +
             std::to_string(w.row0) + ".." + std::to_string(w.row1 - 1) + ")";
  }
  const CellCounts& counts = written->counts;
  std::printf("wrote %s and its .pgm: %d x %d cells%s, %zu free, %zu occupied, %zu unknown\n",
              out->c_str(), written->width, written->height, where.c_str(), counts.free,
              counts.occupied, counts.unknown);
  return kExitOk;
}

}  // namespace linemap::cli
