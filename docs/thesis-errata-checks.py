#!/usr/bin/env python3
"""The computations behind docs/thesis-errata.md, independent of Granota's C++ code.

Run: python3 docs/thesis-errata-checks.py   (needs python3-sympy; prints each check, and
stops with an AssertionError if a number of the errata does not hold).
"""
import math

from sympy import Matrix, Rational, S, binomial, expand, radsimp, sqrt, symbols, zeros, N

t, s, tau = symbols("t s tau")
p0, p1, p2, p3 = symbols("p0:4")


def B(i, n, x=t):
    return binomial(n, i) * x**i * (1 - x) ** (n - i)


def check(what, ok):
    assert ok, what
    print("ok  ", what)


# --- Ex 2.2, 2.3: De Casteljau's last level; Ex 2.5, 2.6: the Bernstein sums agree ---------
for name, P, x4, y4 in [
    ("Ex 2.2/2.5", [(2, 3), (-1, 8), (-5, -3), (3, 0), (-7, -2)], "2-12*t-6*t**2+52*t**3-43*t**4", "3+20*t-96*t**2+120*t**3-49*t**4"),
    ("Ex 2.3/2.6", [(1, 7), (0, -3), (-4, -2), (8, 0), (1, 7)], "1-4*t-18*t**2+76*t**3-54*t**4", "7-40*t+66*t**2-40*t**3+14*t**4"),
]:
    level = [Matrix(p) for p in P]
    while len(level) > 1:
        level = [expand((1 - t) * level[i] + t * level[i + 1]) for i in range(len(level) - 1)]
    bern = expand(sum((B(k, 4) * Matrix(P[k]) for k in range(5)), zeros(2, 1)))
    check(name + ": De Casteljau = Bernstein = printed", level[0] == bern and expand(bern[0] - S(x4)) == 0 and expand(bern[1] - S(y4)) == 0)

# --- Ex 2.7, 2.8: every matrix is right; Ex 2.8's t coefficient is -1735/105 ----------------
Q = Matrix([[0, 0], [1, 3], [4, 2], [8, -2], [1, 5]])
uniform = [Rational(i, 4) for i in range(5)]


def exact_fit(ts, n):
    M = Matrix(5, n + 1, lambda r, c: B(c, n, ts[r]))
    Mp = (M.T * M).inv() * M.T
    return M, Mp, Mp * Q


M, Mp, P = exact_fit(uniform, 2)
check("Ex 2.7: P = (-8/7, 46/35), (323/35, -19/35), (86/35, 116/35)", P == Matrix([[Rational(-8, 7), Rational(46, 35)], [Rational(323, 35), Rational(-19, 35)], [Rational(86, 35), Rational(116, 35)]]))
M, Mp, P = exact_fit(uniform, 3)
check("Ex 2.8: P_0 = (11/70, -13/70), P_1 = (-3371/630, 2711/210)", P[0, 0] == Rational(11, 70) and P[1, 0] == Rational(-3371, 630) and P[1, 1] == Rational(2711, 210))
check("Ex 2.8: the t coefficient of x(t) is 3(P1 - P0) = -347/21 = -1735/105, not -1636/105", 3 * (P[1, 0] - P[0, 0]) == Rational(-1735, 105))

# --- Ex 2.9/2.10: the printed t_i are right for d4 = sqrt(85), wrong for the data -------------
printed = [
    S(0),
    Rational(1540, 4951) + 744 * sqrt(5) / 4951 - 65 * sqrt(34) / 4951 - 160 * sqrt(170) / 4951,
    Rational(3080, 4951) + 1488 * sqrt(5) / 4951 - 130 * sqrt(34) / 4951 - 320 * sqrt(170) / 4951,
    Rational(6056, 4951) + 2720 * sqrt(5) / 4951 - 770 * sqrt(34) / 4951 - 372 * sqrt(170) / 4951,
    S(1),
]
d_printed = [sqrt(10), sqrt(10), 4 * sqrt(2), sqrt(85)]
d_right = [(Q.row(j) - Q.row(j - 1)).norm() for j in range(1, 5)]
check("Ex 2.9: d_4 = |Q_4 - Q_3| = 7*sqrt(2), not sqrt(85)", d_right[3] == 7 * sqrt(2))


def cumulative(d):
    total = sum(d)
    return [S(0)] + [radsimp(sum(d[:i]) / total) for i in range(1, len(d) + 1)]


