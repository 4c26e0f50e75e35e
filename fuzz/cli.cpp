// The command line: subcommands, options and help texts (CLI11), and the mapping to exit codes.
#include "fuzz/cli.hpp"

#include <CLI/CLI.hpp>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"
#include "fuzz/options.hpp"

namespace scenfuzz {

namespace {

// The checks of several simulation options together, which CLI11 cannot make one option at a time.
bool simulation_options_valid(const SimulationCommandOptions& options, std::ostream& err) {
  const std::optional<std::string> problem = check_simulation_options(options);
  if (problem)
    err << "scenfuzz: error: " << *problem << "\nRun with --help for more information.\n";
  return !problem;
}

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "scenfuzz searches the parameter space of a driving scenario for concrete scenarios in "
      "which the automated driving system under test violates its specification.",
      "scenfuzz"};
  app.set_version_flag("--version", std::string("scenfuzz ") + SCENFUZZ_VERSION);
  // Without a subcommand, scenfuzz searches: `scenfuzz --budget 500 base.avu`.
  app.require_subcommand(0, 1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("scenfuzz: error: ") + e.what() +
           "\nRun with --help for more information.\n";
  });
  app.footer(
      "Without a subcommand, scenfuzz searches FILE's parameter ranges for points that violate "
      "its specs and writes every finding into --out. Exit status: 0 success (no finding), 1 "
      "findings (a specification is violated, also for run and stl; for run also an ego plugin "
      "that crashed, hung or failed), 2 a bad command line (an option's value out of its "
      "bounds among them) or a scenario, map or trace file that cannot be read or has errors.");

  FuzzCommandOptions fuzz_options;
  app.add_option("FILE", fuzz_options.path,
                 "Logical scenario to search (AVUnit, scenest or WMG SDL)")
      ->type_name("");
  add_search_options(&app, fuzz_options);

  std::vector<std::string> check_files;
  CLI::App* check = app.add_subcommand(
      "check", "Parse scenario files and report their errors and warnings (nothing when clean)");
  check->add_option("FILE", check_files, "AVUnit, scenest or WMG SDL (.sdl) scenario files")
      ->required()
      ->type_name("");

  std::string space_file;
  bool space_json = false;
  CLI::App* space = app.add_subcommand(
      "space", "Print the parameter space of a scenario: one dimension per range in the file");
  space->add_option("FILE", space_file, "AVUnit, scenest or WMG SDL scenario file")
      ->required()
      ->type_name("");
  space->add_flag("--json", space_json, "Print a JSON document instead of a table");

  MapCommandOptions map_options;
  CLI::App* map = app.add_subcommand(
      "map",
      "Summarise a road map (built-in or Apollo HD map), draw it as SVG, or list the "
      "built-in maps");
  map->add_option("MAP", map_options.name,
                  "A built-in map (crossroads, straight?lanes=3&length=400, ...), the name of an "
                  "Apollo map folder on the map search path (san_francisco), or a map file")
      ->type_name("");
  map->add_option("--map-path", map_options.map_paths,
                  "Folder to look for Apollo maps in (<DIR>/<name>/base_map.bin or .txt); "
                  "repeatable, searched before SCENFUZZ_MAP_PATH and corpora/maps")
      ->type_name("DIR")
      ->allow_extra_args(false);
  map->add_option("--svg", map_options.svg_path, "Draw the map into this SVG file")
      ->type_name("FILE");
  map->add_flag("--labels", map_options.labels, "With --svg: write every lane's id on the lane");
  map->add_flag("--json", map_options.json, "Print JSON (counts, bounds, every lane) instead");
  map->add_flag("--list", map_options.list, "List the built-in maps and their parameters");

  RunCommandOptions run_options;
  CLI::App* run_command = app.add_subcommand(
      "run",
      "Simulate a scenario: print the collisions, whether the ego reached its target and the "
      "robustness of every spec (exit 1 when one is violated); write the trace (CSV, JSON), a "
      "bird's-eye SVG and the concrete scenario");
  run_command->add_option("FILE", run_options.path, "AVUnit, scenest or WMG SDL scenario file")
      ->required()
      ->type_name("");
  add_run_options(run_command, run_options);

  StlCommandOptions stl_options;
  CLI::App* stl = app.add_subcommand(
      "stl",
      "Evaluate an STL formula on a CSV log: print its robustness at the first sample (or at "
      "every sample with --signal); exit 0 when satisfied, 1 when violated");
  stl->add_option("--spec", stl_options.spec,
                  "The formula, in AVUnit's syntax; its names are the log's columns: "
                  "'G[0:5](x > 0.5 & F[0:2](y < 0.1))'")
      ->required()
      ->type_name("FORMULA");
  stl->add_option("--trace", stl_options.trace_path,
                  "CSV log: a header row naming the columns, one of them 'time' (seconds, "
                  "strictly increasing), then one row of numbers per sample")
      ->required()
      ->type_name("FILE.csv");
  stl->add_flag("--signal", stl_options.signal,
                "Print the robustness at every sample as CSV (time,robustness)");
  stl->footer(
      "Prints the robustness as a plain number (inf and -inf for infinities); for a violated "
      "formula, a note on stderr names the atom responsible and the time. Exit status: 0 "
      "satisfied (robustness >= 0), 1 violated (< 0), 2 a bad command line, or a formula or "
      "log that cannot be read or has errors.");

  std::string convert_target;
  std::string convert_file;
  CLI::App* convert = app.add_subcommand(
      "convert",
      "Print a WMG SDL file as level 2: a level-1 file converted (every qualitative word "
      "becomes its default range), a level-2 file printed canonically");
  convert->add_option("--to", convert_target, "The language to write: sdl2 (WMG SDL level 2)")
      ->required()
      ->check(CLI::IsMember({"sdl2"}))
      ->type_name("sdl2");
  convert->add_option("FILE", convert_file, "WMG SDL file (.sdl, level 1 or 2)")
      ->required()
      ->type_name("");

  BenchCommandOptions bench_options;
  std::string bench_algorithm;
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Measure the search: strategies on bundled scenarios, the ARCH-COMP chasing-cars "
      "benchmark, the speed-up of parallel evaluation; prints tables");
  bench->require_subcommand(1);
  bench->footer(
      "Results depend only on the seeds, never on -j; figures and how they were measured: "
      "docs/performance.md.");
  CLI::App* bench_falsification = bench->add_subcommand(
      "falsification",
      "For each scenario and algorithm, search with seeds 1..N: median simulations to the first "
      "finding, findings per 500 simulations, and random's median over ga's");
  bench_falsification
      ->add_option("SCENARIO", bench_options.scenarios,
                   "Logical scenarios, FILE or FILE:SPEC to target one spec (default: five "
                   "bundled ones in corpora/, run from the repository's root)")
      ->type_name("");
  bench_falsification->add_option("--seeds", bench_options.seeds, "Runs per algorithm (default 20)")
      ->type_name("N");
  add_checked_option(bench_falsification, "--budget", bench_options.budget, "N",
                     within(1, kMaxBudget), "Simulations per run", "500");
  bench_falsification->add_flag(
      "--first-only", bench_options.first_finding_only,
      "Stop each run at its first finding: the same first-finding medians in a fraction of the "
      "time, for many seeds (findings per 500 are then not measured)");
  bench_falsification
      ->add_option("--algos", bench_options.algorithms,
                   "Comma-separated algorithms as for --algo (default "
                   "ga,nlopt:LN_COBYLA,halton,random)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->type_name("LIST");
  add_checked_option(bench_falsification, "-j,--jobs", bench_options.jobs, "N", within(0, kMaxJobs),
                     "Searches run at once, one thread each; 0 means all cores", "all cores");
  CLI::App* bench_cc = bench->add_subcommand(
      "cc",
      "ARCH-COMP chasing cars under the competition's protocol: per requirement, runs that stop "
      "at the first falsifying simulation; FR and mean/median simulations beside the published "
      "figures");
  bench_cc
      ->add_option("--runs", bench_options.runs, "Runs per requirement, seeds 1..N (default 10)")
      ->type_name("N");
  add_checked_option(bench_cc, "--budget", bench_options.budget, "N", within(1, kMaxBudget),
                     "Simulations per run at most", "1500");
  bench_cc->add_option("--algo", bench_algorithm, "Search algorithm, as for --algo (default ga)")
      ->type_name("NAME");
  bench_cc
      ->add_option("--requirements", bench_options.requirements,
                   "Comma-separated requirements (default CC1,CC2,CC3,CC4,CC5,CCx)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"CC1", "CC2", "CC3", "CC4", "CC5", "CCx"}))
      ->type_name("LIST");
  bench_cc
      ->add_option("--segments", bench_options.segments,
                   "Piecewise-constant segments of u1 and u2 over the 100 s, 1 to 20 (jumps at "
                   "least 5 s apart; default 20, 40 dimensions)")
      ->check(CLI::Range(1, 20))
      ->type_name("N");
  add_checked_option(bench_cc, "-j,--jobs", bench_options.jobs, "N", within(0, kMaxJobs),
                     "Runs at once; 0 means all cores", "all cores");
  CLI::App* bench_parallel = bench->add_subcommand(
      "parallel",
      "Run one search with -j 1 and with -j 2: wall time of each, the speed-up, and whether "
      "both found the same findings");
  bench_parallel
      ->add_option("SCENARIO", bench_options.scenarios,
                   "Logical scenario, FILE or FILE:SPEC to target one spec (default "
                   "corpora/avunit/pedestrian_step_out.avu:spec1)")
      ->expected(0, 1)
      ->type_name("");
  add_checked_option(bench_parallel, "--budget", bench_options.budget, "N", within(1, kMaxBudget),
                     "Simulations per run", "200");
  bench_parallel->add_option("--algo", bench_algorithm, "Search algorithm (default ga)")
      ->type_name("NAME");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and --version exit 0; every other parse error is a usage error.
    return app.exit(e, out, err) == 0 ? kExitSuccess : kExitUsage;
  }

  if (check->parsed()) return run_check(check_files, err);
  if (space->parsed()) return run_space(space_file, space_json, out, err);
  if (map->parsed()) return run_map(map_options, out, err);
  if (run_command->parsed()) {
    if (!simulation_options_valid(run_options.simulation, err)) return kExitUsage;
    return run_run(run_options, out, err);
  }
  if (stl->parsed()) return run_stl(stl_options, out, err);
  if (convert->parsed()) return run_convert(convert_file, out, err);
  if (bench->parsed()) {
    if (!bench_algorithm.empty()) bench_options.algorithms = {bench_algorithm};
    bench_options.kind = bench_cc->parsed()         ? BenchKind::chasing_cars
                         : bench_parallel->parsed() ? BenchKind::parallel
                                                    : BenchKind::falsification;
    return run_bench(bench_options, out, err);
  }
  if (fuzz_options.path.empty()) {
    err << "scenfuzz: error: name a scenario to search (scenfuzz --budget 500 base.avu) or a "
           "subcommand\nRun with --help for more information.\n";
    return kExitUsage;
  }
  if (!simulation_options_valid(fuzz_options.simulation, err)) return kExitUsage;
  return run_fuzz(fuzz_options, out, err);
}

}  // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  try {
    return run(argc, argv, out, err);
  } catch (const std::exception& e) {
    err << "scenfuzz: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace scenfuzz
