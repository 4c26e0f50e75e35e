// The command line: subcommands, options and help texts (CLI11), and the mapping to exit codes.
#include "fuzz/cli.hpp"

#include <CLI/CLI.hpp>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_init.hpp"
#include "fuzz/campaign/campaign_report.hpp"
#include "fuzz/campaign/campaign_run.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/corpus_search.hpp"
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

// What a parsed subcommand runs; empty after parsing means the search.
using Action = std::function<int(std::ostream& out, std::ostream& err)>;

void declare_app(CLI::App& app) {
  app.set_version_flag("--version", std::string("scenfuzz ") + SCENFUZZ_VERSION);
  // Without a subcommand, scenfuzz searches: `scenfuzz --budget 500 base.avu`.
  app.require_subcommand(0, 1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("scenfuzz: error: ") + e.what() +
           "\nRun with --help for more information.\n";
  });
  app.footer(
      "Without a subcommand, scenfuzz searches FILE's parameter ranges for points that violate "
      "its specs and writes every finding into --out. Exit status: 0 success (nothing violated "
      "among the judged evaluations), 1 findings (a specification is violated or the ego plugin "
      "crashed, hung or failed; also for run and stl), 2 a bad command line (an option's value "
      "out of its bounds among them), a scenario, map or trace file that cannot be read or has "
      "errors, an output folder that is locked, holds an earlier search or cannot be written, or "
      "a search that could judge nothing.");
}

void declare_search(CLI::App& app, FuzzCommandOptions& options, std::vector<std::string>& entries) {
  app.add_option("FILE", entries,
                 "Scenario to search (AVUnit, scenest or WMG SDL; a concrete one is mutated), or "
                 "several, or folders of them: a corpus, the budget shared evenly")
      ->type_name("");
  add_search_options(&app, options);
}

// Each declare_* adds one subcommand to `app`; once it is parsed, `action` runs it. Its options
// live in a shared_ptr that the action keeps.
void declare_check(CLI::App& app, Action& action) {
  struct CheckOptions {
    std::vector<std::string> files;
    ScenarioChoiceOptions choice;
  };
  auto options = std::make_shared<CheckOptions>();
  CLI::App* check = app.add_subcommand(
      "check", "Parse scenario files and report their errors and warnings (nothing when clean)");
  check->add_option("FILE", options->files, "AVUnit, scenest or WMG SDL (.sdl) scenario files")
      ->required()
      ->type_name("");
  add_scenario_options(check, options->choice);
  check->callback([options, &action] {
    action = [options](std::ostream&, std::ostream& err) {
      return run_check(options->files, options->choice, err);
    };
  });
}

void declare_space(CLI::App& app, Action& action) {
  struct SpaceOptions {
    std::string file;
    bool json = false;
    MutationCommandOptions mutation;
    ScenarioChoiceOptions choice;
  };
  auto options = std::make_shared<SpaceOptions>();
  CLI::App* space = app.add_subcommand(
      "space",
      "Print the parameter space of a scenario: one dimension per range in the file; for a "
      "concrete file, the space the search derives around its values (--mutate)");
  space->add_option("FILE", options->file, "AVUnit, scenest or WMG SDL scenario file")
      ->required()
      ->type_name("");
  space->add_flag("--json", options->json, "Print a JSON document instead of a table");
  add_scenario_options(space, options->choice);
  add_mutation_options(space, options->mutation);
  space->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_space(options->file, options->json, options->mutation, options->choice, out, err);
    };
  });
}

void declare_map(CLI::App& app, Action& action) {
  auto options = std::make_shared<MapCommandOptions>();
  CLI::App* map = app.add_subcommand(
      "map",
      "Summarise a road map (built-in or Apollo HD map), draw it as SVG, or list the "
      "built-in maps");
  map->add_option("MAP", options->name,
                  "A built-in map (crossroads, straight?lanes=3&length=400, ...), the name of an "
                  "Apollo map folder on the map search path (san_francisco), a map file, or a "
                  "scenario file (.avu, .scenest, .sdl): the map it builds at the centre of its "
                  "space, and which arm each road of a WMG scenery became")
      ->type_name("");
  map->add_option("--map-path", options->map_paths,
                  "Folder to look for Apollo maps in (<DIR>/<name>/base_map.bin or .txt); "
                  "repeatable, searched before SCENFUZZ_MAP_PATH and corpora/maps")
      ->type_name("DIR")
      ->allow_extra_args(false);
  map->add_option("--svg", options->svg_path, "Draw the map into this SVG file")->type_name("FILE");
  map->add_flag("--labels", options->labels, "With --svg: write every lane's id on the lane");
  map->add_flag("--json", options->json, "Print JSON (counts, bounds, every lane) instead");
  map->add_flag("--list", options->list, "List the built-in maps and their parameters");
  map->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_map(*options, out, err);
    };
  });
}

