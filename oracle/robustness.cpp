#include "oracle/robustness.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include "lang/number_format.hpp"
#include "lang/value.hpp"

namespace scenfuzz {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using Signal = std::vector<double>;

// For every sample i, the samples [begin[i], end[i]) of its window. Both ends are non-decreasing
// in i because times increase, which is what lets every windowed operator run in linear time.
struct Windows {
  std::vector<std::size_t> begin, end;
};

Windows windows_of(std::span<const double> time, const std::optional<TimeInterval>& interval) {
  const std::size_t n = time.size();
  Windows windows;
  windows.begin.resize(n);
  windows.end.resize(n);
  if (!interval) {
    for (std::size_t i = 0; i < n; ++i) {
      windows.begin[i] = i;
      windows.end[i] = n;
    }
    return windows;
  }
  const double lower = interval->lower - kWindowTolerance;
  const double upper = interval->upper + kWindowTolerance;
  std::size_t begin = 0, end = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (begin < n && time[begin] - time[i] < lower) ++begin;
    if (end < begin) end = begin;
    while (end < n && time[end] - time[i] <= upper) ++end;
    windows.begin[i] = begin;
    windows.end[i] = end;
  }
  return windows;
}

// Sliding-window minimum (Prefer = std::less) or maximum (std::greater) over monotone windows,
// with a monotone deque of candidate indices: each index enters and leaves once.
template <class Prefer>
Signal sliding_extreme(const Signal& x, const std::vector<std::size_t>& begin,
                       const std::vector<std::size_t>& end, double empty, Prefer prefer) {
  const std::size_t n = begin.size();
  Signal out(n);
  std::vector<std::size_t> queue(x.size());
  std::size_t head = 0, tail = 0, next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (; next < end[i]; ++next) {
      // A candidate no better than the newcomer can never be the extreme again.
      while (tail > head && !prefer(x[queue[tail - 1]], x[next])) --tail;
      queue[tail++] = next;
    }
    while (head < tail && queue[head] < begin[i]) ++head;
    out[i] = head < tail ? x[queue[head]] : empty;
  }
  return out;
}

Signal window_min(const Signal& x, const std::vector<std::size_t>& begin,
                  const std::vector<std::size_t>& end) {
  return sliding_extreme(x, begin, end, kInfinity, std::less<double>());
}

Signal window_max(const Signal& x, const std::vector<std::size_t>& begin,
                  const std::vector<std::size_t>& end) {
  return sliding_extreme(x, begin, end, -kInfinity, std::greater<double>());
}

Signal suffix_min(Signal x) {
  for (std::size_t i = x.size(); i-- > 1;) x[i - 1] = std::min(x[i - 1], x[i]);
  return x;
}

Signal suffix_max(Signal x) {
  for (std::size_t i = x.size(); i-- > 1;) x[i - 1] = std::max(x[i - 1], x[i]);
  return x;
}

// p U q over the rest of the trace: r(i) = max(q(i), min(p(i), r(i + 1))), r(n) = -inf.
Signal unbounded_until(const Signal& p, const Signal& q) {
  const std::size_t n = p.size();
  Signal r(n);
  double later = -kInfinity;
  for (std::size_t i = n; i-- > 0;) {
    later = std::max(q[i], std::min(p[i], later));
    r[i] = later;
  }
  return r;
}

// p U[a:b] q. The samples of the window at or after i split off as (Donze, Ferrere, Maler, CAV
// 2013): with f the first of them and W the window from f on,
//   max_{j in W} min(q(j), min p[i, j)) = min(min p[i, f), max_{j in W} q(j), (p U q)(f)),
// where the untimed until may look past W only when the window's best q bounds it. Samples of
// the window before i (a negative lower bound) contribute q(j) alone: min p[i, j) is empty.
Signal bounded_until(const Signal& p, const Signal& q, const Windows& windows) {
  const std::size_t n = p.size();
  const Signal untimed = unbounded_until(p, q);
  std::vector<std::size_t> first(n), self(n), past_end(n);
  for (std::size_t i = 0; i < n; ++i) {
    first[i] = std::max(windows.begin[i], i);
    self[i] = i;
    past_end[i] = std::min(windows.end[i], i);
  }
  const Signal p_before_window = window_min(p, self, first);
  const Signal q_in_window = window_max(q, first, windows.end);
  const Signal q_in_past = window_max(q, windows.begin, past_end);
  Signal r(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double from_first = first[i] < n ? untimed[first[i]] : -kInfinity;
    const double future = std::min({p_before_window[i], q_in_window[i], from_first});
    r[i] = std::max(q_in_past[i], future);
  }
  return r;
}

double enumeration_code(const std::string& word) {
  if (word == "red" || word == "left") return 1;
  if (word == "yellow" || word == "right") return 2;
  if (word == "green") return 3;
  return 0;  // off, forward
}

std::string format_time(double seconds) { return format_number(seconds); }

