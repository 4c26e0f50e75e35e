// Map names to maps (physics/map/map_source.hpp): built-in names with "?name=value" parameters
// and the parameters a scenario adds, Apollo map files and folders, the map search path
// (--map-path folders, SCENFUZZ_MAP_PATH, first folder wins) and the errors a user sees for an
// unknown name or a broken file. Apollo maps are small hand-written text maps or symlinks to the
// shared samples, made in a temporary folder at run time.
#include "physics/map/map_source.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "physics/map/road_map.hpp"
#include "tests/support/apollo_text_maps.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A folder of its own per test, removed with everything in it (symlinks are removed, not
// followed, so the shared maps they point to are safe).
class TempDir {
 public:
  TempDir() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("scenfuzz_map_source_test_" + std::to_string(::getpid()) +
                                         "_" + test->test_suite_name() + "_" + test->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }

  // Writes `text` to `relative` (creating its folders) and returns the file's path.
  fs::path write(const fs::path& relative, const std::string& text) const {
    const fs::path file = path_ / relative;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  fs::path path_;
};

// Sets or unsets an environment variable for one test and puts the old value back, so that a
// SCENFUZZ_MAP_PATH of the user running the tests neither changes the results nor gets lost.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_value_ = old;
    apply(value);
  }
  ~ScopedEnvironment() { apply(old_value_); }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  void apply(const std::optional<std::string>& value) const {
    if (value)
      ::setenv(name_, value->c_str(), 1);
    else
      ::unsetenv(name_);
  }

  const char* name_;
  std::optional<std::string> old_value_;
};

std::vector<std::string> lane_ids(const RoadMap& map) {
  std::vector<std::string> ids;
  for (const Lane& lane : map.lanes()) ids.push_back(lane.id);
  return ids;
}

// The MapError message `action` throws; a test failure if it throws nothing or something else.
template <class Action>
std::string map_error(Action action) {
  try {
    action();
  } catch (const MapError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not a MapError: " << error.what();
    return error.what();
  }
  ADD_FAILURE() << "no MapError thrown";
  return "";
}

const MapSearchPath kNoSearchPath{};

// ---- parse_builtin_map_request ----

TEST(MapSourceParse, NameWithoutParameters) {
  const BuiltinMapRequest request = parse_builtin_map_request("straight");
  EXPECT_EQ(request.name, "straight");
  EXPECT_TRUE(request.parameters.empty());
}

TEST(MapSourceParse, ParametersInTheirOrder) {
  const BuiltinMapRequest request = parse_builtin_map_request("straight?lanes=3&length=400");
  EXPECT_EQ(request.name, "straight");
  ASSERT_EQ(request.parameters.size(), 2u);
  EXPECT_EQ(request.parameters[0].name, "lanes");
  EXPECT_EQ(request.parameters[0].value, 3.0);
  EXPECT_EQ(request.parameters[1].name, "length");
  EXPECT_EQ(request.parameters[1].value, 400.0);
}

TEST(MapSourceParse, FlagWordsAreZeroAndOne) {
  for (const auto& [text, value] : std::vector<std::pair<std::string, double>>{
           {"false", 0}, {"no", 0}, {"true", 1}, {"yes", 1}}) {
    const BuiltinMapRequest request = parse_builtin_map_request("straight?two_way=" + text);
    ASSERT_EQ(request.parameters.size(), 1u) << text;
    EXPECT_EQ(request.parameters[0].name, "two_way");
    EXPECT_EQ(request.parameters[0].value, value) << text;
  }
}

TEST(MapSourceParse, NumbersInEveryFormFromCharsReads) {
  for (const auto& [text, value] : std::vector<std::pair<std::string, double>>{
           {"1e2", 100}, {"2.5", 2.5}, {"-3", -3}, {"0.125", 0.125}, {"400", 400}}) {
    const BuiltinMapRequest request = parse_builtin_map_request("straight?length=" + text);
    ASSERT_EQ(request.parameters.size(), 1u) << text;
    EXPECT_EQ(request.parameters[0].value, value) << text;
  }
}

// Range checks belong to the generator: the parser keeps a repeated name and out-of-range
// values as given, in order, so that the later value can override the earlier one.
TEST(MapSourceParse, RepeatedAndOutOfRangeValuesAreKept) {
  const BuiltinMapRequest request = parse_builtin_map_request("straight?lanes=1&lanes=99");
  ASSERT_EQ(request.parameters.size(), 2u);
  EXPECT_EQ(request.parameters[0].value, 1.0);
  EXPECT_EQ(request.parameters[1].value, 99.0);
}

