// The linear-time robustness engine against the quadratic reference (naive_robustness.hpp) on
// random formulas over random traces: every operator, intervals that are empty, zero-width,
// negative or wider than the trace, even and uneven sampling, and small integer values so that
// min and max meet many ties. A failure prints the formula and the trace to reproduce it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "lang/spec.hpp"
#include "lang/value.hpp"
#include "oracle/robustness.hpp"
#include "tests/oracle/naive_robustness.hpp"

namespace scenfuzz {
namespace {

using Signals = std::map<std::string, SignalValues>;

struct Trace {
  std::vector<double> time;
  Signals signals;
  std::vector<double> parameters;
  double step = 0.1;  // typical spacing, for choosing interval bounds near sample distances
};

constexpr std::size_t kCases = 12000;
constexpr int kMaximumDepth = 5;
// Numeric signals; every trace also has the discrete enumeration c, the discrete flag f and the
// distance stoplineAhead.
const std::array<std::string, 3> kNumericSignals = {"x", "y", "z"};
const std::array<std::string, 7> kWords = {"red",     "yellow", "green", "off",
                                           "forward", "left",   "right"};

std::string number_text(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return value < 0 ? "(" + std::string(buffer) + ")" : std::string(buffer);
}

std::string bound_text(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// Fully parenthesised AVUnit-like text, so that a failing formula can be read and re-typed.
std::string term_text(const SpecTerm& term) {
  switch (term.kind) {
    case TermKind::number:
      if (term.value.op == ValueOp::parameter)
        return "parameter" + std::to_string(term.value.parameter);
      return number_text(term.value.constant);
    case TermKind::word:
    case TermKind::signal:
    case TermKind::column: return term.name;
    case TermKind::negate: return "-(" + term_text(term.operands[0]) + ")";
    case TermKind::add:
    case TermKind::subtract:
    case TermKind::multiply:
    case TermKind::divide: {
      const char* symbol = term.kind == TermKind::add        ? " + "
                           : term.kind == TermKind::subtract ? " - "
                           : term.kind == TermKind::multiply ? " * "
                                                             : " / ";
      return "(" + term_text(term.operands[0]) + symbol + term_text(term.operands[1]) + ")";
    }
    default: return "<term>";
  }
}

// Spaced so that `[-1 : 10]` is not read as the time of day 1:10.
std::string interval_text(const Formula& formula) {
  if (!formula.interval) return "";
  return "[" + bound_text(formula.interval->lower) + " : " + bound_text(formula.interval->upper) +
         "]";
}

std::string formula_text(const Formula& formula) {
  static const std::array<const char*, 6> kCompare = {" < ", " <= ", " > ", " >= ", " == ", " != "};
  switch (formula.kind) {
    case FormulaKind::comparison:
      return "(" + term_text(formula.terms[0]) + kCompare[static_cast<int>(formula.compare)] +
             term_text(formula.terms[1]) + ")";
    case FormulaKind::predicate: {
      const SpecTerm& term = formula.terms[0];
      if (term.operands.empty()) return term.name;
      return term.name + "(" + term_text(term.operands[0]) + ")";
    }
    case FormulaKind::negation: return "~" + formula_text(formula.operands[0]);
    case FormulaKind::conjunction:
    case FormulaKind::disjunction:
    case FormulaKind::implication: {
      const char* symbol = formula.kind == FormulaKind::conjunction   ? " & "
                           : formula.kind == FormulaKind::disjunction ? " | "
                                                                      : " -> ";
      return "(" + formula_text(formula.operands[0]) + symbol + formula_text(formula.operands[1]) +
             ")";
    }
    case FormulaKind::always:
      return "G" + interval_text(formula) + "(" + formula_text(formula.operands[0]) + ")";
    case FormulaKind::eventually:
      return "F" + interval_text(formula) + "(" + formula_text(formula.operands[0]) + ")";
    case FormulaKind::next: return "X(" + formula_text(formula.operands[0]) + ")";
    case FormulaKind::until:
      return "(" + formula_text(formula.operands[0]) + " U" + interval_text(formula) + " " +
             formula_text(formula.operands[1]) + ")";
  }
  return "<formula>";
}

std::string trace_text(const Trace& trace) {
  std::ostringstream text;
  text << "time:";
  for (double t : trace.time) text << ' ' << number_text(t);
  for (const auto& [name, signal] : trace.signals) {
    text << '\n' << name << (signal.discrete ? " (discrete):" : ":");
    for (double value : signal.values) text << ' ' << number_text(value);
  }
  for (std::size_t p = 0; p < trace.parameters.size(); ++p)
    text << "\nparameter" << p << " = " << number_text(trace.parameters[p]);
  return text.str();
}

std::string values_text(const std::vector<double>& values) {
  std::string text;
  for (double value : values) text += " " + number_text(value);
  return text;
}

// Equal infinities agree; finite values agree within 1e-9, relative for large ones.
bool agree(double a, double b) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : random_(seed) {}

  int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }
  double real(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random_);
  }
  bool chance(double probability) { return real(0, 1) < probability; }