void declare_run(CLI::App& app, Action& action) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand(
      "run",
      "Simulate a scenario: print the collisions, whether the ego reached its target and the "
      "robustness of every spec (exit 1 when one is violated or the ego plugin fails); write the "
      "trace (CSV, JSON), a bird's-eye SVG and the concrete scenario");
  run->add_option("FILE", options->path, "AVUnit, scenest or WMG SDL scenario file")
      ->required()
      ->type_name("");
  add_run_options(run, *options);
  run->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      if (!simulation_options_valid(options->simulation, err)) return kExitUsage;
      return run_run(*options, out, err);
    };
  });
}

void declare_reconstruct(CLI::App& app, Action& action) {
  auto options = std::make_shared<ReconstructCommandOptions>();
  CLI::App* reconstruct = app.add_subcommand(
      "reconstruct",
      "Reconstruct an accident description (.acc): search its unknowns (speeds, start distances, "
      "event timings) for a run in which the described collisions happen as described; write it "
      "as a replayable AVUnit scenario with the ego in the victim's place, its trace and picture "
      "(exit 1 when the budget ran out first: the closest run is written)");
  reconstruct->add_option("FILE", options->path, "accident description (.acc)")
      ->required()
      ->type_name("");
  add_reconstruct_options(reconstruct, *options);
  reconstruct->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      if (!simulation_options_valid(options->simulation, err)) return kExitUsage;
      return run_reconstruct(*options, out, err);
    };
  });
}

void declare_stl(CLI::App& app, Action& action) {
  auto options = std::make_shared<StlCommandOptions>();
  CLI::App* stl = app.add_subcommand(
      "stl",
      "Evaluate an STL formula on a CSV log: print its robustness at the first sample (or at "
      "every sample with --signal); exit 0 when satisfied, 1 when violated");
  stl->add_option("--spec", options->spec,
                  "The formula, in AVUnit's syntax; its names are the log's columns: "
                  "'G[0:5](x > 0.5 & F[0:2](y < 0.1))'")
      ->required()
      ->type_name("FORMULA");
  stl->add_option("--trace", options->trace_path,
                  "CSV log: a header row naming the columns, one of them 'time' (seconds, "
                  "strictly increasing), then one row of numbers per sample")
      ->required()
      ->type_name("FILE.csv");
  stl->add_flag("--signal", options->signal,
                "Print the robustness at every sample as CSV (time,robustness)");
  stl->footer(
      "Prints the robustness as a plain number (inf and -inf for infinities); for a violated "
      "formula, a note on stderr names the atom responsible and the time. Exit status: 0 "
      "satisfied (robustness >= 0), 1 violated (< 0), 2 a bad command line, or a formula or "
      "log that cannot be read or has errors.");
  stl->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_stl(*options, out, err);
    };
  });
}

void declare_convert(CLI::App& app, Action& action) {
  auto file = std::make_shared<std::string>();
  CLI::App* convert = app.add_subcommand(
      "convert",
      "Print a WMG SDL file as level 2: a level-1 file converted (every qualitative word "
      "becomes its default range), a level-2 file printed canonically");
  // One target language so far: the option is there so that scripts name it.
  convert->add_option("--to", "The language to write: sdl2 (WMG SDL level 2)")
      ->required()
      ->check(CLI::IsMember({"sdl2"}))
      ->type_name("sdl2");
  convert->add_option("FILE", *file, "WMG SDL file (.sdl, level 1 or 2)")
      ->required()
      ->type_name("");
  convert->callback([file, &action] {
    action = [file](std::ostream& out, std::ostream& err) { return run_convert(*file, out, err); };
  });
}

