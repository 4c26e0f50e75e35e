// The level-2 tree edits `scenfuzz tmin` makes on WMG SDL findings (lang/wmg/reduce.hpp): on
// every corpus file and level-1 test file (as the level-2 text it converts to), each edit leaves
// a tree that prints, parses back equal and translates without errors; and on cut_in.sdl and small
// hand-made files, exactly what each edit removes or changes.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lang/wmg/parser.hpp"
#include "lang/wmg/reduce.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "lang/wmg/wmg.hpp"
#include "test_files.hpp"
#include "wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

Level2File tree_of(const std::string& text) {
  Level2ParseResult parsed = parse_level2(SourceFile("t.sdl", text));
  EXPECT_TRUE(parsed.file) << text;
  return parsed.file ? *parsed.file : Level2File{};
}

// The level-2 tree a file stands for (a level-1 file converted).
Level2File tree_of_file(const std::filesystem::path& path) {
  const Level2Text level2 = level2_text(scenfuzz::test::load(path));
  EXPECT_FALSE(level2.diagnostics.has_errors()) << path;
  return tree_of(level2.text);
}

bool translates(const Level2File& file) {
  return parse(SourceFile("t.sdl", print_level2(file))).ok();
}

// `edited` prints as text that parses back to the same tree and, when `translating` (the random
// level-1 test files need not translate), translates without errors.
void expect_valid(const Level2File& edited, const std::string& what, bool translating = true) {
  const std::string text = print_level2(edited);
  Level2ParseResult again = parse_level2(SourceFile("edited.sdl", text));
  ASSERT_TRUE(again.file) << what << "\n" << text;
  EXPECT_EQ(*again.file, edited) << what;
  if (!translating) return;
  const ParseResult translated = parse(SourceFile("edited.sdl", text));
  EXPECT_TRUE(translated.ok()) << what << "\n" << text;
}

std::vector<std::filesystem::path> all_files() {
  std::vector<std::filesystem::path> files =
      scenfuzz::test::files_in(test::wmg_corpus_dir(), {".sdl"});
  for (const auto& path :
       scenfuzz::test::files_in(scenfuzz::test::lang_data_dir() / "wmg", {".sdl"}))
    files.push_back(path);
  return files;
}

// All true but `index`.
std::vector<bool> all_but(std::size_t count, std::size_t index) {
  std::vector<bool> kept(count, true);
  kept[index] = false;
  return kept;
}

TEST(WmgReduce, EveryEditOfEveryFileStaysAValidFile) {
  const std::vector<std::filesystem::path> files = all_files();
  ASSERT_GE(files.size(), 15u);
  std::size_t actors = 0, phases = 0, weather = 0, translated_files = 0;
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const Level2File start = tree_of_file(path);
    const bool translating = translates(start);
    // Every corpus file translates.
    if (path.parent_path() == test::wmg_corpus_dir()) {
      EXPECT_TRUE(translating);
    }
    translated_files += translating;
    expect_valid(start, "unchanged", translating);
    const std::vector<std::string> others = other_actors(start);
    for (std::size_t i = 0; i < others.size(); ++i, ++actors) {
      Level2File edited = start;
      remove_actors(edited, all_but(others.size(), i));
      expect_valid(edited, "without " + others[i], translating);
    }
    Level2File no_actors = start;
    remove_actors(no_actors, std::vector<bool>(others.size(), false));
    expect_valid(no_actors, "without any actor but the ego", translating);
    EXPECT_TRUE(other_actors(no_actors).empty());
    const std::vector<PhaseName> all_phases = manoeuvre_phases(start);
    for (std::size_t i = 0; i < all_phases.size(); ++i, ++phases) {
      Level2File edited = start;
      remove_phases(edited, all_but(all_phases.size(), i));
      expect_valid(
          edited,
          "without phase " + std::to_string(all_phases[i].number) + " of " + all_phases[i].actor,
          translating);
      EXPECT_EQ(manoeuvre_phases(edited).size() + 1, all_phases.size());
    }
    Level2File calm = start;
    weather += weather_components(start).size();
    neutral_weather(calm, weather_components(start));
    set_time_of_day(calm, 12 * 3600);
    expect_valid(calm, "neutral weather at noon", translating);
    EXPECT_TRUE(weather_components(calm).empty());
    Level2File rounded = start;
    std::vector<double> numbers = file_numbers(start);
    for (double& number : numbers) number += 0.25;
    set_file_numbers(rounded, numbers);
    expect_valid(rounded, "numbers changed", translating);
    EXPECT_EQ(file_numbers(rounded), numbers);
  }
  // The edits were tried on something.
  EXPECT_GE(actors, 10u);
  EXPECT_GE(phases, 10u);
  EXPECT_GE(weather, 10u);
  EXPECT_GE(translated_files, 11u);
}

