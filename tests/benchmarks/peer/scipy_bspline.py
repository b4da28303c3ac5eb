#!/usr/bin/env python3
"""scipy's BSpline on the data of tests/benchmarks/bench_bsplines.cpp's BM_BSplineEvaluate.

A cubic B-spline with 10^4 control points P_i = (i/100, sin(i/50) + 0.3 cos(i/7)) on the
clamped knot vector (4 zeros, interior knots j/(n - p + 1), 4 ones), evaluated with
scipy.interpolate.BSpline.__call__ at 10^6 parameters u_k = k/(10^6 - 1) in one call. Prints
one JSON line: the median of 3 timed calls (time.perf_counter) in ms, the per-point time in ns,
the median CPU time of the same calls (time.process_time: on a shared machine the steadier one),
and the point at u = 0.37 (checked against Granota's in bench_bsplines.cpp's comment).

    python3 tests/benchmarks/peer/scipy_bspline.py        (needs python3-scipy)
"""
import json
import statistics
import sys
import time

import numpy as np
from scipy.interpolate import BSpline

DEGREE = 3
POINTS = 10_000
PARAMETERS = 1_000_000
REPETITIONS = 3


def data():
    i = np.arange(POINTS, dtype=float)
    control = np.column_stack((i / 100, np.sin(i / 50) + 0.3 * np.cos(i / 7)))
    n, p = POINTS - 1, DEGREE
    interior = np.arange(1, n - p + 1, dtype=float) / (n - p + 1)
    knots = np.concatenate((np.zeros(p + 1), interior, np.ones(p + 1)))
    u = np.arange(PARAMETERS, dtype=float) / (PARAMETERS - 1)
    return knots, control, u


def main():
    knots, control, u = data()
    spline = BSpline(knots, control, DEGREE, extrapolate=False)
    spline(u)  # warm-up
    times, cpu_times = [], []
    for _ in range(REPETITIONS):
        start, cpu_start = time.perf_counter(), time.process_time()
        values = spline(u)
        times.append(time.perf_counter() - start)
        cpu_times.append(time.process_time() - cpu_start)
    seconds = statistics.median(times)
    at = spline(np.array([0.37]))[0]
    print(json.dumps({
        "scipy": __import__("scipy").__version__,
        "python": sys.version.split()[0],
        "points": POINTS, "parameters": PARAMETERS, "degree": DEGREE,
        "median_ms": seconds * 1e3, "ns_per_point": seconds / PARAMETERS * 1e9,
        "median_cpu_ms": statistics.median(cpu_times) * 1e3,
        "point_at_0.37": [float(at[0]), float(at[1])],
        "checksum": float(values.sum()),
    }))


if __name__ == "__main__":
    main()
