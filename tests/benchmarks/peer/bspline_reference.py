#!/usr/bin/env python3
"""Exact values of the peer comparison's B-spline curves: de Boor's algorithm in Python's
fractions.Fraction, on the exact rational values of the doubles (every double is a dyadic
rational), written independently of Granota's code (Piegl & Tiller eq. (3.8); a rational curve
on its homogeneous points, divided at the end).

Reads the cases JSON (bspline_cases.py) and prints {"values": [[[x, y] as strings "p/q"]]}.
"""
import json
import sys
from fractions import Fraction


def span(knots, p, n, u):
    """k with u_k <= u < u_{k+1}, p <= k <= n; u = u_{n+1} gives the last non-empty span."""
    if u >= knots[n + 1]:
        k = n
        while k > p and knots[k] == knots[k + 1]:
            k -= 1
        return k
    k = p
    while knots[k + 1] <= u:
        k += 1
    return k


def de_boor(c, u):
    p = c["degree"]
    knots = [Fraction(k) for k in c["knots"]]
    n = len(c["points"]) - 1
    w = [Fraction(x) for x in c.get("weights") or [1.0] * (n + 1)]
    h = [(Fraction(x) * w[i], Fraction(y) * w[i], w[i]) for i, (x, y) in enumerate(c["points"])]
    u = Fraction(u)
    k = span(knots, p, n, u)
    d = h[k - p:k + 1]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = k - p + j
            a = (u - knots[i]) / (knots[i + p + 1 - r] - knots[i])
            d[j] = tuple((1 - a) * d[j - 1][m] + a * d[j][m] for m in range(3))
    x, y, wt = d[p]
    return [x / wt, y / wt]


if __name__ == "__main__":
    cases = json.load(open(sys.argv[1]))["cases"]
    print(json.dumps({"values": [[[str(v) for v in de_boor(c, u)] for u in c["u"]] for c in cases]}))