// Evaluates formulas bottom-up; optionally keeps every node's signal for explanations.
class Evaluator {
 public:
  Evaluator(const SignalSource& source, bool keep) : source_(source), keep_(keep) {}

  Signal formula(const Formula& f) {
    Signal result = compute(f);
    if (keep_) kept_[&f] = result;
    return result;
  }

  SignalValues term(const SpecTerm& t) {
    const std::size_t n = source_.time.size();
    switch (t.kind) {
      case TermKind::number:
      case TermKind::time_of_day: return {Signal(n, evaluate(t.value, source_.parameters)), false};
      case TermKind::word: return {Signal(n, enumeration_code(t.name)), true};
      case TermKind::signal:
      case TermKind::column: return leaf(t);
      case TermKind::object:
      case TermKind::position:
      case TermKind::vector:
        throw OracleError(t.location,
                          "not a number: a trace projection, position or vector "
                          "is an argument of dis, vel, spd, acc or diff");
      case TermKind::negate: {
        Signal x = term(t.operands[0]).values;
        for (double& v : x) v = -v;
        return {std::move(x), false};
      }
      default: break;
    }
    Signal a = term(t.operands[0]).values;
    const Signal b = term(t.operands[1]).values;
    for (std::size_t i = 0; i < n; ++i) a[i] = arithmetic(t.kind, a[i], b[i]);
    return {std::move(a), false};
  }

  const Signal& kept(const Formula& f) const { return kept_.at(&f); }

 private:
  static double arithmetic(TermKind kind, double a, double b) {
    switch (kind) {
      case TermKind::add: return a + b;
      case TermKind::subtract: return a - b;
      case TermKind::multiply: return a * b;
      case TermKind::divide: return a / b;
      default: return std::pow(a, b);
    }
  }

  SignalValues leaf(const SpecTerm& t) {
    if (!source_.leaf) throw OracleError(t.location, "no signal source for '" + t.name + "'");
    SignalValues values = source_.leaf(t);
    assert(values.values.size() == source_.time.size());
    return values;
  }

  // A side of a comparison, checked to be a number everywhere.
  SignalValues side(const SpecTerm& t, const Formula& comparison) {
    SignalValues values = term(t);
    for (std::size_t i = 0; i < values.values.size(); ++i)
      if (std::isnan(values.values[i]))
        throw OracleError(comparison.location,
                          "this comparison meets a value that is not a "
                          "number at t = " +
                              format_time(source_.time[i]) + " s");
    return values;
  }

  Signal comparison(const Formula& f) {
    const SignalValues left = side(f.terms[0], f);
    const SignalValues right = side(f.terms[1], f);
    const std::size_t n = left.values.size();
    Signal r(n);
    const bool discrete = left.discrete && right.discrete;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = left.values[i], b = right.values[i];
      if (discrete) {
        r[i] = holds(f.compare, a, b) ? 1.0 : -1.0;
        continue;
      }
      switch (f.compare) {
        case CompareOp::less:
        case CompareOp::less_equal: r[i] = b - a; break;
        case CompareOp::greater:
        case CompareOp::greater_equal: r[i] = a - b; break;
        case CompareOp::equal: r[i] = -std::abs(a - b); break;
        case CompareOp::not_equal: r[i] = std::abs(a - b); break;
      }
    }
    return r;
  }

  static bool holds(CompareOp op, double a, double b) {
    switch (op) {
      case CompareOp::less: return a < b;
      case CompareOp::less_equal: return a <= b;
      case CompareOp::greater: return a > b;
      case CompareOp::greater_equal: return a >= b;
      case CompareOp::equal: return a == b;
      case CompareOp::not_equal: return a != b;
    }
    return false;
  }

  // `hornOn`: +1 where set, -1 where not. `stoplineAhead(2)`: 2 - the distance.
  Signal predicate(const Formula& f) {
    const SpecTerm& signal = f.terms[0];
    Signal values = side(signal, f).values;
    if (signal.operands.size() == 1) {
      const Signal distance = side(signal.operands[0], f).values;
      for (std::size_t i = 0; i < values.size(); ++i) values[i] = distance[i] - values[i];
    } else {
      for (double& v : values) v = v != 0 ? 1.0 : -1.0;
    }
    return values;
  }

  Signal compute(const Formula& f) {
    switch (f.kind) {
      case FormulaKind::comparison: return comparison(f);
      case FormulaKind::predicate: return predicate(f);
      case FormulaKind::negation: {
        Signal x = formula(f.operands[0]);
        for (double& v : x) v = -v;
        return x;
      }
      case FormulaKind::conjunction:
      case FormulaKind::disjunction:
      case FormulaKind::implication: {
        Signal a = formula(f.operands[0]);
        const Signal b = formula(f.operands[1]);
        for (std::size_t i = 0; i < a.size(); ++i) {
          if (f.kind == FormulaKind::conjunction) a[i] = std::min(a[i], b[i]);
          if (f.kind == FormulaKind::disjunction) a[i] = std::max(a[i], b[i]);
          if (f.kind == FormulaKind::implication) a[i] = std::max(-a[i], b[i]);
        }
        return a;
      }
      case FormulaKind::always:
      case FormulaKind::eventually: {
        Signal x = formula(f.operands[0]);
        const bool always = f.kind == FormulaKind::always;
        if (!f.interval) return always ? suffix_min(std::move(x)) : suffix_max(std::move(x));
        const Windows windows = windows_of(source_.time, f.interval);
        return always ? window_min(x, windows.begin, windows.end)
                      : window_max(x, windows.begin, windows.end);
      }
      case FormulaKind::next: {
        Signal x = formula(f.operands[0]);
        if (x.empty()) return x;
        std::rotate(x.begin(), x.begin() + 1, x.end());
        x.back() = kInfinity;
        return x;
      }
      case FormulaKind::until: {
        const Signal p = formula(f.operands[0]);
        const Signal q = formula(f.operands[1]);
        if (!f.interval) return unbounded_until(p, q);
        return bounded_until(p, q, windows_of(source_.time, f.interval));
      }
    }
    return {};
  }

  const SignalSource& source_;
  bool keep_;
  std::unordered_map<const Formula*, Signal> kept_;
};