  Trace random_trace() {
    Trace trace;
    const auto samples = static_cast<std::size_t>(integer(1, 60));
    static const std::array<double, 7> kSteps = {0.05, 0.1, 0.2, 0.25, 0.3, 0.5, 1.0};
    trace.step = kSteps[static_cast<std::size_t>(integer(0, static_cast<int>(kSteps.size()) - 1))];
    const double start = chance(0.8) ? 0.0 : real(-5, 5);
    const int spacing = integer(0, 3);
    double time = start;
    for (std::size_t i = 0; i < samples; ++i) {
      switch (spacing) {
        // i * step, multiplied as the simulator does: 3 * 0.1 is 0.30000000000000004, so window
        // edges fall a rounding error away from samples.
        case 0: time = start + static_cast<double>(i) * trace.step; break;
        // Accumulated, drifting by rounding.
        case 1:
          if (i > 0) time += trace.step;
          break;
        // Uneven: multiples of the step, so that window edges still meet samples.
        case 2:
          if (i > 0) time += trace.step * integer(1, 4);
          break;
        // Uneven: arbitrary gaps.
        default:
          if (i > 0) time += real(0.001, 2 * trace.step);
          break;
      }
      trace.time.push_back(time);
    }
    // Small integers give ties; reals give distinct values.
    const bool integers = chance(0.7);
    for (const std::string& name : kNumericSignals) {
      SignalValues signal;
      for (std::size_t i = 0; i < samples; ++i)
        signal.values.push_back(integers ? integer(-3, 3) : real(-3, 3));
      trace.signals[name] = signal;
    }
    SignalValues colour{{}, true}, flag{{}, true}, distance;
    for (std::size_t i = 0; i < samples; ++i) {
      colour.values.push_back(integer(0, 3));
      flag.values.push_back(integer(0, 1));
      distance.values.push_back(integers ? integer(0, 6) : real(0, 6));
    }
    trace.signals["c"] = colour;
    trace.signals["f"] = flag;
    trace.signals["stoplineAhead"] = distance;
    trace.parameters = {integers ? integer(-2, 2) : real(-2, 2)};
    return trace;
  }

  Formula random_formula(int depth, const Trace& trace) {
    if (depth == 0 || chance(0.25)) return atom();
    Formula formula;
    formula.kind = static_cast<FormulaKind>(
        integer(static_cast<int>(FormulaKind::negation), static_cast<int>(FormulaKind::until)));
    const int operands =
        formula.kind == FormulaKind::conjunction || formula.kind == FormulaKind::disjunction ||
                formula.kind == FormulaKind::implication || formula.kind == FormulaKind::until
            ? 2
            : 1;
    for (int k = 0; k < operands; ++k) formula.operands.push_back(random_formula(depth - 1, trace));
    if ((formula.kind == FormulaKind::always || formula.kind == FormulaKind::eventually ||
         formula.kind == FormulaKind::until) &&
        chance(0.7))
      formula.interval = interval(trace);
    return formula;
  }

