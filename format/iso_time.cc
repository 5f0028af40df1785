#include "format/iso_time.h"

#include <cstdio>
#include <ctime>
#include <string>

namespace linemap {

std::string Iso8601FromStamp(std::uint32_t sec, std::uint32_t nsec) {
  // A stamp whose nanoseconds reach a second is read as its sum.
  const std::time_t seconds = static_cast<std::time_t>(sec) + nsec / 1000000000u;
  nsec %= 1000000000u;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[48];
  const int n =
      std::snprintf(text, sizeof(text), "%04d-%02d-%02dT%02d:%02d:%02d", utc.tm_year + 1900,
                    utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec);
  std::string out(text, static_cast<std::size_t>(n));
  if (nsec > 0) {
    char fraction[16];
    std::snprintf(fraction, sizeof(fraction), ".%09u", nsec);
    std::string digits = fraction;
    while (digits.back() == '0') digits.pop_back();
    out += digits;
  }
  return out + "Z";
}

}  // namespace linemap
