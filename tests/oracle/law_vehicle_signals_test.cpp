// The law signals read from the ego's lamps and horn (oracle/law_vehicle_signals.*) on hand-made
// signals columns: Apollo's turn-signal codes (right is 2, not LawBreaker's boolean 1), both
// sides flashing as the hazard warning, one lamp per flag, an empty column as all off, and a
// fog-light law judged by them.
#include "oracle/law_vehicle_signals.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "physics/actors/vehicle_signals.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

namespace bit = vehicle_signal;

std::string scenario_with(const std::string& environment, const std::string& specs) {
  return "ego = AV((\"east_0\"->50, , 0), (\"east_0\"->300));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {}; {}; {}; " +
         environment +
         "};\n"
         "Trace trace = EXE(scenario);\n" +
         specs;
}

// A standing ego whose signals column is `signals` (one per sample; empty: it shows none).
Trace ego_showing(std::size_t samples, std::vector<VehicleSignals> signals) {
  Trace trace = test::empty_trace(samples);
  trace.actors.push_back(
      test::still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, 0));
  trace.actors[kEgo].signals = std::move(signals);
  test::perceive_perfectly(trace);
  return trace;
}

class LawVehicleSignalsTest : public ::testing::Test {
 protected:
  // The first spec's signal (its first term) at every sample.
  SignalValues values(const Trace& trace, const std::string& spec) {
    const test::ParsedScenario parsed = test::parse_scenario(scenario_with("", spec));
    const TraceSignals signals(trace, parsed.scenario, parsed.parameters, map);
    return signals.leaf(parsed.scenario.specs.at(0).formula.terms.at(0));
  }

  // Every spec's robustness at t = 0.
  std::vector<double> robustness(const Trace& trace, const std::string& specs,
                                 const std::string& environment = "") {
    return test::spec_robustness(trace, test::parse_scenario(scenario_with(environment, specs)),
                                 map);
  }

  RoadMap map = load_map("straight", map_search_path({}));
};

TEST_F(LawVehicleSignalsTest, TurnSignalIsApollosTurnSignalCode) {
  const Trace trace = ego_showing(
      6, {0, bit::left_indicator, bit::right_indicator, bit::left_indicator | bit::right_indicator,
          bit::hazard_lights, bit::hazard_lights | bit::left_indicator | bit::low_beam});
  const SignalValues turn = values(trace, "trace |= turnSignal == left;\n");
  EXPECT_EQ(turn.values, (std::vector<double>{0, 1, 2, 3, 3, 3}));
  EXPECT_TRUE(turn.discrete);
  // LawBreaker stores the indicator as a boolean, so its `turnSignal == right` is never true
  // (its quirk Q1); here the right indicator is `right`.
  const Trace right = ego_showing(1, {bit::right_indicator});
  EXPECT_EQ(robustness(right,
                       "trace |= turnSignal == right;\n"
                       "trace |= turnSignal == left;\n"
                       "trace |= turnSignal == off;\n"),
            (std::vector<double>{1, -1, -1}));
}

TEST_F(LawVehicleSignalsTest, EachLampAndTheHornIsItsOwnFlag) {
  const Trace trace = ego_showing(5, {bit::horn, bit::high_beam, bit::low_beam, bit::fog_lights,
                                      bit::wipers | bit::brake_lights});
  EXPECT_EQ(values(trace, "trace |= hornOn;\n").values, (std::vector<double>{1, 0, 0, 0, 0}));
  EXPECT_EQ(values(trace, "trace |= highBeamOn;\n").values, (std::vector<double>{0, 1, 0, 0, 0}));
  EXPECT_EQ(values(trace, "trace |= lowBeamOn;\n").values, (std::vector<double>{0, 0, 1, 0, 0}));
  EXPECT_EQ(values(trace, "trace |= fogLightOn;\n").values, (std::vector<double>{0, 0, 0, 1, 0}));
  EXPECT_TRUE(values(trace, "trace |= hornOn;\n").discrete);
  // Flags have robustness +1 when set, -1 when not.
  EXPECT_EQ(robustness(trace,
                       "trace |= hornOn;\n"
                       "trace |= ~highBeamOn;\n"
                       "trace |= F highBeamOn;\n"),
            (std::vector<double>{1, 1, 1}));
}

TEST_F(LawVehicleSignalsTest, TheWarningFlashIsBothSidesFlashing) {
  const Trace trace =
      ego_showing(4, {bit::left_indicator, bit::hazard_lights,
                      bit::left_indicator | bit::right_indicator, bit::right_indicator});
  EXPECT_EQ(values(trace, "trace |= warningFlashOn;\n").values, (std::vector<double>{0, 1, 1, 0}));
}

TEST_F(LawVehicleSignalsTest, AnEmptyColumnIsEverySignalOffWithTheEngineRunning) {
  const Trace trace = ego_showing(3, {});
  for (const char* flag :
       {"hornOn", "highBeamOn", "lowBeamOn", "fogLightOn", "warningFlashOn", "manualIntervention"})
    EXPECT_EQ(values(trace, std::string("trace |= ") + flag + ";\n").values,
              std::vector<double>(3, 0))
        << flag;
  EXPECT_EQ(values(trace, "trace |= turnSignal == off;\n").values, std::vector<double>(3, 0));
  EXPECT_EQ(values(trace, "trace |= engineOn;\n").values, std::vector<double>(3, 1));
}

TEST_F(LawVehicleSignalsTest, LawBreakersFogLightLawIsJudgedOnTheLamps) {
  // law58_sub3: in fog, fog lights and hazard lights.
  const std::string law = "trace |= G (fog >= 0.5 -> (fogLightOn & warningFlashOn));\n";
  const std::string fog = "Environment(12:00, {fog: 0.6})";
  const VehicleSignals both = bit::fog_lights | bit::hazard_lights;
  EXPECT_GT(robustness(ego_showing(3, {both, both, both}), law, fog).at(0), 0);
  EXPECT_LT(robustness(ego_showing(3, {both, bit::fog_lights, both}), law, fog).at(0), 0);
  EXPECT_LT(robustness(ego_showing(3, {}), law, fog).at(0), 0) << "no lamps at all";
  EXPECT_GT(robustness(ego_showing(3, {}), law).at(0), 0) << "no fog";
}

}  // namespace
}  // namespace scenfuzz
