#include "core/curves/splines/monotone_spline.h"

#include "core/base/enum_names.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace granota {

namespace {

constexpr std::array<EnumName<MonotoneMethod>, 2> kMonotoneMethodNames{
    {{MonotoneMethod::FritschCarlson, "fritsch-carlson"}, {MonotoneMethod::Steffen, "steffen"}}};

/// Fritsch–Carlson's circle α² + β² ≤ 9 lies in the monotonicity region, but touches its edge
/// at (3, 0) and (0, 3); slopes scaled onto the circle of radius 3 itself can be carried just
/// outside by rounding, where the exact proof would (rightly) fail. A radius smaller by a
/// relative 10⁻¹² leaves room for the few units in the last place that rounding costs.
constexpr double kFritschCarlsonRadius = 3.0 * (1.0 - 1e-12);

double sign(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

/// The slope at x_i of the parabola through points i−1, i, i+1 (three-point formula), and at
/// an end the one-sided parabola's slope (Steffen eq. 26; FC 1980 step 1).
double interiorParabolaSlope(double d0, double d1, double h0, double h1) { return (d0 * h1 + d1 * h0) / (h0 + h1); }
double endParabolaSlope(double dNear, double dFar, double hNear, double hFar)
{
    return dNear * (1.0 + hNear / (hNear + hFar)) - dFar * hNear / (hNear + hFar);
}

std::vector<double> fritschCarlson(const std::vector<double>& h, const std::vector<double>& d)
{
    const std::size_t k = d.size(), n = k + 1;
    std::vector<double> m(n);
    if (k == 1)
        return {d[0], d[0]};
    // Step 1: the three-point formula; step 2: 0 at a local extremum of the data and beside a flat step.
    m[0] = endParabolaSlope(d[0], d[1], h[0], h[1]);
    m[k] = endParabolaSlope(d[k - 1], d[k - 2], h[k - 1], h[k - 2]);
    if (m[0] * d[0] <= 0)
        m[0] = 0;
    if (m[k] * d[k - 1] <= 0)
        m[k] = 0;
    for (std::size_t i = 1; i < k; ++i)
        m[i] = d[i - 1] * d[i] <= 0 ? 0.0 : interiorParabolaSlope(d[i - 1], d[i], h[i - 1], h[i]);
    // Step 3: (α, β) of each piece onto the circle when outside it. Shrinking a slope only
    // moves the neighbouring piece's (α, β) towards the origin, inside the circle still.
    for (std::size_t i = 0; i < k; ++i) {
        if (d[i] == 0)
            continue;
        const double alpha = m[i] / d[i], beta = m[i + 1] / d[i];
        const double radius = std::hypot(alpha, beta);
        if (radius > kFritschCarlsonRadius) {
            const double tau = kFritschCarlsonRadius / radius;
            m[i] = tau * alpha * d[i];
            m[i + 1] = tau * beta * d[i];
        }
    }
    return m;
}

std::vector<double> steffen(const std::vector<double>& h, const std::vector<double>& d)
{
    const std::size_t k = d.size(), n = k + 1;
    if (k == 1)
        return {d[0], d[0]};
    std::vector<double> m(n);
    // Eq. 11: interior slopes.
    for (std::size_t i = 1; i < k; ++i) {
        const double p = interiorParabolaSlope(d[i - 1], d[i], h[i - 1], h[i]);
        m[i] = (sign(d[i - 1]) + sign(d[i])) * std::min({std::abs(d[i - 1]), std::abs(d[i]), std::abs(p) / 2});
    }
    // Eq. 26–27: the ends.
    const auto end = [](double p, double dNear) {
        if (p * dNear <= 0)
            return 0.0;
        return std::abs(p) > 2 * std::abs(dNear) ? 2 * dNear : p;
    };
    m[0] = end(endParabolaSlope(d[0], d[1], h[0], h[1]), d[0]);
    m[k] = end(endParabolaSlope(d[k - 1], d[k - 2], h[k - 1], h[k - 2]), d[k - 1]);
    return m;
}

/// The sign test on a quadratic in Bernstein form Σ e_j B_j²: ≥ 0 on [0, 1].
bool nonNegativeQuadratic(const std::array<Rational, 3>& e, bool& byControlPolygon)
{
    byControlPolygon = e[0] >= 0 && e[1] >= 0 && e[2] >= 0;
    if (byControlPolygon)
        return true;
    return e[0] >= 0 && e[2] >= 0 && e[1] * e[1] <= e[0] * e[2];
}

} // namespace

std::string_view monotoneMethodName(MonotoneMethod method) { return nameOf(kMonotoneMethodNames, method, "steffen"); }
std::optional<MonotoneMethod> parseMonotoneMethod(std::string_view name) { return parseName(kMonotoneMethodNames, name); }

Expected<std::vector<double>> monotoneSlopes(const std::vector<Vec2<double>>& data, MonotoneMethod method)
{
    const std::size_t n = data.size();
    if (n < 2)
        return makeError(ErrorCode::TooFewPoints,
                         "Monotone interpolation needs at least 2 points (got " + std::to_string(n) + ").");
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(data[i].x) || !std::isfinite(data[i].y))
            return makeError(ErrorCode::InvalidInput,
                             "Point " + std::to_string(i) + " is not a finite number (NaN or infinity).");
    for (std::size_t i = 0; i + 1 < n; ++i)
        if (!(data[i].x < data[i + 1].x))
            return makeError(ErrorCode::NotIncreasing, "The abscissae must increase strictly: x_" + std::to_string(i + 1) +
                                                           " is not greater than x_" + std::to_string(i) + ".");
    std::vector<double> h(n - 1), d(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        h[i] = data[i + 1].x - data[i].x;
        d[i] = (data[i + 1].y - data[i].y) / h[i];
        if (!std::isfinite(h[i]) || !std::isfinite(d[i]))
            return makeError(ErrorCode::OutOfRange, "The data overflow: the coordinates are too large or too close together.");
    }
    std::vector<double> m = method == MonotoneMethod::FritschCarlson ? fritschCarlson(h, d) : steffen(h, d);
    for (double v : m)
        if (!std::isfinite(v))
            return makeError(ErrorCode::OutOfRange, "The data overflow: the coordinates are too large or too close together.");
    return m;
}