void declare_tmin(CLI::App& app, Action& action) {
  auto options = std::make_shared<TminCommandOptions>();
  CLI::App* tmin = app.add_subcommand(
      "tmin",
      "Minimise a failing scenario while the same failure mode persists: remove actors, "
      "waypoints and obstacles, neutral weather and noon, fewer digits, a shorter run");
  tmin->add_option("FINDING", options->path,
                   "A finding the search wrote (replayed with its header's seed and options), or "
                   "a concrete scenario (replayed as 'scenfuzz run' does)")
      ->required()
      ->type_name("");
  tmin->add_option("-o,--out", options->out_path,
                   "Write the minimised scenario (in FINDING's language) here (default "
                   "FINDING's folder, <name>.min.avu or <name>.min.sdl)")
      ->type_name("FILE");
  tmin->footer(
      "Exit status: 0 written; 2 a file that cannot be read, is not a concrete scenario, or no "
      "longer fails the same way when replayed. docs/search.md describes the steps.");
  tmin->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_tmin(*options, out, err);
    };
  });
}

void declare_coverage(CLI::App& app, Action& action) {
  auto options = std::make_shared<CoverageCommandOptions>();
  CLI::App* coverage = app.add_subcommand(
      "coverage",
      "Print the behaviour-coverage features a corpus covers (manoeuvres, road features, "
      "interactions, weather and light, law sub-violations; docs/coverage.md) and which seeds "
      "cover each");
  coverage
      ->add_option("FILE", options->paths,
                   "Seed scenario files (.avu, .scenest, .sdl) and folders of them")
      ->required()
      ->type_name("");
  coverage->add_flag("--json", options->json, "Print a JSON document instead of tables");
  add_corpus_options(coverage, *options);
  coverage->footer(
      "A concrete seed is one simulation; a logical seed (with ranges) is simulated at the centre "
      "of its space and 8 points of a scrambled Halton sequence. Seeds that cannot be covered are "
      "listed with their errors. The output is the same for any -j. Exit status: 0 when at least "
      "one seed was covered, 2 when none could be (or a bad command line).");
  coverage->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      if (!simulation_options_valid(options->simulation, err)) return kExitUsage;
      return run_coverage(*options, out, err);
    };
  });
}

void declare_cmin(CLI::App& app, Action& action) {
  auto options = std::make_shared<CminCommandOptions>();
  CLI::App* cmin = app.add_subcommand(
      "cmin",
      "Minimise a seed corpus: copy the smallest subset of seeds that keeps its behaviour "
      "coverage (docs/corpus.md)");
  cmin->add_option("IN", options->inputs, "Seed scenario files and folders of them")
      ->required()
      ->type_name("");
  cmin->add_option("-o,--output", options->out_dir,
                   "Output folder: new, empty, or an earlier cmin's (which it resumes)")
      ->required()
      ->type_name("DIR");
  add_corpus_options(cmin, *options);
  cmin->footer(
      "Kept seeds are copied unchanged into DIR with cmin.json saying what each covers and why "
      "each dropped seed was dropped; DIR/cmin.control lets a killed run resume. Exit status: 0 "
      "success; 2 a bad command line, a DIR that cannot be used, no seed that could be covered, "
      "or an interruption (rerun to resume).");
  cmin->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      if (!simulation_options_valid(options->simulation, err)) return kExitUsage;
      return run_cmin(*options, out, err);
    };
  });
}

// `bench`'s options, shared by its three subcommands.
struct BenchLine {
  BenchCommandOptions options;
  std::string algorithm;  // cc, parallel: --algo
};

