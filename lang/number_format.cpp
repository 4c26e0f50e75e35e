#include "lang/number_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace scenfuzz {

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also for -0.0, which would read back as a negated zero
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string format_time_of_day(double seconds) {
  long total = std::lround(seconds);
  long hours = total / 3600, minutes = (total / 60) % 60, rest = total % 60;
  char buffer[32];
  if (rest == 0)
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld", hours, minutes);
  else
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", hours, minutes, rest);
  return buffer;
}

}  // namespace scenfuzz
