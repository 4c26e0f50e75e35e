// Signals from a CSV log (`scenfuzz stl --trace`): an RFC 4180 scanner that keeps every field's
// place in the file, so that each problem is reported at file:line:column with a caret, and the
// SignalSource that lets a formula name the columns.
#include "oracle/csv_signals.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>

#include "lang/avunit/builtins.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz {

namespace {

constexpr std::string_view kTimeColumn = "time";

struct Field {
  std::string text;         // quotes removed and "" unescaped; blanks around an unquoted field
                            // dropped
  SourceLocation location;  // as written, quotes included
  bool malformed = false;   // already reported: a stray or missing quote
};

struct Row {
  std::vector<Field> fields;
  SourceLocation end;  // just after the last field, where a missing field would go
  bool blank = false;  // nothing but blanks on the line
};

bool is_continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim_blanks(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

// Reads rows one at a time, tracking line and column (in code points, as diagnostics count).
class CsvScanner {
 public:
  CsvScanner(const SourceFile& file, Diagnostics& diagnostics)
      : text_(file.text()), diagnostics_(diagnostics) {
    // Spreadsheets write a UTF-8 byte order mark; it is not part of the first column's name.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      position_ = 3;
      column_ = 2;
    }
  }

  // The next row, or nullopt at the end of the file.
  std::optional<Row> next_row() {
    if (at_end()) return std::nullopt;
    Row row;
    skip_blanks();
    if (at_line_end()) {
      row.blank = true;
      row.end = here();
      skip_line_end();
      return row;
    }
    while (true) {
      row.fields.push_back(read_field());
      if (at_end() || peek() != ',') break;
      advance();
    }
    row.end = here();
    skip_line_end();
    return row;
  }

  // Whether only blank lines are left.
  bool only_blank_lines_left() const {
    for (std::size_t i = position_; i < text_.size(); ++i)
      if (!is_blank(text_[i]) && text_[i] != '\r' && text_[i] != '\n') return false;
    return true;
  }

  SourceLocation here() const { return {line_, column_, static_cast<std::uint32_t>(position_), 0}; }

 private:
  bool at_end() const { return position_ >= text_.size(); }
  char peek() const { return text_[position_]; }

  void advance() {
    const char c = text_[position_++];
    if (c == '\n') {
      ++line_;
      column_ = 1;
    } else if (!is_continuation_byte(c)) {
      ++column_;
    }
  }

  // A lone CR before the end of the file counts as a line end, as CRLF does.
  bool at_line_end() const {
    if (at_end() || peek() == '\n') return true;
    return peek() == '\r' && (position_ + 1 == text_.size() || text_[position_ + 1] == '\n');
  }
  bool at_field_end() const { return at_line_end() || peek() == ','; }

  void skip_line_end() {
    if (!at_end() && peek() == '\r') advance();
    if (!at_end() && peek() == '\n') advance();
  }
  void skip_blanks() {
    while (!at_end() && is_blank(peek())) advance();
  }

  Field read_field() {
    skip_blanks();
    Field field;
    field.location = here();
    if (!at_end() && peek() == '"') {
      read_quoted(field);
    } else {
      std::size_t content_end = position_;
      while (!at_field_end()) {
        const char c = peek();
        if (c == '"' && !field.malformed) {
          SourceLocation quote = here();
          quote.length = 1;
          diagnostics_.error(quote,
                             "a '\"' inside a field that does not start with one: quote the "
                             "whole field and double the quote (\"\")");
          field.malformed = true;
        }
        advance();
        if (!is_blank(c)) content_end = position_;
      }
      field.location.length = static_cast<std::uint32_t>(content_end - field.location.offset);
      field.text = text_.substr(field.location.offset, field.location.length);
    }
    return field;
  }

  void read_quoted(Field& field) {
    advance();  // the opening quote
    while (true) {
      if (at_end()) {
        SourceLocation opening = field.location;
        opening.length = 1;
        diagnostics_.error(opening, "this quoted field has no closing '\"'");
        field.malformed = true;
        break;
      }
      const char c = peek();
      advance();
      if (c != '"') {
        field.text += c;
        continue;
      }
      if (at_end() || peek() != '"') break;
      field.text += '"';
      advance();
    }
    field.location.length = static_cast<std::uint32_t>(position_ - field.location.offset);
    skip_blanks();
    if (!at_field_end()) {
      if (!field.malformed)
        diagnostics_.error(here(), "expected ',' or the end of the line after a quoted field");
      field.malformed = true;
      while (!at_field_end()) advance();
    }
  }

  std::string_view text_;
  Diagnostics& diagnostics_;
  std::size_t position_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t column_ = 1;
};

// "time, x, y" — cut short for very wide files, where the whole list would bury the message.
std::string name_list(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 12;
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) {
    if (i > 0) list += ", ";
    list += names[i];
  }
  if (names.size() > kShown) list += ", ... (" + std::to_string(names.size()) + " columns)";
  return list;
}

