// Signals from a CSV log written by another tool (`scenfuzz stl --trace FILE.csv`): a header row
// of column names, one of them `time` (seconds), then one row per sample. Every other column is
// a signal that a formula names directly (`x`, `ego.speed`, `trafficLightAhead.color`).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

struct CsvSignals {
  std::vector<double> time;
  std::map<std::string, std::vector<double>> columns;  // every column but `time`, by name
};

// Reads RFC 4180 CSV (comma separated, optional double quotes, CRLF or LF, a trailing newline
// or not). Problems are errors in `diagnostics` naming file:line:column and what was expected,
// and give nullopt: no header or no `time` column, a duplicate or empty column name, a row with
// a different number of fields, a field that is not a finite number, times not strictly
// increasing, no data row.
std::optional<CsvSignals> read_csv_signals(const SourceFile& file, Diagnostics& diagnostics);

// A SignalSource over the CSV's samples: a TermKind::signal term without arguments reads the
// column of its name; a distance predicate `P(d)` reads column P; anything else is an
// OracleError naming the term ("no column 'z'; the columns are: x, y"). Columns are numeric,
// never discrete. Valid while `signals` lives.
SignalSource csv_signal_source(const CsvSignals& signals);

}  // namespace scenfuzz