TEST(MapSourceParse, PairWithoutValueOrName) {
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?lanes"); }),
              HasSubstr("expected name=value, found 'lanes'"));
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?=3"); }),
              HasSubstr("expected name=value, found '=3'"));
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?&lanes=3"); }),
              HasSubstr("expected name=value"));
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?lanes=3&&length=400"); }),
              HasSubstr("expected name=value"));
  // The message quotes the whole name, so the user sees which map reference is wrong.
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?lanes=3&length"); }),
              HasSubstr("map 'straight?lanes=3&length'"));
}

// A trailing '&' is an empty pair, as "straight?&lanes=3" and "a=1&&b=2" have one.
TEST(MapSourceParse, TrailingAmpersandIsAnEmptyPair) {
  EXPECT_THAT(map_error([] { parse_builtin_map_request("straight?lanes=3&"); }),
              HasSubstr("expected name=value"));
}

TEST(MapSourceParse, ValueThatIsNotANumber) {
  for (const char* value : {"abc", "", "3x", "0x10", " 3", "3 ", "+3", "1,5"}) {
    const std::string text = std::string("straight?lanes=") + value;
    EXPECT_THAT(map_error([&text] { parse_builtin_map_request(text); }),
                HasSubstr("parameter 'lanes' needs a number, not '" + std::string(value) + "'"))
        << text;
  }
}

// ---- describe_map and load_map: built-in maps ----

TEST(MapSourceBuiltin, DefaultsWithoutParameters) {
  const RoadMap straight = load_map("straight", kNoSearchPath);
  EXPECT_EQ(straight.name(), "straight");
  EXPECT_EQ(straight.source(), "built-in");
  // Two lanes each way.
  EXPECT_THAT(lane_ids(straight),
              ::testing::UnorderedElementsAre("east_0", "east_1", "west_0", "west_1"));
  EXPECT_EQ(load_map("crossroads", kNoSearchPath).lanes().size(), 32u);
}

TEST(MapSourceBuiltin, ParametersInTheName) {
  EXPECT_EQ(load_map("straight?lanes=3", kNoSearchPath).lanes().size(), 6u);
  EXPECT_THAT(lane_ids(load_map("straight?two_way=false", kNoSearchPath)),
              ::testing::UnorderedElementsAre("east_0", "east_1"));
  const RoadMap short_road = load_map("straight?lanes=1&length=1e2", kNoSearchPath);
  ASSERT_EQ(short_road.lanes().size(), 2u);
  EXPECT_DOUBLE_EQ(short_road.lanes()[0].length(), 100.0);
  EXPECT_EQ(load_map("crossroads?lanes=1", kNoSearchPath).lanes().size(), 20u);
  // The last of a repeated parameter counts.
  EXPECT_EQ(load_map("straight?lanes=1&lanes=3", kNoSearchPath).lanes().size(), 6u);
}

TEST(MapSourceBuiltin, ExtraParametersOverrideTheName) {
  const RoadMap one_each_way = load_map("straight?lanes=3", kNoSearchPath, {{"lanes", 1}});
  EXPECT_THAT(lane_ids(one_each_way), ::testing::UnorderedElementsAre("east_0", "west_0"));
  // Parameters of the name that the extra ones do not mention stay.
  const RoadMap one_way = load_map("straight?two_way=no&length=200", kNoSearchPath, {{"lanes", 3}});
  EXPECT_EQ(one_way.lanes().size(), 3u);
  EXPECT_DOUBLE_EQ(one_way.lanes()[0].length(), 200.0);
  EXPECT_EQ(load_map("straight?two_way=0", kNoSearchPath, {{"two_way", 1}}).lanes().size(), 4u);
  EXPECT_EQ(load_map("crossroads?lanes=1", kNoSearchPath, {{"lanes", 2}}).lanes().size(), 32u);

  const MapDescription description =
      describe_map("straight?lanes=3", kNoSearchPath, {{"lanes", 1}});
  EXPECT_EQ(description.name, "straight");
  EXPECT_EQ(description.lanes.size(), 2u);
}

TEST(MapSourceBuiltin, BadParametersNameTheParameter) {
  EXPECT_THAT(map_error([] { load_map("straight?lanes=7", kNoSearchPath); }),
              HasSubstr("parameter 'lanes' = 7 is outside its range 1..6"));
  EXPECT_THAT(map_error([] { load_map("straight?bogus=1", kNoSearchPath); }),
              HasSubstr("unknown parameter 'bogus'"));
  EXPECT_THAT(map_error([] {
                load_map("straight", kNoSearchPath, {{"lanes", 2.5}});
              }),
              HasSubstr("must be a whole number"));
  EXPECT_THAT(map_error([] { load_map("straight?lanes=abc", kNoSearchPath); }),
              HasSubstr("needs a number, not 'abc'"));
}

