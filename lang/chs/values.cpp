// Reading the values of CH-Scenario's `key: value` lines.
#include "lang/chs/values.hpp"

#include <charconv>
#include <cmath>

namespace scenfuzz::chs {

namespace {

// A decimal number at text[at...]: its value and length, or nullopt.
std::optional<std::pair<double, std::size_t>> number_at(std::string_view text, std::size_t at) {
  std::size_t from = at;
  if (from < text.size() && text[from] == '+') ++from;  // from_chars takes no '+'
  double value = 0;
  const char* begin = text.data() + from;
  auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error != std::errc() || end == begin) return std::nullopt;
  return std::pair{value, static_cast<std::size_t>(end - text.data()) - at};
}

}  // namespace

std::optional<Number> read_number(const Value& value, Diagnostics& diagnostics,
                                  const std::string& what) {
  const std::string_view text = value.text();
  auto number = number_at(text, 0);
  if (!number || number->second != text.size()) {
    diagnostics.error(value.location(),
                      "expected a number for " + what + ", found '" + std::string(text) + "'");
    return std::nullopt;
  }
  if (!std::isfinite(number->first)) {
    diagnostics.error(value.location(), what + " must be a finite number");
    return std::nullopt;
  }
  return Number{number->first, value.location()};
}

std::optional<Flag> read_flag(const Value& value, Diagnostics& diagnostics,
                              const std::string& what) {
  const std::string word = normalised(value.text());
  if (word == "1" || word == "true") return Flag{true, value.location()};
  if (word == "0" || word == "false") return Flag{false, value.location()};
  diagnostics.error(value.location(), "expected 0, 1, true or false for " + what + ", found '" +
                                          std::string(value.text()) + "'");
  return std::nullopt;
}

std::optional<Text> read_text(const Value& value, Diagnostics& diagnostics,
                              const std::string& what) {
  if (value.text().empty()) {
    diagnostics.error(value.location(), "expected " + what + " after the colon");
    return std::nullopt;
  }
  return Text{std::string(value.text()), value.location()};
}

bool read_points(const Line& line, std::size_t begin, std::vector<Point>& points,
                 Diagnostics& diagnostics) {
  const std::string_view text = line.text;
  std::size_t at = begin;
  auto skip_blanks = [&] {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  };
  auto fail = [&](const std::string& expected) {
    const std::size_t length = at < text.size() ? 1 : 0;
    const std::string found =
        at < text.size() ? "'" + std::string(1, text[at]) + "'" : "the end of the line";
    diagnostics.error(line.at(at, length), "expected " + expected + ", found " + found);
    return false;
  };
  skip_blanks();
  if (at == text.size()) return fail("a point such as (0.0, 25.0)");
  while (at < text.size()) {
    const std::size_t start = at;
    if (text[at] != '(') return fail("'(' to start a point such as (0.0, 25.0)");
    ++at;
    skip_blanks();
    auto x = number_at(text, at);
    if (!x) return fail("the point's x in metres");
    const SourceLocation x_at = line.at(at, x->second);
    at += x->second;
    skip_blanks();
    if (at >= text.size() || text[at] != ',') return fail("',' between the point's x and y");
    ++at;
    skip_blanks();
    auto y = number_at(text, at);
    if (!y) return fail("the point's y in metres");
    const SourceLocation y_at = line.at(at, y->second);
    at += y->second;
    skip_blanks();
    if (at >= text.size() || text[at] != ')') return fail("')' to end the point");
    ++at;
    const SourceLocation where = line.at(start, at - start);
    if (!std::isfinite(x->first) || !std::isfinite(y->first)) {
      diagnostics.error(where, "a point's coordinates must be finite numbers");
      return false;
    }
    points.push_back({x->first, y->first, where, x_at, y_at});
    skip_blanks();
    if (at < text.size() && text[at] == ',') ++at;
    skip_blanks();
  }
  return true;
}

}  // namespace scenfuzz::chs
