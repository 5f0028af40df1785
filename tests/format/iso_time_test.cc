// Iso8601FromStamp against instants worked out by hand (the date command's
// `date -u -d @SEC` gives the same).
#include "format/iso_time.h"

#include <gtest/gtest.h>

namespace linemap {
namespace {

TEST(Iso8601FromStampTest, GivesUtcWithTheFractionTrimmed) {
  EXPECT_EQ(Iso8601FromStamp(0, 0), "1970-01-01T00:00:00Z");
  // 1,700,000,000 s: 19,675 days (2023-11-14) and 22:13:20.
  EXPECT_EQ(Iso8601FromStamp(1700000000, 0), "2023-11-14T22:13:20Z");
  EXPECT_EQ(Iso8601FromStamp(1700000000, 500000000), "2023-11-14T22:13:20.5Z");
  EXPECT_EQ(Iso8601FromStamp(1700000000, 1), "2023-11-14T22:13:20.000000001Z");
  EXPECT_EQ(Iso8601FromStamp(1700000000, 123456780), "2023-11-14T22:13:20.12345678Z");
  // A leap day, and the last second a uint32 holds (2106-02-07T06:28:15).
  EXPECT_EQ(Iso8601FromStamp(1709208000, 0), "2024-02-29T12:00:00Z");
  EXPECT_EQ(Iso8601FromStamp(4294967295u, 0), "2106-02-07T06:28:15Z");
  // Nanoseconds of a second or more carry into the seconds.
  EXPECT_EQ(Iso8601FromStamp(1700000000, 1500000000u), "2023-11-14T22:13:21.5Z");
}

}  // namespace
}  // namespace linemap
