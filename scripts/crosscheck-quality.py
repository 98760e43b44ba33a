#!/usr/bin/python3
"""Cross-checks core/quality against a peer implementation, and times the peer for docs/BENCHMARKS.md.

  scripts/crosscheck-quality.py --figures build/tests/crosscheck/quality_figures
      Runs our figures tool on fixed inputs and compares every figure with the peer: statsmodels'
      normal_ad (Anderson-Darling), scipy.stats (normal and chi-square quantiles), numpy (quantiles,
      moments, subgroup statistics) and scipy.integrate (d2 of the range, independent of our table).
      Exits 1 when a figure differs by more than its stated tolerance.

  scripts/crosscheck-quality.py --bench build/tests/bench/trueturn_bench [--values 1000000]
      Writes one fixed series (numpy, seed 12345) to a file, runs our Google Benchmark on it
      (TRUETURN_QUALITY_BENCH_VALUES) and times the peer on the same values in the same run; prints
      a Markdown table for docs/BENCHMARKS.md. Both columns are medians of 3 runs in CPU time.

Debian 12: python3-numpy, python3-scipy, python3-statsmodels (scripts/install-deps.sh --with-test-tools).
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy import integrate, special, stats
from statsmodels.stats.diagnostic import normal_ad

# Montgomery, Introduction to Statistical Quality Control (2009), Table 6.3 (piston rings, 25 x 5) and
# Section 6.4 (mortgage-loan costs), as in tests/core/support/published_data.h.
PISTON_RINGS = [
    74.030, 74.002, 74.019, 73.992, 74.008, 73.995, 73.992, 74.001, 74.011, 74.004, 73.988, 74.024, 74.021,
    74.005, 74.002, 74.002, 73.996, 73.993, 74.015, 74.009, 73.992, 74.007, 74.015, 73.989, 74.014, 74.009,
    73.994, 73.997, 73.985, 73.993, 73.995, 74.006, 73.994, 74.000, 74.005, 73.985, 74.003, 73.993, 74.015,
    73.988, 74.008, 73.995, 74.009, 74.005, 74.004, 73.998, 74.000, 73.990, 74.007, 73.995, 73.994, 73.998,
    73.994, 73.995, 73.990, 74.004, 74.000, 74.007, 74.000, 73.996, 73.983, 74.002, 73.998, 73.997, 74.012,
    74.006, 73.967, 73.994, 74.000, 73.984, 74.012, 74.014, 73.998, 73.999, 74.007, 74.000, 73.984, 74.005,
    73.998, 73.996, 73.994, 74.012, 73.986, 74.005, 74.007, 74.006, 74.010, 74.018, 74.003, 74.000, 73.984,
    74.002, 74.003, 74.005, 73.997, 74.000, 74.010, 74.013, 74.020, 74.003, 73.982, 74.001, 74.015, 74.005,
    73.996, 74.004, 73.999, 73.990, 74.006, 74.009, 74.010, 73.989, 73.990, 74.009, 74.014, 74.015, 74.008,
    73.993, 74.000, 74.010, 73.982, 73.984, 73.995, 74.017, 74.013,
]
LOAN_COSTS = [310, 288, 297, 298, 307, 303, 294, 297, 308, 306, 294, 299, 297, 299, 314, 295, 293, 306, 301, 304]


def cases():
    """Fixed inputs: the published data sets and seeded samples (normal, skewed, heavy-tailed, minimal)."""
    rng = np.random.default_rng(20240101)
    normal = rng.normal(25.0, 0.004, 5000)
    skewed = 10.0 + rng.gamma(2.0, 0.002, 2000)
    heavy = 40.0 + 0.003 * rng.standard_t(3, 3000)
    minimal = np.array([5.01, 5.03, 4.98, 5.00, 5.02, 4.99, 5.04, 4.97])
    return [
        ("piston rings, X-bar-R n=5", np.array(PISTON_RINGS), dict(lsl=73.95, usl=74.05, subgroup=5, spread="range")),
        ("piston rings, X-bar-s n=5", np.array(PISTON_RINGS), dict(lsl=73.95, usl=74.05, subgroup=5, spread="stddev")),
        ("loan costs, I-MR", np.array(LOAN_COSTS, dtype=float), dict(lsl=270.0, usl=330.0, subgroup=1)),
        ("normal 5000, I-MR, target off-centre", normal, dict(lsl=24.985, usl=25.015, target=25.002, subgroup=1)),
        ("gamma 2000, X-bar-R n=4", skewed, dict(lsl=10.0, usl=10.03, subgroup=4, spread="range")),
        ("t(3) 3000, I-MR, 90 %", heavy, dict(lsl=39.98, usl=40.02, subgroup=1, confidence=0.90)),
        ("8 values, I-MR", minimal, dict(lsl=4.9, usl=5.1, subgroup=1)),
    ]


def dagostino_stephens_p(a):
    """p-value of A*^2 = a (D'Agostino & Stephens 1986, Table 4.9), as in statsmodels' normal_ad."""
    if a < 0.2:
        return 1 - math.exp(-13.436 + 101.14 * a - 223.73 * a**2)
    if a < 0.34:
        return 1 - math.exp(-8.318 + 42.796 * a - 59.938 * a**2)
    if a < 0.6:
        return math.exp(0.9177 - 4.279 * a - 1.38 * a**2)
    return math.exp(1.2937 - 5.709 * a + 0.0186 * a**2) if a <= 13 else 0.0


def d2_exact(n):
    """d2(n) = integral of 1 - Phi(x)^n - (1 - Phi(x))^n (the mean range of n standard normal values)."""
    return integrate.quad(lambda x: 1 - stats.norm.cdf(x) ** n - stats.norm.sf(x) ** n, -12, 12, epsabs=1e-13)[0]


def c4_exact(n):
    return math.sqrt(2.0 / (n - 1)) * math.exp(special.gammaln(n / 2.0) - special.gammaln((n - 1) / 2.0))


def peer_figures(x, settings):
    """The same figures as quality_figures, computed with numpy / scipy / statsmodels."""
    n_sub = settings.get("subgroup", 1)
    conf = settings.get("confidence", 0.95)
    lsl, usl = settings["lsl"], settings["usl"]
    target = settings.get("target", 0.5 * (lsl + usl))
    count = len(x)
    mean = float(np.mean(x))
    s = float(np.std(x, ddof=1))
    if n_sub == 1:
        mr_bar = float(np.mean(np.abs(np.diff(x))))
        sigma_within = mr_bar / d2_exact(2)
        chart = dict(centre=mean, ucl=mean + 3 * sigma_within, lcl=mean - 3 * sigma_within, spread_centre=mr_bar)
        d3 = math.sqrt(2 - 4 / math.pi)
        chart["spread_ucl"] = (1 + 3 * d3 / d2_exact(2)) * mr_bar
    else:
        groups = x[: (count // n_sub) * n_sub].reshape(-1, n_sub)
        means = groups.mean(axis=1)
        if settings["spread"] == "range":
            spread_bar = float(np.mean(groups.max(axis=1) - groups.min(axis=1)))
            sigma_within = spread_bar / d2_exact(n_sub)
        else:
            spread_bar = float(np.mean(groups.std(axis=1, ddof=1)))
            sigma_within = spread_bar / c4_exact(n_sub)
        centre = float(np.mean(means))
        half = 3 * sigma_within / math.sqrt(n_sub)
        chart = dict(centre=centre, ucl=centre + half, lcl=centre - half, spread_centre=spread_bar)
    with np.errstate(divide="ignore"):
        ad2, ad_p = normal_ad(np.asarray(x))
    if not np.isfinite(ad2):
        # statsmodels evaluates ln(1 - Phi(z)) as log1p(-Phi(z)), which is -inf once Phi(z) rounds to 1
        # (z > 8.3, e.g. in the t(3) sample); the same statistic with scipy's accurate tails (logcdf, logsf),
        # and its p-value by the D'Agostino-Stephens formulas that normal_ad uses.
        w = np.sort((np.asarray(x) - mean) / s)
        i = np.arange(1, count + 1)
        ad2 = -count - np.sum((2 * i - 1) / count * (stats.norm.logcdf(w) + stats.norm.logsf(w[::-1])))
        ad_p = dagostino_stephens_p(ad2 * (1 + 0.75 / count + 2.25 / count**2))
    alpha = 1 - conf
    z = stats.norm.ppf(1 - alpha / 2)
    dof = count - 1

    def chi_ci(c, nu):
        return [c * math.sqrt(stats.chi2.ppf(alpha / 2, nu) / nu), c * math.sqrt(stats.chi2.ppf(1 - alpha / 2, nu) / nu)]

    def bissell_ci(c):
        h = z * math.sqrt(1 / (9 * count) + c * c / (2 * (count - 1)))
        return [c - h, c + h]

    width, nearest = usl - lsl, min(usl - mean, mean - lsl)
    cp, cpk = width / (6 * sigma_within), nearest / (3 * sigma_within)
    pp, ppk = width / (6 * s), nearest / (3 * s)
    cpm = width / (6 * math.sqrt(np.sum((x - target) ** 2) / (count - 1)))
    a2 = ((mean - target) / s) ** 2
    nu_boyles = count * (1 + a2) ** 2 / (1 + 2 * a2)
    low, median, high = np.quantile(x, [0.00135, 0.5, 0.99865])
    return dict(
        n=count, mean=mean, sigma_within=sigma_within, sigma_overall=s, a2=float(ad2),
        a2_adjusted=float(ad2) * (1 + 0.75 / count + 2.25 / count**2), ad_p=float(ad_p),
        method="percentile" if ad_p < 0.05 else "normal",
        normal=dict(cp=cp, cpk=cpk, pp=pp, ppk=ppk, cpm=cpm, cp_ci=chi_ci(cp, dof), cpk_ci=bissell_ci(cpk),
                    pp_ci=chi_ci(pp, dof), ppk_ci=bissell_ci(ppk), cpm_ci=chi_ci(cpm, nu_boyles)),
        percentile=dict(low=low, median=median, high=high, pp=width / (high - low),
                        ppk=min((usl - median) / (high - median), (median - lsl) / (median - low))),
        chart=chart,
    )


class Checker:
    def __init__(self):
        self.failures = 0
        self.checks = 0

    def close(self, label, ours, peer, rel=0.0, abs_=0.0):
        """|ours - peer| <= abs_ + rel |peer|."""
        self.checks += 1
        tolerance = abs_ + rel * abs(peer)
        ok = math.isfinite(ours) and math.isfinite(peer) and abs(ours - peer) <= tolerance
        if not ok:
            self.failures += 1
        print(f"  {'ok ' if ok else 'BAD'} {label:28s} ours {ours:.12g}  peer {peer:.12g}  (tol {tolerance:.2g})")

    def equal(self, label, ours, peer):
        self.checks += 1
        ok = ours == peer
        if not ok:
            self.failures += 1
        print(f"  {'ok ' if ok else 'BAD'} {label:28s} ours {ours}  peer {peer}")


def crosscheck(figures_exe):
    check = Checker()
    # Quantiles: Boost.Math and scipy (Cephes) in double precision.
    # Tolerances: 1e-12 relative (normal), 1e-10 relative (chi-square: inverse incomplete gamma).
    q = json.loads(subprocess.run([figures_exe, "--quantiles"], check=True, capture_output=True, text=True).stdout)
    print("quantiles (Boost.Math vs scipy.stats)")
    for p, value in q["normal"]:
        check.close(f"norm.ppf({p:g})", value, stats.norm.ppf(p), rel=1e-12, abs_=1e-15)
    for p, dof, value in q["chi2"]:
        check.close(f"chi2.ppf({p:g}, {dof:g})", value, stats.chi2.ppf(p, dof), rel=1e-10)

    for name, x, settings in cases():
        args = [figures_exe, "--lsl", repr(settings["lsl"]), "--usl", repr(settings["usl"]),
                "--subgroup", str(settings.get("subgroup", 1)), "--confidence", repr(settings.get("confidence", 0.95))]
        if "target" in settings:
            args += ["--target", repr(settings["target"])]
        if "spread" in settings:
            args += ["--spread", settings["spread"]]
        run = subprocess.run(args, input="\n".join(repr(float(v)) for v in x), check=True, capture_output=True,
                             text=True)
        ours = json.loads(run.stdout)
        peer = peer_figures(x, settings)
        print(name)
        # Moments and Anderson-Darling (statsmodels normal_ad, same D'Agostino-Stephens p formulas): the sums
        # are taken in a different order and ln Phi differently (our tail series): 1e-9 relative.
        check.equal("n", int(ours["n"]), peer["n"])
        check.close("mean", ours["mean"], peer["mean"], rel=1e-13)
        check.close("sigma overall", ours["sigma_overall"], peer["sigma_overall"], rel=1e-9)
        check.close("A^2", ours["a2"], peer["a2"], rel=1e-9)
        check.close("A*^2", ours["a2_adjusted"], peer["a2_adjusted"], rel=1e-9)
        check.close("AD p-value", ours["ad_p"], peer["ad_p"], rel=1e-8, abs_=1e-12)
        check.equal("method", ours["method"], peer["method"])
        # sigma within: ours divides by the published three-decimal d2 (|d2 - exact| <= 0.0005, i.e. 4.4e-4
        # relative at n = 2), the peer by d2 integrated numerically; s-bar/c4: c4 exact on both sides.
        within_rel = 4.5e-4 if settings.get("spread") != "stddev" else 1e-12
        check.close("sigma within", ours["sigma_within"], peer["sigma_within"], rel=within_rel)
        # Indices and intervals from sigma within carry its tolerance; those from sigma overall 1e-9.
        for key in ("cp", "cpk"):
            check.close(key, ours["normal"][key], peer["normal"][key], rel=within_rel + 1e-9)
            for i, side in enumerate(("lower", "upper")):
                # A Bissell bound is C -+ h: its error is C's error (within_rel |C|) plus h's (smaller).
                check.close(f"{key} CI {side}", ours["normal"][key + "_ci"][i], peer["normal"][key + "_ci"][i],
                            abs_=2 * within_rel * abs(peer["normal"][key]) + 1e-9)
        for key in ("pp", "ppk", "cpm"):
            check.close(key, ours["normal"][key], peer["normal"][key], rel=1e-9)
            for i, side in enumerate(("lower", "upper")):
                check.close(f"{key} CI {side}", ours["normal"][key + "_ci"][i], peer["normal"][key + "_ci"][i],
                            rel=1e-9, abs_=1e-12)
        # Percentile method: numpy.quantile's default ("linear") is Hyndman & Fan definition 7, as ours.
        for key in ("low", "median", "high", "pp", "ppk"):
            check.close(f"percentile {key}", ours["percentile"][key], peer["percentile"][key], rel=1e-12)
        # Chart limits: ours use the published A2 (three decimals, within 0.0005 of the exact 3/(d2 sqrt n)),
        # D4 (within 0.0009 of 1 + 3 d3/d2) and, for I-MR, 3/1.128 (within 3 * 0.0005/1.128^2 = 0.0012 of
        # 3/d2(2)); the peer the exact constants. Tolerance: that many units of R-bar (or MR-bar) on the
        # limits, 1e-12 relative on the centre lines.
        spread_bar = peer["chart"]["spread_centre"]
        limit_units = 0.0012 if settings.get("subgroup", 1) == 1 else 0.0005
        check.close("chart centre", ours["chart"]["centre"], peer["chart"]["centre"], rel=1e-12)
        check.close("chart spread centre", ours["chart"]["spread_centre"], spread_bar, rel=1e-12)
        for key in ("ucl", "lcl"):
            check.close(f"chart {key}", ours["chart"][key], peer["chart"][key], abs_=limit_units * spread_bar + 1e-12)
        if "spread_ucl" in peer["chart"]:
            check.close("chart MR UCL", ours["chart"]["spread_ucl"], peer["chart"]["spread_ucl"],
                        abs_=0.001 * spread_bar)
    print(f"crosscheck-quality: {check.checks - check.failures} of {check.checks} figures agree with the peer")
    return 1 if check.failures else 0


def median_of(repeats, fn):
    """Median CPU time of this process over `repeats` runs, seconds (CPU rather than wall time, so that other
    work on the machine does not count; numpy and scipy run these operations on one thread)."""
    times = []
    for _ in range(repeats):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return sorted(times)[len(times) // 2]


def peer_timings(x, subgroup):
    """The peer's time on the same work as our benchmarks (median CPU time of 3 runs, seconds)."""
    lsl, usl = 19.95, 20.05

    def capability():
        normal_ad(x)
        np.quantile(x, [0.00135, 0.5, 0.99865])
        mean, s = np.mean(x), np.std(x, ddof=1)
        groups = x[: len(x) // subgroup * subgroup].reshape(-1, subgroup)
        sigma = np.mean(groups.max(axis=1) - groups.min(axis=1)) / 2.326
        n = len(x)
        cp = (usl - lsl) / (6 * sigma)
        cpk = min(usl - mean, mean - lsl) / (3 * sigma)
        stats.chi2.ppf([0.025, 0.975], n - 1)
        stats.norm.ppf(0.975)
        return cp, cpk, s

    def xbar_r():
        groups = x[: len(x) // subgroup * subgroup].reshape(-1, subgroup)
        means = groups.mean(axis=1)
        ranges = groups.max(axis=1) - groups.min(axis=1)
        centre, r_bar = means.mean(), ranges.mean()
        return np.flatnonzero((means > centre + 0.577 * r_bar) | (means < centre - 0.577 * r_bar))

    def individuals():
        mr = np.abs(np.diff(x))
        centre, sigma = x.mean(), mr.mean() / 1.128
        return np.flatnonzero(np.abs(x - centre) > 3 * sigma), np.flatnonzero(mr > 3.267 * mr.mean())

    def ewma():
        from scipy.signal import lfilter
        lam = 0.2
        z, _ = lfilter([lam], [1, -(1 - lam)], x, zi=[(1 - lam) * 20.0])
        return z

    def cusum():
        # No vectorised peer: a Python loop over the values (numpy scalars would be slower still).
        upper = lower = 0.0
        k, h = 0.5 * 0.01, 5 * 0.01
        alarms = 0
        for v in x.tolist():
            upper = max(0.0, v - 20.0 - k + upper)
            lower = max(0.0, 20.0 - k - v + lower)
            alarms += upper > h or lower > h
        return alarms

    return {
        "capability": median_of(3, capability),
        "xbar_r": median_of(3, xbar_r),
        "individuals": median_of(3, individuals),
        "ewma": median_of(3, ewma),
        "cusum": median_of(3, cusum),
    }


def bench(bench_exe, count):
    rng = np.random.default_rng(12345)
    x = rng.normal(20.0, 0.01, count)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "values.f64")
        x.astype("<f8").tofile(path)
        env = dict(os.environ, TRUETURN_QUALITY_BENCH_VALUES=path)
        out = subprocess.run([bench_exe, "--benchmark_filter=Quality", "--benchmark_format=json",
                              "--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true"],
                             check=True, capture_output=True, text=True, env=env).stdout
        ours = {b["run_name"]: b for b in json.loads(out)["benchmarks"] if b.get("aggregate_name") == "median"}
        peer = peer_timings(x, 5)
    rows = [
        ("Capability study (AD test, quantiles, sigma within R-bar/d2 n = 5, indices with intervals)",
         "BM_QualityCapability", "capability", "statsmodels normal_ad + numpy quantile/moments + scipy chi2/norm"),
        ("X-bar-R chart, n = 5 (subgroups, limits, points beyond)", "BM_QualityXbarR", "xbar_r", "numpy reshape"),
        ("I-MR chart", "BM_QualityIndividuals", "individuals", "numpy"),
        ("EWMA chart, lambda 0.2, exact limits", "BM_QualityEwma", "ewma", "scipy.signal.lfilter (no limits)"),
        ("Tabular CUSUM", "BM_QualityCusum", "cusum", "Python loop"),
    ]
    print(f"| work on {count:,} values | TrueTurn | peer | peer implementation |")
    print("|---|---|---|---|")
    for label, ours_name, peer_key, peer_label in rows:
        b = ours.get(ours_name)
        ours_ms = b["cpu_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]] if b else float("nan")
        print(f"| {label} | {ours_ms:.1f} ms | {peer[peer_key] * 1e3:.1f} ms | {peer_label} |")
    analysis = ours.get("BM_QualityPointAnalysis")
    if analysis:
        ms = analysis["cpu_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[analysis["time_unit"]]
        print(f"| Whole point analysis (X-bar-R n = 5, Western Electric rules, capability) | {ms:.1f} ms | | |")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--figures", help="path of build/tests/crosscheck/quality_figures")
    parser.add_argument("--bench", help="path of build/tests/bench/trueturn_bench")
    parser.add_argument("--values", type=int, default=1_000_000, help="values of the benchmark series")
    args = parser.parse_args()
    if args.figures:
        return crosscheck(args.figures)
    if args.bench:
        return bench(args.bench, args.values)
    parser.error("give --figures or --bench")
    return 2


if __name__ == "__main__":
    sys.exit(main())
