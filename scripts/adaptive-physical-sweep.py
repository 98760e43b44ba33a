#!/usr/bin/python3
"""The adaptive loop on the physical lathe (issue 27's first must-show), measured with the trueturn binary.

  scripts/adaptive-physical-sweep.py --trueturn build/app/trueturn [--parts 3000] [--seeds 1 2 3 4 5 6]

For paper-2012-group1..3, z = 1..4 and each seed runs `simulate --parts N --warmup 0 --mismatch-action adapt --json`
and the same with `--mismatch-action alarm` (the fixed LQG, its alarms ignored), and prints per run the model
alarms, whether one came in the last two thirds of the run, the adaptations, and k_eff (over every part) of both.
The summary line counts the runs without an alarm in the last two thirds and those where the adaptive loop's k_eff
is at least the fixed LQG's. About 1 s per run pair on one core.
"""

import argparse
import json
import subprocess
import sys


def simulate(trueturn, group, z, seed, parts, action):
    p = subprocess.run([trueturn, "simulate", "--preset", "paper-2012-group%d" % group, "--delay", str(z), "--parts",
                        str(parts), "--warmup", "0", "--seed", str(seed), "--mismatch-action", action, "--json"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("simulate failed (group %d, z = %d, seed %d, %s): %s" % (group, z, seed, action, p.stderr.strip()))
    return json.loads(p.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trueturn", default="build/app/trueturn")
    ap.add_argument("--parts", type=int, default=3000)
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5, 6])
    args = ap.parse_args()
    runs = quiet = at_least = 0
    for group in (1, 2, 3):
        for z in (1, 2, 3, 4):
            for seed in args.seeds:
                adapt = simulate(args.trueturn, group, z, seed, args.parts, "adapt")
                fixed = simulate(args.trueturn, group, z, seed, args.parts, "alarm")
                late = [a["part"] for a in adapt["alarms"] if a["part"] > args.parts // 3]
                runs += 1
                quiet += 0 if late else 1
                at_least += 1 if adapt["k_eff"] >= fixed["k_eff"] else 0
                print("group %d z %d seed %d: alarms %s, late %d; adaptations %s; k_eff adapt %.2f, fixed LQG %.2f" %
                      (group, z, seed, [a["part"] for a in adapt["alarms"]][:6], len(late),
                       [(a["part"], a["kind"]) for a in adapt["adaptations"]][:6], adapt["k_eff"], fixed["k_eff"]),
                      flush=True)
    print("%d runs: %d without an alarm after part %d, %d with the adaptive k_eff at least the fixed LQG's" %
          (runs, quiet, args.parts // 3, at_least))


if __name__ == "__main__":
    main()