t_from_printed_d = cumulative(d_printed)
check("Ex 2.9: the printed rationalisation equals sqrt(10)/(2sqrt(10)+4sqrt(2)+sqrt(85)) etc.", all(expand(a - b) == 0 for a, b in zip(printed, t_from_printed_d)))
right = cumulative(d_right)
check("Ex 2.9: t_1 = (11sqrt(5) - 10)/101, t_2 = (22sqrt(5) - 20)/101, t_3 = (14sqrt(5) + 24)/101",
      expand(right[1] - (11 * sqrt(5) - 10) / 101) == 0 and expand(right[2] - (22 * sqrt(5) - 20) / 101) == 0 and expand(right[3] - (14 * sqrt(5) + 24) / 101) == 0)
for i in range(1, 4):
    print("      t_%d right %.6f printed %.6f difference %+.6f" % (i, N(right[i]), N(printed[i]), N(printed[i] - right[i])))


def sse(ts, n):
    M = Matrix(5, n + 1, lambda r, c: B(c, n, ts[r])).evalf(40)
    R = Q - M * ((M.T * M).inv() * M.T * Q)
    return float(sum(x**2 for x in R))


# BezParamProp: the distance for t_i is |Q_{i-1}| from the origin, so t_0 = t_1 = 0.
origin = [Q.row(j).norm() for j in range(4)]
annex = [S(0)] + [radsimp(sum(origin[:i]) / sum(origin)) for i in range(1, 5)]
check("Annex III: t = 0, 0, 0.19913, 0.48074, 1", [round(float(x), 5) for x in annex] == [0, 0, 0.19913, 0.48074, 1])
for n in (2, 3):
    print("      n = %d: sse uniform %.3f, chord %.3f, printed t %.3f, Annex III %.3f" % (n, sse(uniform, n), sse(right, n), sse(printed, n), sse(annex, n)))
check("sse for n = 3: uniform 29/7, chord 0.237, Annex III 5.000", abs(sse(uniform, 3) - 29 / 7) < 1e-12 and round(sse(right, 3), 3) == 0.237 and round(sse(annex, 3), 3) == 5.0)

# --- Lemma 2.3: the matrix meets Def 2.8; the proof's c_2 expands to +2 tau p_0 --------------
A = Matrix([[0, 1, 0, 0], [-tau, 0, tau, 0], [2 * tau, tau - 3, 3 - 2 * tau, -tau], [-tau, 2 - tau, tau - 2, tau]])
c = A * Matrix([p0, p1, p2, p3])
p = sum(c[k] * s**k for k in range(4))
check("Lemma 2.3: p(0) = p1, p(1) = p2, p'(0) = tau(p2 - p0), p'(1) = tau(p3 - p1)",
      all(expand(e) == 0 for e in (p.subs(s, 0) - p1, p.subs(s, 1) - p2, p.diff(s).subs(s, 0) - tau * (p2 - p0), p.diff(s).subs(s, 1) - tau * (p3 - p1))))
c2 = expand(3 * (p2 - p1) - 2 * tau * (p2 - p0) - tau * (p3 - p1))
check("Lemma 2.3's proof: 3(p2-p1) - 2tau(p2-p0) - tau(p3-p1) has +2 tau p0 (printed: -2 tau p0)", expand(c2 - c[2]) == 0 and c2.coeff(p0) == 2 * tau)

# --- Ex 2.13: the twelve printed segments ------------------------------------------------------
half = Rational(1, 2)
q = [(3, 5), (2, 2), (6, 0), (8, 3), (7, 5)]


def seg(pts):
    C = A.subs(tau, half) * Matrix(pts)
    return [expand(sum(C[k, j] * s**k for k in range(4))) for j in range(2)]


check("Ex 2.13: p_1 cyclic = (s^3 + s^2/2 - 5s/2 + 3, 2s^3 - 7s^2/2 - 3s/2 + 5)", seg([q[4], q[0], q[1], q[2]]) == [s**3 + s**2 / 2 - 5 * s / 2 + 3, 2 * s**3 - 7 * s**2 / 2 - 3 * s / 2 + 5])
check("Ex 2.13: p_4 open = (2s^3 - 7s^2/2 + s/2 + 8, -s^3/2 + 5s/2 + 3)", seg([q[2], q[3], q[4], q[4]]) == [2 * s**3 - 7 * s**2 / 2 + s / 2 + 8, -(s**3) / 2 + 5 * s / 2 + 3])

