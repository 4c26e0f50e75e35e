// Small helpers the SVG pictures (the map's and the trace's) share to write SVG text: escaped text,
// numbers without trailing zeros, attributes.
#pragma once

#include <string>
#include <string_view>

namespace scenfuzz {

void append_escaped(std::string& out, std::string_view text);

// `value` rounded to `decimals`, without trailing zeros ("0" for a non-finite value).
void append_number(std::string& out, double value, int decimals = 3);
std::string number_text(double value, int decimals);

// With its trailing zeros, as people write times: "7.00".
std::string fixed_text(double value, int decimals);

// ` name="value"`.
void append_attribute(std::string& out, std::string_view name, double value);
void append_attribute(std::string& out, std::string_view name, std::string_view value);

}  // namespace scenfuzz
