// Every seed of corpora/ (AVUnit, WMG SDL and the benchmarks), simulated at the middle of its
// search space, gives a picture that a viewer draws (rsvg-convert, from Debian's librsvg2-bin,
// turns it into a PNG of the picture's size), whose labels all lie inside the canvas without
// covering one another, and whose sides are within 1:3 of each other. Without rsvg-convert the
// rendering part is skipped, loudly; seeds on Apollo maps need the shared folder, likewise.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/corpus_seeds.hpp"
#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "physics/trace/trace_svg.hpp"
#include "sampler/parameter_space.hpp"
#include "svg_labels.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

using test::corpus_seeds;
using test::parse_seed;

bool have_rsvg_convert() { return std::system("command -v rsvg-convert >/dev/null 2>&1") == 0; }

// "" when rsvg-convert turns `svg` into a PNG of width x height pixels; else what went wrong.
std::string render_problem(const fs::path& svg, double width, double height) {
  const fs::path png = fs::path(svg).replace_extension(".png");
  const std::string command = "rsvg-convert '" + svg.string() + "' -o '" + png.string() + "' 2>&1";
  if (const int status = std::system(command.c_str()); status != 0)
    return "rsvg-convert exited with status " + std::to_string(status);
  std::ifstream in(png, std::ios::binary);
  std::string header(24, '\0');
  if (!in.read(header.data(), 24) || !header.starts_with("\x89PNG\r\n\x1a\n"))
    return "no PNG written";
  const auto big_endian = [&](std::size_t at) {
    unsigned value = 0;
    for (std::size_t i = at; i < at + 4; ++i)
      value = value << 8 | static_cast<unsigned char>(header[i]);
    return static_cast<double>(value);
  };
  if (std::abs(big_endian(16) - width) > 1 || std::abs(big_endian(20) - height) > 1)
    return "PNG of " + std::to_string(big_endian(16)) + " x " + std::to_string(big_endian(20));
  return "";
}

TEST(TracePictureCorpus, EverySeedsPictureRendersWithItsLabelsOnTheCanvasApart) {
  const bool rsvg = have_rsvg_convert();
  if (!rsvg)
    std::printf(
        "\n*** rsvg-convert NOT FOUND: the pictures are NOT RENDERED, only their layout is "
        "checked.\n*** Install it with scripts/install-deps.sh (Debian package librsvg2-bin).\n\n");
  const fs::path folder =
      fs::temp_directory_path() / ("scenfuzz-trace-pictures-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ostringstream skipped;
  std::size_t pictures = 0;
  for (const fs::path& path : corpus_seeds()) {
    SCOPED_TRACE(path.filename().string());
    const std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file);
    const std::optional<ScenarioTemplate> scenario = parse_seed(*file);
    ASSERT_TRUE(scenario) << "does not parse";
    const ParameterSpace space = parameter_space(*scenario);
    const std::vector<double> values =
        decode(space, std::vector<double>(space.dimensions.size(), 0.5));
    const test::SeedRun run = test::simulate_seed(*file, *scenario, values);
    if (run.map_missing) {
      ASSERT_FALSE(test::have_shared_dir()) << run.error;
      skipped << "  " << path.filename().string() << " (its map is in the shared folder)\n";
      continue;
    }
    ASSERT_TRUE(run.trace) << run.error;
    const Trace& trace = *run.trace;
    const RoadMap& map = *run.map;
    // A caption as long as a finding's, to make the title wrap.
    TraceSvgOptions options;
    options.caption.spec = "no_collision_with_any_vehicle_or_pedestrian";
    options.caption.robustness = -0.125;
    options.caption.time = trace.time.empty() ? 0 : trace.time.back() / 2;
    options.caption.responsibility = "shared";
    options.caption.reason =
        "the other entered the ego's lane 1.1 s before impact, less than the ego's stopping "
        "time at 8 m/s2";
    const std::string svg = render_trace_svg(map, trace, options);
    ++pictures;
    EXPECT_EQ(test::layout_problems(svg), "");
    if (!rsvg) continue;
    const fs::path svg_path = folder / (path.stem().string() + ".svg");
    std::ofstream(svg_path) << svg;
    const test::SvgLabels read = test::svg_labels(svg);
    EXPECT_EQ(render_problem(svg_path, read.width, read.height), "");
  }
  if (!skipped.str().empty())
    std::printf("SKIPPED, shared folder %s not found:\n%s", SCENFUZZ_SHARED_DIR,
                skipped.str().c_str());
  EXPECT_GT(pictures, 20u);
  if (!HasFailure()) fs::remove_all(folder);
}

}  // namespace
}  // namespace scenfuzz
