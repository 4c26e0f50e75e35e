// Significant digits of a number as its shortest exact text shows them (480 has 2, 0.125 has 3),
// and rounding to fewer: what `scenfuzz tmin` shortens every number of a scenario with.
#pragma once

namespace scenfuzz {

// The digits of the shortest scientific text that reads back as `value` (0 for 0, inf and NaN).
int significant_digits(double value);

// `value` rounded to `digits` (>= 1) significant decimal digits: the double nearest that decimal.
double round_to_significant(double value, int digits);

}  // namespace scenfuzz