// A field as quoted in a message, cut short.
std::string quoted_text(std::string_view text) {
  constexpr std::size_t kLongest = 32;
  if (text.size() <= kLongest) return "'" + std::string(text) + "'";
  return "'" + std::string(text.substr(0, kLongest)) + "...'";
}

// Parses a field as a finite double (std::from_chars: locale-independent, the whole field must
// be the number), or returns why it is not one.
std::optional<double> parse_number(std::string_view field, const std::string& column,
                                   std::string& problem) {
  std::string_view text = trim_blanks(field);
  if (text.empty()) {
    problem = "empty field in column '" + column + "': expected a number";
    return std::nullopt;
  }
  std::string_view digits = text;
  // from_chars refuses a leading '+', which other tools write (printf's %+g).
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range && end == digits.data() + digits.size()) {
    problem = quoted_text(text) + " in column '" + column + "' is out of the range of a double";
    return std::nullopt;
  }
  if (error != std::errc() || end != digits.data() + digits.size()) {
    problem = "expected a number in column '" + column + "', got " + quoted_text(text);
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    problem = "expected a finite number in column '" + column + "', got " + quoted_text(text);
    return std::nullopt;
  }
  return value;
}

struct Header {
  std::vector<std::string> names;
  std::size_t time_index = 0;
};

// Whether the row looks like data rather than names: every field a number.
bool all_numbers(const Row& row) {
  for (const Field& field : row.fields) {
    std::string ignored;
    if (!parse_number(field.text, "", ignored)) return false;
  }
  return true;
}

std::optional<Header> read_header(const Row& row, const SourceFile& file,
                                  Diagnostics& diagnostics) {
  Header header;
  std::map<std::string, SourceLocation> seen;
  std::optional<std::size_t> time_index;
  bool ok = true;
  for (std::size_t i = 0; i < row.fields.size(); ++i) {
    const Field& field = row.fields[i];
    header.names.push_back(field.text);
    if (field.malformed) {
      ok = false;
      continue;
    }
    if (field.text.empty()) {
      diagnostics.error(field.location, "empty column name: every column needs a name");
      ok = false;
      continue;
    }
    auto [first, inserted] = seen.emplace(field.text, field.location);
    if (!inserted) {
      diagnostics.error(field.location, "duplicate column '" + field.text + "'");
      diagnostics.note(first->second, "'" + field.text + "' is first named here");
      ok = false;
      continue;
    }
    if (field.text == kTimeColumn) time_index = i;
  }
  if (!time_index && ok) {
    SourceLocation whole_line{1, 1, 0, static_cast<std::uint32_t>(file.line_text(1).size())};
    std::string message =
        "no 'time' column: the first line must name the columns, one of them 'time' (seconds)";
    for (const Field& field : row.fields) {
      std::string lower = field.text;
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower == kTimeColumn) {
        message += "; names are case-sensitive, and '" + field.text + "' is not 'time'";
        break;
      }
    }
    if (all_numbers(row)) message += "; this line holds numbers, not names";
    diagnostics.error(whole_line, message);
    ok = false;
  }
  if (!ok) return std::nullopt;
  header.time_index = *time_index;
  return header;
}

}  // namespace