void declare_bench_falsification(CLI::App& bench, BenchLine& line) {
  CLI::App* falsification = bench.add_subcommand(
      "falsification",
      "For each scenario and algorithm, search with seeds 1..N: median simulations to the first "
      "finding, findings per 500 simulations, and random's median over ga's");
  BenchCommandOptions& options = line.options;
  falsification
      ->add_option("SCENARIO", options.scenarios,
                   "Logical scenarios, FILE or FILE:SPEC to target one spec (default: five "
                   "bundled ones in corpora/, run from the repository's root)")
      ->type_name("");
  add_checked_option(falsification, "--seeds", options.seeds, "N", within(1, kMaxBudget),
                     "Runs per algorithm", "20");
  add_checked_option(falsification, "--budget", options.budget, "N", within(1, kMaxBudget),
                     "Simulations per run", "500");
  falsification->add_flag(
      "--first-only", options.first_finding_only,
      "Stop each run at its first finding: the same first-finding medians in a fraction of the "
      "time, for many seeds (findings per 500 are then not measured)");
  falsification
      ->add_option("--algos", options.algorithms,
                   "Comma-separated algorithms as for --algo (default "
                   "ga,nlopt:LN_COBYLA,halton,random)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->type_name("LIST");
  add_checked_option(falsification, "-j,--jobs", options.jobs, "N", within(0, kMaxJobs),
                     "Searches run at once, one thread each; 0 means all cores", "all cores");
  falsification->callback([&line] { line.options.kind = BenchKind::falsification; });
}

void declare_bench_cc(CLI::App& bench, BenchLine& line) {
  CLI::App* cc = bench.add_subcommand(
      "cc",
      "ARCH-COMP chasing cars under the competition's protocol: per requirement, runs that stop "
      "at the first falsifying simulation; FR and mean/median simulations beside the published "
      "figures");
  BenchCommandOptions& options = line.options;
  add_checked_option(cc, "--runs", options.runs, "N", within(1, kMaxBudget),
                     "Runs per requirement, seeds 1..N", "10");
  add_checked_option(cc, "--budget", options.budget, "N", within(1, kMaxBudget),
                     "Simulations per run at most", "1500");
  cc->add_option("--algo", line.algorithm, "Search algorithm, as for --algo (default ga)")
      ->type_name("NAME");
  cc->add_option("--requirements", options.requirements,
                 "Comma-separated requirements (default CC1,CC2,CC3,CC4,CC5,CCx)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"CC1", "CC2", "CC3", "CC4", "CC5", "CCx"}))
      ->type_name("LIST");
  add_checked_option(cc, "--segments", options.segments, "N", within(1, 20),
                     "Piecewise-constant segments of u1 and u2 over the 100 s (jumps at least "
                     "5 s apart; 20 segments are 40 dimensions)",
                     "20");
  add_checked_option(cc, "-j,--jobs", options.jobs, "N", within(0, kMaxJobs),
                     "Runs at once; 0 means all cores", "all cores");
  cc->callback([&line] { line.options.kind = BenchKind::chasing_cars; });
}

void declare_bench_parallel(CLI::App& bench, BenchLine& line) {
  CLI::App* parallel = bench.add_subcommand(
      "parallel",
      "Run one search with -j 1 and with -j 2: wall time of each, the speed-up, and whether "
      "both found the same findings");
  parallel
      ->add_option("SCENARIO", line.options.scenarios,
                   "Logical scenario, FILE or FILE:SPEC to target one spec (default "
                   "corpora/avunit/pedestrian_step_out.avu:spec1)")
      ->expected(0, 1)
      ->type_name("");
  add_checked_option(parallel, "--budget", line.options.budget, "N", within(1, kMaxBudget),
                     "Simulations per run", "200");
  parallel->add_option("--algo", line.algorithm, "Search algorithm (default ga)")
      ->type_name("NAME");
  parallel->callback([&line] { line.options.kind = BenchKind::parallel; });
}

void declare_bench(CLI::App& app, Action& action) {
  auto line = std::make_shared<BenchLine>();
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Measure the search: strategies on bundled scenarios, the ARCH-COMP chasing-cars "
      "benchmark, the speed-up of parallel evaluation; prints tables");
  bench->require_subcommand(1);
  bench->footer(
      "Results depend only on the seeds, never on -j; figures and how they were measured: "
      "docs/performance.md.");
  declare_bench_falsification(*bench, *line);
  declare_bench_cc(*bench, *line);
  declare_bench_parallel(*bench, *line);
  // The bench's own callback runs after its subcommand's.
  bench->callback([line, &action] {
    action = [line](std::ostream& out, std::ostream& err) {
      BenchCommandOptions options = line->options;
      if (!line->algorithm.empty()) options.algorithms = {line->algorithm};
      return run_bench(options, out, err);
    };
  });
}

void declare_campaign_report(CLI::App& campaign, Action& action) {
  auto options = std::make_shared<CampaignReportOptions>();
  CLI::App* report = campaign.add_subcommand(
      "report",
      "Write the campaign's static HTML report: new, regressed, still failing, flaky and fixed "
      "failure modes with their pictures and replay commands, per seed the best robustness "
      "against simulations, the trend across runs (readable while a run runs)");
  report->add_option("DIR", options->dir, "The campaign folder")->required()->type_name("");
  report->add_option("--out", options->out, "Write the report here (default DIR/report.html)")
      ->type_name("FILE");
  report->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_campaign_report(*options, out, err);
    };
  });
}