 private:
  TimeInterval interval(const Trace& trace) {
    const double span = trace.time.back() - trace.time.front();
    TimeInterval result;
    switch (integer(0, 3)) {
      case 0: result.lower = 0; break;
      case 1: result.lower = trace.step * integer(-4, 6); break;
      case 2: result.lower = real(-2, 3) * trace.step * 4; break;
      default: result.lower = span * real(-1.2, 1.2); break;
    }
    switch (integer(0, 4)) {
      case 0: result.upper = result.lower; break;  // zero width: at most one sample
      case 1: result.upper = result.lower + trace.step * integer(1, 6); break;
      case 2: result.upper = result.lower + real(0, 8) * trace.step; break;
      case 3: result.upper = result.lower + span * real(0.5, 3); break;  // past the trace end
      default: result.upper = result.lower + 1e6; break;                 // wider than any trace
    }
    return result;
  }

  SpecTerm number(double value) {
    SpecTerm term;
    term.kind = TermKind::number;
    term.value = constant_value(value);
    return term;
  }

  SpecTerm named(TermKind kind, const std::string& name) {
    SpecTerm term;
    term.kind = kind;
    term.name = name;
    return term;
  }

  SpecTerm numeric_term(int depth) {
    const int choice = integer(0, depth > 0 ? 9 : 5);
    if (choice <= 2)
      return named(TermKind::signal, kNumericSignals[static_cast<std::size_t>(integer(
                                         0, static_cast<int>(kNumericSignals.size()) - 1))]);
    if (choice == 3) return number(integer(-3, 3));
    if (choice == 4) return number(std::round(real(-3, 3) * 4) / 4);
    if (choice == 5) {
      SpecTerm term;
      term.kind = TermKind::number;
      term.value = parameter_value(0);
      return term;
    }
    SpecTerm term;
    if (choice == 6) {
      term.kind = TermKind::negate;
      term.operands.push_back(numeric_term(depth - 1));
      return term;
    }
    static const std::array<TermKind, 4> kArithmetic = {TermKind::add, TermKind::subtract,
                                                        TermKind::multiply, TermKind::divide};
    term.kind = kArithmetic[static_cast<std::size_t>(integer(0, 3))];
    term.operands.push_back(numeric_term(depth - 1));
    // Never divide by something that can be zero: infinities from terms are not under test.
    term.operands.push_back(term.kind == TermKind::divide ? number(integer(0, 1) ? 2 : -0.5)
                                                          : numeric_term(depth - 1));
    return term;
  }

  SpecTerm discrete_term() {
    if (chance(0.5)) return named(TermKind::signal, "c");
    if (chance(0.2)) return named(TermKind::signal, "f");
    return named(TermKind::word,
                 kWords[static_cast<std::size_t>(integer(0, static_cast<int>(kWords.size()) - 1))]);
  }

  Formula atom() {
    Formula formula;
    const int choice = integer(0, 9);
    if (choice <= 5) {
      formula.kind = FormulaKind::comparison;
      formula.compare = static_cast<CompareOp>(integer(0, 5));
      if (choice <= 2) {
        formula.terms = {numeric_term(2), numeric_term(2)};
      } else if (choice <= 4) {
        formula.terms = {discrete_term(), discrete_term()};
      } else {
        // Discrete against numeric: an ordinary numeric comparison.
        formula.terms = {discrete_term(), numeric_term(1)};
        if (chance(0.5)) std::swap(formula.terms[0], formula.terms[1]);
      }
      return formula;
    }
    formula.kind = FormulaKind::predicate;
    if (choice <= 7) {
      // A flag: the discrete one, or a numeric signal read as true where it is not zero.
      formula.terms.push_back(named(TermKind::signal, choice == 6 ? "f" : "x"));
    } else {
      SpecTerm term = named(TermKind::signal, "stoplineAhead");
      term.operands.push_back(number(integer(0, 1) ? integer(0, 5) : real(0, 5)));
      formula.terms.push_back(term);
    }
    return formula;
  }

  std::mt19937_64 random_;
};

SignalSource source_for(const Trace& trace) {
  const Signals* signals = &trace.signals;
  return SignalSource{trace.time,
                      [signals](const SpecTerm& term) {
                        auto found = signals->find(term.name);
                        if (found == signals->end())
                          throw OracleError(term.location, "no signal " + term.name);
                        return found->second;
                      },
                      trace.parameters};
}

