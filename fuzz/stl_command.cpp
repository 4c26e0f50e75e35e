// `scenfuzz stl --spec FORMULA --trace FILE.csv [--signal]`: the robustness of one STL formula on
// a CSV log written by another tool, so that the oracle can be used (and checked, against RTAMT)
// without a simulation.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/number_format.hpp"
#include "oracle/csv_signals.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace {

// The formula's text at `location`, as the user wrote it.
std::string spec_text(const SourceFile& spec, const SourceLocation& location) {
  if (!location.known() || location.end_offset() > spec.text().size()) return "";
  return spec.text().substr(location.offset, location.length);
}

// Why the formula is violated, as a note on the --spec text: the atom that gives the robustness
// at the first sample and where in the log it does so.
std::string explain_violation(const Formula& formula, const SourceFile& spec,
                              const SignalSource& source) {
  const RobustnessWitness witness = explain_robustness(formula, source, 0);
  Diagnostic note;
  note.severity = Severity::note;
  if (witness.atom == nullptr) {
    note.message = "violated with robustness " + format_number(witness.robustness) +
                   ", which no atom gives: a window of F or U holds no sample (the log ends at "
                   "t = " +
                   format_number(source.time.back()) + ")";
    return format_diagnostic(spec, note);
  }
  // Under a negation the atom's own robustness has the opposite sign; saying which it is keeps
  // the note true for every formula.
  const double atom_robustness = robustness_signal(*witness.atom, source)[witness.sample];
  note.location = witness.atom->location;
  note.message = "violated by '" + spec_text(spec, witness.atom->location) +
                 "' at t = " + format_number(source.time[witness.sample]) +
                 " (its robustness there: " + format_number(atom_robustness) + ")";
  return format_diagnostic(spec, note);
}

}  // namespace

int run_stl(const StlCommandOptions& options, std::ostream& out, std::ostream& err) {
  const SourceFile spec("--spec", options.spec);
  const avunit::FormulaParseResult parsed = avunit::parse_formula(spec);
  err << format_diagnostics(spec, parsed.diagnostics);
  if (!parsed.formula) return kExitBadInput;
  const Formula& formula = *parsed.formula;

  std::optional<SourceFile> trace = read_input(options.trace_path, err);
  if (!trace) return kExitBadInput;
  Diagnostics csv_diagnostics;
  const std::optional<CsvSignals> signals = read_csv_signals(*trace, csv_diagnostics);
  err << format_diagnostics(*trace, csv_diagnostics);
  if (!signals) return kExitBadInput;
  const SignalSource source = csv_signal_source(*signals);

  std::vector<double> robustness;
  std::string explanation;
  try {
    robustness = robustness_signal(formula, source);
    if (robustness.front() < 0) explanation = explain_violation(formula, spec, source);
  } catch (const OracleError& error) {
    err << format_diagnostic(spec, {Severity::error, error.location(), error.what()});
    return kExitBadInput;
  }
  if (std::isnan(robustness.front())) {
    err << format_diagnostic(spec, {Severity::error, formula.location,
                                    "the robustness at t = " + format_number(source.time[0]) +
                                        " is not a number (an arithmetic such as inf - inf)"});
    return kExitBadInput;
  }

  if (options.signal) {
    std::string table = "time,robustness\n";
    for (std::size_t i = 0; i < robustness.size(); ++i)
      table += format_number(source.time[i]) + "," + format_number(robustness[i]) + "\n";
    out << table;
  } else {
    out << format_number(robustness.front()) << "\n";
  }
  out.flush();
  err << explanation;
  return robustness.front() < 0 ? kExitViolated : kExitSuccess;
}

}  // namespace scenfuzz
