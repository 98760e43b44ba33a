#!/usr/bin/python3
"""Cross-checks the feedback's margins of `trueturn feed-stabilise` (paper 003) against scipy.signal.

  scripts/crosscheck-feed-margins.py --trueturn build/app/trueturn

For the preset hydraulic-feed and a few changed spools (xi = 0.5, 2.0; T_z = 5 ms), runs
`trueturn feed-stabilise --regulator feedback --json` and takes the loop's plant and controller as the JSON
gives them (feedback_design.plant, .controller: numerator and denominator, highest power first). With
scipy.signal (TransferFunction, freqresp) on a logarithmic grid of 0.1 .. 1e6 rad/s, crossings refined by
scipy.optimize.brentq, it computes the gain margin (1/|L| where the phase is -180 deg), the phase margin
(180 deg + arg L where |L| = 1), their frequencies and the closed-loop poles (numpy.roots of den + num), and
compares them with the JSON's `margins`: margins and frequencies within 1e-6 relative, poles within 1e-6.
Also prints the preset's figures, the reference values of tests/core/sim/hydraulic/feed_feedback_test.cpp.
Exits 1 when a figure differs by more than its tolerance.

Debian 12: python3-numpy, python3-scipy (scripts/install-deps.sh --with-test-tools).
"""

import argparse
import json
import subprocess
import sys

import numpy as np
from scipy import signal
from scipy.optimize import brentq

CASES = [
    ("preset", []),
    ("xi=0.5", ["--xi", "0.5"]),
    ("xi=2", ["--xi", "2"]),
    ("T_z=5ms", ["--set", "spool.time_constant_s=0.005"]),
]


def margins(num, den):
    loop = signal.TransferFunction(num, den)
    w = np.logspace(-1, 6, 2801)
    _, h = signal.freqresp(loop, w)

    def at(x):
        return signal.freqresp(loop, [x])[1][0]

    gm, wp, pm, wc = None, None, None, None
    for k in range(1, len(w)):
        a, b = h[k - 1], h[k]
        if (abs(a) < 1.0) != (abs(b) < 1.0):
            x = brentq(lambda v: abs(at(v)) - 1.0, w[k - 1], w[k], xtol=1e-14, rtol=1e-13)
            p = np.degrees(np.angle(at(x))) + 180.0
            p = (p + 180.0) % 360.0 - 180.0
            if pm is None or p < pm:
                pm, wc = p, x
        if (a.imag < 0.0) != (b.imag < 0.0):
            x = brentq(lambda v: at(v).imag, w[k - 1], w[k], xtol=1e-14, rtol=1e-13)
            v = at(x)
            if v.real < 0.0 and abs(v) < 1.0 and (gm is None or 1.0 / abs(v) < gm):
                gm, wp = 1.0 / abs(v), x
    closed = np.polyadd(den, num)
    return {"gain_margin": gm, "phase_crossover_rad_s": wp, "phase_margin_deg": pm, "gain_crossover_rad_s": wc,
            "poles": sorted(np.roots(closed), key=lambda z: (round(z.real, 6), z.imag))}


def ours(trueturn, extra):
    out = subprocess.run([trueturn, "feed-stabilise", "--regulator", "feedback", "--json"] + extra,
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def close(x, y, tol):
    return abs(x - y) <= tol * max(1.0, abs(y))


def compare(name, j, failures):
    design = j["feedback_design"]
    num = np.polymul(design["controller"]["numerator"], design["plant"]["numerator"])
    den = np.polymul(design["controller"]["denominator"], design["plant"]["denominator"])
    peer = margins(num, den)
    m = j["margins"]
    for key in ("gain_margin", "phase_crossover_rad_s", "phase_margin_deg", "gain_crossover_rad_s"):
        x, y = m[key], peer[key]
        ok = close(x, y, 1e-6)
        print("%-8s %-22s ours %.9g  scipy %.9g  %s" % (name, key, x, y, "ok" if ok else "DIFFERS"))
        if not ok:
            failures.append((name, key))
    theirs = peer["poles"]
    mine = sorted((complex(p["re"], p["im"]) for p in m["closed_loop_poles_per_s"]),
                  key=lambda z: (round(z.real, 6), z.imag))
    ok = len(mine) == len(theirs) and all(abs(a - b) <= 1e-6 * max(1.0, abs(b)) for a, b in zip(mine, theirs))
    print("%-8s closed-loop poles      %s  %s" % (name, ", ".join("%.6g%+.6gj" % (z.real, z.imag) for z in theirs),
                                                  "ok" if ok else "DIFFERS"))
    if not ok:
        failures.append((name, "poles"))
    if name == "preset":
        print("reference (scipy %s): K_p %.12g; loop num %s; den %s" % (
            __import__("scipy").__version__, design["gain_s"], list(num), list(den)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--trueturn", required=True)
    args = parser.parse_args()
    failures = []
    for name, extra in CASES:
        compare(name, ours(args.trueturn, extra), failures)
    if failures:
        print("DIFFERENT:", failures)
        return 1
    print("all figures agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