TEST(WmgReduce, RemovingTheCutterRemovesEverythingThatNamesIt) {
  Level2File file = tree_of_file(test::wmg_corpus_dir() / "cut_in.sdl");
  ASSERT_EQ(other_actors(file), std::vector<std::string>{"Cutter"});
  EXPECT_TRUE(remove_actors(file, {false}).empty());
  const std::string text = print_level2(file);
  EXPECT_EQ(text.find("Cutter"), std::string::npos) << text;
  // Its WHEN ... DO had nothing else to do: the ego's AUTO stands in for it (the grammar wants
  // one); the END conditions do not name it.
  EXPECT_NE(text.find("WHEN: [Ego] is [Going Ahead]\nDO: AUTO\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("PHASE"), std::string::npos) << text;
  EXPECT_NE(text.find("END: [Clock] >= [30] OR Collision"), std::string::npos) << text;
  EXPECT_NE(text.find("Vehicle [Ego] in [R1.L2]"), std::string::npos) << text;
}

// Ego, A placed relative to the ego, B relative to A; B's phase ends on an offset to the ego, the
// ego's AUTO waits for A, an END condition names B.
const std::string kChain =
    "VERSION: 1.0\nAUTHOR: 'a'\n" +
    test::scenery_with_roads(test::road("", "Length [500] AND Lane width [3.5]\n")) +
    "DYNAMIC ELEMENTS:\n"
    "INITIAL: Vehicle [Ego] in [R1.L1] at heading angle [0]\n"
    "  AND Vehicle [A] in [R1.L1] with a [Longitudinal] offset of [20]\n"
    "      AND at relative position [F] with relative heading angle [0] to [Ego]\n"
    "  AND Vehicle [B] in [R1.L1] with a [Longitudinal] offset of [20]\n"
    "      AND at relative position [F] with relative heading angle [0] to [A]\n"
    "  AND Vehicle [C] in [R1.L1] with a [Longitudinal] offset of [-20]\n"
    "      AND at relative position [R] with relative heading angle [0] to [Ego]\n"
    "WHEN: [Ego] is [Going Ahead] AND [A] is [Going Ahead]\nDO: AUTO\n"
    "WHEN: [Ego] is [Going Ahead] at a speed of [50]\n"
    "DO: [B]\n"
    "  PHASE 1: [Drive_Away] [-, 60, 2] [Ego: 30, F]\n"
    "    WHILE: [B] [Longitudinal] offset to [Ego] < [40]\n"
    "  PHASE 2: [Drive_Towards] [-, 30, 2] [Ego: 10, F]\n"
    "  AND: [C]\n"
    "  PHASE 1: [Drive_Towards] [-, 70, 2] [B: 5, R]\n"
    "  PHASE 2: [Drive_Away] [-, 40, 3] [Ego: 10, R]\n"
    "    WHILE: [C] [Longitudinal] offset to [B] < [-5]\n"
    "END: [B] [Longitudinal] offset to [Ego] > [100] OR Collision\n" +
    test::Parts{}.environment;

TEST(WmgReduce, AnActorPlacedRelativeToARemovedOneGoesToo) {
  Level2File file = tree_of(kChain);
  ASSERT_TRUE(parse(SourceFile("chain.sdl", kChain)).ok());
  ASSERT_EQ(other_actors(file), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(remove_actors(file, {false, true, true}), std::vector<std::string>{"B"});
  expect_valid(file, "without A");
  EXPECT_EQ(other_actors(file), std::vector<std::string>{"C"});
  const std::string text = print_level2(file);
  // The AUTO's condition on A went, C's phase relative to B went, C's WHILE on B went with it
  // (its phase stays), the END condition on B went.
  EXPECT_NE(text.find("WHEN: [Ego] is [Going Ahead]\nDO: AUTO"), std::string::npos) << text;
  EXPECT_NE(text.find("DO: [C]\n  PHASE 1: [Drive_Away] [-, 40, 3] [Ego: 10, R]\n\nEND: Collision"),
            std::string::npos)
      << text;
  for (const char* gone : {"[A]", "[B]", "WHILE"})
    EXPECT_EQ(text.find(gone), std::string::npos) << gone << "\n" << text;
}

TEST(WmgReduce, RemovedPhasesAreNumberedAgainAndEmptySequencesGo) {
  Level2File file = tree_of(kChain);
  const std::vector<PhaseName> phases = manoeuvre_phases(file);
  ASSERT_EQ(phases.size(), 4u);
  EXPECT_EQ(phases[2].actor, "C");
  EXPECT_EQ(phases[2].number, 1);
  remove_phases(file, {true, false, false, true});
  expect_valid(file, "phases removed");
  const std::string text = print_level2(file);
  EXPECT_NE(text.find("PHASE 1: [Drive_Away] [-, 40, 3] [Ego: 10, R]"), std::string::npos) << text;
  EXPECT_EQ(text.find("PHASE 2"), std::string::npos) << text;
  // Without any phase, the WHEN ... DO of B and C goes; the AUTO stays.
  remove_phases(file, {false, false});
  expect_valid(file, "no phases");
  EXPECT_EQ(file.dynamics.sequences.size(), 1u);
  EXPECT_TRUE(file.dynamics.sequences[0].autonomous);
}

TEST(WmgReduce, NeutralWeatherAndNoon) {
  Level2File file = tree_of_file(test::wmg_corpus_dir() / "cut_in.sdl");
  EXPECT_EQ(weather_components(file), (std::vector<std::string>{"wind", "cloudiness", "rainfall"}));
  neutral_weather(file, {"wind", "rainfall"});
  EXPECT_EQ(weather_components(file), std::vector<std::string>{"cloudiness"});
  EXPECT_TRUE(set_time_of_day(file, 12 * 3600));
  EXPECT_FALSE(set_time_of_day(file, 12 * 3600));
  const std::string text = print_level2(file);
  EXPECT_EQ(text.find("Wind"), std::string::npos) << text;
  EXPECT_NE(text.find("Rainfall [Light Rain: 0]"), std::string::npos) << text;
  EXPECT_NE(text.find("Cloudiness [0 to 8]"), std::string::npos) << text;
  EXPECT_NE(text.find("Time of the day [12:00]"), std::string::npos) << text;
}

TEST(WmgReduce, NumbersAreWalkedInAFixedOrderWithoutTheEndConditionsAndTime) {
  Level2File file = tree_of(kChain);
  // Speed limit, length, lane width; the ego's heading, A's offset and heading, B's, C's; the
  // WHEN speed; four phases of three numbers, two WHILE values; cloudiness, rainfall. Not the END
  // condition's 100.
  const std::vector<double> numbers = file_numbers(file);
  ASSERT_EQ(numbers.size(), 3u + 7u + 1u + 14u + 2u);
  EXPECT_EQ(numbers[0], 100);
  EXPECT_EQ(numbers[1], 500);
  EXPECT_EQ(numbers[2], 3.5);
  EXPECT_EQ(numbers[10], 50);
  std::vector<double> changed = numbers;
  changed[1] = 512.25;
  set_file_numbers(file, changed);
  EXPECT_NE(print_level2(file).find("Length [512.25]"), std::string::npos);
  EXPECT_NE(print_level2(file).find("> [100] OR Collision"), std::string::npos);
}

}  // namespace
}  // namespace scenfuzz::wmg