void collect_nodes(const Formula& formula, std::set<const Formula*>& nodes,
                   std::map<FormulaKind, std::size_t>& kinds) {
  nodes.insert(&formula);
  ++kinds[formula.kind];
  for (const Formula& operand : formula.operands) collect_nodes(operand, nodes, kinds);
}

TEST(RobustnessAgreement, EngineMatchesDefinitionOnRandomFormulasAndTraces) {
  Generator generator(0x5CE4F0225EEDull);
  std::map<FormulaKind, std::size_t> kinds;
  std::size_t failures = 0, infinite_samples = 0, explained = 0;
  for (std::size_t index = 0; index < kCases && failures < 5; ++index) {
    const Trace trace = generator.random_trace();
    const Formula formula = generator.random_formula(generator.integer(0, kMaximumDepth), trace);
    const SignalSource source = source_for(trace);
    const std::string reproduction = "case " + std::to_string(index) +
                                     "\nformula: " + formula_text(formula) + "\n" +
                                     trace_text(trace);
    std::set<const Formula*> nodes;
    collect_nodes(formula, nodes, kinds);

    const std::vector<double> expected = test::naive_robustness(formula, source);
    std::vector<double> got;
    try {
      got = robustness_signal(formula, source);
    } catch (const std::exception& error) {
      ADD_FAILURE() << "engine threw: " << error.what() << "\n" << reproduction;
      ++failures;
      continue;
    }
    bool same = got.size() == expected.size();
    for (std::size_t i = 0; same && i < got.size(); ++i) same = agree(got[i], expected[i]);
    if (!same) {
      ADD_FAILURE() << reproduction << "\nexpected:" << values_text(expected)
                    << "\ngot:     " << values_text(got);
      ++failures;
      continue;
    }
    infinite_samples += static_cast<std::size_t>(
        std::count_if(expected.begin(), expected.end(), [](double v) { return std::isinf(v); }));

    // The witness names a node of this formula whose value at the witness sample is the
    // robustness, up to the sign that negations above it flip.
    const auto sample =
        static_cast<std::size_t>(generator.integer(0, static_cast<int>(trace.time.size()) - 1));
    RobustnessWitness witness;
    try {
      witness = explain_robustness(formula, source, sample);
    } catch (const std::exception& error) {
      ADD_FAILURE() << "explain_robustness threw: " << error.what() << " at sample " << sample
                    << "\n"
                    << reproduction;
      ++failures;
      continue;
    }
    std::string problem;
    if (!agree(witness.robustness, expected[sample])) {
      problem = "witness robustness " + number_text(witness.robustness);
    } else if (std::isinf(expected[sample])) {
      if (witness.atom != nullptr) problem = "an atom for an infinite robustness";
    } else if (witness.atom == nullptr || nodes.count(witness.atom) == 0) {
      problem = "no atom of this formula";
    } else if (witness.atom->kind != FormulaKind::comparison &&
               witness.atom->kind != FormulaKind::predicate) {
      problem = "the witness is not an atom: " + formula_text(*witness.atom);
    } else if (witness.sample >= trace.time.size()) {
      problem = "witness sample " + std::to_string(witness.sample) + " outside the trace";
    } else {
      const double atom_value = test::naive_robustness(*witness.atom, source)[witness.sample];
      if (!agree(std::abs(atom_value), std::abs(expected[sample])))
        problem = "atom " + formula_text(*witness.atom) + " is " + number_text(atom_value) +
                  " at sample " + std::to_string(witness.sample);
    }
    if (!problem.empty()) {
      ADD_FAILURE() << "explain_robustness at sample " << sample << " (robustness "
                    << number_text(expected[sample]) << "): " << problem << "\n"
                    << reproduction;
      ++failures;
      continue;
    }
    ++explained;
  }
  EXPECT_EQ(failures, 0u);
  // The generator reaches every operator, and empty windows do occur.
  for (int kind = 0; kind <= static_cast<int>(FormulaKind::until); ++kind)
    EXPECT_GT(kinds[static_cast<FormulaKind>(kind)], 100u) << "formula kind " << kind;
  EXPECT_GT(infinite_samples, 100u);
  EXPECT_EQ(explained, kCases);
}

}  // namespace
}  // namespace scenfuzz
