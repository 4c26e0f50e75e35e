#include "oracle/robustness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/value.hpp"
#include "oracle/signal_pool.hpp"
#include "oracle/window_offsets.hpp"

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

// The windows of samples 0, 1, 2, ... in turn, without storing them: the two-pointer walk of
// windows_of.
class WindowCursor {
 public:
  WindowCursor(std::span<const double> time, const TimeInterval& interval)
      : time_(time),
        lower_(interval.lower - kWindowTolerance),
        upper_(interval.upper + kWindowTolerance) {}

  // The window [begin, end) of sample i; called with i = 0, 1, 2, ...
  std::pair<std::size_t, std::size_t> operator()(std::size_t i) {
    const std::size_t n = time_.size();
    while (begin_ < n && time_[begin_] - time_[i] < lower_) ++begin_;
    if (end_ < begin_) end_ = begin_;
    while (end_ < n && time_[end_] - time_[i] <= upper_) ++end_;
    return {begin_, end_};
  }

 private:
  std::span<const double> time_;
  double lower_, upper_;
  std::size_t begin_ = 0, end_ = 0;
};

struct Minimum {
  double operator()(double a, double b) const { return std::min(a, b); }
};
struct Maximum {
  double operator()(double a, double b) const { return std::max(a, b); }
};

// Sliding-window minimum (Extreme = Minimum, identity +inf) or maximum (Maximum, -inf) over
// monotone windows (`window(i)` gives sample i's [begin, end), both non-decreasing in i), with two
// stacks: the window is a front part [begin, split), whose suffix extremes were computed when it
// was cut off, and a back part [split, end), kept as one running extreme. When the window's start
// passes `split`, the front is rebuilt from the samples still in it. Each sample is rebuilt at most
// once, and no branch depends on the values: a monotone deque's pops did, and mispredicted on
// every other sample of a random walk.
template <class Window, class Extreme>
void sliding_extreme(const Signal& x, Window window, double identity, Extreme extreme, Signal& out,
                     Signal& suffix) {
  const std::size_t n = x.size();
  suffix.resize(n);
  std::size_t split = 0, next = 0;  // the back part is [split, next)
  double back = identity;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [begin, end] = window(i);
    for (; next < end; ++next) back = extreme(back, x[next]);
    if (begin > split) {
      double running = identity;
      for (std::size_t k = next; k-- > begin;) suffix[k] = running = extreme(running, x[k]);
      split = next;
      back = identity;
    }
    out[i] = extreme(begin < split ? suffix[begin] : identity, back);
  }
}

