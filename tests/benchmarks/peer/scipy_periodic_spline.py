#!/usr/bin/env python3
"""The peer of BM_ClosedSpline (tests/benchmarks/bench_splines.cpp): scipy's
CubicSpline(bc_type='periodic') through the same n points on r(θ) = 1 + 0.3 sin 5θ, as a
parametric curve: x(u) and y(u) in one call (axis 0), u the cumulative chord lengths, the
first point repeated at the end as scipy's periodic ends require. The knots are computed
inside the timed part, as Granota's are. Prints the median of 7 runs in milliseconds.
    python3 tests/benchmarks/peer/scipy_periodic_spline.py [N]   (default 100000)
Needs Debian's python3-scipy (/usr/bin/python3)."""
import statistics
import sys
import time

import numpy as np
from scipy.interpolate import CubicSpline


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    theta = 2 * np.pi * np.arange(n) / n
    r = 1 + 0.3 * np.sin(5 * theta)
    points = np.column_stack((r * np.cos(theta), r * np.sin(theta)))
    closed = np.vstack((points, points[:1]))
    times = []
    for _ in range(7):
        start = time.perf_counter()
        steps = np.hypot(*np.diff(closed, axis=0).T)
        u = np.concatenate(([0.0], np.cumsum(steps)))
        spline = CubicSpline(u, closed, bc_type='periodic', axis=0)
        times.append(time.perf_counter() - start)
    assert spline.c.shape == (4, n, 2)
    print(f"{1e3 * statistics.median(times):.3f}")


if __name__ == '__main__':
    main()