std::optional<CsvSignals> read_csv_signals(const SourceFile& file, Diagnostics& diagnostics) {
  const std::size_t errors_before = diagnostics.error_count();
  CsvScanner scanner(file, diagnostics);

  std::optional<Row> first = scanner.next_row();
  if (!first || (first->blank && scanner.only_blank_lines_left())) {
    diagnostics.error(SourceLocation{1, 1, 0, 0},
                      "empty file: expected a header row naming the columns, one of them 'time'");
    return std::nullopt;
  }
  if (first->blank) {
    diagnostics.error(SourceLocation{1, 1, 0, 0},
                      "the first line is blank: expected a header row naming the columns, one "
                      "of them 'time'");
    return std::nullopt;
  }
  const SourceLocation header_location{1, 1, 0,
                                       static_cast<std::uint32_t>(file.line_text(1).size())};
  std::optional<Header> header = read_header(*first, file, diagnostics);
  if (!header) return std::nullopt;

  const std::size_t width = header->names.size();
  std::vector<std::vector<double>> values(width);
  // Reported once per column: a column of text would otherwise give an error on every row.
  std::vector<std::size_t> bad_fields(width, 0);
  std::vector<SourceLocation> first_bad(width);
  std::optional<SourceLocation> pending_blank;
  std::optional<double> previous_time;
  std::size_t rows = 0;
  bool rows_ok = true;

  while (std::optional<Row> row = scanner.next_row()) {
    if (diagnostics.too_many_errors()) break;
    if (row->blank) {
      // Blank lines at the end are a trailing newline or two; between rows they are a mistake.
      if (!pending_blank) pending_blank = row->end;
      continue;
    }
    if (pending_blank) {
      diagnostics.error(*pending_blank, "blank line between rows: expected " +
                                            std::to_string(width) +
                                            " fields: " + name_list(header->names));
      pending_blank.reset();
      rows_ok = false;
    }
    ++rows;
    const std::vector<Field>& fields = row->fields;
    if (fields.size() != width) {
      const std::string message = "this row has " + std::to_string(fields.size()) +
                                  (fields.size() == 1 ? " field" : " fields") + "; expected " +
                                  std::to_string(width) + ": " + name_list(header->names);
      if (fields.size() < width) {
        diagnostics.error(row->end, message);
      } else {
        diagnostics.error(span(fields[width].location, fields.back().location), message);
      }
      rows_ok = false;
      continue;
    }
    std::optional<double> time;
    for (std::size_t i = 0; i < width; ++i) {
      const Field& field = fields[i];
      if (field.malformed) {
        rows_ok = false;
        continue;
      }
      std::string problem;
      std::optional<double> value = parse_number(field.text, header->names[i], problem);
      if (!value) {
        if (bad_fields[i]++ == 0) {
          diagnostics.error(field.location, problem);
          first_bad[i] = field.location;
        }
        rows_ok = false;
        continue;
      }
      values[i].push_back(*value);
      if (i == header->time_index) time = value;
    }
    if (time) {
      if (previous_time && !(*time > *previous_time)) {
        diagnostics.error(fields[header->time_index].location,
                          "time " + format_number(*time) +
                              " does not come after the previous row's " +
                              format_number(*previous_time) + ": times must increase strictly");
        rows_ok = false;
      }
      previous_time = time;
    }
  }
  for (std::size_t i = 0; i < width; ++i)
    if (bad_fields[i] > 1)
      diagnostics.note(
          first_bad[i],
          "column '" + header->names[i] + "' has " + std::to_string(bad_fields[i] - 1) + " more " +
              (bad_fields[i] == 2 ? "field that is" : "fields that are") + " not a finite number");

  if (rows == 0 && diagnostics.error_count() == errors_before) {
    diagnostics.error(header_location,
                      "no samples: the header is not followed by any row of numbers");
    return std::nullopt;
  }
  if (!rows_ok || diagnostics.error_count() != errors_before) return std::nullopt;

  CsvSignals signals;
  for (std::size_t i = 0; i < width; ++i) {
    if (i == header->time_index)
      signals.time = std::move(values[i]);
    else
      signals.columns.emplace(header->names[i], std::move(values[i]));
  }
  return signals;
}

namespace {

// What a formula can name: `time`, then the other columns in order.
std::string column_list(const CsvSignals& signals) {
  std::vector<std::string> names{std::string(kTimeColumn)};
  for (const auto& [name, values] : signals.columns) names.push_back(name);
  return name_list(names);
}

SignalValues csv_leaf(const CsvSignals& signals, const SpecTerm& term) {
  const bool reads_column =
      term.kind == TermKind::signal &&
      (term.operands.empty() ||
       (term.operands.size() == 1 &&
        avunit::signal_class(term.name) == avunit::SignalClass::distance_predicate));
  if (reads_column) {
    if (term.name == kTimeColumn) return {signals.time, false};
    if (auto found = signals.columns.find(term.name); found != signals.columns.end())
      return {found->second, false};
    throw OracleError(term.location,
                      "no column '" + term.name + "'; the columns are: " + column_list(signals));
  }
  const std::string what =
      term.kind == TermKind::column ? "'." + term.name + "' of a trace" : "'" + term.name + "'";
  throw OracleError(term.location, what +
                                       " needs a simulated trace; a CSV log gives only its "
                                       "columns: " +
                                       column_list(signals));
}

}  // namespace

SignalSource csv_signal_source(const CsvSignals& signals) {
  SignalSource source;
  source.time = signals.time;
  source.leaf = [&signals](const SpecTerm& term) { return csv_leaf(signals, term); };
  return source;
}

}  // namespace scenfuzz
