#include "tools/linemap/cli.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>

#include "format/file_io.h"

namespace linemap::cli {
namespace {

const OptionSpec* FindOption(const CommandSpec& spec, const std::string& name) {
  for (const OptionSpec& option : spec.options) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

bool ParseDouble(const std::string& text, double* out) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  auto result = std::from_chars(begin, end, *out);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(*out);
}

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

// ".a", ".a or .b", ".a, .b or .c".
std::string Alternatives(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += i + 1 == items.size() ? " or " : ", ";
    text += items[i];
  }
  return text;
}

// The folder holding `path` ("." for a bare name).
std::string FolderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// `folder` exists, is a folder and we may make files in it; `what` names
// the output the message is about.
Status CheckFolderTakesFiles(const std::string& folder, const std::string& what) {
  struct stat st;
  if (::stat(folder.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ENOENT) {
      return InvalidArgumentError("cannot write '" + what + "': the folder '" + folder +
                                  "' does not exist")
          .WithErrno(err);
    }
    return InvalidArgumentError("cannot write '" + what + "': cannot reach the folder '" + folder +
                                "' (" + std::strerror(err) + ")")
        .WithErrno(err);
  }
  if (!S_ISDIR(st.st_mode)) {
    return InvalidArgumentError("cannot write '" + what + "': '" + folder + "' is not a folder")
        .WithErrno(ENOTDIR);
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    const int err = errno;
    return InvalidArgumentError("cannot write '" + what + "': no new file can be made in '" +
                                folder + "' (" + std::strerror(err) + ")")
        .WithErrno(err);
  }
  return Status::Ok();
}

// The options that raise a limit (the chunk, inflated and chain limits have
// none).
struct LimitFlag {
  Limit limit;
  const char* option;
};
constexpr LimitFlag kLimitFlags[] = {
    {Limit::kCells, "--max-cells"},
    {Limit::kFileBytes, "--max-file-bytes"},
    {Limit::kSegments, "--max-segments"},
    {Limit::kObjects, "--max-objects"},
    {Limit::kToleranceCells, "--max-tolerance-cells"},
};

// The option of `command` that raises `limit`, or "" when it has none.
std::string LimitOption(const std::string& command, Limit limit) {
  for (const LimitFlag& flag : kLimitFlags) {
    if (flag.limit != limit) continue;
    for (const CommandEntry& entry : Commands()) {
      if (entry.spec->name == command && FindOption(*entry.spec, flag.option) != nullptr) {
        return flag.option;
      }
    }
  }
  return "";
}

}  // namespace

bool ParsedArgs::Has(const std::string& name) const {
  return flags.count(name) > 0 || values.count(name) > 0;
}

