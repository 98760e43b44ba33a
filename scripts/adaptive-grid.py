#!/usr/bin/python3
"""The adaptive loop's grids (issue "Adaptive control"), run with the real `trueturn` binary; figures in
docs/DECISIONS.md ("The adaptive run-to-run loop") and README.md.

  scripts/adaptive-grid.py --trueturn build/app/trueturn physical      [--seeds 6] [--jobs 2]
  scripts/adaptive-grid.py --trueturn build/app/trueturn mismatch      [--seeds 1]
  scripts/adaptive-grid.py --trueturn build/app/trueturn matching      [--parts 20000]

physical: paper-2012-group1..3, z = 1..4, seeds 1..6, 3,000 parts (1,000 machined first, the last 2,000 counted),
  the mismatch action adapt (the product's default; given explicitly, as the physical presets' own is alarm). Per run: a mismatch alarm in the last 2,000 parts or not, and k_eff of
  the last 2,000 parts against the fixed LQG (the same run with --mismatch-action alarm) and the best EWMA (the larger
  of `--ewma-weight auto` and the weights 0.1, 0.2, .., 1.0 simulated on the same seed). Passes when >= 90 % of the
  runs have no alarm in the last 2,000 parts and k_eff >= both.
mismatch: paper-2012, z = 1..4, plant delay z + 1, plant gain 0.5 and 2, 3,000 parts (the last 1,000 counted).
  Passes when no run is unstable (every correction inside its limits, k_eff of the last 1,000 parts > 1), each
  adapted within 300 parts of its first alarm, and k_eff of the last 1,000 parts within 15 % of the analytic k_eff
  of the LQG designed for the true plant (the product's own closed-loop Lyapunov analysis of that design:
  `simulate --json` plant.lqg_k_eff_analytic).
matching: paper-2012, z = 1..4, 20,000 parts: no alarm, no adaptation.

Exits 1 when a grid misses its criterion. Prints one line per run and a summary; --json FILE writes every figure.
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys


def simulate(trueturn, args):
    out = subprocess.run([trueturn, "simulate", "--json"] + args, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError("trueturn simulate %s: %s" % (" ".join(args), out.stderr.strip()))
    return json.loads(out.stdout)


def mismatch_alarms(result):
    return [a for a in result.get("alarms", []) if a["kind"] == "model_mismatch"]


def physical_run(trueturn, preset, z, seed, ewma_grid):
    common = ["--preset", preset, "--delay", str(z), "--seed", str(seed), "--parts", "2000", "--warmup", "1000"]
    adaptive = simulate(trueturn, common + ["--mismatch-action", "adapt"])
    fixed = simulate(trueturn, common + ["--mismatch-action", "alarm"])
    ewma = [simulate(trueturn, common + ["--controller", "ewma", "--ewma-weight", "auto"])]
    for w in ewma_grid:
        ewma.append(simulate(trueturn, common + ["--controller", "ewma", "--ewma-weight", "%.2f" % w]))
    best = max(ewma, key=lambda r: r["k_eff"])
    late = [a for a in mismatch_alarms(adaptive) if a["part"] > 1000]
    return {
        "preset": preset, "z": z, "seed": seed,
        "k_eff": adaptive["k_eff"], "k_eff_fixed_lqg": fixed["k_eff"],
        "k_eff_best_ewma": best["k_eff"], "best_ewma_weight": best.get("ewma_weight"),
        "alarms": [a["part"] for a in mismatch_alarms(adaptive)], "alarm_in_last_2000": bool(late),
        "adaptations": [(a["kind"], a["part"]) for a in adaptive["adaptations"]],
        "max_switch_step_mm": adaptive["corrections"]["max_switch_step_mm"],
        "limit_step_mm": adaptive["corrections"]["limit_step_mm"],
    }


def mismatch_run(trueturn, z, kind, seed):
    common = ["--preset", "paper-2012", "--delay", str(z), "--seed", str(seed), "--parts", "1000", "--warmup", "2000"]
    extra = ["--plant-delay", str(z + 1)] if kind == "delay" else ["--plant-gain", kind]
    result = simulate(trueturn, common + extra)
    k_true = result["plant"]["lqg_k_eff_analytic"]
    alarms = mismatch_alarms(result)
    adapted = [a for a in result["adaptations"] if a["kind"] == "adapted"]
    c = result["corrections"]
    first_alarm = alarms[0]["part"] if alarms else None
    return {
        "z": z, "mismatch": kind, "seed": seed, "k_eff": result["k_eff"], "k_eff_true_lqg_analytic": k_true,
        "ratio": result["k_eff"] / k_true if result["k_eff"] else None,
        "first_alarm": first_alarm, "adapted_at": adapted[0]["part"] if adapted else None,
        "adapted_after": adapted[0]["part"] - first_alarm if adapted and first_alarm else None,
        "identified_delay": adapted[-1]["model_after"]["delay"] if adapted else None,
        "identified_gain": adapted[-1]["model_after"]["gain"] if adapted else None,
        "max_abs_mm": c["max_abs_mm"], "limit_abs_mm": c["limit_abs_mm"],
        "max_switch_step_mm": c["max_switch_step_mm"], "limit_step_mm": c["limit_step_mm"],
        "alarms": [a["part"] for a in alarms],
    }


def run_grid(jobs, tasks):
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(lambda t: t[0](*t[1:]), tasks))


def physical(args):
    grid = [round(0.1 * k, 2) for k in range(1, 11)] if args.ewma_grid else []
    tasks = [(physical_run, args.trueturn, "paper-2012-group%d" % g, z, s, grid)
             for g in (1, 2, 3) for z in (1, 2, 3, 4) for s in range(1, args.seeds + 1)]
    rows = run_grid(args.jobs, tasks)
    quiet = sum(1 for r in rows if not r["alarm_in_last_2000"])
    better = sum(1 for r in rows if r["k_eff"] >= max(r["k_eff_fixed_lqg"], r["k_eff_best_ewma"]))
    both = sum(1 for r in rows if not r["alarm_in_last_2000"]
               and r["k_eff"] >= max(r["k_eff_fixed_lqg"], r["k_eff_best_ewma"]))
    bumpless = all(r["max_switch_step_mm"] <= r["limit_step_mm"] for r in rows)
    for r in rows:
        print("%-18s z=%d seed=%d  k_eff %.3f  fixed LQG %.3f  best EWMA %.3f (w %s)  alarms %s  adaptations %s"
              % (r["preset"], r["z"], r["seed"], r["k_eff"], r["k_eff_fixed_lqg"], r["k_eff_best_ewma"],
                 r["best_ewma_weight"], r["alarms"], r["adaptations"]))
    n = len(rows)
    print("runs %d: no alarm in the last 2000 parts %d (%.0f %%); k_eff >= max(fixed LQG, best EWMA) %d (%.0f %%); "
          "both %d (%.0f %%); switches bumpless: %s"
          % (n, quiet, 100.0 * quiet / n, better, 100.0 * better / n, both, 100.0 * both / n, bumpless))
    ok = quiet >= 0.9 * n and better >= 0.9 * n and bumpless
    return rows, ok


def mismatch(args):
    tasks = [(mismatch_run, args.trueturn, z, kind, s)
             for z in (1, 2, 3, 4) for kind in ("delay", "0.5", "2") for s in range(1, args.seeds + 1)]
    rows = run_grid(args.jobs, tasks)
    ok = True
    for r in rows:
        stable = r["max_abs_mm"] < r["limit_abs_mm"] and r["k_eff"] and r["k_eff"] > 1.0
        fast = r["adapted_after"] is not None and r["adapted_after"] <= 300
        close = r["ratio"] is not None and abs(r["ratio"] - 1.0) <= 0.15
        bumpless = r["max_switch_step_mm"] <= r["limit_step_mm"]
        ok = ok and stable and fast and close and bumpless
        print("z=%d %-5s seed=%d  k_eff %.3f  true-plant LQG %.3f (ratio %.3f)  alarm %s  adapted %s (+%s)  delay %s "
              "gains %s  %s"
              % (r["z"], r["mismatch"], r["seed"], r["k_eff"], r["k_eff_true_lqg_analytic"], r["ratio"] or 0.0,
                 r["first_alarm"], r["adapted_at"], r["adapted_after"], r["identified_delay"],
                 ["%.2f" % g for g in (r["identified_gain"] or [])],
                 "ok" if stable and fast and close and bumpless else "MISSES"))
    print("runs %d: all stable, adapted within 300 parts, k_eff within 15 %% and bumpless: %s" % (len(rows), ok))
    return rows, ok


def matching(args):
    rows = []
    for z in (1, 2, 3, 4):
        r = simulate(args.trueturn, ["--preset", "paper-2012", "--delay", str(z), "--parts", str(args.parts)])
        rows.append({"z": z, "k_eff": r["k_eff"], "alarms": len(mismatch_alarms(r)),
                     "adaptations": len(r["adaptations"])})
        print("z=%d  k_eff %.3f  alarms %d  adaptations %d" % (z, r["k_eff"], rows[-1]["alarms"],
                                                               rows[-1]["adaptations"]))
    ok = all(r["alarms"] == 0 and r["adaptations"] == 0 for r in rows)
    print("matching plant, %d parts: no alarm and no adaptation: %s" % (args.parts, ok))
    return rows, ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--trueturn", required=True)
    parser.add_argument("grid", choices=("physical", "mismatch", "matching"))
    parser.add_argument("--seeds", type=int, default=None)
    parser.add_argument("--parts", type=int, default=20000)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--ewma-grid", action="store_true", default=True)
    parser.add_argument("--no-ewma-grid", dest="ewma_grid", action="store_false")
    parser.add_argument("--json")
    args = parser.parse_args()
    if args.seeds is None:
        args.seeds = 6 if args.grid == "physical" else 1
    rows, ok = {"physical": physical, "mismatch": mismatch, "matching": matching}[args.grid](args)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