// Sliding extreme over constant offsets by van Herk / Gil-Werman: the samples padded with the
// identity are cut into blocks of the window's width w; every window spans the suffix of one
// block and the prefix of the next, so out[i] = extreme(suffix[i], prefix[i + w - 1]). Three
// branch-free passes, whatever the width.
template <class Extreme>
void van_herk_extreme(const Signal& x, Offsets offsets, double identity, Extreme extreme,
                      Signal& out, Signal& padded, Signal& suffix) {
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  // Indices outside the trace are the identity, so offsets beyond +-n change nothing.
  const std::ptrdiff_t first = std::max(offsets.first, -n);
  const std::ptrdiff_t last = std::min(offsets.last, n);
  if (last < first || n == 0) {
    std::fill(out.begin(), out.end(), identity);
    return;
  }
  const std::ptrdiff_t width = last - first + 1;
  const std::ptrdiff_t m = n + width - 1;  // padded[k] is x[k + first]
  padded.assign(static_cast<std::size_t>(m), identity);
  const std::ptrdiff_t copy_begin = std::max<std::ptrdiff_t>(0, -first);
  const std::ptrdiff_t copy_end = std::min(m, n - first);
  if (copy_begin < copy_end)
    std::copy(x.begin() + (copy_begin + first), x.begin() + (copy_end + first),
              padded.begin() + copy_begin);
  suffix.resize(static_cast<std::size_t>(m));
  for (std::ptrdiff_t block = 0; block < m; block += width) {
    const std::ptrdiff_t end = std::min(block + width, m);
    double running = identity;
    for (std::ptrdiff_t k = end; k-- > block;)
      suffix[static_cast<std::size_t>(k)] = running =
          extreme(running, padded[static_cast<std::size_t>(k)]);
  }
  for (std::ptrdiff_t block = 0; block < m; block += width) {
    const std::ptrdiff_t end = std::min(block + width, m);
    double running = identity;
    for (std::ptrdiff_t k = block; k < end; ++k) {
      running = extreme(running, padded[static_cast<std::size_t>(k)]);
      const std::ptrdiff_t i = k - (width - 1);
      if (i >= 0)
        out[static_cast<std::size_t>(i)] = extreme(suffix[static_cast<std::size_t>(i)], running);
    }
  }
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
void unbounded_until(const Signal& p, const Signal& q, Signal& r) {
  double later = -kInfinity;
  for (std::size_t i = p.size(); i-- > 0;) {
    later = std::max(q[i], std::min(p[i], later));
    r[i] = later;
  }
}

// bounded_until's working signals, each of n samples, lent by the evaluator.
struct UntilParts {
  Signal untimed, p_before_window, q_in_window, q_in_past;
};

// p U[a:b] q. The samples of the window at or after i split off as (Donze, Ferrere, Maler, CAV
// 2013): with f the first of them and W the window from f on,
//   max_{j in W} min(q(j), min p[i, j)) = min(min p[i, f), max_{j in W} q(j), (p U q)(f)),
// where the untimed until may look past W only when the window's best q bounds it. Samples of
// the window before i (a negative lower bound) contribute q(j) alone: min p[i, j) is empty.
// Each pass walks the windows afresh with its own cursor rather than storing them: no memory of
// n indices twice over, for a few comparisons per sample.
void bounded_until(const Signal& p, const Signal& q, std::span<const double> time,
                   const TimeInterval& interval, UntilParts& parts, Signal& suffix, Signal& r) {
  const std::size_t n = p.size();
  unbounded_until(p, q, parts.untimed);
  WindowCursor before(time, interval), within(time, interval), past(time, interval),
      merge(time, interval);
  sliding_extreme(
      p, [&](std::size_t i) { return std::pair(i, std::max(before(i).first, i)); }, kInfinity,
      Minimum(), parts.p_before_window, suffix);
  sliding_extreme(
      q,
      [&](std::size_t i) {
        const auto [begin, end] = within(i);
        return std::pair(std::max(begin, i), end);
      },
      -kInfinity, Maximum(), parts.q_in_window, suffix);
  sliding_extreme(
      q,
      [&](std::size_t i) {
        const auto [begin, end] = past(i);
        return std::pair(begin, std::min(end, i));
      },
      -kInfinity, Maximum(), parts.q_in_past, suffix);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t first = std::max(merge(i).first, i);
    const double from_first = first < n ? parts.untimed[first] : -kInfinity;
    const double future = std::min({parts.p_before_window[i], parts.q_in_window[i], from_first});
    r[i] = std::max(parts.q_in_past[i], future);
  }
}

double enumeration_code(const std::string& word) {
  if (word == "red" || word == "left") return 1;
  if (word == "yellow" || word == "right") return 2;
  if (word == "green") return 3;
  return 0;  // off, forward
}

std::string format_time(double seconds) { return format_number(seconds); }

// A term's value: a signal, or one number for every sample (constants are never spread out).
struct Operand {
  Signal values;
  double scalar = 0;
  bool is_scalar = false;
  bool discrete = false;
};

// Evaluates formulas bottom-up; optionally keeps every node's signal for explanations. Buffers
// freed by one node are reused by the next, and kept for the thread's next evaluation
// (signal_pool.hpp), so a repeat evaluation allocates little more than its result.
class Evaluator {
 public:
  Evaluator(const SignalSource& source, bool keep)
      : source_(source), keep_(keep), spare_(take_spare_signals()) {}
  ~Evaluator() { keep_spare_signals(std::move(spare_)); }
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;

  // Samples before `first` are the start state the trace was given (robustness_if_started_later):
  // every atom there that only universal operators read is as favourable to the whole formula as
  // it can be. Samples from `end` on are not the trace's but what might come after it
  // (robustness_if_continued): every atom there is.
  void excuse(std::size_t first, std::size_t end) {
    first_observed_ = first;
    observed_end_ = end;
  }

  Signal formula(const Formula& f) {
    Signal result = compute(f);
    if (keep_) kept_[&f] = result;
    return result;
  }

  SignalValues term_values(const SpecTerm& t) {
    Operand operand = term(t);
    if (operand.is_scalar) operand.values.assign(size(), operand.scalar);
    return {std::move(operand.values), operand.discrete};
  }

