#include "tools/linemap/cli.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

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
      if (option->output && parsed.values.count(name) > 0) {
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

bool EndsWithIgnoringCase(const std::string& s, const std::string& suffix) {
  if (s.size() <= suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), s.end() - suffix.size(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

Status CheckOutputExtension(const std::string& path, const std::vector<std::string>& extensions,
                            const std::string& format) {
  for (const std::string& extension : extensions) {
    if (EndsWithIgnoringCase(path, extension)) return Status::Ok();
  }
  return InvalidArgumentError("output '" + path + "' must end in " + Alternatives(extensions) +
                              ": it is written as " + format);
}

int ReportError(const std::string& command, const Status& status) {
  std::cerr << "linemap " << command << ": " << status.message() << "\n";
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
