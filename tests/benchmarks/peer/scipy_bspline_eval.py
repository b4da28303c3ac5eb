#!/usr/bin/env python3
"""Evaluates B-spline curves with scipy.interpolate.BSpline (python3-scipy).

Reads {"cases": [{"degree", "knots", "points", "weights"?, "u"}]} (a file, or stdin with "-"),
prints {"scipy": version, "values": [[[x, y] for each u] for each case]} with every double
written exactly (repr). A rational curve is evaluated as scipy's polynomial B-spline of the
homogeneous points (w x, w y, w), then divided by w: scipy has no NURBS of its own.
Used by bspline_compare.sh and by tests/test_bspline_peers.cpp.
"""
import json
import sys

import numpy as np
import scipy
from scipy.interpolate import BSpline


def evaluate(c):
    knots = np.array(c["knots"], dtype=float)
    points = np.array(c["points"], dtype=float)
    u = np.array(c["u"], dtype=float)
    weights = c.get("weights")
    if weights:
        w = np.array(weights, dtype=float)
        homogeneous = np.column_stack((points * w[:, None], w))
        h = BSpline(knots, homogeneous, c["degree"], extrapolate=False)(u)
        values = h[:, :2] / h[:, 2:3]
    else:
        values = BSpline(knots, points, c["degree"], extrapolate=False)(u)
    return [[float(x), float(y)] for x, y in values]


def main():
    source = sys.stdin if len(sys.argv) < 2 or sys.argv[1] == "-" else open(sys.argv[1])
    data = json.load(source)
    print(json.dumps({"scipy": scipy.__version__, "values": [evaluate(c) for c in data["cases"]]}))


if __name__ == "__main__":
    main()