  const Signal& kept(const Formula& f) const { return kept_.at(&f); }

 private:
  std::size_t size() const { return source_.time.size(); }

  // The smallest spare buffer with room for `room` samples, or spare_.end().
  SpareSignals::iterator spare_with_room(std::size_t room) {
    auto best = spare_.end();
    for (auto spare = spare_.begin(); spare != spare_.end(); ++spare)
      if (spare->capacity() >= room &&
          (best == spare_.end() || spare->capacity() < best->capacity()))
        best = spare;
    return best;
  }

  // A buffer of size() samples with room for `room` (van Herk's padded signals are longer than
  // the trace): the smallest spare with that room, so that the long ones stay for padded signals;
  // a new one when none has it.
  Signal acquire(std::size_t room = 0) {
    room = std::max(room, size());
    Signal buffer;
    if (const auto best = spare_with_room(room); best != spare_.end()) {
      buffer = std::move(*best);
      spare_.erase(best);
    }
    buffer.reserve(room);
    buffer.resize(size());
    return buffer;
  }

  // The room van_herk_extreme's padded and suffix signals need.
  std::size_t padded_room(Offsets offsets) const {
    const auto n = static_cast<std::ptrdiff_t>(size());
    const std::ptrdiff_t width = std::min(offsets.last, n) - std::max(offsets.first, -n) + 1;
    return size() + static_cast<std::size_t>(std::max<std::ptrdiff_t>(width, 1)) - 1;
  }

  void release(Signal&& buffer) {
    if (buffer.capacity() >= size()) spare_.push_back(std::move(buffer));
  }

  static Operand scalar(double value, bool discrete) { return {{}, value, true, discrete}; }

  Operand term(const SpecTerm& t) {
    switch (t.kind) {
      case TermKind::number:
      case TermKind::time_of_day: return scalar(evaluate(t.value, source_.parameters), false);
      case TermKind::word: return scalar(enumeration_code(t.name), true);
      case TermKind::signal:
      case TermKind::column: return leaf(t);
      case TermKind::object:
      case TermKind::position:
      case TermKind::vector:
        throw OracleError(t.location,
                          "not a number: a trace projection, position or vector "
                          "is an argument of dis, vel, spd, acc or diff");
      case TermKind::negate: {
        Operand x = term(t.operands[0]);
        x.discrete = false;
        x.scalar = -x.scalar;
        for (double& v : x.values) v = -v;
        return x;
      }
      default: break;
    }
    Operand a = term(t.operands[0]);
    Operand b = term(t.operands[1]);
    if (a.is_scalar && b.is_scalar) return scalar(arithmetic(t.kind, a.scalar, b.scalar), false);
    Operand result{a.is_scalar ? std::move(b.values) : std::move(a.values), 0, false, false};
    for (std::size_t i = 0; i < size(); ++i)
      result.values[i] = arithmetic(t.kind, a.is_scalar ? a.scalar : result.values[i],
                                    b.is_scalar   ? b.scalar
                                    : a.is_scalar ? result.values[i]
                                                  : b.values[i]);
    if (!a.is_scalar && !b.is_scalar) release(std::move(b.values));
    return result;
  }

  static double arithmetic(TermKind kind, double a, double b) {
    switch (kind) {
      case TermKind::add: return a + b;
      case TermKind::subtract: return a - b;
      case TermKind::multiply: return a * b;
      case TermKind::divide: return a / b;
      default: return std::pow(a, b);
    }
  }

  Operand leaf(const SpecTerm& t) {
    if (!source_.leaf) throw OracleError(t.location, "no signal source for '" + t.name + "'");
    SignalValues values = source_.leaf(t);
    SCENFUZZ_DEMAND(values.values.size() == size());
    // Copied into a kept buffer while one is long enough, and the leaf's own freed at once: malloc
    // hands that still-mapped block to the next leaf. Kept, it would join the kept buffers, and
    // every evaluation would take as many new ones as it has leaves.
    if (spare_with_room(size()) == spare_.end())
      return {std::move(values.values), 0, false, values.discrete};
    Signal kept = acquire();
    std::copy(values.values.begin(), values.values.end(), kept.begin());
    return {std::move(kept), 0, false, values.discrete};
  }

