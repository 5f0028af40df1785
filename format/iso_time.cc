#include "format/iso_time.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <regex>
#include <string>

namespace linemap {
namespace {

// Days in `month` (1-12) of `year` in the Gregorian calendar ISO 8601 uses.
int DaysInMonth(int year, int month) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[month - 1];
}

bool IsIso8601DateTime(const std::string& text) {
  static const std::regex kForm(
      R"((\d{4})-(0[1-9]|1[0-2])-(0[1-9]|[12]\d|3[01]))"
      R"((T([01]\d|2[0-3]):[0-5]\d(:([0-5]\d|60)(\.\d+)?)?(Z|[+-]([01]\d|2[0-3])(:?[0-5]\d)?)?)?)");
  std::smatch date;
  if (!std::regex_match(text, date, kForm)) return false;
  return std::stoi(date[3].str()) <=
         DaysInMonth(std::stoi(date[1].str()), std::stoi(date[2].str()));
}

}  // namespace

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

Status CheckIso8601Time(std::string_view what, const std::string& text) {
  const auto control = std::find_if(text.begin(), text.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f;
  });
  if (control != text.end()) {
    char code[8];
    std::snprintf(code, sizeof(code), "0x%02x", static_cast<unsigned char>(*control));
    return InvalidArgumentError(std::string(what) + " holds the control character " + code +
                                ": give an ISO 8601 time such as 2024-05-01T12:00:00Z");
  }
  if (!IsIso8601DateTime(text)) {
    return InvalidArgumentError(std::string(what) + " '" + text +
                                "' is not an ISO 8601 date or date-time such as "
                                "2024-05-01T12:00:00Z (or 2024-05-01, 2024-05-01T12:00+02:00)");
  }
  return Status::Ok();
}

}  // namespace linemap
