#!/usr/bin/python3
"""Runs the drift grid of the corrective pulse (paper 002) on the trueturn binary and prints it as a table.

  scripts/corner-drift-grid.py --trueturn build/app/trueturn [--preset NAME|FILE.json] [--seeds 3 7]
                              [--drifts 0.5 0.75 1.5 2 2.5 3] [--kinds friction gain inertia] [--axis z|x]
                              [--jobs N]

Trains the network once on the preset (`corner train --preset P --seed 1`), then for every drift kind (friction, gain, inertia),
factor and work seed runs `corner --net NET --seed S --moves 80 --drift F --drift-kind K --json` twice:
with retraining and with `--no-retrain` (the network kept). The drift starts at move 40 on the drive of
--axis (default Z).
Prints one Markdown row per run: the exit code, the change of the mean trajectory error by the pulse over
the moves after the first retraining with the retrained network and, over the same moves, with the kept
one (the paper's -69 % is a change of -69 %), the retrainings accepted and refused, and the monitor's
difference over its last full window after the last retraining against its threshold. Exits 1 when a run does
not exit 0. --jobs runs that many drifts at once (the rows keep their order). About 3 s per run with retraining on an idle core (the training 2 s once).
"""

import argparse
import concurrent.futures
import json
import subprocess
import sys
import tempfile
from pathlib import Path


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr.strip()


def reduction(moves, first):
    without = sum(m["error_without_mm"] for m in moves[first:])
    with_ = sum(m["error_with_mm"] for m in moves[first:])
    return 100.0 * (1.0 - with_ / without) if without > 0 else 0.0


def grid_row(args, net, kind, drift, seed):
    """One drift with retraining and with the network kept: (ran, Markdown row)."""
    base = [args.trueturn, "corner", "--preset", args.preset, "--net", net, "--seed", str(seed), "--moves",
            str(args.moves), "--drift", str(drift), "--drift-kind", kind, "--drift-axis", args.axis, "--json"]
    rc, out, err = run(base)
    rc_kept, out_kept, err_kept = run(base + ["--no-retrain"])
    label = f"| {args.axis.upper()} {kind} | {drift:g} | {seed}"
    if rc != 0 or rc_kept != 0:
        return False, f"{label} | {rc}/{rc_kept} | {err or err_kept} | | | |"
    j = json.loads(out)
    kept = json.loads(out_kept)
    events = j["retrain_events"]
    accepted = sum(1 for e in events if e["accepted"])
    if events:
        first = events[0]["move"] + 1
        retrained = f"{-reduction(j['moves'], first):+.1f} %"
        kept_text = f"{-reduction(kept['moves'], first):+.1f} %"
    else:
        retrained = kept_text = "no retraining"
    monitor = j["monitor"]
    last = monitor["last_difference_pct"]
    last_text = "—" if last is None else f"{last:+.1f} % (threshold {monitor['threshold_pct']:g} %)"
    return True, f"{label} | 0 | {retrained} | {kept_text} | {accepted} / {len(events) - accepted} | {last_text} |"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trueturn", default="build/app/trueturn")
    ap.add_argument("--seeds", type=int, nargs="+", default=[3, 7])
    ap.add_argument("--drifts", type=float, nargs="+", default=[0.5, 0.75, 1.5, 2.0, 2.5, 3.0])
    ap.add_argument("--kinds", nargs="+", default=["friction", "gain", "inertia"])
    ap.add_argument("--axis", choices=["x", "z"], default="z")
    ap.add_argument("--moves", type=int, default=80)
    ap.add_argument("--preset", default="1v340-feed-drives")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        net = str(Path(tmp) / "net.json")
        rc, _, err = run([args.trueturn, "corner", "train", "--preset", args.preset, "--seed", "1", "--out", net,
                          "--json"])
        if rc != 0:
            sys.exit(f"corner train failed: {err}")
        print("| kind | drift | seed | exit | error change, retrained | error change, kept | accepted / refused "
              "| monitor's last difference |")
        print("|---|---|---|---|---|---|---|---|")
        cases = [(kind, drift, seed) for kind in args.kinds for drift in args.drifts for seed in args.seeds]
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            rows = pool.map(lambda case: grid_row(args, net, *case), cases)
            failures = 0
            for ok, row in rows:
                failures += 0 if ok else 1
                print(row, flush=True)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
