// ROS time stamps as the ISO 8601 text of a map's `time` metadata
// (spec/format.md 4.3).
#ifndef LINEMAP_FORMAT_ISO_TIME_H_
#define LINEMAP_FORMAT_ISO_TIME_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "linemap/status.h"

namespace linemap {

// The instant `sec` seconds and `nsec` nanoseconds after the Unix epoch, in UTC:
// "2026-11-29T17:45:12Z", with the nanoseconds as a fraction of the second without trailing zeros
// ("...:12.5Z") when not 0. A ROS 1 header stamp (std_msgs/Header: uint32 sec, nsec) is such a
// pair.
std::string Iso8601FromStamp(std::uint32_t sec, std::uint32_t nsec);

// Whether `text` is a `time` the format takes: an extended ISO 8601 date
// (YYYY-MM-DD, a day the calendar has) or date-time (that, "T", hh:mm,
// optionally :ss and a fraction, optionally a zone: Z, +hh:mm, +hhmm, +hh
// or -). A reader of the key parses it: "yesterday" or 2026-02-30 would be
// stored and fail there, and a control character would also split the
// line `linemap info` prints it on. The error (invalid argument) names
// `what` (the option or keyword that gave it).
Status CheckIso8601Time(std::string_view what, const std::string& text);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_ISO_TIME_H_
