#!/usr/bin/env python3
"""Random floating-point B-spline curves for the peer comparison (bspline_compare.sh), seeded.

Degrees 1-5; for each degree a clamped and an unclamped knot vector, polynomial and rational
(weights in [0.5, 2]); interior knots drawn at random (some repeated up to the degree);
control points in [-1, 1]^2; the parameters u drawn in the domain [u_p, u_{n+1}] plus both of
its ends and every interior knot of the domain. Prints JSON:
  {"cases": [{"name", "degree", "clamped", "knots", "points", "weights"?, "u"}]}

    python3 tests/benchmarks/peer/bspline_cases.py [SEED] [VALUES_PER_CASE]
"""
import json
import random
import sys


def knot_vector(rng, degree, count, clamped):
    """count = n + p + 2 knots; clamped: p + 1 equal ends on [0, 1]; else spread on [0, 3]."""
    p = degree
    if clamped:
        inner = count - 2 * (p + 1)
        interior = []
        while len(interior) < inner:
            k = round(rng.uniform(0.02, 0.98), 6)
            times = min(rng.choice([1, 1, 1, 2, p]), p, inner - len(interior))
            interior += [k] * times
        return [0.0] * (p + 1) + sorted(interior) + [1.0] * (p + 1)
    knots = sorted(round(rng.uniform(0, 3), 6) for _ in range(count))
    if rng.random() < 0.5 and p >= 2:  # a repeated interior knot, multiplicity up to p
        i = rng.randrange(p + 1, count - p - 1)
        for j in range(1, rng.randint(2, p) if p > 2 else 2):
            if i + j < count - p - 1:
                knots[i + j] = knots[i]
    return knots


def case(rng, degree, clamped, rational, values):
    n = degree + rng.randint(1, 8)  # n + 1 control points, at least p + 2
    knots = knot_vector(rng, degree, n + degree + 2, clamped)
    a, b = knots[degree], knots[n + 1]
    if a == b:
        return None
    points = [[rng.uniform(-1, 1), rng.uniform(-1, 1)] for _ in range(n + 1)]
    u = sorted({a, b} | {k for k in knots if a < k < b} | {rng.uniform(a, b) for _ in range(values)})
    c = {"name": f"p={degree} {'clamped' if clamped else 'unclamped'}{' rational' if rational else ''}",
         "degree": degree, "clamped": clamped, "knots": knots, "points": points, "u": u}
    if rational:
        c["weights"] = [rng.uniform(0.5, 2) for _ in range(n + 1)]
    return c


def cases(seed=36, values=8):
    rng = random.Random(seed)
    out = []
    for degree in range(1, 6):
        for clamped in (True, False):
            for rational in (False, True):
                c = None
                while c is None:
                    c = case(rng, degree, clamped, rational, values)
                out.append(c)
    return out


if __name__ == "__main__":
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 36
    values = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    print(json.dumps({"seed": seed, "cases": cases(seed, values)}))
