#!/usr/bin/env python3
"""Side-by-side benchmark of the high-precision path: `wedge curve --digits D` against the
project's independent mpmath implementation (tests/reference/wedge_mpmath.py), same speeds,
same digits, in one run on this machine.

For each curve (the classical one: frictionless, uncoupled; the coupled frictional one:
Theta 89 deg, gamma 0.6, the paper's construction) the script times
  * the mpmath implementation: the eight matching integrals and V/(c1 cot Theta) at each
    speed, one process (wall = CPU);
  * `wedge curve ... --quantities v_over_c1_cot_theta` (V alone, with its estimate) and the
    full report, wall and CPU time (the binary uses every core);
checks that the two agree (largest relative difference of V) and prints the ratios.

Run from the repository root after `cargo build --release`:
    python3 benches/side_by_side.py [--digits 30,60,100] [--points 40,6]
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "reference"))
import wedge_mpmath as W  # noqa: E402
from mpmath import mp, mpf  # noqa: E402

WEDGE = os.path.join(ROOT, "target", "release", "wedge")

# name, Theta (deg), gamma, coupled, p range
CURVES = [
    ("classical", 86, "0", False, ("0.05", "0.45")),
    ("coupled frictional (Theta 89, gamma 0.6)", 89, "0.6", True, ("0.05", "0.45")),
]


def alphas(lo_p, hi_p, n, dps):
    """The alpha grid of `wedge curve --alpha-range lo,hi,n` (m/s), as decimal strings."""
    with mp.workdps(dps + 30):
        c1 = mpf(W.C1)
        lo, hi = mpf(lo_p) * c1, mpf(hi_p) * c1
        return [mp.nstr(lo + (hi - lo) * k / (n - 1), dps + 25) for k in range(n)]


def mpmath_curve(theta, gamma, coupled, alpha_list, dps):
    """V/(c1 cot Theta) of the paper's construction at each alpha, by wedge_mpmath.Model."""
    out = []
    for a in alpha_list:
        with mp.workdps(dps + 30):
            p = mp.nstr(mpf(a) / mpf(W.C1), dps + 25)
        model = W.Model(theta, gamma, coupled, p, dps)
        errs = []
        with mp.workdps(dps):
            _, vq, cq = W.matching(model, model.integrals(errs), model.pole_unit()[0], True)
            out.append(vq / cq)
    return out


def run_wedge(theta, gamma, coupled, alpha_list, dps, quantities):
    args = [
        WEDGE, "curve", "--theta-deg", str(theta), "--gamma", gamma,
        "--coupling", "on" if coupled else "off", "--solution", "paper",
        "--alpha-range", "%s,%s,%d" % (alpha_list[0], alpha_list[-1], len(alpha_list)),
        "--digits", str(dps), "--json",
    ]
    if quantities:
        args += ["--quantities", quantities]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    res = subprocess.run(args, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if res.returncode != 0:
        sys.exit("wedge failed: %s" % res.stderr.strip())
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    rows = json.loads(res.stdout, parse_float=str)
    return [r["v_over_c1_cot_theta"] for r in rows], wall, cpu


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--digits", default="30")
    ap.add_argument("--points", default="40,6", help="points of the classical, coupled curves")
    opts = ap.parse_args()
    if not os.path.exists(WEDGE):
        sys.exit("build first: cargo build --release")
    points = [int(x) for x in opts.points.split(",")]
    print("| curve | digits | points | mpmath (s) | wedge, V alone: wall / CPU (s) | "
          "wedge, full report: wall / CPU (s) | ratio mpmath / wedge V alone (wall, CPU) | "
          "largest relative difference |")
    print("|---|---|---|---|---|---|---|---|")
    for (name, theta, gamma, coupled, (lo, hi)), n in zip(CURVES, points):
        for dps in [int(d) for d in opts.digits.split(",")]:
            grid = alphas(lo, hi, n, dps)
            t0 = time.perf_counter()
            ref = mpmath_curve(theta, gamma, coupled, grid, dps)
            t_mp = time.perf_counter() - t0
            v, wall, cpu = run_wedge(theta, gamma, coupled, grid, dps, "v_over_c1_cot_theta")
            _, wall_full, cpu_full = run_wedge(theta, gamma, coupled, grid, dps, None)
            with mp.workdps(dps + 30):
                worst = max(abs(mpf(x) - r) / abs(r) for x, r in zip(v, ref))
            print("| %s | %d | %d | %.3f | %.3f / %.3f | %.3f / %.3f | %.0fx, %.0fx | %s |" % (
                name, dps, n, t_mp, wall, cpu, wall_full, cpu_full, t_mp / wall, t_mp / cpu,
                mp.nstr(worst, 2)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