// Follows the value of `f` at `sample` down to the atom that gives it.
class Explainer {
 public:
  Explainer(const Evaluator& evaluator, std::span<const double> time)
      : evaluator_(evaluator), time_(time) {}

  RobustnessWitness explain(const Formula& f, std::size_t sample) {
    const double value = evaluator_.kept(f)[sample];
    RobustnessWitness witness{value, nullptr, sample};
    const Formula* node = &f;
    std::size_t at = sample;
    while (true) {
      const double target = evaluator_.kept(*node)[at];
      std::optional<std::pair<const Formula*, std::size_t>> next = step(*node, at, target);
      if (!next) return witness;
      std::tie(node, at) = *next;
      if (node->kind == FormulaKind::comparison || node->kind == FormulaKind::predicate) {
        witness.atom = node;
        witness.sample = at;
        return witness;
      }
    }
  }

 private:
  using Step = std::optional<std::pair<const Formula*, std::size_t>>;

  const Signal& of(const Formula& f) const { return evaluator_.kept(f); }

  // The child and sample whose value `target` is, or nullopt when none is (an infinity from an
  // empty window or from X at the last sample).
  Step step(const Formula& f, std::size_t at, double target) const {
    const std::size_t n = time_.size();
    switch (f.kind) {
      case FormulaKind::comparison:
      case FormulaKind::predicate: return Step({&f, at});
      case FormulaKind::negation: return Step({&f.operands[0], at});
      case FormulaKind::conjunction:
      case FormulaKind::disjunction:
        return Step({of(f.operands[0])[at] == target ? &f.operands[0] : &f.operands[1], at});
      case FormulaKind::implication:
        return Step({-of(f.operands[0])[at] == target ? &f.operands[0] : &f.operands[1], at});
      case FormulaKind::next:
        if (at + 1 >= n) return std::nullopt;
        return Step({&f.operands[0], at + 1});
      case FormulaKind::always:
      case FormulaKind::eventually: {
        const Windows windows = windows_of(time_, f.interval);
        const Signal& x = of(f.operands[0]);
        for (std::size_t j = windows.begin[at]; j < windows.end[at]; ++j)
          if (x[j] == target) return Step({&f.operands[0], j});
        return std::nullopt;
      }
      case FormulaKind::until: {
        const Windows windows = windows_of(time_, f.interval);
        const Signal& p = of(f.operands[0]);
        const Signal& q = of(f.operands[1]);
        // min p[at, j), kept as j moves on; empty (+inf) for window samples at or before `at`.
        double p_before = kInfinity;
        std::size_t p_at = at, scanned = at;
        for (std::size_t j = windows.begin[at]; j < windows.end[at]; ++j) {
          for (; scanned < j; ++scanned)
            if (p[scanned] < p_before) p_before = p[scanned], p_at = scanned;
          if (std::min(q[j], p_before) != target) continue;
          if (q[j] == target) return Step({&f.operands[1], j});
          return Step({&f.operands[0], p_at});
        }
        return std::nullopt;
      }
    }
    return std::nullopt;
  }

  const Evaluator& evaluator_;
  std::span<const double> time_;
};

}  // namespace

SignalValues term_signal(const SpecTerm& term, const SignalSource& source) {
  return Evaluator(source, false).term(term);
}

std::vector<double> robustness_signal(const Formula& formula, const SignalSource& source) {
  return Evaluator(source, false).formula(formula);
}

RobustnessWitness explain_robustness(const Formula& formula, const SignalSource& source,
                                     std::size_t sample) {
  Evaluator evaluator(source, true);
  evaluator.formula(formula);
  if (sample >= source.time.size()) return {kInfinity, nullptr, sample};
  return Explainer(evaluator, source.time).explain(formula, sample);
}

}  // namespace scenfuzz