  [[noreturn]] void not_a_number(const Formula& comparison, std::size_t sample) {
    throw OracleError(comparison.location,
                      "this comparison meets a value that is not a number at t = " +
                          format_time(source_.time[sample]) + " s");
  }

  // r[i] = robustness(a[i], b[i]) written over a buffer of one side, with a NaN check folded in.
  template <class Robustness>
  Signal combine(const Formula& f, Operand& a, Operand& b, Robustness robustness) {
    Signal r = !a.is_scalar ? std::move(a.values) : !b.is_scalar ? std::move(b.values) : acquire();
    const double* left = a.is_scalar ? nullptr : r.data();
    const double* right = b.is_scalar ? nullptr : (a.is_scalar ? r.data() : b.values.data());
    std::size_t first_nan = size();
    for (std::size_t i = 0; i < size(); ++i) {
      const double x = left ? left[i] : a.scalar, y = right ? right[i] : b.scalar;
      if ((std::isnan(x) || std::isnan(y)) && first_nan == size()) first_nan = i;
      r[i] = robustness(x, y);
    }
    if (!a.is_scalar && !b.is_scalar) release(std::move(b.values));
    if (first_nan < size()) not_a_number(f, first_nan);
    return r;
  }

  Signal comparison(const Formula& f) {
    Operand a = term(f.terms[0]);
    Operand b = term(f.terms[1]);
    if (a.discrete && b.discrete) {
      const CompareOp op = f.compare;
      return combine(f, a, b, [op](double x, double y) { return holds(op, x, y) ? 1.0 : -1.0; });
    }
    switch (f.compare) {
      case CompareOp::less:
      case CompareOp::less_equal: return combine(f, a, b, [](double x, double y) { return y - x; });
      case CompareOp::greater:
      case CompareOp::greater_equal:
        return combine(f, a, b, [](double x, double y) { return x - y; });
      case CompareOp::equal:
        return combine(f, a, b, [](double x, double y) { return -std::abs(x - y); });
      case CompareOp::not_equal:
        return combine(f, a, b, [](double x, double y) { return std::abs(x - y); });
    }
    return {};
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
    Operand value = term(signal);
    if (signal.operands.size() == 1) {
      Operand distance = term(signal.operands[0]);
      return combine(f, value, distance, [](double x, double d) { return d - x; });
    }
    Operand unused = scalar(0, false);
    return combine(f, value, unused, [](double x, double) { return x != 0 ? 1.0 : -1.0; });
  }

  // bounded_until's decomposition where every part is a constant-offset window too: with the
  // window [i + lo, i + hi], p before it is [i, i + lo) and the past part [i + lo, i - 1].
  void until_over_offsets(const Signal& p, const Signal& q, Offsets window, Signal& r) {
    const std::size_t n = size();
    const std::size_t room = std::max(
        {padded_room({0, window.first - 1}), padded_room(window), padded_room({0, window.last})});
    Signal padded = acquire(room), suffix = acquire(room), extreme_p = acquire(),
           extreme_q = acquire();
    unbounded_until(p, q, r);  // read at i + lo >= i (or at i) before r[i] is written
    if (window.first >= 0) {
      const auto lo = static_cast<std::size_t>(window.first);
      van_herk_extreme(p, {0, window.first - 1}, kInfinity, Minimum(), extreme_p, padded, suffix);
      van_herk_extreme(q, window, -kInfinity, Maximum(), extreme_q, padded, suffix);
      for (std::size_t i = 0; i < n; ++i)
        r[i] = std::min({extreme_p[i], extreme_q[i], i + lo < n ? r[i + lo] : -kInfinity});
    } else {
      van_herk_extreme(q, {window.first, std::min<std::ptrdiff_t>(window.last, -1)}, -kInfinity,
                       Maximum(), extreme_p, padded, suffix);
      van_herk_extreme(q, {0, window.last}, -kInfinity, Maximum(), extreme_q, padded, suffix);
      for (std::size_t i = 0; i < n; ++i)
        r[i] = std::max(extreme_p[i], std::min(extreme_q[i], r[i]));
    }
    for (Signal* buffer : {&padded, &suffix, &extreme_p, &extreme_q}) release(std::move(*buffer));
  }

