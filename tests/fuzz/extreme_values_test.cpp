// Exit status 3 ("internal error") is unreachable from user input: every corpus scenario, with one
// of its numbers at a time replaced by an extreme (huge, tiny, zero, negative), is simulated by
// `scenfuzz run` through the real command line, and must end in 0, 1 or 2, never 3, never a
// crash. The replacements are chosen by a fixed stride so that every run of the test simulates
// the same thousand-odd variants.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

struct Variant {
  std::string name;  // "cut_in_straight.avu, number 7 -> 1e300"
  std::string text;
  std::string extension;
};

// Plain decimals: AVUnit has no exponents. 1e300, -1e300, 0, -1, 1e-300, 1e9.
const std::string kExtremes[] = {"1" + std::string(300, '0'),
                                 "-1" + std::string(300, '0'),
                                 "0",
                                 "-1",
                                 "0." + std::string(299, '0') + "1",
                                 "1000000000"};

// Every number of `text` (not inside a string or comment: good enough for the corpus, whose
// strings are lane ids and names) with its start and length.
std::vector<std::pair<std::size_t, std::size_t>> numbers_in(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> numbers;
  const std::regex number(R"((^|[^A-Za-z0-9_."])(\d+(\.\d+)?))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
       it != std::sregex_iterator(); ++it) {
    const std::size_t start = static_cast<std::size_t>(it->position(2));
    const std::size_t line_start = text.rfind('\n', start) + 1;
    const std::string before = text.substr(line_start, start - line_start);
    if (before.find("//") != std::string::npos || before.find('#') != std::string::npos) continue;
    if (std::count(before.begin(), before.end(), '"') % 2 == 1) continue;
    numbers.emplace_back(start, static_cast<std::size_t>(it->length(2)));
  }
  return numbers;
}

std::vector<Variant> variants() {
  std::vector<Variant> result;
  std::size_t counter = 0;
  for (const char* folder : {"corpora/avunit", "corpora/wmg"}) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(SCENFUZZ_SOURCE_DIR) / folder))
      if (entry.path().extension() == ".avu" || entry.path().extension() == ".sdl")
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      std::ifstream in(file);
      std::stringstream buffer;
      buffer << in.rdbuf();
      const std::string text = buffer.str();
      const auto numbers = numbers_in(text);
      for (std::size_t k = 0; k < numbers.size(); ++k) {
        // Every number of the corpus, each with the next extreme in turn.
        const std::string& extreme = kExtremes[counter++ % std::size(kExtremes)];
        Variant variant;
        variant.name = file.filename().string() + ", number " + std::to_string(k) + " (" +
                       text.substr(numbers[k].first, numbers[k].second) + ") -> " +
                       (extreme.size() > 12 ? extreme.substr(0, 6) + "..." : extreme);
        variant.text = text;
        variant.text.replace(numbers[k].first, numbers[k].second, extreme);
        variant.extension = file.extension().string();
        result.push_back(std::move(variant));
      }
    }
  }
  return result;
}

TEST(ExtremeValuesTest, NoScenarioNumberMakesAnInternalError) {
  const fs::path dir =
      fs::temp_directory_path() / ("scenfuzz_extreme_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<Variant> all = variants();
  ASSERT_GT(all.size(), 100u);
  std::size_t rejected = 0;
  for (const Variant& variant : all) {
    const fs::path path = dir / ("variant" + variant.extension);
    std::ofstream(path) << variant.text;
    const std::string file = path.string(), out = (dir / "out").string();
    const std::string maps = std::string(SCENFUZZ_SHARED_DIR) + "/maps/apollo";
    const char* argv[] = {"scenfuzz", "run",        file.c_str(), "--at",
                          "mid",      "--out",      out.c_str(),  "--duration",
                          "8",        "--map-path", maps.c_str()};
    std::ostringstream stdout_text, stderr_text;
    const int status = run_cli(static_cast<int>(std::size(argv)), argv, stdout_text, stderr_text);
    EXPECT_TRUE(status == 0 || status == 1 || status == 2)
        << variant.name << ": exit " << status << "\n"
        << stderr_text.str();
    if (status == 2) {
      if (std::getenv("SCENFUZZ_SHOW_REJECTIONS"))
        std::cout << variant.name << ": " << stderr_text.str();
      ++rejected;
      EXPECT_FALSE(stderr_text.str().empty()) << variant.name << ": exit 2 without a reason";
    }
  }
  std::cout << all.size() << " variants, " << rejected << " rejected with a reason\n";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace scenfuzz
