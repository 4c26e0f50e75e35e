// The search guide of a conjunction: which conjuncts a formula splits into, and a guide that is
// negative exactly where the minimum is, yet still moves with a conjunct that is not the minimum.
#include "oracle/search_guide.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"

namespace scenfuzz {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

Formula formula(const std::string& text) {
  const avunit::FormulaParseResult parsed = avunit::parse_formula(SourceFile("--spec", text));
  EXPECT_TRUE(parsed.formula) << text;
  return parsed.formula.value_or(Formula{});
}

std::vector<FormulaKind> kinds(const std::vector<Formula>& formulas) {
  std::vector<FormulaKind> result;
  for (const Formula& each : formulas) result.push_back(each.kind);
  return result;
}

TEST(TopLevelConjuncts, NestedConjunctionsFlattenInOrder) {
  const std::vector<Formula> conjuncts = top_level_conjuncts(formula("a > 1 & (b > 2 & c > 3)"));
  ASSERT_EQ(conjuncts.size(), 3u);
  EXPECT_EQ(conjuncts[0], formula("a > 1"));
  EXPECT_EQ(conjuncts[1].terms, formula("b > 2").terms);
  EXPECT_EQ(conjuncts[2].terms, formula("c > 3").terms);
}

TEST(TopLevelConjuncts, AnAlwaysOverAConjunctionSplitsIntoOneAlwaysPerConjunct) {
  const std::vector<Formula> conjuncts =
      top_level_conjuncts(formula("G[0, 5] (a > 1 & b > 2) & F (c > 3)"));
  ASSERT_EQ(conjuncts.size(), 3u);
  EXPECT_EQ(kinds(conjuncts),
            (std::vector{FormulaKind::always, FormulaKind::always, FormulaKind::eventually}));
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(conjuncts[i].interval);
    EXPECT_EQ(conjuncts[i].interval->upper, 5.0);
    ASSERT_EQ(conjuncts[i].operands.size(), 1u);
    EXPECT_EQ(conjuncts[i].operands[0].kind, FormulaKind::comparison);
  }
}

TEST(TopLevelConjuncts, OtherFormulasStayWhole) {
  // F does not distribute over a conjunction, nor a negation over a disjunction here.
  for (const char* text : {"F (a > 1 & b > 2)", "a > 1 | b > 2", "~(a > 1 & b > 2)", "a > 1"})
    EXPECT_EQ(top_level_conjuncts(formula(text)).size(), 1u) << text;
}

TEST(ConjunctGuide, IsNegativeExactlyWhenTheMinimumIs) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> value(-3.0, 10.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> conjuncts(1 + trial % 4);
    double minimum = infinity;
    for (double& each : conjuncts) {
      each = value(random);
      minimum = std::min(minimum, each);
    }
    EXPECT_EQ(conjunct_guide(conjuncts) < 0, minimum < 0);
  }
}

TEST(ConjunctGuide, MovesWithAConjunctThatIsNotTheMinimum) {
  // A parked van passed 1.27 m away every time: the minimum is a plateau, the guide is not.
  const std::vector<double> far = {6.0, 1.27};
  const std::vector<double> near = {2.0, 1.27};
  EXPECT_LT(conjunct_guide(near), conjunct_guide(far));
  EXPECT_GT(conjunct_guide(near), 0.0);
  // Among violations, deeper is lower.
  EXPECT_LT(conjunct_guide(std::vector{-2.0, 1.27}), conjunct_guide(std::vector{-1.0, 1.27}));
}

TEST(ConjunctGuide, OneConjunctIsItsOwnGuide) {
  for (const double robustness : {-2.5, 0.0, 0.75, 12.0})
    EXPECT_NEAR(conjunct_guide(std::vector{robustness}), robustness, 1e-12);
}

TEST(ConjunctGuide, Infinities) {
  EXPECT_EQ(conjunct_guide(std::vector{-infinity, 3.0}), -infinity);
  EXPECT_EQ(conjunct_guide(std::vector{infinity, infinity}), infinity);
  EXPECT_NEAR(conjunct_guide(std::vector{infinity, 3.0}), 3.0, 1e-12);
  EXPECT_LT(conjunct_guide(std::vector{infinity, -1.0}), 0.0);
}

}  // namespace
}  // namespace scenfuzz