  void bounded_until_over_cursors(const Signal& p, const Signal& q, const TimeInterval& interval,
                                  Signal& r) {
    UntilParts parts{acquire(), acquire(), acquire(), acquire()};
    Signal suffix = acquire();
    bounded_until(p, q, source_.time, interval, parts, suffix, r);
    for (Signal* buffer :
         {&parts.untimed, &parts.p_before_window, &parts.q_in_window, &parts.q_in_past, &suffix})
      release(std::move(*buffer));
  }

  // An atom's robustness at the excused samples: +inf where it is counted as it stands, -inf
  // under an odd number of negations (there -inf is what serves the whole formula best). At the
  // start only where no existential operator reads it: there the samples were observed, and what
  // they did for an F is real, but an excused sample must not satisfy it.
  Signal excused(Signal r) const {
    const double best = negated_ ? -kInfinity : kInfinity;
    if (!existential_)
      for (std::size_t i = 0; i < std::min(first_observed_, r.size()); ++i) r[i] = best;
    for (std::size_t i = observed_end_; i < r.size(); ++i) r[i] = best;
    return r;
  }

  Signal negated(const Formula& f) {
    negated_ = !negated_;
    Signal x = formula(f);
    negated_ = !negated_;
    return x;
  }

  // `f` as an operand of a temporal operator; `existential` when the operator asks for some
  // sample rather than every one (F, G under an odd number of negations, U).
  Signal read_by(const Formula& f, bool existential) {
    const bool outer = existential_;
    existential_ = outer || existential;
    Signal x = formula(f);
    existential_ = outer;
    return x;
  }

  Signal compute(const Formula& f) {
    switch (f.kind) {
      case FormulaKind::comparison: return excused(comparison(f));
      case FormulaKind::predicate: return excused(predicate(f));
      case FormulaKind::negation: {
        Signal x = negated(f.operands[0]);
        for (double& v : x) v = -v;
        return x;
      }
      case FormulaKind::conjunction:
      case FormulaKind::disjunction:
      case FormulaKind::implication: {
        Signal a =
            f.kind == FormulaKind::implication ? negated(f.operands[0]) : formula(f.operands[0]);
        Signal b = formula(f.operands[1]);
        if (f.kind == FormulaKind::conjunction)
          for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::min(a[i], b[i]);
        if (f.kind == FormulaKind::disjunction)
          for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::max(a[i], b[i]);
        if (f.kind == FormulaKind::implication)
          for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::max(-a[i], b[i]);
        release(std::move(b));
        return a;
      }
      case FormulaKind::always:
      case FormulaKind::eventually: {
        const bool always = f.kind == FormulaKind::always;
        Signal x = read_by(f.operands[0], always == negated_);
        if (!f.interval) return always ? suffix_min(std::move(x)) : suffix_max(std::move(x));
        Signal out = acquire();
        if (const std::optional<Offsets> offsets =
                constant_window_offsets(source_.time, *f.interval)) {
          Signal padded = acquire(padded_room(*offsets)), suffix = acquire(padded_room(*offsets));
          if (always)
            van_herk_extreme(x, *offsets, kInfinity, Minimum(), out, padded, suffix);
          else
            van_herk_extreme(x, *offsets, -kInfinity, Maximum(), out, padded, suffix);
          release(std::move(padded));
          release(std::move(suffix));
        } else {
          WindowCursor window(source_.time, *f.interval);
          Signal suffix = acquire();
          if (always)
            sliding_extreme(x, window, kInfinity, Minimum(), out, suffix);
          else
            sliding_extreme(x, window, -kInfinity, Maximum(), out, suffix);
          release(std::move(suffix));
        }
        release(std::move(x));
        return out;
      }
      case FormulaKind::next: {
        Signal x = formula(f.operands[0]);
        if (x.empty()) return x;
        std::rotate(x.begin(), x.begin() + 1, x.end());
        x.back() = kInfinity;
        return x;
      }
      case FormulaKind::until: {
        // Either polarity asks for some sample (U, or release under a negation).
        Signal p = read_by(f.operands[0], true);
        Signal q = read_by(f.operands[1], true);
        Signal r = acquire();
        if (!f.interval)
          unbounded_until(p, q, r);
        else if (const std::optional<Offsets> offsets =
                     constant_window_offsets(source_.time, *f.interval))
          until_over_offsets(p, q, *offsets, r);
        else
          bounded_until_over_cursors(p, q, *f.interval, r);
        release(std::move(p));
        release(std::move(q));
        return r;
      }
    }
    return {};
  }

