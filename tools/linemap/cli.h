// The linemap command-line tool's shared pieces: option parsing, --help text,
// error reporting and exit codes. Each command lives in its own cmd_*.cc.
//
// Exit codes: 0 success, 1 failure while working, 2 bad usage or bad input.
#ifndef LINEMAP_TOOLS_LINEMAP_CLI_H_
#define LINEMAP_TOOLS_LINEMAP_CLI_H_

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "linemap/status.h"

namespace linemap::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct OptionSpec {
  std::string name;        // "--json"
  std::string value_name;  // "X,Y"; empty for a flag without a value
  std::string help;        // one line, with the unit and the default
};

struct CommandSpec {
  std::string name;      // "info"
  std::string synopsis;  // "MAP [--json]"
  std::string summary;   // one line for `linemap --help`
  std::string details;   // paragraphs after the synopsis; may be empty
  std::vector<OptionSpec> options;
  int min_positional = 0;
  int max_positional = 0;
};

class ParsedArgs {
 public:
  std::vector<std::string> positional;

  bool Has(const std::string& name) const;
  std::optional<std::string> Get(const std::string& name) const;
  // Typed getters: a missing option gives the fallback; a malformed one an
  // kInvalidArgument status naming the option.
  StatusOr<double> GetDouble(const std::string& name, double fallback) const;
  StatusOr<int> GetInt(const std::string& name, int fallback) const;
  // A count or a size: decimal digits only, from `min` up to 2^64 - 1 (no
  // sign, fraction or exponent).
  StatusOr<std::uint64_t> GetUint64(const std::string& name, std::uint64_t fallback,
                                    std::uint64_t min = 0) const;
  // "A,B[,C...]" with exactly `count` numbers (or count..max_count).
  StatusOr<std::vector<double>> GetDoubleList(const std::string& name, int count,
                                              int max_count = -1) const;

  std::map<std::string, std::string> values;
  std::set<std::string> flags;
};

// Prints the command's --help text to stdout.
void PrintHelp(const CommandSpec& spec);

// Parses argv after the command name. Returns nullopt and sets *exit_code
// when the caller should return at once: --help (0) or bad usage (2, with a
// message on stderr).
std::optional<ParsedArgs> ParseArgs(const CommandSpec& spec, const std::vector<std::string>& args,
                                    int* exit_code);

// Refuses an output name that does not end in one of `extensions` (".csv",
// compared in any case), so that no file holds another format than its name
// says: kInvalidArgument naming `path`, the extensions and `format`, what
// the command writes ("CSV").
Status CheckOutputExtension(const std::string& path, const std::vector<std::string>& extensions,
                            const std::string& format);

// Refuses, before any work, an output file that the atomic save at the end
// would refuse after it (CheckSaveTarget, format/file_io.h: the save's own
// rules). Creates nothing. kInvalidArgument naming `path`: an output that
// cannot be written at all is bad usage (exit 2), and finding it now spares
// minutes of encoding a large map.
Status CheckOutputWritable(const std::string& path);

// The same for a folder a command writes files into, making it when missing
// (bench --svg-dir, encode BAG --all -o DIR): an existing `dir` must be a
// writable folder; a missing one needs a writable parent folder, or with
// `make_parents` (create_directories) a writable nearest existing ancestor.
Status CheckOutputFolderWritable(const std::string& dir, bool make_parents);

// Prints "linemap <command>: <message>" on stderr and returns the exit code
// for the status: 2 for bad input (invalid, missing, corrupt, unsupported,
// over a limit), 1 otherwise. A refusal over a limit (Status::limit()) that
// the command has an option for names the option (--max-cells N) unless the
// message does already.
int ReportError(const std::string& command, const Status& status);

// A command's entry point: argv after the command name.
using CommandFn = int (*)(const std::vector<std::string>& args);

struct CommandEntry {
  const CommandSpec* spec;
  CommandFn run;
};

// Every command, in the order `linemap --help` lists them.
const std::vector<CommandEntry>& Commands();

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_CLI_H_