# --- §4.1: where v_0 falls on Processing's screen (y down) -------------------------------------
r, n = 120, 10
alpha = 2 * math.pi / n
text_v0 = (r * math.cos(math.pi / 2), r * math.sin(math.pi / 2))
code_v0 = (r * math.cos(-math.pi / 2), r * math.sin(-math.pi / 2))
code_v1 = (r * math.cos(-math.pi / 2 + alpha), r * math.sin(-math.pi / 2 + alpha))
check("§4.1: the text's v_0 is below the centre (y grows downwards)", text_v0[1] > 0)
check("§4.1: Annex II's v_0 is above it and v_1 up and to the right (clockwise on screen)", code_v0[1] < 0 and code_v1[0] > 0 and code_v1[1] < 0)

# --- §4.5 and Annex II's five passes, the body alone, as SeedFrog.java orders it ---------------
cx, cy, C, Areal = 640.0, 360.0, 0.05, 20000.0


def polygon():
    v = [[cx + r * math.cos(-math.pi / 2 + i * alpha), cy + r * math.sin(-math.pi / 2 + i * alpha)] for i in range(n)]
    return v + [v[0][:]]


def area(v):  # calculaarea: (x_i - x_{i+1})(y_i + y_{i+1})/2, no absolute value
    return sum((v[i][0] - v[i + 1][0]) * (v[i][1] + v[i + 1][1]) / 2 for i in range(n))


def text_area(v):  # §4.5's words: positive when the second vertex has the larger x
    return sum((v[i + 1][0] - v[i][0]) * (v[i][1] + v[i + 1][1]) / 2 for i in range(n))


check("§4.5: calculaarea gives +42320.5 for Annex II's decagon; the text's sign -42320.5", round(area(polygon()), 1) == 42320.5 and round(text_area(polygon()), 1) == -42320.5)


def mean_corrections(v, passes, held=None):
    corr = [[0.0, 0.0] for _ in range(n + 1)]
    count = [0] * (n + 1)
    a, b = [None] * (n + 1), [None] * (n + 1)
    for i in range(n):  # molls = 1
        m = [(v[i][0] + v[i + 1][0]) / 2, (v[i][1] + v[i + 1][1]) / 2]
        d = [v[i][0] - v[i + 1][0], v[i][1] - v[i + 1][1]]
        length = math.hypot(*d)
        a[i] = [m[0] + 0.5 * d[0] / length, m[1] + 0.5 * d[1] / length]
        b[i + 1] = [m[0] - 0.5 * d[0] / length, m[1] - 0.5 * d[1] / length]
    a[n], b[0] = a[0][:], b[n][:]

    def add(i, dx, dy):
        corr[i][0] += dx
        corr[i][1] += dy
        count[i] += 1

    for _ in range(passes):
        for i in range(n + 1):
            add(i, a[i][0] - v[i][0], a[i][1] - v[i][1])
            add(i, b[i][0] - v[i][0], b[i][1] - v[i][1])
    if held:
        mouse, reach = held
        for i in (0, 1, n - 1, n):
            d = [v[i][0] - mouse[0], v[i][1] - mouse[1]]
            length = math.hypot(*d)
            add(i, mouse[0] + reach[i] * d[0] / length - v[i][0], mouse[1] + reach[i] * d[1] / length - v[i][1])
    F = C * (Areal - area(v)) / n
    for _ in range(passes):
        for i in range(n + 1):
            before, after = (n - 1 if i == 0 else i - 1), (1 if i == n else i + 1)
            nx, ny = v[after][1] - v[before][1], v[before][0] - v[after][0]
            length = math.hypot(nx, ny)
            add(i, F * nx / length, F * ny / length)
    return [[cc[0] / k, cc[1] / k] for cc, k in zip(corr, count)]


body = polygon()
for i in range(n + 1):
    body[i][1] += 5 * math.sin(i)  # deformed
five, one = mean_corrections(body, 5), mean_corrections(body, 1)
check("Annex II: not held, five passes = one pass (to rounding)", max(abs(x - y) for u, w in zip(five, one) for x, y in zip(u, w)) < 1e-12)
mouse = [cx, cy - 30]
reach = {i: 1.3 * math.dist(body[i], mouse) for i in (0, 1, n - 1, n)}
five, one = mean_corrections(body, 5, (mouse, reach)), mean_corrections(body, 1, (mouse, reach))
print("      held, vertex 1: five passes (%.2f, %.2f), one pass (%.2f, %.2f)" % (*five[1], *one[1]))
check("Annex II: held, the passes change an anchor's move (the grab weighs 1/16, not 1/4)", abs(five[1][0] - one[1][0]) > 1)
print("all checks hold")
