// `linemap encode RECORDING.bag`: nav_msgs/OccupancyGrid messages read from a
// ROS 1 bag and encoded as .lmap files. The reading (rosbag's C++ API) lives
// in the module liblinemap_rosbag.so (ros/bag_reader.h), loaded only for a
// bag input; a build without rosbag (no LINEMAP_ROSBAG_MODULE_NAME) refuses
// every bag input with a message saying so.
#ifndef LINEMAP_TOOLS_LINEMAP_BAG_INPUT_H_
#define LINEMAP_TOOLS_LINEMAP_BAG_INPUT_H_

#include <string>
#include <vector>

#include "linemap/codec.h"
#include "tools/linemap/cli.h"

namespace linemap::cli {

// --topic, --index, --all: appended to `encode`'s options.
std::vector<OptionSpec> WithBagOptions(std::vector<OptionSpec> options);

// True when `encode` should read `input` as a bag: its name ends in .bag
// (any case), or a bag option is given.
bool IsBagInput(const std::string& input, const ParsedArgs& args);

// Refuses --topic, --index and --all with an input named as a map YAML, an
// image or an .lmap file (they read a bag; the bag reader's own error about
// such a file would not say so).
Status CheckBagOptionsApplyTo(const std::string& input, const ParsedArgs& args);

// Encodes the maps of `bag_path` chosen by `args` (the last message on
// --topic, default /map; --index K the K-th, counted from 0; --all every one,
// into the folder -o names, as STAMP.lmap) with `options`; prints what was
// written and returns the exit code.
int EncodeBag(const std::string& bag_path, const ParsedArgs& args, const EncodeOptions& options);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_BAG_INPUT_H_
