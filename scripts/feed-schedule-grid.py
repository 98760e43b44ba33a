#!/usr/bin/python3
"""The feed schedule of paper 004 over the whole grid the product must hold: does the scheduled pass stay
within +-10 % of Yc on the simulator at every depth, level and feed step, for every experiment seed?

  scripts/feed-schedule-grid.py --trueturn build/app/trueturn [--seeds 1-8] [--work DIR]

For each seed: `deformation-experiment --preset feed-scheduling --seed S`, `fit-deformation --stepwise`.
For each cell (depth 0.5, 0.75, 1.0, 1.5, 2.0 mm x level fraction 0, 0.5, 1 x feed step 0.005, 0.01 mm/rev
x seed), the preset's pass (fmin 0.05, fmax 0.4 mm/rev, z 380 -> 60 mm, L_min 5 mm):
  - as the paper schedules it: `schedule-feed ... --verify` (switch at the level, the model alone);
  - as TrueTurn holds it: `schedule-feed ... --switch centred --verify --refine --experiment exp.csv`.
Prints a Markdown table (worst deviation over the seeds per cell, rounds and bars of the refinement) for
docs/BENCHMARKS.md and exits 1 when a refined cell misses the band. About 480 runs of trueturn.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

DEPTHS = [0.5, 0.75, 1.0, 1.5, 2.0]
LEVELS = [0.0, 0.5, 1.0]
STEPS = [0.005, 0.01]


def run(trueturn, args, allowed=(0,)):
    p = subprocess.run([trueturn] + args, capture_output=True, text=True)
    if p.returncode not in allowed:
        sys.exit("trueturn %s: exit %d: %s" % (" ".join(args), p.returncode, p.stderr.strip()))
    return json.loads(p.stdout) if "--json" in args else None


def seeds_of(text):
    lo, _, hi = text.partition("-")
    return list(range(int(lo), int(hi or lo) + 1))


def schedule(trueturn, model, depth, q, step, extra):
    args = ["schedule-feed", "--model", model, "--depth", str(depth), "--feed-min", "0.05", "--feed-max", "0.4",
            "--feed-step", str(step), "--z-start", "380", "--z-end", "60", "--level-fraction", str(q),
            "--min-length", "5", "--verify", "--json"] + extra
    return run(trueturn, args, allowed=(0, 3))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trueturn", required=True)
    parser.add_argument("--seeds", default="1-8")
    parser.add_argument("--work")
    a = parser.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="feed-grid-")
    started = time.time()
    cells = {}
    for seed in seeds_of(a.seeds):
        csv = os.path.join(work, "exp%d.csv" % seed)
        model = os.path.join(work, "model%d.json" % seed)
        run(a.trueturn, ["deformation-experiment", "--preset", "feed-scheduling", "--seed", str(seed), "--csv", csv])
        run(a.trueturn, ["fit-deformation", csv, "--stepwise", "--out", model, "--json"])
        for depth in DEPTHS:
            for q in LEVELS:
                for step in STEPS:
                    paper = schedule(a.trueturn, model, depth, q, step, [])
                    held = schedule(a.trueturn, model, depth, q, step,
                                    ["--switch", "centred", "--refine", "--experiment", csv])
                    r = held.get("refine", {})
                    cells.setdefault((depth, q, step), []).append(
                        (seed, paper["verify"]["max_deviation_pct"], held["verify"]["max_deviation_pct"],
                         r.get("rounds_run", 0), r.get("bars", 0)))
    misses = 0
    print("| a, mm | Q | f_mm, mm/rev | paper's rule, model alone: worst over seeds | TrueTurn (centred, refined): "
          "worst over seeds | refined seeds | rounds (max) | bars (min .. max) |")
    print("|---|---|---|---|---|---|---|---|")
    for (depth, q, step), rows in sorted(cells.items()):
        paper = max(rows, key=lambda r: r[1])
        held = max(rows, key=lambda r: r[2])
        misses += sum(1 for r in rows if r[2] > 10.0)
        refined = [r for r in rows if r[3] > 0]
        bars = [r[4] for r in refined] or [0]
        print("| %g | %g | %g | %.1f %% (seed %d) | %.1f %% (seed %d) | %d of %d | %d | %d .. %d |" %
              (depth, q, step, paper[1], paper[0], held[2], held[0], len(refined), len(rows),
               max(r[3] for r in rows), min(bars), max(bars)))
    total = sum(len(r) for r in cells.values())
    paper_misses = sum(1 for rows in cells.values() for r in rows if r[1] > 10.0)
    print()
    print("%d cells: the paper's rule with the model alone misses +-10 %% in %d; TrueTurn misses in %d (%.0f s)." %
          (total, paper_misses, misses, time.time() - started))
    return 1 if misses else 0


if __name__ == "__main__":
    sys.exit(main())
