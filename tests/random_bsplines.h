#pragma once
/// \file random_bsplines.h
/// B-splines with rational knots, points and weights from a seeded generator, for the exact
/// tests of core/curves/bsplines/: clamped or floating ends, interior knots repeated up to a
/// given multiplicity, and the parameters worth evaluating at.
#include "core/curves/bsplines/bspline_curve.h"
#include "rational_points.h"

#include <random>
#include <vector>

namespace granota::testing {

struct RandomBSplineOptions {
    int degree = 3;
    int maxMultiplicity = 1; ///< of each interior knot, 1..degree
    int maxInterior = 3;     ///< distinct interior knots, 0..maxInterior
    bool clamped = true;     ///< p + 1 equal knots at each end, else p + 1 distinct ones
    bool rational = false;   ///< weights a/b in [1/3, 5]
};

inline BSplineCurve<Rational> randomBSpline(std::mt19937& rng, const RandomBSplineOptions& o)
{
    std::uniform_int_distribution<int> step(1, 5), stepDen(1, 4), mult(1, o.maxMultiplicity), interior(0, o.maxInterior),
        wNum(1, 15), wDen(1, 3);
    BSplineCurve<Rational> c;
    c.degree = o.degree;
    Rational u(0);
    const auto group = [&](int m) {
        for (int i = 0; i < m; ++i)
            c.knots.push_back(u);
        u += frac(step(rng), stepDen(rng));
    };
    for (int i = 0; i < (o.clamped ? 1 : o.degree + 1); ++i)
        group(o.clamped ? o.degree + 1 : 1);
    const int d = interior(rng);
    for (int i = 0; i < d; ++i)
        group(mult(rng));
    for (int i = 0; i < (o.clamped ? 1 : o.degree + 1); ++i)
        group(o.clamped ? o.degree + 1 : 1);
    const int n = static_cast<int>(c.knots.size()) - o.degree - 2;
    c.points = randomRational(rng, n);
    if (o.rational)
        for (int i = 0; i <= n; ++i)
            c.weights.push_back(frac(wNum(rng), wDen(rng)));
    return c;
}

/// Parameters in the domain worth evaluating at: every distinct knot in it, and three
/// rational points inside each non-empty span (1/3, 1/2 and 5/7 of the way).
inline std::vector<Rational> testParameters(const BSplineCurve<Rational>& c)
{
    std::vector<Rational> us;
    const auto p = static_cast<std::size_t>(c.degree);
    for (std::size_t k = p; k < c.points.size(); ++k) {
        const Rational& a = c.knots[k];
        const Rational& b = c.knots[k + 1];
        if (!(a < b))
            continue;
        us.push_back(a);
        for (const Rational& f : {frac(1, 3), frac(1, 2), frac(5, 7)})
            us.push_back(Rational(a + f * (b - a)));
    }
    us.push_back(c.domainEnd());
    return us;
}

} // namespace granota::testing
