// The leaves of the WMG SDL level-2 syntax tree: numbers and ranges, names, enumeration words.
// Every leaf keeps where it was written, so that the translation can point errors into the file
// and a finding can be printed by replacing exactly the text of each range.
#pragma once

#include <cstdint>
#include <string>

#include "lang/source_location.hpp"

namespace scenfuzz::wmg {

// A DOUBLE_RANGE `low to high`, or a lone DOUBLE (then low == high and is_range is false).
// `location` spans exactly the text `low to high` (or the lone number, with its sign).
struct NumberRange {
  double low = 0.0;
  double high = 0.0;
  bool is_range = false;
  SourceLocation location;
  bool operator==(const NumberRange&) const = default;
};

// An INT: counts and numbers that name things (phases, lanes, versions), never searched.
struct WholeNumber {
  std::int64_t value = 0;
  SourceLocation location;
  bool operator==(const WholeNumber&) const = default;
};

// An ID, a ROAD_ID (R1) or a LANE_ID (L1, P1), as written.
struct Identifier {
  std::string name;
  SourceLocation location;
  bool operator==(const Identifier&) const = default;
};

// The contents of a STRING, without its quotes.
struct Text {
  std::string text;
  SourceLocation location;
  bool operator==(const Text&) const = default;
};

// A value of one of the grammar's enumerations ("Motorway", "Give way", "Drive_CutIn") in its
// canonical spelling, or a STRING where the enumeration allows one. The translation maps it.
struct Label {
  std::string text;
  bool is_string = false;
  SourceLocation location;
  bool operator==(const Label&) const = default;
};

// ROAD_LANE_QNAME: `R1.L2`.
struct LaneName {
  Identifier road;
  Identifier lane;
  SourceLocation location;
  bool operator==(const LaneName&) const = default;
};

// A value of a small closed enumeration, with where it was written.
template <typename Enumeration>
struct Located {
  Enumeration value{};
  SourceLocation location;
  bool operator==(const Located&) const = default;
};

}  // namespace scenfuzz::wmg