std::optional<std::string> ParsedArgs::Get(const std::string& name) const {
  auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

StatusOr<double> ParsedArgs::GetDouble(const std::string& name, double fallback) const {
  std::optional<std::string> text = Get(name);
  if (!text) return fallback;
  double v = 0;
  if (!ParseDouble(*text, &v)) {
    return InvalidArgumentError(name + " expects a number, not '" + *text + "'");
  }
  return v;
}

StatusOr<int> ParsedArgs::GetInt(const std::string& name, int fallback) const {
  std::optional<std::string> text = Get(name);
  if (!text) return fallback;
  int v = 0;
  auto result = std::from_chars(text->data(), text->data() + text->size(), v);
  if (result.ec == std::errc::result_out_of_range && result.ptr == text->data() + text->size()) {
    return InvalidArgumentError(
        name + " is out of range (" + std::to_string(std::numeric_limits<int>::min()) + " to " +
        std::to_string(std::numeric_limits<int>::max()) + "), not '" + *text + "'");
  }
  if (result.ec != std::errc() || result.ptr != text->data() + text->size()) {
    return InvalidArgumentError(name + " expects a whole number, not '" + *text + "'");
  }
  return v;
}

StatusOr<std::uint64_t> ParsedArgs::GetUint64(const std::string& name, std::uint64_t fallback,
                                              std::uint64_t min) const {
  std::optional<std::string> text = Get(name);
  if (!text) return fallback;
  const std::string range = " from " + std::to_string(min) + " to " +
                            std::to_string(std::numeric_limits<std::uint64_t>::max());
  std::uint64_t v = 0;
  const bool digits = !text->empty() && std::all_of(text->begin(), text->end(),
                                                    [](char c) { return c >= '0' && c <= '9'; });
  const auto result = std::from_chars(text->data(), text->data() + text->size(), v);
  if (!digits || result.ptr != text->data() + text->size()) {
    return InvalidArgumentError(name + " expects a whole number" + range + ", not '" + *text + "'");
  }
  if (result.ec == std::errc::result_out_of_range || v < min) {
    return InvalidArgumentError(name + " must be" + range + ", not " + *text);
  }
  return v;
}

StatusOr<std::vector<double>> ParsedArgs::GetDoubleList(const std::string& name, int count,
                                                        int max_count) const {
  std::optional<std::string> text = Get(name);
  if (!text) return std::vector<double>();
  if (max_count < count) max_count = count;
  std::vector<double> numbers;
  for (const std::string& part : SplitCommas(*text)) {
    double v = 0;
    if (!ParseDouble(part, &v)) {
      return InvalidArgumentError(name + " expects comma-separated numbers, not '" + *text + "'");
    }
    numbers.push_back(v);
  }
  if (static_cast<int>(numbers.size()) < count || static_cast<int>(numbers.size()) > max_count) {
    const std::string want = count == max_count
                                 ? std::to_string(count)
                                 : std::to_string(count) + " to " + std::to_string(max_count);
    return InvalidArgumentError(name + " expects " + want + " comma-separated numbers, not '" +
                                *text + "'");
  }
  return numbers;
}

void PrintHelp(const CommandSpec& spec) {
  std::printf("Usage: linemap %s %s\n\n%s\n", spec.name.c_str(), spec.synopsis.c_str(),
              spec.summary.c_str());
  if (!spec.details.empty()) std::printf("\n%s\n", spec.details.c_str());
  std::printf("\nOptions:\n");
  for (const OptionSpec& option : spec.options) {
    std::string left = option.name;
    if (!option.value_name.empty()) left += " " + option.value_name;
    std::printf("  %-26s %s\n", left.c_str(), option.help.c_str());
  }
  std::printf("  %-26s %s\n", "--help", "show this help and exit");
  std::printf("\nExit status: 0 success, 1 failure while working, 2 bad usage or bad input.\n");
}

std::optional<ParsedArgs> ParseArgs(const CommandSpec& spec, const std::vector<std::string>& args,
                                    int* exit_code) {
  ParsedArgs parsed;
  auto usage_error = [&](const std::string& message) {
    std::cerr << "linemap " << spec.name << ": " << message << " (see 'linemap " << spec.name
              << " --help')\n";
    *exit_code = kExitBadInput;
    return std::nullopt;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      PrintHelp(spec);
      *exit_code = kExitOk;
      return std::nullopt;
    }
    if (arg.size() > 1 && arg[0] == '-' &&
        !(arg.size() > 1 && (std::isdigit(arg[1]) || arg[1] == '.'))) {
      std::string name = arg;
      std::optional<std::string> inline_value;
      const std::size_t eq = arg.find('=');
      if (eq != std::string::npos) {
        name = arg.substr(0, eq);
        inline_value = arg.substr(eq + 1);
      }
      const OptionSpec* option = FindOption(spec, name);
      if (option == nullptr) return usage_error("unknown option " + name);
      if (option->value_name.empty()) {
        if (inline_value) return usage_error(name + " takes no value");
        parsed.flags.insert(name);
        continue;
      }
      std::optional<std::string> value = inline_value;
      if (!value && i + 1 < args.size()) value = args[++i];
      if (!value) return usage_error(name + " needs a value (" + option->value_name + ")");
      // The last would win without a word: `--tolerance 2 --tolerance 0`
      // would save exact, `-o a -o b` never write a.
      if (parsed.values.count(name) > 0) {
        return usage_error(name + " given twice ('" + parsed.values[name] + "' and '" + *value +
                           "'); give one " + option->value_name);
      }
      parsed.values[name] = *value;
      continue;
    }
    parsed.positional.push_back(arg);
  }
  const int n = static_cast<int>(parsed.positional.size());
  if (n < spec.min_positional)
    return usage_error("missing argument; usage: linemap " + spec.name + " " + spec.synopsis);
  if (n > spec.max_positional)
    return usage_error("unexpected argument '" + parsed.positional.back() + "'");
  return parsed;
}

Status CheckOutputExtension(const std::string& path, const std::vector<std::string>& extensions,
                            const std::string& format) {
  const std::size_t slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  for (const std::string& extension : extensions) {
    // "dir/.yaml" ends in .yaml but names no file before it (decode would
    // write a hidden ".yaml" and ".pgm").
    if (base.size() == extension.size() && HasExtension("name" + base, extension)) {
      return InvalidArgumentError("output '" + path + "' has no file name before " + extension +
                                  ": give one, as in 'map" + extension + "'");
    }
    if (HasExtension(path, extension)) return Status::Ok();
  }
  return InvalidArgumentError("output '" + path + "' must end in " + Alternatives(extensions) +
                              ": it is written as " + format);
}

Status CheckOutputWritable(const std::string& path) {
  // The library's own rules (AtomicFileWriter::Open's), found without a
  // trace; refused here, before the work, they are a usage error.
  const Status target = CheckSaveTarget(path);
  if (target.ok()) return target;
  return InvalidArgumentError(target.message());
}

Status CheckOutputFolderWritable(const std::string& dir, bool make_parents) {
  if (dir.empty()) return InvalidArgumentError("empty output folder name");
  struct stat st;
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) return InvalidArgumentError("'" + dir + "' is not a folder");
    return CheckFolderTakesFiles(dir, dir);
  }
  std::string parent = dir;
  while (parent.size() > 1 && parent.back() == '/') parent.pop_back();
  parent = FolderOf(parent);
  if (make_parents) {
    // create_directories makes every missing folder down from the nearest
    // existing one.
    while (parent != "." && parent != "/" && ::stat(parent.c_str(), &st) != 0 && errno == ENOENT) {
      parent = FolderOf(parent);
    }
  }
  return CheckFolderTakesFiles(parent, dir);
}

int ReportError(const std::string& command, const Status& status) {
  std::string message = status.message();
  const std::string option = LimitOption(command, status.limit());
  if (!option.empty() && message.find(option) == std::string::npos) {
    message += " (" + option + " N raises the limit)";
  }
  std::cerr << "linemap " << command << ": " << message << "\n";
  switch (status.code()) {
    case StatusCode::kInvalidArgument:
    case StatusCode::kNotFound:
    case StatusCode::kCorrupt:
    case StatusCode::kUnsupported:
    case StatusCode::kResourceExhausted:
    case StatusCode::kPermissionDenied:
      return kExitBadInput;
    default:
      return kExitFailure;
  }
}

}  // namespace linemap::cli
