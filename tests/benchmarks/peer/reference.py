#!/usr/bin/env python3
"""High-precision references for the peer comparison (compare.sh), independent of both
Granota and bezier-js: mpmath at 40 digits, the curves in power form with exact rational
coefficients. Length: mpmath.quad of |c'| split at the cusps (the real roots of |c'|^2 in
[0, 1]); box: the ends and the real roots of x', y' in (0, 1); closest point: the ends and
the real roots in [0, 1] of (c - p).c', the smallest distance. Prints one line of JSON."""
import json
import sys
from fractions import Fraction
from math import comb

import mpmath as mp

mp.mp.dps = 40


def power_form(ctrl):
    """Coefficients a_k (ascending) of sum_i b_i C(n,i) t^i (1-t)^(n-i), exact."""
    n = len(ctrl) - 1
    a = [Fraction(0)] * (n + 1)
    for i, b in enumerate(ctrl):
        for j in range(n - i + 1):  # (1-t)^(n-i) = sum_j C(n-i,j) (-t)^j
            a[i + j] += Fraction(b) * comb(n, i) * comb(n - i, j) * (-1) ** j
    return a


def deriv(a):
    return [k * a[k] for k in range(1, len(a))] or [Fraction(0)]


def mul(a, b):
    r = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def add(a, b):
    r = [Fraction(0)] * max(len(a), len(b))
    for i, x in enumerate(a):
        r[i] += x
    for i, y in enumerate(b):
        r[i] += y
    return r


def ev(a, t):
    return mp.polyval([mp.mpf(c.numerator) / c.denominator for c in reversed(a)], t)


def roots01(a, closed):
    while len(a) > 1 and a[-1] == 0:
        a = a[:-1]
    if len(a) <= 1:
        return []
    co = [mp.mpf(c.numerator) / c.denominator for c in reversed(a)]
    rs = mp.polyroots(co, maxsteps=500, extraprec=400)
    out = []
    for r in rs:
        if abs(mp.im(r)) < mp.mpf(10) ** -25:
            t = mp.re(r)
            lo, hi = (0, 1) if closed else (mp.mpf(10) ** -30, 1 - mp.mpf(10) ** -30)
            if lo <= t <= hi:
                out.append(t)
    return sorted(out)


def main():
    spec = json.load(open(sys.argv[1]))
    res = []
    for c in spec["curves"]:
        X = power_form([Fraction(str(p[0])) for p in c["points"]])
        Y = power_form([Fraction(str(p[1])) for p in c["points"]])
        dX, dY = deriv(X), deriv(Y)
        speed2 = add(mul(dX, dX), mul(dY, dY))
        cusps = roots01(speed2, True)  # double roots: polyroots still finds them at 40 digits
        cuts = sorted([mp.mpf(0), mp.mpf(1)] + cusps)
        length = mp.quad(lambda t: mp.sqrt(max(mp.mpf(0), ev(speed2, t))), cuts)
        xs = [ev(X, t) for t in [0, 1] + roots01(dX, False)]
        ys = [ev(Y, t) for t in [0, 1] + roots01(dY, False)]
        proj = []
        for px, py in c["project"]:
            px, py = Fraction(str(px)), Fraction(str(py))
            g = add(mul(add(X, [-px]), dX), mul(add(Y, [-py]), dY))
            best = None
            for t in [mp.mpf(0), mp.mpf(1)] + roots01(g, True):
                d = mp.sqrt((ev(X, t) - px) ** 2 + (ev(Y, t) - py) ** 2)
                if best is None or d < best[1]:
                    best = (t, d)
            t, d = best
            proj.append({"t": mp.nstr(t, 25), "point": [mp.nstr(ev(X, t), 25), mp.nstr(ev(Y, t), 25)],
                         "distance": mp.nstr(d, 25)})
        res.append({"name": c["name"], "length": mp.nstr(length, 25),
                    "bbox": [[mp.nstr(min(xs), 25), mp.nstr(min(ys), 25)],
                             [mp.nstr(max(xs), 25), mp.nstr(max(ys), 25)]],
                    "project": proj})
    print(json.dumps({"reference": "mpmath", "curves": res}))


main()
