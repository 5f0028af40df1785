// What lmap_server and lmap_saver share: finding the ROS master within a
// bounded wait, and reading numbers from their command lines.
#ifndef LINEMAP_ROS_NODE_SUPPORT_H_
#define LINEMAP_ROS_NODE_SUPPORT_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "linemap/status.h"

namespace linemap::ros_bridge {

// Exit codes, as the `linemap` tool's: 1 failure while working (no master,
// a file that cannot be written), 2 bad usage or bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// The exit code for a failed `status`, as `linemap` maps them: 2 for bad
// input (invalid, missing, corrupt, unsupported, over a limit), 1 otherwise.
int ExitCodeFor(const Status& status);

// Seconds a node waits for the master by default before giving up.
inline constexpr double kDefaultMasterWaitSeconds = 10.0;

// The master rospy and the ROS command-line tools (rosgraph) use when
// ROS_MASTER_URI is not set.
inline constexpr const char* kDefaultMasterUri = "http://localhost:11311/";

// roscpp aborts the process when neither ROS_MASTER_URI nor a `__master:=URI`
// argument names the master; like rospy, a node then uses
// kDefaultMasterUri (sets ROS_MASTER_URI; call before ros::init, while the
// process has one thread).
void UseDefaultMasterUriIfUnset(int argc, char** argv);

// ros::init(argc, argv, name, options), then waits for the master: polls
// it (ros::master::check) every 0.1 s until it answers or `seconds` have
// passed since the call; fails (I/O error, naming the URI and the wait) when
// it never answered. Sets ROS_MASTER_URI first as UseDefaultMasterUriIfUnset
// does.
Status InitNodeAndWaitForMaster(int& argc, char** argv, const std::string& name,
                                std::uint32_t options, double seconds);

// The value of the last `_NAME:=VALUE` among the arguments, as ros::init
// reads them into the private parameter ~NAME, or nullopt. Lets a node check
// such a parameter before it has a master to ask.
std::optional<std::string> PrivateParameterArgument(int argc, char** argv, const std::string& name);

// A non-negative finite number of seconds, or a message naming `option`.
StatusOr<double> ParseSeconds(const std::string& option, const std::string& text);
// A finite number, or a message naming `option`.
StatusOr<double> ParseNumber(const std::string& option, const std::string& text);

// The arguments after the program name, without ROS's remappings
// (`name:=value`), as ros::removeROSArgs leaves them.
std::vector<std::string> NonRosArguments(int argc, char** argv);

// A node's first steps: standard output line by line (so that a log file or
// a pipe shows each message when it is written, not when the node exits),
// and `usage` printed when -h or --help is among the arguments. True when
// it was: the node then exits 0.
bool StartNodeOutput(int argc, char** argv, const char* usage);

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_NODE_SUPPORT_H_
