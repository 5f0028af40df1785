// ROS time stamps as the ISO 8601 text of a map's `time` metadata
// (spec/format.md 4.3).
#ifndef LINEMAP_FORMAT_ISO_TIME_H_
#define LINEMAP_FORMAT_ISO_TIME_H_

#include <cstdint>
#include <string>

namespace linemap {

// The instant `sec` seconds and `nsec` nanoseconds after the Unix epoch, in UTC:
// "2026-11-29T17:45:12Z", with the nanoseconds as a fraction of the second without trailing zeros
// ("...:12.5Z") when not 0. A ROS 1 header stamp (std_msgs/Header: uint32 sec, nsec) is such a
// pair.
std::string Iso8601FromStamp(std::uint32_t sec, std::uint32_t nsec);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_ISO_TIME_H_
