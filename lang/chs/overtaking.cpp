// A track's overtake as phases started by what is around the vehicle (overtaking.hpp). Offsets
// are between centres, in the overtaker's frame (manoeuvre_trigger.hpp): ahead and to the left
// positive. The distances are what a careful driver leaves; docs/ch-scenario.md lists them.
#include "lang/chs/overtaking.hpp"

#include "lang/demand.hpp"
#include "lang/formula_builders.hpp"

namespace scenfuzz::chs {

namespace {

// Within half a lane to either side a road user is in line with the overtaker (the trigger's
// relative sectors draw the same line); from there to this far it is in a neighbouring lane (a
// CH lane is at most 5.25 m wide: outline_map.hpp gives a half round(W / 3.5) lanes).
constexpr double kInLine = 1.75;        // m
constexpr double kNeighbourLane = 6.5;  // m
// Close behind: within this plus two seconds at its written speed of the road user ahead, and
// that road user at least 5 km/h slower than its written speed.
constexpr double kCloseMargin = 15;  // m, two half lengths and a gap
constexpr double kCloseTime = 2;     // s
constexpr double kSlower = 5 / 3.6;  // m/s
// Pulling out, the lane on the left must be clear from this far behind to where it would be
// close behind again; of oncoming traffic, to this far ahead (what two vehicles at 50 km/h close
// in 9 s, the lane change and the pass).
constexpr double kLeftClearBehind = 30;  // m
constexpr double kOncomingClear = 250;   // m
// Coming back, the lane on the right must be clear from this far behind (what it passed: the
// two half lengths of a bus and a car and a gap) to this far ahead, and of anything it is still
// closing on (driving at least 5 km/h faster than it) within the distance it would be close
// behind again. What it is not closing on (it was held back) it comes back behind, giving the
// overtake up.
constexpr double kRightClearBehind = 15;  // m
constexpr double kRightClearAhead = 10;   // m

class Conditions {
 public:
  Conditions(const std::string& overtaker, const Value& speed, SourceLocation at)
      : overtaker_(overtaker), speed_(speed), at_(at) {}

  // In line ahead of the overtaker, close, and slower than it drives.
  Formula ahead_and_slower(const std::string& other) const {
    return all(
        {in_band(other, -kInLine, kInLine), above(lon(other), 0), close(other), slower(other)});
  }

  // In the lane on the left where the overtaker would pull out into it.
  Formula blocks_the_left(const std::string& other) const {
    const Formula oncoming = combined(FormulaKind::disjunction, above(heading(other), 90),
                                      below(heading(other), -90), at_);
    const Formula in_reach = combined(
        FormulaKind::disjunction, close(other),
        combined(FormulaKind::conjunction, oncoming, below(lon(other), kOncomingClear), at_), at_);
    return all(
        {in_band(other, kInLine, kNeighbourLane), above(lon(other), -kLeftClearBehind), in_reach});
  }

  // In the lane on the right where the overtaker would come back into it.
  Formula blocks_the_right(const std::string& other) const {
    const Formula in_reach =
        combined(FormulaKind::disjunction, below(lon(other), kRightClearAhead),
                 combined(FormulaKind::conjunction, close(other), closing_on(other), at_), at_);
    return all({in_band(other, -kNeighbourLane, -kInLine), above(lon(other), -kRightClearBehind),
                in_reach});
  }

  Formula all(std::vector<Formula> formulas) const {
    return fold(FormulaKind::conjunction, formulas);
  }
  Formula any(std::vector<Formula> formulas) const {
    return fold(FormulaKind::disjunction, formulas);
  }
  Formula none(std::vector<Formula> formulas) const {
    return negated(any(std::move(formulas)), at_);
  }

 private:
  SpecTerm of_pair(const char* signal, const std::string& other) const {
    return signal_term(signal, at_, {word_term(other, at_), word_term(overtaker_, at_)});
  }
  SpecTerm lon(const std::string& other) const { return of_pair("longitudinal_offset", other); }
  SpecTerm lat(const std::string& other) const { return of_pair("lateral_offset", other); }
  SpecTerm heading(const std::string& other) const { return of_pair("relative_heading", other); }

  Formula above(SpecTerm term, double value) const {
    return comparison(CompareOp::greater, std::move(term), number_term(value, at_), at_);
  }
  Formula below(SpecTerm term, double value) const {
    return comparison(CompareOp::less, std::move(term), number_term(value, at_), at_);
  }
  Formula in_band(const std::string& other, double low, double high) const {
    return combined(FormulaKind::conjunction, above(lat(other), low), below(lat(other), high), at_);
  }

  // Nearer ahead than kCloseMargin + kCloseTime * its speed.
  Formula close(const std::string& other) const {
    const Value reach =
        binary_value(ValueOp::add, constant_value(kCloseMargin),
                     binary_value(ValueOp::multiply, constant_value(kCloseTime), speed_, at_), at_);
    return comparison(CompareOp::less, lon(other), value_term(reach, at_), at_);
  }

  Formula slower(const std::string& other) const {
    const Value slowest = binary_value(ValueOp::subtract, speed_, constant_value(kSlower), at_);
    return comparison(CompareOp::less, signal_term("speed", at_, {word_term(other, at_)}),
                      value_term(slowest, at_), at_);
  }

  // speed(other) < speed(overtaker) - kSlower: as it drives now, not as written.
  Formula closing_on(const std::string& other) const {
    SpecTerm slowest;
    slowest.kind = TermKind::subtract;
    slowest.operands = {signal_term("speed", at_, {word_term(overtaker_, at_)}),
                        number_term(kSlower, at_)};
    slowest.location = at_;
    return comparison(CompareOp::less, signal_term("speed", at_, {word_term(other, at_)}),
                      std::move(slowest), at_);
  }

  Formula fold(FormulaKind kind, std::vector<Formula>& formulas) const {
    SCENFUZZ_DEMAND(!formulas.empty());
    Formula result = std::move(formulas.front());
    for (std::size_t i = 1; i < formulas.size(); ++i)
      result = combined(kind, std::move(result), std::move(formulas[i]), at_);
    return result;
  }

  const std::string& overtaker_;
  const Value& speed_;
  SourceLocation at_;
};

}  // namespace

std::vector<ManoeuvrePhase> overtake_phases(const std::string& overtaker, const Value& speed,
                                            const std::vector<std::string>& others,
                                            SourceLocation at) {
  SCENFUZZ_DEMAND(!others.empty());
  const Conditions c(overtaker, speed, at);
  std::vector<Formula> ahead, left, right;
  for (const std::string& other : others) {
    ahead.push_back(c.ahead_and_slower(other));
    left.push_back(c.blocks_the_left(other));
    right.push_back(c.blocks_the_right(other));
  }
  // Out at its own speed, which it may have lost behind the slower road user.
  ManoeuvrePhase out;
  out.manoeuvre = "Overtake";
  out.parameters.push_back({"speed", speed, at});
  out.start_when = c.all({c.any(std::move(ahead)), c.none(std::move(left))});
  out.location = at;
  ManoeuvrePhase back;
  back.manoeuvre = "LaneChangeRight";
  back.start_when = c.none(std::move(right));
  back.location = at;
  return {std::move(out), std::move(back)};
}

}  // namespace scenfuzz::chs