Expected<PiecewisePolynomial<double>> monotoneSpline(const std::vector<Vec2<double>>& data, MonotoneMethod method)
{
    auto slopes = monotoneSlopes(data, method);
    if (!slopes)
        return slopes.error();
    const std::vector<double>& m = *slopes;
    PiecewisePolynomial<double> spline;
    spline.localOrigin = true;
    for (const auto& p : data)
        spline.knots.push_back(p.x);
    for (std::size_t i = 0; i + 1 < data.size(); ++i) {
        // The Hermite cubic in u = x − x_i: y_i + m_i u + c u² + e u³.
        const double h = data[i + 1].x - data[i].x, delta = (data[i + 1].y - data[i].y) / h;
        const double c = (3 * delta - 2 * m[i] - m[i + 1]) / h;
        const double e = (m[i] + m[i + 1] - 2 * delta) / (h * h);
        if (!std::isfinite(c) || !std::isfinite(e))
            return makeError(ErrorCode::OutOfRange, "The data overflow: the coordinates are too large or too close together.");
        spline.pieces.push_back(Polynomial<double>(std::vector<double>{data[i].y, m[i], c, e}));
    }
    return spline;
}

MonotonePieceProof proveMonotonePiece(double y0, double y1, double m0, double m1, double h)
{
    assert(std::isfinite(y0) && std::isfinite(y1) && std::isfinite(m0) && std::isfinite(m1) && h > 0);
    const Rational a = exactRational(y0), b = exactRational(y1), length = exactRational(h);
    MonotonePieceProof proof;
    proof.bernstein = {a, Rational(a + length * exactRational(m0) / 3), Rational(b - length * exactRational(m1) / 3), b};
    for (std::size_t j = 0; j < 3; ++j)
        proof.derivativeBernstein[j] = 3 * (proof.bernstein[j + 1] - proof.bernstein[j]);
    const auto& e = proof.derivativeBernstein;
    const std::array<Rational, 3> negated{Rational(-e[0]), Rational(-e[1]), Rational(-e[2])};
    bool polygonUp = false, polygonDown = false;
    if (e[0] == 0 && e[1] == 0 && e[2] == 0) {
        proof.verdict = PieceMonotonicity::Constant;
        proof.byControlPolygon = true;
    } else if (nonNegativeQuadratic(e, polygonUp)) {
        proof.verdict = PieceMonotonicity::Increasing;
        proof.byControlPolygon = polygonUp;
    } else if (nonNegativeQuadratic(negated, polygonDown)) {
        proof.verdict = PieceMonotonicity::Decreasing;
        proof.byControlPolygon = polygonDown;
    }
    const Rational& low = std::min(a, b);
    const Rational& high = std::max(a, b);
    proof.withinData = std::all_of(proof.bernstein.begin(), proof.bernstein.end(),
                                   [&](const Rational& v) { return low <= v && v <= high; });
    return proof;
}

std::vector<MonotonePieceProof> proveMonotone(const std::vector<Vec2<double>>& data, const std::vector<double>& slopes)
{
    assert(data.size() == slopes.size());
    std::vector<MonotonePieceProof> proofs;
    for (std::size_t i = 0; i + 1 < data.size(); ++i)
        proofs.push_back(proveMonotonePiece(data[i].y, data[i + 1].y, slopes[i], slopes[i + 1], data[i + 1].x - data[i].x));
    return proofs;
}

} // namespace granota
