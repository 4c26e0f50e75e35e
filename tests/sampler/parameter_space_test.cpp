// The parameter space of a hand-built template and its unit-cube encoding.
#include "sampler/parameter_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz {
namespace {

Parameter continuous(std::string name, double lower, double upper, std::string unit) {
  Parameter p;
  p.name = std::move(name);
  p.kind = ParameterKind::continuous;
  p.lower = lower;
  p.upper = upper;
  p.unit = std::move(unit);
  p.location = {.line = 3, .column = 28, .offset = 40, .length = 12};
  return p;
}

Parameter angle(std::string name, double lower, double upper) {
  Parameter p = continuous(std::move(name), lower, upper, "deg");
  p.kind = ParameterKind::angle;
  return p;
}

Parameter discrete(std::string name, std::vector<std::string> choices) {
  Parameter p;
  p.name = std::move(name);
  p.kind = ParameterKind::discrete;
  p.lower = 0;
  p.upper = static_cast<double>(choices.size()) - 1;
  p.choices = std::move(choices);
  return p;
}

// npc1's speed in [5, 10] m/s, a heading in [-30, 30] deg, and the weather as one of 3 levels.
ScenarioTemplate three_parameter_template() {
  ScenarioTemplate t;
  t.has_scenario = true;
  t.parameters.push_back(continuous("npc1.init.speed", 5.0, 10.0, "m/s"));
  t.parameters.push_back(angle("npc1.init.heading", -30.0, 30.0));
  t.parameters.push_back(discrete("weather.rain.level", {"light", "middle", "heavy"}));
  Actor npc;
  npc.name = "npc1";
  npc.initial.speed = parameter_value(0);
  t.vehicles.push_back(npc);
  return t;
}

TEST(ParameterSpace, OneDimensionPerParameterInOrder) {
  const ScenarioTemplate t = three_parameter_template();
  const ParameterSpace space = parameter_space(t);
  ASSERT_EQ(space.dimensions.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Dimension& d = space.dimensions[i];
    const Parameter& p = t.parameters[i];
    EXPECT_EQ(d.name, p.name);
    EXPECT_EQ(d.kind, p.kind);
    EXPECT_EQ(d.lower, p.lower);
    EXPECT_EQ(d.upper, p.upper);
    EXPECT_EQ(d.unit, p.unit);
    EXPECT_EQ(d.choices, p.choices);
    EXPECT_EQ(d.location.line, p.location.line);
    EXPECT_EQ(d.location.column, p.location.column);
  }
  EXPECT_EQ(space.dimensions[0].unit, "m/s");
  EXPECT_EQ(space.dimensions[2].choices.size(), 3u);
}

TEST(ParameterSpace, ConcreteTemplateHasNoDimensions) {
  ScenarioTemplate t;
  t.has_scenario = true;
  EXPECT_TRUE(parameter_space(t).dimensions.empty());
  EXPECT_TRUE(decode(parameter_space(t), {}).empty());
  EXPECT_TRUE(encode(parameter_space(t), {}).empty());
}

TEST(ParameterSpace, KindNames) {
  EXPECT_EQ(kind_name(ParameterKind::continuous), "continuous");
  EXPECT_EQ(kind_name(ParameterKind::angle), "angle");
  EXPECT_EQ(kind_name(ParameterKind::discrete), "discrete");
}

TEST(Decode, CornersAreTheBoundsExactly) {
  const ParameterSpace space = parameter_space(three_parameter_template());
  const std::vector<double> low = decode(space, std::vector<double>{0.0, 0.0, 0.0});
  const std::vector<double> high = decode(space, std::vector<double>{1.0, 1.0, 1.0});
  EXPECT_EQ(low, (std::vector<double>{5.0, -30.0, 0.0}));
  EXPECT_EQ(high, (std::vector<double>{10.0, 30.0, 2.0}));
}

TEST(Decode, ContinuousIsLinear) {
  const ParameterSpace space = parameter_space(three_parameter_template());
  const std::vector<double> mid = decode(space, std::vector<double>{0.5, 0.25, 0.5});
  EXPECT_DOUBLE_EQ(mid[0], 7.5);
  EXPECT_DOUBLE_EQ(mid[1], -15.0);
}

TEST(Decode, BoundsHoldForAwkwardIntervals) {
  // 0.1 + 1.0 * (0.3 - 0.1) is not 0.3 in binary floating point: decode must still hit it.
  ScenarioTemplate t;
  t.parameters.push_back(continuous("x", 0.1, 0.3, "m"));
  const ParameterSpace space = parameter_space(t);
  EXPECT_EQ(decode(space, std::vector<double>{1.0})[0], 0.3);
  EXPECT_EQ(decode(space, std::vector<double>{0.0})[0], 0.1);
  double previous = 0.1;
  for (int i = 0; i <= 1000; ++i) {
    const double v = decode(space, std::vector<double>{i / 1000.0})[0];
    EXPECT_GE(v, 0.1);
    EXPECT_LE(v, 0.3);
    EXPECT_GE(v, previous) << "decode is monotonic";
    previous = v;
  }
}

TEST(Decode, DiscreteCellsSplitTheUnitIntervalEvenly) {
  ScenarioTemplate t;
  t.parameters.push_back(discrete("level", {"light", "middle", "heavy"}));
  const ParameterSpace space = parameter_space(t);
  auto index = [&](double u) { return decode(space, std::vector<double>{u})[0]; };
  EXPECT_EQ(index(0.0), 0.0);
  EXPECT_EQ(index(0.3333), 0.0);
  EXPECT_EQ(index(std::nextafter(1.0 / 3.0, 0.0)), 0.0);
  EXPECT_EQ(index(0.3334), 1.0);
  EXPECT_EQ(index(0.5), 1.0);
  EXPECT_EQ(index(0.6666), 1.0);
  EXPECT_EQ(index(0.6667), 2.0);
  EXPECT_EQ(index(1.0), 2.0) << "u = 1 falls in the last cell, not past it";
}

TEST(Decode, SingleChoiceIsAlwaysIndexZero) {
  ScenarioTemplate t;
  t.parameters.push_back(discrete("type", {"Sedan"}));
  const ParameterSpace space = parameter_space(t);
  for (double u : {0.0, 0.5, 1.0}) EXPECT_EQ(decode(space, std::vector<double>{u})[0], 0.0);
}

TEST(Encode, DiscreteGoesToTheMiddleOfItsCell) {
  ScenarioTemplate t;
  t.parameters.push_back(discrete("level", {"light", "middle", "heavy", "extreme"}));
  const ParameterSpace space = parameter_space(t);
  EXPECT_DOUBLE_EQ(encode(space, std::vector<double>{0.0})[0], 0.125);
  EXPECT_DOUBLE_EQ(encode(space, std::vector<double>{1.0})[0], 0.375);
  EXPECT_DOUBLE_EQ(encode(space, std::vector<double>{3.0})[0], 0.875);
}

TEST(Encode, ContinuousBoundsAreTheCorners) {
  const ParameterSpace space = parameter_space(three_parameter_template());
  EXPECT_EQ(encode(space, std::vector<double>{5.0, -30.0, 0.0})[0], 0.0);
  EXPECT_EQ(encode(space, std::vector<double>{10.0, 30.0, 0.0})[0], 1.0);
  EXPECT_EQ(encode(space, std::vector<double>{10.0, 30.0, 0.0})[1], 1.0);
  EXPECT_DOUBLE_EQ(encode(space, std::vector<double>{7.5, 0.0, 0.0})[0], 0.5);
}

TEST(Encode, ZeroWidthIntervalGoesToTheMiddle) {
  ScenarioTemplate t;
  t.parameters.push_back(continuous("fixed", 4.0, 4.0, "m"));
  const ParameterSpace space = parameter_space(t);
  EXPECT_EQ(encode(space, std::vector<double>{4.0})[0], 0.5);
  EXPECT_EQ(decode(space, std::vector<double>{0.5})[0], 4.0);
}

TEST(RoundTrip, DecodeOfEncodeGivesTheValuesBack) {
  const ParameterSpace space = parameter_space(three_parameter_template());
  for (double speed : {5.0, 5.1, 7.25, 9.999, 10.0})
    for (double heading : {-30.0, -0.5, 0.0, 12.5, 30.0})
      for (double level : {0.0, 1.0, 2.0}) {
        const std::vector<double> values = {speed, heading, level};
        const std::vector<double> back = decode(space, encode(space, values));
        EXPECT_NEAR(back[0], speed, 1e-12);
        EXPECT_NEAR(back[1], heading, 1e-12);
        EXPECT_EQ(back[2], level) << "discrete values round-trip exactly";
      }
}

TEST(RoundTrip, EncodeOfDecodeStaysInTheSameCell) {
  const ParameterSpace space = parameter_space(three_parameter_template());
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const std::vector<double> point = {u, u, u};
    const std::vector<double> again = encode(space, decode(space, point));
    EXPECT_NEAR(again[0], u, 1e-12);
    EXPECT_NEAR(again[1], u, 1e-12);
    // Discrete: the middle of the cell u fell into.
    EXPECT_EQ(decode(space, again)[2], decode(space, point)[2]);
    for (double x : again) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 1.0);
    }
  }
}

#ifndef NDEBUG
TEST(ParameterSpaceDeathTest, DecodeRejectsPointsOutsideTheUnitCube) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const ParameterSpace space = parameter_space(three_parameter_template());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DEATH(decode(space, std::vector<double>{nan, 0.5, 0.5}), "outside");
  EXPECT_DEATH(decode(space, std::vector<double>{1.5, 0.5, 0.5}), "outside");
  EXPECT_DEATH(decode(space, std::vector<double>{0.5, -0.1, 0.5}), "outside");
  EXPECT_DEATH(decode(space, std::vector<double>{0.5, 0.5}), "wrong dimension");
}

TEST(ParameterSpaceDeathTest, EncodeRejectsValuesOutsideTheBounds) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const ParameterSpace space = parameter_space(three_parameter_template());
  EXPECT_DEATH(encode(space, std::vector<double>{11.0, 0.0, 0.0}), "bounds");
  EXPECT_DEATH(encode(space, std::vector<double>{5.0, 0.0, 3.0}), "choice index");
  EXPECT_DEATH(encode(space, std::vector<double>{5.0, 0.0, 0.5}), "choice index");
}
#endif

}  // namespace
}  // namespace scenfuzz