// A built-in name means the built-in map even where a search-path folder has the same name, so
// a stray folder cannot change what every scenario on "crossroads" drives on.
TEST(MapSourceBuiltin, BuiltinNamesWinOverTheSearchPath) {
  const TempDir temp;
  temp.write("crossroads/base_map.txt", test::one_lane_map("impostor"));
  const RoadMap map = load_map("crossroads", MapSearchPath{{temp.path()}});
  EXPECT_EQ(map.source(), "built-in");
  EXPECT_FALSE(map.find_lane("impostor"));
}

// ---- Apollo maps take no parameters ----

TEST(MapSourceApollo, ParametersAreAnError) {
  const TempDir temp;
  const fs::path file = temp.write("town/base_map.txt", test::one_lane_map("lane_1"));
  const MapSearchPath search_path{{temp.path()}};
  ASSERT_EQ(load_map("town", search_path).lanes().size(), 1u);

  EXPECT_THAT(map_error([&] { describe_map("town?lanes=2", search_path); }),
              HasSubstr("only built-in maps take parameters"));
  EXPECT_THAT(map_error([&] {
                describe_map("town", search_path, {{"lanes", 2}});
              }),
              HasSubstr("apply only to built-in maps"));
  EXPECT_THAT(map_error([&] {
                load_map(file.string(), search_path, {{"lanes", 2}});
              }),
              HasSubstr("apply only to built-in maps"));
}

TEST(MapSourceApollo, MalformedTextMapNamesFileAndLine) {
  const TempDir temp;
  const fs::path file = temp.write("broken/base_map.txt", test::kBrokenMap);
  const std::string at_line = file.string() + ":" + std::to_string(test::kBrokenMapLine) + ":";
  // By path and by name on the search path alike.
  EXPECT_THAT(map_error([&] { load_map(file.string(), kNoSearchPath); }), HasSubstr(at_line));
  EXPECT_THAT(map_error([&] { load_map("broken", MapSearchPath{{temp.path()}}); }),
              HasSubstr(at_line));
}

// ---- resolve_map_file ----

TEST(MapSourceResolve, FilePathsAreTakenAsGiven) {
  const TempDir temp;
  // The file is not read here, so any bytes will do, and the name need not be base_map.
  const fs::path text = temp.write("maps/mine.txt", "not read");
  const fs::path binary = temp.write("maps/mine.bin", "not read");
  EXPECT_EQ(resolve_map_file(text.string(), kNoSearchPath), text);
  EXPECT_EQ(resolve_map_file(binary.string(), kNoSearchPath), binary);

  const fs::path missing = temp.path() / "maps" / "missing.txt";
  EXPECT_THAT(map_error([&] { resolve_map_file(missing.string(), kNoSearchPath); }),
              HasSubstr(missing.string() + ": error: no such file"));
}

TEST(MapSourceResolve, FolderPathPrefersBinaryThenText) {
  const TempDir temp;
  const fs::path both_bin = temp.write("both/base_map.bin", "not read");
  temp.write("both/base_map.txt", "not read");
  const fs::path text_only = temp.write("text_only/base_map.txt", "not read");
  fs::create_directories(temp.path() / "empty");
  temp.write("empty/other.txt", "not a base map");

  EXPECT_EQ(resolve_map_file((temp.path() / "both").string(), kNoSearchPath), both_bin);
  EXPECT_EQ(resolve_map_file((temp.path() / "text_only").string(), kNoSearchPath), text_only);
  const std::string empty = (temp.path() / "empty").string();
  EXPECT_THAT(map_error([&] { resolve_map_file(empty, kNoSearchPath); }),
              HasSubstr(empty + ": error: the folder has no base_map.bin or base_map.txt"));
}

TEST(MapSourceResolve, NameInASearchPathFolder) {
  const TempDir temp;
  const fs::path first = temp.path() / "first", second = temp.path() / "second";
  const fs::path town_bin = temp.write("second/town/base_map.bin", "not read");
  temp.write("second/town/base_map.txt", "not read");
  const fs::path village = temp.write("first/village/base_map.txt", "not read");
  const MapSearchPath search_path{{first, second}};
  EXPECT_EQ(resolve_map_file("town", search_path), town_bin);
  EXPECT_EQ(resolve_map_file("village", search_path), village);
}

