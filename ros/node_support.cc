#include "ros/node_support.h"

#include <ros/init.h>
#include <ros/master.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <thread>

namespace linemap::ros_bridge {

int ExitCodeFor(const Status& status) {
  switch (status.code()) {
    case StatusCode::kOk:
      return kExitOk;
    case StatusCode::kInvalidArgument:
    case StatusCode::kNotFound:
    case StatusCode::kCorrupt:
    case StatusCode::kUnsupported:
    case StatusCode::kResourceExhausted:
    case StatusCode::kPermissionDenied:
      return kExitBadInput;
    case StatusCode::kIoError:
    case StatusCode::kInternal:
      break;
  }
  return kExitFailure;
}

void UseDefaultMasterUriIfUnset(int argc, char** argv) {
  const char* env = std::getenv("ROS_MASTER_URI");
  if (env != nullptr && env[0] != '\0') return;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]).starts_with("__master:=")) return;
  }
  ::setenv("ROS_MASTER_URI", kDefaultMasterUri, /*overwrite=*/1);
}

Status InitNodeAndWaitForMaster(int& argc, char** argv, const std::string& name,
                                std::uint32_t options, double seconds) {
  using Clock = std::chrono::steady_clock;
  // Longer waits are as good as forever, and keep the deadline and roscpp's
  // WallDuration (32-bit seconds) in range.
  const double wait = std::min(seconds, 1e8);
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                        std::chrono::duration<double>(wait));
  UseDefaultMasterUriIfUnset(argc, argv);
  // ros::init stores each `_name:=value` argument on the master's parameter
  // server, retrying until a master answers: without a timeout a node given
  // one would hang there when no master runs. The timeout applies to each
  // argument in turn, so the wait is shared among them (three arguments and
  // --wait-master 2 waited 6 s). A timeout of 0 means none.
  int private_parameters = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg(argv[i]);
    private_parameters +=
        arg.starts_with("_") && !arg.starts_with("__") && arg.find(":=") != std::string_view::npos;
  }
  const double per_parameter = wait / std::max(private_parameters, 1);
  ros::master::setRetryTimeout(ros::WallDuration(std::max(per_parameter, 1e-3)));
  ros::init(argc, argv, name, options);
  // A running node that loses its master waits for it to come back, as
  // roscpp's nodes do.
  ros::master::setRetryTimeout(ros::WallDuration(0));
  while (!ros::master::check()) {
    if (Clock::now() >= deadline) {
      char text[64];
      std::snprintf(text, sizeof(text), "%.1f", seconds);
      return IoError("no ROS master at " + ros::master::getURI() + " (waited " + text +
                     " s; start one with `rosmaster` or `roscore`, or set ROS_MASTER_URI)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return Status::Ok();
}

std::optional<std::string> PrivateParameterArgument(int argc, char** argv,
                                                    const std::string& name) {
  const std::string prefix = "_" + name + ":=";
  std::optional<std::string> value;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg(argv[i]);
    if (arg.starts_with(prefix)) value = std::string(arg.substr(prefix.size()));
  }
  return value;
}

StatusOr<double> ParseNumber(const std::string& option, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
    return InvalidArgumentError(option + " needs a number, not '" + text + "'");
  }
  return value;
}

StatusOr<double> ParseSeconds(const std::string& option, const std::string& text) {
  StatusOr<double> value = ParseNumber(option, text);
  if (value.ok() && *value < 0) return InvalidArgumentError(option + " must not be negative");
  return value;
}

std::vector<std::string> NonRosArguments(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.find(":=") == std::string::npos) args.push_back(arg);
  }
  return args;
}

bool StartNodeOutput(int argc, char** argv, const char* usage) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") {
      std::fputs(usage, stdout);
      return true;
    }
  }
  return false;
}

}  // namespace linemap::ros_bridge
