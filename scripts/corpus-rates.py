#!/usr/bin/env python3
"""Violation rates of the corpus seeds at uniformly random points (issue 18, "The corpus and
the measure").

A seed is worth searching only if none of its specs is violated at most random points: a spec
violated almost everywhere says more about its ranges or thresholds than about the driver. For
every seed in corpora/ (not corpora/benchmarks/) this runs

    scenfuzz --algo random --budget 200 --seed 0 -j 2 SEED --out DIR/<seed>

and prints, per seed and spec, the violated count over the judged points, the rate, the
time-outs (a run ended by its duration while the ego still progressed: not a violation), the
stuck runs (violations where the ego had stopped making progress), the start-states (only the
scenario's start state violated the spec: not a violation), the evaluations with an ego
collision, and, from summary.json, how many of the written findings' collisions the
responsibility oracle puts on the ego (ego or shared) or on the other.
Rates above the limit (default 20 %) are marked with '!'.

Usage: scripts/corpus-rates.py [--scenfuzz BIN] [--out DIR] [--map-path DIR] [--budget N]
                               [--jobs N] [--markdown] [SEED_FILE ...]
"""

import argparse
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
SEED_SUFFIXES = (".avu", ".sdl", ".scenest")


def corpus_seeds(corpora: Path) -> list[Path]:
    """Every seed file under corpora/ except the benchmarks (they are not searched for findings)."""
    seeds = []
    for path in sorted(corpora.rglob("*")):
        if path.suffix not in SEED_SUFFIXES or not path.is_file():
            continue
        if "benchmarks" in path.relative_to(corpora).parts:
            continue
        seeds.append(path)
    return seeds


def run_search(args, seed: Path, out: Path) -> None:
    command = [args.scenfuzz, "--algo", "random", "--budget", str(args.budget), "--seed", "0",
               "-j", str(args.jobs), "--quiet", "--force", str(seed), "--out", str(out)]
    for folder in args.map_path:
        command += ["--map-path", folder]
    result = subprocess.run(command, capture_output=True, text=True)
    # Exit 1 means findings; only 2 is an error of the seed or the command.
    if result.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(command)} exited {result.returncode}:\n{result.stderr}")


def parse_endings(text: str) -> dict[str, str]:
    """'reach=time-out;clearance=stuck' -> {'reach': 'time-out', 'clearance': 'stuck'}."""
    endings = {}
    for item in filter(None, text.split(";")):
        spec, _, ending = item.partition("=")
        endings[spec] = ending
    return endings


def count_evaluations(evaluations_csv: Path, specs: list[str]) -> tuple[int, dict, int]:
    """Judged points, per spec {violated, time_outs, stuck, start_states}, and evaluations with a
    collision."""
    judged = 0
    per_spec = {spec: {"violated": 0, "time_outs": 0, "stuck": 0, "start_states": 0}
                for spec in specs}
    collisions = 0
    with evaluations_csv.open(newline="") as handle:
        for row in csv.DictReader(handle):
            if row["status"] != "judged":
                continue
            judged += 1
            endings = parse_endings(row.get("endings", ""))
            # The responsibility of the ego's first collision, '-' without one (docs/search.md).
            if row.get("responsibility", "") not in ("", "-"):
                collisions += 1
            for spec in specs:
                value = row.get(f"robustness.{spec}", "")
                ending = endings.get(spec, "")
                if ending == "time-out":
                    # A time-out is its own verdict, never a violation (docs/search.md).
                    per_spec[spec]["time_outs"] += 1
                elif ending == "start-state":
                    # Only the scenario's start state violated it: not a violation either.
                    per_spec[spec]["start_states"] += 1
                elif value != "" and float(value) < 0:
                    per_spec[spec]["violated"] += 1
                    if ending == "stuck":
                        per_spec[spec]["stuck"] += 1
    return judged, per_spec, collisions


def finding_responsibilities(summary: dict) -> dict[str, int]:
    """The responsibility the oracle gave the collision of each written finding (summary.json's
    per-finding `responsibility`): {'ego': n, 'shared': n, 'other': n}."""
    counts = {"ego": 0, "shared": 0, "other": 0}
    for finding in summary.get("findings", []):
        verdict = finding.get("responsibility")
        if verdict in counts:
            counts[verdict] += 1
    return counts


def measure(args, seed: Path) -> dict:
    name = seed.relative_to(REPO / "corpora").with_suffix("").as_posix().replace("/", "__")
    out = Path(args.out) / name
    run_search(args, seed, out)
    summary = json.loads((out / "summary.json").read_text())
    specs = summary.get("specs", [])
    judged, per_spec, collisions = count_evaluations(out / "evaluations.csv", specs)
    return {"seed": seed.relative_to(REPO / "corpora").as_posix(), "judged": judged,
            "specs": per_spec, "collisions": collisions,
            "responsibility": finding_responsibilities(summary)}


def print_table(results: list[dict], limit: float, markdown: bool) -> None:
    header = ["seed", "spec", "violated", "rate", "time-outs", "stuck", "start-states",
              "collisions",
              "findings' collisions ego/shared/other"]
    rows = []
    for result in results:
        r = result["responsibility"]
        for spec, counts in result["specs"].items():
            rate = counts["violated"] / result["judged"] if result["judged"] else 0.0
            mark = " !" if rate > limit else ""
            rows.append([result["seed"], spec, f"{counts['violated']}/{result['judged']}",
                         f"{100 * rate:.1f} %{mark}", str(counts["time_outs"]),
                         str(counts["stuck"]), str(counts["start_states"]),
                         str(result["collisions"]),
                         f"{r['ego']}/{r['shared']}/{r['other']}"])
    if markdown:
        print("| " + " | ".join(header) + " |")
        print("| --- | --- |" + " ---: |" * (len(header) - 2))
        for row in rows:
            print("| `" + row[0] + "` | `" + row[1] + "` | " + " | ".join(row[2:]) + " |")
        return
    widths = [max(len(row[i]) for row in rows + [header]) for i in range(len(header))]
    for row in [header] + rows:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("seeds", nargs="*", help="seed files (default every seed in corpora/)")
    parser.add_argument("--scenfuzz", default=str(REPO / "build/ci/bin/scenfuzz"))
    parser.add_argument("--out", default="/tmp/corpus-rates", help="folder for the searches")
    parser.add_argument("--map-path", action="append",
                        default=[p for p in [os.environ.get("SCENFUZZ_MAP_PATH")] if p],
                        help="Apollo map folder (default $SCENFUZZ_MAP_PATH)")
    parser.add_argument("--budget", type=int, default=200)
    parser.add_argument("--jobs", "-j", type=int, default=2)
    parser.add_argument("--limit", type=float, default=0.2, help="rate marked with '!'")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args()

    seeds = [Path(s).resolve() for s in args.seeds] or corpus_seeds(REPO / "corpora")
    results = []
    for seed in seeds:
        print(f"measuring {seed.relative_to(REPO)}", file=sys.stderr)
        results.append(measure(args, seed))
    print_table(results, args.limit, args.markdown)
    over = sum(1 for r in results for c in r["specs"].values()
               if r["judged"] and c["violated"] / r["judged"] > args.limit)
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