// LawBreaker files write Dreamview's display names: "San Francisco" is the san_francisco folder.
TEST(MapSourceResolve, DisplayNamesAreNormalisedToFolderNames) {
  EXPECT_EQ(normalised_map_name("San Francisco"), "san_francisco");
  EXPECT_EQ(normalised_map_name(" Borregas Ave "), "borregas_ave");
  EXPECT_EQ(normalised_map_name("Sunnyvale-Big-Loop"), "sunnyvale_big_loop");
  EXPECT_EQ(normalised_map_name("san_francisco"), "san_francisco");

  const TempDir temp;
  const fs::path folder = temp.write("maps/san_francisco/base_map.txt", "not read");
  const MapSearchPath search_path{{temp.path() / "maps"}};
  EXPECT_EQ(resolve_map_file("San Francisco", search_path), folder);
  EXPECT_EQ(resolve_map_file("san_francisco", search_path), folder);
  // A folder of the exact name wins over the normalised one.
  const fs::path exact = temp.write("maps/San Francisco/base_map.txt", "not read");
  EXPECT_EQ(resolve_map_file("San Francisco", search_path), exact);
  // Nothing under either name: the message names both.
  EXPECT_THAT(map_error([&] { resolve_map_file("Borregas Ave", search_path); }),
              HasSubstr("no folder of the map search path has Borregas Ave/base_map.bin or "
                        "base_map.txt (nor borregas_ave/, its folder name)"));
}

TEST(MapSourceResolve, FirstFolderWins) {
  const TempDir temp;
  const fs::path first = temp.path() / "first", second = temp.path() / "second";
  // Text in the first folder beats binary in the second: order first, then format.
  const fs::path in_first = temp.write("first/town/base_map.txt", "not read");
  temp.write("second/town/base_map.bin", "not read");
  EXPECT_EQ(resolve_map_file("town", MapSearchPath{{first, second}}), in_first);
  EXPECT_EQ(resolve_map_file("town", MapSearchPath{{second, first}}),
            second / "town" / "base_map.bin");

  // A folder of the right name without a map file does not stop the search.
  fs::create_directories(temp.path() / "hollow" / "town");
  EXPECT_EQ(resolve_map_file("town", MapSearchPath{{temp.path() / "hollow", first}}), in_first);
}

TEST(MapSourceResolve, LoadsTheMapTheSearchFinds) {
  const TempDir temp;
  temp.write("first/town/base_map.txt", test::one_lane_map("lane_first"));
  temp.write("second/town/base_map.txt", test::one_lane_map("lane_second"));
  const RoadMap map =
      load_map("town", MapSearchPath{{temp.path() / "first", temp.path() / "second"}});
  EXPECT_EQ(map.name(), "town");
  EXPECT_EQ(map.source(), (temp.path() / "first" / "town" / "base_map.txt").string());
  EXPECT_EQ(lane_ids(map), std::vector<std::string>{"lane_first"});
}

TEST(MapSourceResolve, UnknownNameListsBuiltinMapsAndSearchedFolders) {
  const TempDir temp;
  const fs::path first = temp.path() / "first", second = temp.path() / "second";
  fs::create_directories(first);
  const std::string message = map_error([&] {
    resolve_map_file("atlantis", MapSearchPath{{first, second}});
  });
  EXPECT_THAT(message, StartsWith("map 'atlantis' not found"));
  for (const BuiltinMapInfo& info : builtin_maps()) EXPECT_THAT(message, HasSubstr(info.name));
  EXPECT_THAT(message, HasSubstr(first.string()));
  EXPECT_THAT(message, HasSubstr(second.string()));
  EXPECT_THAT(message, HasSubstr("--map-path"));
  EXPECT_THAT(message, HasSubstr("SCENFUZZ_MAP_PATH"));
  // load_map gives the same message: it is what `scenfuzz map` and the fuzzer print.
  EXPECT_EQ(map_error([&] { load_map("atlantis", MapSearchPath{{first, second}}); }), message);
}

TEST(MapSourceResolve, EmptyName) {
  EXPECT_THAT(map_error([] { resolve_map_file("", kNoSearchPath); }), HasSubstr("empty"));
}

// ---- map_search_path and SCENFUZZ_MAP_PATH ----

TEST(MapSourceSearchPath, CommandLineThenEnvironmentThenCorpora) {
  const ScopedEnvironment environment("SCENFUZZ_MAP_PATH", "/env/one:/env/two");
  const MapSearchPath path = map_search_path({"/cli/one", "/cli/two"});
  ASSERT_EQ(path.directories.size(), 5u);
  EXPECT_EQ(path.directories[0], fs::path("/cli/one"));
  EXPECT_EQ(path.directories[1], fs::path("/cli/two"));
  EXPECT_EQ(path.directories[2], fs::path("/env/one"));
  EXPECT_EQ(path.directories[3], fs::path("/env/two"));
  EXPECT_EQ(path.directories[4].filename(), "maps");
  EXPECT_EQ(path.directories[4].parent_path().filename(), "corpora");
}

