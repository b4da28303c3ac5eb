#include "core/curves/bezier/degree_reduction.h"

#include "core/curves/bezier/degree_elevation.h"
#include "core/exact/rational_matrix.h"

#include <cmath>

namespace granota {

namespace {

/// ∫_0^1 B_i^a B_j^b = C(a,i) C(b,j) / ((a+b+1) C(a+b, i+j)).
Rational bernsteinProductIntegral(int a, int i, int b, int j)
{
    Rational q = binomial(a, i) * binomial(b, j) / (Rational(a + b + 1) * binomial(a + b, i + j));
    q.canonicalize();
    return q;
}

/// G⁻¹H, (m+1)×(n+1), m = n − 1: the reduced control points are this times P.
Expected<RationalMatrix> reductionOperator(int n)
{
    const int m = n - 1;
    RationalMatrix G(m + 1, m + 1), H(m + 1, n + 1);
    for (int i = 0; i <= m; ++i) {
        for (int j = 0; j <= m; ++j)
            G(i, j) = bernsteinProductIntegral(m, i, m, j);
        for (int k = 0; k <= n; ++k)
            H(i, k) = bernsteinProductIntegral(m, i, n, k);
    }
    return G.solve(H);
}

/// ∫|Σ B_k^n d_k|² = Σ_kl d_k·d_l ∫B_k^n B_l^n, exactly.
Rational squaredL2(const std::vector<RPoint>& d)
{
    const int n = static_cast<int>(d.size()) - 1;
    Rational s(0);
    for (int k = 0; k <= n; ++k)
        for (int l = 0; l <= n; ++l) {
            const auto& a = d[static_cast<std::size_t>(k)];
            const auto& b = d[static_cast<std::size_t>(l)];
            s += bernsteinProductIntegral(n, k, n, l) * (a.x * b.x + a.y * b.y);
        }
    return s;
}

double l2Error(const std::vector<RPoint>& P, const std::vector<RPoint>& reduced)
{
    const std::vector<RPoint> r = elevateDegree(reduced);
    std::vector<RPoint> d;
    for (std::size_t i = 0; i < P.size(); ++i)
        d.push_back(P[i] - r[i]);
    const double e2 = toDouble(squaredL2(d));
    return std::sqrt(std::max(0.0, e2));
}

Error nothingToReduce()
{
    return makeError(ErrorCode::TooFewPoints,
                     "degree reduction needs at least two control points (degree 0 has nothing to reduce)");
}

} // namespace

Expected<DegreeReduction<Rational>> reduceDegree(const std::vector<RPoint>& P)
{
    if (P.size() < 2)
        return nothingToReduce();
    const int n = static_cast<int>(P.size()) - 1;
    auto M = reductionOperator(n);
    if (!M)
        return M.error();
    DegreeReduction<Rational> out;
    for (int i = 0; i < n; ++i) {
        RPoint q(Rational(0), Rational(0));
        for (int k = 0; k <= n; ++k)
            q += (*M)(i, k) * P[static_cast<std::size_t>(k)];
        out.points.push_back(q);
    }
    out.exact = elevateDegree(out.points) == P;
    out.error = out.exact ? 0.0 : l2Error(P, out.points);
    return out;
}

Expected<DegreeReduction<double>> reduceDegree(const std::vector<Point>& P)
{
    if (P.size() < 2)
        return nothingToReduce();
    const int n = static_cast<int>(P.size()) - 1;
    if (n > 40)
        return makeError(ErrorCode::OutOfRange,
                         "degree reduction is limited to degree 40 (the least-squares system is too ill-conditioned beyond)");
    for (const Point& p : P)
        if (!isFinite(p))
            return makeError(ErrorCode::InvalidInput, "degree reduction needs finite control points");
    // Every double is a rational: reduce exactly and round once, so the points are the
    // correctly rounded optimum and the error is that of the rounded points.
    auto r = reduceDegree(toRational(P));
    if (!r)
        return r.error();
    DegreeReduction<double> out;
    out.points = toDouble(r->points);
    out.exact = r->exact;
    out.error = r->exact ? 0.0 : l2Error(toRational(P), toRational(out.points));
    return out;
}

} // namespace granota
