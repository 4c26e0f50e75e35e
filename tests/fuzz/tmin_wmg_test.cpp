// `scenfuzz tmin` on WMG SDL (fuzz/tmin_wmg.hpp): the reduction on a fake predicate (which actors
// and phases go, weather, noon, rounding, the duration cut), and end to end: a concrete cut-in
// with two planted vehicles driving far behind loses them and is written as `.min.sdl` that
// replays to the same failure, and a finding of the search on corpora/wmg/cut_in.sdl is minimised
// beside itself and replays to its mode.
#include "fuzz/tmin_wmg.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/reduce.hpp"

namespace scenfuzz {
namespace {

using test::Outcome;

// A concrete cut-in: Cutter changes into the ego's lane and hits it at about 3 s (not the ego's
// fault, so the replay counts --all-collisions); Far1 and Far2 start 150 m and 120 m behind.
constexpr const char* kPlanted = R"(# replay: scenfuzz run planted.sdl --seed 0 --all-collisions
VERSION: 1.0
AUTHOR: 'scenfuzz'
EXTENSION: None

SCENERY ELEMENTS:
DO: 'Three-lane motorway' [Motorway1] as:
Junctions: None
Roads:
R1: START
  Road type [Motorway] as [R1]
  with zone as [N/A]
  AND speed limit of [130]
  in a [Rural] environment
  with Number of lanes [3] as [R1.L1, R1.L2, R1.L3]
  Road traffic direction [Left-handed]
  Lane type [Traffic lane]
  Lane markings [Broken line]
  Road surface type [Uniform]
  with surface condition [Dry]
  Horizontal road geometry [Curved]
  with curvature radius of [S1: 1313.0955836092871]
  Vertical road geometry [Level plane]
  Transverse road geometry [Divided]
  Road banking angle [Level Plane]
  with [No] roadside feature
  Roadway edge features [Solid barriers]
  Length [1146.548118286004]
  AND Lane width [3.5962074799426014]
END

DYNAMIC ELEMENTS:
INITIAL:
  Vehicle [Ego] in [R1.L2] at heading angle [0]
  AND Vehicle [Cutter] in [R1.L3]
      with a [Longitudinal] offset of [20.299058459655242]
      AND at relative position [FSL]
      with relative heading angle [0] to [Ego]
  AND Vehicle [Far1] in [R1.L1]
      with a [Longitudinal] offset of [-150.125]
      AND at relative position [RSR]
      with relative heading angle [0] to [Ego]
  AND Vehicle [Far2] in [R1.L1]
      with a [Longitudinal] offset of [30]
      AND at relative position [R]
      with relative heading angle [0] to [Far1]
  AND Global timer [Clock] = [0]

WHEN: [Ego] is [Going Ahead] in [R1.L2] at a speed of [86.37826332330117]
DO: [Cutter]
  PHASE 1: [Drive_Away] [-, 62.441353923947425, 2.03074940026397] [Ego: 28.577494927895494, FSL]
    WHILE: [Clock] < [2]
  PHASE 2: [LaneChangeRight_CutIn] [-, 52.206078170891445, 2.1532926670211827] [Ego: 27.819248526952613, F]
    WHILE: [Cutter] [Lateral] offset to [Ego] > [0.2]
  AND: [Far1]
  PHASE 1: [Drive_Away] [-, 40.5, 3.25] [Ego: 100, RSR]

END: [Clock] >= [30] OR Collision

ENVIRONMENT ELEMENTS:
DO: [Weather1]
  Wind [7.5]
  Cloudiness [3]
  Rainfall [Moderate Rain: 4.37]
  Time of the day [16:56]
  Illumination [Day] with [Sun] as light source
    at [20] degree elevation AND [F] position
)";

wmg::Level2File planted_tree() {
  wmg::Level2ParseResult parsed = wmg::parse_level2(SourceFile("planted.sdl", kPlanted));
  EXPECT_TRUE(parsed.file);
  return parsed.file ? *parsed.file : wmg::Level2File{};
}

TminCheck failing(double failure_time = 3, double end_time = 3) {
  TminCheck check;
  check.same_failure = true;
  check.failure_time = failure_time;
  check.end_time = end_time;
  return check;
}

bool has_change(const WmgTminReduction& reduction, const std::string& change) {
  for (const std::string& line : reduction.changes)
    if (line == change) return true;
  return false;
}

// The failure needs Cutter and its lane change (phase 2), rain over 4 mm/h and the Cutter's
// offset between 20 and 21 m; it happens at 4.2 s of a 30 s run.
TEST(WmgTminReduction, KeepsExactlyWhatTheFailureNeeds) {
  const WmgTminPredicate fails = [](const WmgTminCandidate& candidate) {
    const wmg::Level2File& file = candidate.file;
    bool cut_in = false;
    for (const wmg::Ssms& ssms : file.dynamics.sequences)
      for (const wmg::ManoeuvreSequence& sequence : ssms.sequences)
        for (const wmg::ManoeuvrePhase& phase : sequence.phases)
          cut_in |= sequence.actor.name == "Cutter" && phase.type.text == "LaneChangeRight_CutIn";
    const std::vector<wmg::RelativeActorInit>& relative = file.dynamics.initialisation.relative;
    const bool close = !relative.empty() && relative[0].actor.name == "Cutter" &&
                       relative[0].offsets[0].offset.low >= 20 &&
                       relative[0].offsets[0].offset.low <= 21;
    TminCheck check = failing(4.2, 30);
    check.same_failure = cut_in && close && file.environment.rainfall.intensity.low > 4;
    return check;
  };
  const WmgTminReduction reduction =
      reduce_failing_wmg(WmgTminCandidate{planted_tree(), std::nullopt}, failing(4.2, 30), fails);
  const wmg::Level2File& result = reduction.result.file;
  EXPECT_EQ(wmg::other_actors(result), std::vector<std::string>{"Cutter"});
  EXPECT_EQ(reduction.actors_removed, 2u);
  EXPECT_TRUE(has_change(reduction, "removed vehicle Far1"));
  EXPECT_TRUE(has_change(reduction, "removed vehicle Far2"));
  // Far1's phase went with Far1; of Cutter's, the first.
  EXPECT_EQ(reduction.phases_removed, 1u);
  EXPECT_TRUE(has_change(reduction, "removed phase 1 of Cutter"));
  ASSERT_EQ(wmg::manoeuvre_phases(result).size(), 1u);
  EXPECT_EQ(wmg::manoeuvre_phases(result)[0].number, 1);
  EXPECT_EQ(wmg::weather_components(result), std::vector<std::string>{"rainfall"});
  EXPECT_TRUE(has_change(reduction, "removed weather wind"));
  EXPECT_TRUE(has_change(reduction, "removed weather cloudiness"));
  EXPECT_TRUE(has_change(reduction, "time of day 16:56 -> 12:00"));
  // 20.299... stays in [20, 21] with one digit; 4.37 mm/h needs two to stay over 4.
  EXPECT_EQ(result.dynamics.initialisation.relative[0].offsets[0].offset.low, 20);
  EXPECT_EQ(result.environment.rainfall.intensity.low, 4.4);
  EXPECT_LT(reduction.digits_after, reduction.digits_before);
  EXPECT_EQ(reduction.result.duration, 6);
  EXPECT_TRUE(has_change(reduction, "duration cut to 6 s (the run went on to 30 s)"));
}

// "failure mode: ..." of a file's header or of tmin's output.
std::string mode_line(const std::string& text) {
  const std::size_t at = text.find("failure mode: ");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

class WmgTminCommandTest : public test::CommandTest {
 protected:
  // `scenfuzz run` on tmin's output, with the replay command tmin printed.
  Outcome replay_of(const Outcome& tmin) {
    const std::string mark = "replay: scenfuzz run ";
    const std::size_t at = tmin.out.find(mark);
    EXPECT_NE(at, std::string::npos) << tmin.out;
    if (at == std::string::npos) return {};
    const std::string line =
        tmin.out.substr(at + mark.size(), tmin.out.find('\n', at) - at - mark.size());
    std::vector<std::string> words{"run"};
    for (std::size_t start = 0; start < line.size();) {
      const std::size_t end = std::min(line.find(' ', start), line.size());
      std::string word = line.substr(start, end - start);
      if (word.size() >= 2 && word.front() == '\'') word = word.substr(1, word.size() - 2);
      words.push_back(word);
      start = end + 1;
    }
    words.push_back("--out");
    words.push_back((dir_ / "replay").string());
    return scenfuzz(words);
  }
};

TEST_F(WmgTminCommandTest, RemovesThePlantedVehiclesAndWritesWmgSdlThatFailsTheSameWay) {
  const std::string input = write("planted.sdl", kPlanted);
  const Outcome tmin = scenfuzz({"tmin", input});
  ASSERT_EQ(tmin.exit_code, 0) << tmin.out << tmin.err;
  const std::filesystem::path out_path = dir_ / "planted.min.sdl";
  ASSERT_TRUE(std::filesystem::exists(out_path)) << tmin.out;
  EXPECT_NE(tmin.out.find("removed vehicle Far1\nremoved vehicle Far2\n"), std::string::npos)
      << tmin.out;
  EXPECT_NE(tmin.out.find("actors 3 -> 1,"), std::string::npos) << tmin.out;
  EXPECT_NE(mode_line(tmin.out).find("collision | collision | Cutter | other"), std::string::npos)
      << tmin.out;
  const std::string minimised = test::slurp(out_path);
  // A WMG SDL header, then the level-2 text without the planted vehicles.
  EXPECT_TRUE(minimised.starts_with("# scenfuzz tmin: " + input)) << minimised;
  EXPECT_EQ(mode_line(minimised), mode_line(tmin.out));
  const std::string body = minimised.substr(minimised.find("# WMG SDL level 2, printed by"));
  for (const char* gone : {"Far1", "Far2", "Wind", "16:56"})
    EXPECT_EQ(body.find(gone), std::string::npos) << gone << "\n" << minimised;
  EXPECT_NE(body.find("Time of the day [12:00]"), std::string::npos) << minimised;
  const Outcome replay = replay_of(tmin);
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("spec no_collision: robustness -"), std::string::npos) << replay.out;
  EXPECT_NE(replay.out.find("violated: the ego and Cutter"), std::string::npos) << replay.out;
  // Minimal already: a second tmin changes nothing.
  const Outcome again = scenfuzz({"tmin", out_path.string(), "-o", (dir_ / "again.sdl").string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("nothing could be removed or changed"), std::string::npos) << again.out;
}

TEST_F(WmgTminCommandTest, MinimisesAFindingOfTheSearchOnTheCutIn) {
  const std::string search_dir = (dir_ / "search").string();
  const Outcome search =
      scenfuzz({"--budget", "60", "--seed", "1", "--all-collisions", "--out", search_dir,
                test::source_file("corpora/wmg/cut_in.sdl"), "--quiet"});
  ASSERT_EQ(search.exit_code, 1) << search.out << search.err;
  std::string finding;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "search" / "findings"))
    if (entry.path().extension() == ".sdl" && (finding.empty() || entry.path().string() < finding))
      finding = entry.path().string();
  ASSERT_FALSE(finding.empty());
  const Outcome tmin = scenfuzz({"tmin", finding});
  ASSERT_EQ(tmin.exit_code, 0) << tmin.out << tmin.err;
  const std::filesystem::path finding_path(finding);
  const std::filesystem::path out_path =
      finding_path.parent_path() / (finding_path.stem().string() + ".min.sdl");
  ASSERT_TRUE(std::filesystem::exists(out_path)) << tmin.out;
  EXPECT_EQ(mode_line(test::slurp(finding)), mode_line(tmin.out));
  EXPECT_EQ(mode_line(test::slurp(out_path)), mode_line(tmin.out));
  EXPECT_NE(tmin.out.find("significant digits"), std::string::npos) << tmin.out;
  const Outcome replay = replay_of(tmin);
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("violated: the ego and Cutter"), std::string::npos) << replay.out;
  // Deterministic: the same finding gives the same file.
  const std::string first = test::slurp(out_path);
  ASSERT_EQ(scenfuzz({"tmin", finding}).exit_code, 0);
  EXPECT_EQ(test::slurp(out_path), first);
}

TEST_F(WmgTminCommandTest, AnOutputNamedInAnotherLanguageIsRefused) {
  const std::string input = write("planted.sdl", kPlanted);
  const Outcome wrong = scenfuzz({"tmin", input, "-o", (dir_ / "planted.min.avu").string()});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("is written in WMG SDL, so its name must end in .sdl"),
            std::string::npos)
      << wrong.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "planted.min.avu"));
}

}  // namespace
}  // namespace scenfuzz