void declare_campaign_run(CLI::App& campaign, Action& action) {
  auto options = std::make_shared<CampaignRunOptions>();
  CLI::App* run = campaign.add_subcommand(
      "run",
      "Run the campaign: replay its known failure modes, then search its seeds x specs in rounds "
      "until the budget is spent; a killed or interrupted run is continued by the next one. Exit "
      "1 when the run found a new failure mode or a regression");
  run->add_option("DIR", options->dir, "The campaign folder (with campaign.toml)")
      ->required()
      ->type_name("");
  add_checked_option(run, "-j,--jobs", options->jobs, "N", within(0, kMaxJobs),
                     "Searches at once (overrides [search] jobs); 0 means all cores",
                     "[search] jobs");
  run->add_option("--junit", options->junit,
                  "Also write the run as JUnit XML for CI: one test case per failure mode "
                  "(new, still failing, flaky, regressed: failures; fixed: passes)")
      ->type_name("FILE");
  run->add_flag("--json", options->json,
                "Print the run's summary as JSON, one line on stdout; progress goes to stderr");
  add_checked_option(run, "--worker-timeout", options->worker_timeout, "SECONDS", positive(86400),
                     "Under mpirun: seconds a worker rank may stay silent (it sends a heartbeat "
                     "every second) before its search goes to another",
                     "");
  run->footer(
      "Exit status: 0 no new failure mode and no regression; 1 a new failure mode or a "
      "regression; 2 errors. docs/campaigns.md describes the run and its outputs.");
  run->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_campaign(*options, out, err);
    };
  });
}

void declare_campaign(CLI::App& app, Action& action) {
  auto options = std::make_shared<CampaignInitOptions>();
  CLI::App* campaign = app.add_subcommand(
      "campaign",
      "Nightly falsification campaigns: a folder with campaign.toml (seeds, ego, budget, search "
      "options) and the campaign's database");
  campaign->require_subcommand(1);
  campaign->footer("docs/campaigns.md describes campaign.toml and the database.");
  CLI::App* init = campaign->add_subcommand(
      "init",
      "Start a campaign folder: write DIR/campaign.toml, commented, listing FILES as its seeds "
      "(never overwrites an existing one)");
  init->add_option("DIR", options->dir, "The campaign folder, created if missing")
      ->required()
      ->type_name("");
  init->add_option("FILES", options->files,
                   "Seed scenario files (.avu, .scenest, .sdl) and folders of them")
      ->required()
      ->type_name("");
  init->callback([options, &action] {
    action = [options](std::ostream& out, std::ostream& err) {
      return run_campaign_init(*options, out, err);
    };
  });
  declare_campaign_report(*campaign, action);
  declare_campaign_run(*campaign, action);
}

int run_search_command(FuzzCommandOptions& options, const std::vector<std::string>& entries,
                       std::ostream& out, std::ostream& err) {
  if (entries.empty()) {
    err << "scenfuzz: error: name a scenario to search (scenfuzz --budget 500 base.avu) or a "
           "subcommand\nRun with --help for more information.\n";
    return kExitUsage;
  }
  if (!simulation_options_valid(options.simulation, err)) return kExitUsage;
  if (is_corpus_search(entries)) return run_corpus_search(options, entries, out, err);
  options.path = entries.front();
  return run_fuzz(options, out, err);
}

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "scenfuzz searches the parameter space of a driving scenario for concrete scenarios in "
      "which the automated driving system under test violates its specification.",
      "scenfuzz"};
  declare_app(app);
  FuzzCommandOptions search;
  std::vector<std::string> search_entries;
  declare_search(app, search, search_entries);
  Action action;
  for (void (*declare)(CLI::App&, Action&) :
       {declare_check, declare_space, declare_map, declare_run, declare_reconstruct, declare_stl,
        declare_convert, declare_tmin, declare_coverage, declare_cmin, declare_bench,
        declare_campaign})
    declare(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and --version exit 0; every other parse error is a usage error.
    return app.exit(e, out, err) == 0 ? kExitSuccess : kExitUsage;
  }
  return action ? action(out, err) : run_search_command(search, search_entries, out, err);
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