TEST(MapSourceSearchPath, EmptyEnvironmentEntriesAreSkipped) {
  {
    const ScopedEnvironment environment("SCENFUZZ_MAP_PATH", ":/env/one::/env/two:");
    const MapSearchPath path = map_search_path({});
    ASSERT_EQ(path.directories.size(), 3u);
    EXPECT_EQ(path.directories[0], fs::path("/env/one"));
    EXPECT_EQ(path.directories[1], fs::path("/env/two"));
  }
  {
    const ScopedEnvironment environment("SCENFUZZ_MAP_PATH", "");
    EXPECT_EQ(map_search_path({}).directories.size(), 1u);
  }
  {
    const ScopedEnvironment environment("SCENFUZZ_MAP_PATH", std::nullopt);
    EXPECT_EQ(map_search_path({"/cli"}).directories.size(), 2u);
  }
}

TEST(MapSourceSearchPath, EnvironmentFoldersAreSearchedInOrder) {
  const TempDir temp;
  const fs::path one = temp.path() / "one", two = temp.path() / "two",
                 three = temp.path() / "three";
  fs::create_directories(one);
  temp.write("two/town/base_map.txt", test::one_lane_map("lane_two"));
  temp.write("three/town/base_map.txt", test::one_lane_map("lane_three"));
  temp.write("three/hamlet/base_map.txt", test::one_lane_map("lane_hamlet"));
  const ScopedEnvironment environment("SCENFUZZ_MAP_PATH",
                                      one.string() + ":" + two.string() + ":" + three.string());

  EXPECT_EQ(lane_ids(load_map("town", map_search_path({}))), std::vector<std::string>{"lane_two"});
  EXPECT_EQ(lane_ids(load_map("hamlet", map_search_path({}))),
            std::vector<std::string>{"lane_hamlet"});
  // --map-path folders come before the environment's.
  EXPECT_EQ(lane_ids(load_map("town", map_search_path({three}))),
            std::vector<std::string>{"lane_three"});

  const std::string message = map_error([] { load_map("atlantis", map_search_path({})); });
  EXPECT_THAT(message,
              HasSubstr("'" + one.string() + "' '" + two.string() + "' '" + three.string() + "'"));
}

// ---- the shared sample maps, through symlinks ----

fs::path apollo_dir() { return test::shared_dir() / "maps" / "apollo"; }

TEST(MapSourceShared, SanFranciscoByNamePrefersTheBinaryFile) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const RoadMap map = load_map("san_francisco", MapSearchPath{{apollo_dir()}});
  EXPECT_EQ(map.name(), "san_francisco");
  EXPECT_EQ(map.source(), (apollo_dir() / "san_francisco" / "base_map.bin").string());
  EXPECT_EQ(map.lanes().size(), 1524u);
  EXPECT_EQ(map.junctions().size(), 91u);
  EXPECT_EQ(map.traffic_lights().size(), 201u);
  EXPECT_EQ(map.stop_sign_count(), 9u);
  EXPECT_EQ(map.crosswalks().size(), 43u);
  EXPECT_TRUE(map.find_lane("lane_540"));
}

TEST(MapSourceShared, SymlinkedFoldersAndFiles) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const TempDir temp;
  // A folder linked under another name is found by that name.
  fs::create_directory_symlink(apollo_dir() / "cubetown", temp.path() / "my_town");
  const RoadMap linked = load_map("my_town", MapSearchPath{{temp.path()}});
  EXPECT_EQ(linked.lanes().size(), 18u);
  EXPECT_EQ(linked.source(), (temp.path() / "my_town" / "base_map.bin").string());

  // Only a text file: it is read as text, and gives the same map.
  fs::create_directories(temp.path() / "text" / "cubetown");
  fs::create_symlink(apollo_dir() / "cubetown" / "base_map.txt",
                     temp.path() / "text" / "cubetown" / "base_map.txt");
  const RoadMap text = load_map("cubetown", MapSearchPath{{temp.path() / "text", apollo_dir()}});
  EXPECT_EQ(text.source(), (temp.path() / "text" / "cubetown" / "base_map.txt").string());
  EXPECT_EQ(lane_ids(text), lane_ids(linked));
  EXPECT_EQ(text.junctions().size(), 2u);
  EXPECT_EQ(text.traffic_lights().size(), 3u);
  EXPECT_EQ(text.stop_sign_count(), 3u);
}

}  // namespace
}  // namespace scenfuzz
