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
    return makeError(ErrorCode::TooFewPoints, "degree reduction needs at least two control points (degree 0 has nothing to reduce)");
}

/// The curve whose elevation P is, if there is one: R_0 = P_0, R_i = (P_i − (i/n) R_{i−1}) / (1 − i/n)
/// from degree_elevation.h's formula, then checked against P.
std::optional<std::vector<RPoint>> unelevate(const std::vector<RPoint>& P)
{
    const int n = static_cast<int>(P.size()) - 1;
    std::vector<RPoint> R{P[0]};
    for (int i = 1; i < n; ++i) {
        const Rational a = frac(i, n);
        const Rational b = Rational(1) - a;
        const RPoint prev = R.back();
        R.push_back(Rational(1 / b) * (P[static_cast<std::size_t>(i)] - a * prev));
    }
    if (elevateDegree(R) != P)
        return std::nullopt;
    return R;
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
        return makeError(ErrorCode::OutOfRange, "degree reduction is limited to degree 40 (the least-squares system is too ill-conditioned beyond)");
    for (const Point& p : P)
        if (!isFinite(p))
            return makeError(ErrorCode::InvalidInput, "degree reduction needs finite control points");
    const std::vector<RPoint> exactP = toRational(P);
    DegreeReduction<double> out;
    if (const auto R = unelevate(exactP)) {
        out.points = toDouble(*R);
        out.exact = true;
        return out;
    }
    auto M = reductionOperator(n);
    if (!M)
        return M.error();
    const Eigen::MatrixXd Md = M->toDouble();
    for (int i = 0; i < n; ++i) {
        Point q(0, 0);
        for (int k = 0; k <= n; ++k) {
            q.x += Md(i, k) * P[static_cast<std::size_t>(k)].x;
            q.y += Md(i, k) * P[static_cast<std::size_t>(k)].y;
        }
        out.points.push_back(q);
    }
    out.error = l2Error(exactP, toRational(out.points));
    return out;
}

} // namespace granota
