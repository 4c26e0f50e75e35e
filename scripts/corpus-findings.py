#!/usr/bin/env python3
"""What a search of every corpus seed reports (issue 18, "The corpus and the measure").

For every seed in corpora/ (not corpora/benchmarks/) this runs the search a user runs,

    scenfuzz --budget 300 --seed 0 -j 2 SEED --out DIR/<seed>

and prints per seed the findings written (one per failure mode), the violating evaluations they
stand for, the findings by the responsibility of their collision (ego, shared, other, none: no
collision), the time-outs, the simulations whose first ego collision was not the ego's fault,
and the start-states (evaluations of a spec only the scenario's start state violated); then the
totals and the share of findings the ego is responsible for (ego or shared, and findings without
a collision, which violate a spec of the ego's own driving). Each finding's
file is listed with --list, to read by hand.

Usage: scripts/corpus-findings.py [--scenfuzz BIN] [--out DIR] [--map-path DIR] [--budget N]
                                  [--jobs N] [--list] [SEED_FILE ...]
"""

import argparse
import json
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
SEED_SUFFIXES = (".avu", ".sdl", ".scenest")
KINDS = ("ego", "shared", "other", "none")


def corpus_seeds(corpora: Path) -> list[Path]:
    return [path for path in sorted(corpora.rglob("*"))
            if path.is_file() and path.suffix in SEED_SUFFIXES
            and "benchmarks" not in path.relative_to(corpora).parts]


def search(args, seed: Path, out: Path) -> dict:
    command = [args.scenfuzz, "--budget", str(args.budget), "--seed", "0", "-j", str(args.jobs),
               "--quiet", "--force", str(seed), "--out", str(out)]
    for folder in args.map_path:
        command += ["--map-path", folder]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode not in (0, 1):  # 1: findings; 2: an error of the seed or command
        raise RuntimeError(f"{' '.join(command)} exited {result.returncode}:\n{result.stderr}")
    return json.loads((out / "summary.json").read_text())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenfuzz", default=str(REPO / "build/ci/bin/scenfuzz"))
    parser.add_argument("--out", default="/tmp/corpus-findings")
    parser.add_argument("--map-path", action="append", default=[])
    parser.add_argument("--budget", type=int, default=300)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--list", action="store_true", help="list every finding's file and mode")
    parser.add_argument("seeds", nargs="*", type=Path)
    args = parser.parse_args()
    seeds = args.seeds or corpus_seeds(REPO / "corpora")

    totals = dict.fromkeys(KINDS, 0)
    total_findings = total_evaluations = total_time_outs = total_not_egos = total_starts = 0
    print(f"{'seed':42} {'findings':>8} {'evals':>6} " +
          " ".join(f"{k:>6}" for k in KINDS) + f" {'t-outs':>6} {'coll.other':>10} {'starts':>6}")
    for seed in seeds:
        summary = search(args, seed, Path(args.out) / seed.stem)
        findings = summary["findings"]
        kinds = dict.fromkeys(KINDS, 0)
        for finding in findings:
            kinds[finding.get("responsibility", "none")] += 1
        evaluations = summary["failure_modes"]["evaluations"]
        time_outs = sum(summary.get("time_outs", {}).values()) \
            if isinstance(summary.get("time_outs"), dict) else 0
        starts = sum(summary.get("start_state", {}).values()) \
            if isinstance(summary.get("start_state"), dict) else 0
        not_egos = summary["ego_collisions"]["other"]
        print(f"{seed.stem:42} {len(findings):8} {evaluations:6} " +
              " ".join(f"{kinds[k]:6}" for k in KINDS) + f" {time_outs:6} {not_egos:10}"
              f" {starts:6}")
        if args.list:
            for finding in findings:
                print(f"    {finding.get('file', '-')}: {finding['mode']}")
        for k in KINDS:
            totals[k] += kinds[k]
        total_findings += len(findings)
        total_evaluations += evaluations
        total_time_outs += time_outs
        total_not_egos += not_egos
        total_starts += starts
    print(f"{'total':42} {total_findings:8} {total_evaluations:6} " +
          " ".join(f"{totals[k]:6}" for k in KINDS) + f" {total_time_outs:6} {total_not_egos:10}"
          f" {total_starts:6}")
    if total_findings:
        egos = totals["ego"] + totals["shared"] + totals["none"]
        collisions = totals["ego"] + totals["shared"] + totals["other"]
        print(f"findings the ego is responsible for (ego, shared or no collision): {egos} of "
              f"{total_findings} ({100 * egos / total_findings:.0f} %)")
        if collisions:
            print(f"of the findings with a collision, the ego's or shared: "
                  f"{totals['ego'] + totals['shared']} of {collisions} "
                  f"({100 * (totals['ego'] + totals['shared']) / collisions:.0f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
