// Iso8601FromStamp against instants worked out by hand (the date command's
// `date -u -d @SEC` gives the same).
#include "format/iso_time.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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

namespace linemap {
namespace {

// What a saver stores is what the format's `time` takes.
TEST(CheckIso8601TimeTest, TakesEveryStampItsSaversWrite) {
  for (const auto& [sec, nsec] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {0, 0}, {1700000000, 500000000}, {1709208000, 1}, {4294967295u, 999999999}}) {
    EXPECT_TRUE(CheckIso8601Time("time", Iso8601FromStamp(sec, nsec)).ok())
        << Iso8601FromStamp(sec, nsec);
  }
}

TEST(CheckIso8601TimeTest, NamesWhatGaveTheTextRefused) {
  const Status bad = CheckIso8601Time("time", "2026-02-30");
  EXPECT_EQ(bad.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(bad.message().rfind("time '2026-02-30' is not an ISO 8601 date", 0), 0u)
      << bad.message();
  EXPECT_NE(CheckIso8601Time("--time", "a\nb").message().find("--time holds the control"),
            std::string::npos);
  EXPECT_TRUE(CheckIso8601Time("time", "2024-02-29T23:59:60.5+05:30").ok());
}

}  // namespace
}  // namespace linemap