  const SignalSource& source_;
  bool keep_;
  std::size_t first_observed_ = 0;
  std::size_t observed_end_ = std::numeric_limits<std::size_t>::max();
  bool negated_ = false;
  bool existential_ = false;
  std::unordered_map<const Formula*, Signal> kept_;
  SpareSignals spare_;  // buffers free for the next node
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

// The first sample not within `start` seconds of the first: the first the trace is judged on
// once its start is excused.
std::size_t first_observed_sample(std::span<const double> time, double start) {
  std::size_t first = 0;
  while (first < time.size() && time[first] - time[0] < start - kWindowTolerance) ++first;
  return first;
}

}  // namespace

SignalValues term_signal(const SpecTerm& term, const SignalSource& source) {
  return Evaluator(source, false).term_values(term);
}

std::vector<double> robustness_signal(const Formula& formula, const SignalSource& source) {
  return Evaluator(source, false).formula(formula);
}

double robustness_excusing(const Formula& formula, const SignalSource& source,
                           const ExcusedSamples& excused) {
  const std::size_t n = source.time.size();
  if (n == 0) return kInfinity;  // nothing observed violates anything
  const std::size_t first_observed = first_observed_sample(source.time, excused.start);
  if (!excused.end_horizon) {
    Evaluator evaluator(source, false);
    evaluator.excuse(first_observed, n);
    return evaluator.formula(formula).front();
  }
  // The trace's own step carries on past its end, as far as the formula reads, at most as long
  // again as the trace (and at least one sample, for operators over the rest of the trace).
  const double step = n > 1 ? source.time[n - 1] - source.time[n - 2] : 1.0;
  const auto wanted = static_cast<std::size_t>(std::ceil(*excused.end_horizon / step)) + 1;
  const std::size_t extra = std::clamp<std::size_t>(wanted, 1, std::max<std::size_t>(n, 1));
  std::vector<double> time(source.time.begin(), source.time.end());
  for (std::size_t k = 1; k <= extra; ++k)
    time.push_back(source.time[n - 1] + static_cast<double>(k) * step);
  SignalSource continued;
  continued.time = time;
  continued.parameters = source.parameters;
  // Leaves hold their last value (any finite value will do: the atoms overwrite what they give
  // there), so that arithmetic over them meets no new NaN.
  continued.leaf = [&source, &time](const SpecTerm& term) {
    SignalValues values = source.leaf(term);
    values.values.resize(time.size(), values.values.empty() ? 0.0 : values.values.back());
    return values;
  };
  Evaluator evaluator(continued, false);
  evaluator.excuse(first_observed, n);
  return evaluator.formula(formula).front();
}

double robustness_if_continued(const Formula& formula, const SignalSource& source, double horizon) {
  return robustness_excusing(formula, source, {0, horizon});
}

double robustness_before(const Formula& formula, const SignalSource& source, std::size_t samples,
                         double horizon) {
  samples = std::min(samples, source.time.size());
  SignalSource before;
  before.time = source.time.first(samples);
  before.parameters = source.parameters;
  before.leaf = [&source, samples](const SpecTerm& term) {
    SignalValues values = source.leaf(term);
    if (values.values.size() > samples) values.values.resize(samples);
    return values;
  };
  return robustness_if_continued(formula, before, horizon);
}

double robustness_if_started_later(const Formula& formula, const SignalSource& source,
                                   double grace) {
  return robustness_excusing(formula, source, {grace, std::nullopt});
}

RobustnessWitness explain_robustness(const Formula& formula, const SignalSource& source,
                                     std::size_t sample) {
  Evaluator evaluator(source, true);
  evaluator.formula(formula);
  if (sample >= source.time.size()) return {kInfinity, nullptr, sample};
  return Explainer(evaluator, source.time).explain(formula, sample);
}

RobustnessWitness explain_robustness_if_started_later(const Formula& formula,
                                                      const SignalSource& source, double grace) {
  const std::size_t n = source.time.size();
  if (n == 0) return {kInfinity, nullptr, 0};  // as robustness_excusing: nothing observed
  Evaluator evaluator(source, true);
  evaluator.excuse(first_observed_sample(source.time, grace), n);
  evaluator.formula(formula);
  return Explainer(evaluator, source.time).explain(formula, 0);
}

}  // namespace scenfuzz
