// Significant digits through std::to_chars: its shortest form is exactly what reads back, so the
// count does not depend on the standard library's printf.
#include "fuzz/significant_digits.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

#include "lang/demand.hpp"

namespace scenfuzz {

int significant_digits(double value) {
  if (value == 0 || !std::isfinite(value)) return 0;
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::scientific);
  SCENFUZZ_DEMAND(result.ec == std::errc());
  // "-4.8e+02": the mantissa's digits.
  int digits = 0;
  for (const char* c = buffer.data(); c != result.ptr && *c != 'e'; ++c)
    if (*c >= '0' && *c <= '9') ++digits;
  return digits;
}

double round_to_significant(double value, int digits) {
  SCENFUZZ_DEMAND(digits >= 1);
  if (value == 0 || !std::isfinite(value) || digits >= significant_digits(value)) return value;
  std::array<char, 64> buffer{};
  const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                     std::chars_format::scientific, digits - 1);
  SCENFUZZ_DEMAND(written.ec == std::errc());
  double rounded = 0;
  const auto read = std::from_chars(buffer.data(), written.ptr, rounded);
  SCENFUZZ_DEMAND(read.ec == std::errc());
  return rounded;
}

}  // namespace scenfuzz
