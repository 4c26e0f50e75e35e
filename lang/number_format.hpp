// Numbers and times printed so that reading them back gives exactly the same double.
#pragma once

#include <string>

namespace scenfuzz {

// Shortest text that reads back to the same double ("0.1", "553090.1", "1e-07").
std::string format_number(double value);
// Seconds since midnight as H:MM, or H:MM:SS when not a whole minute (rounded to the second).
std::string format_time_of_day(double seconds);

}  // namespace scenfuzz
