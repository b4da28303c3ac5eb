#include "core/curves/splines/catmull_rom.h"

#include "core/base/number_format.h"
#include "core/base/enum_names.h"

#include <algorithm>
#include <cassert>
#include <cctype>

namespace granota {

// Def 2.10's options, by the names the CLI and the saved documents use.
constexpr std::array<EnumName<CatmullRomMode>, 3> kModeNames{
    {{CatmullRomMode::Open, "open"}, {CatmullRomMode::Cyclic, "cyclic"}, {CatmullRomMode::Closed, "closed"}}};

std::optional<CatmullRomMode> parseCatmullRomMode(std::string_view text)
{
    return parseName(kModeNames, text, NameMatch::IgnoreCaseTrim); // "  Closed " is closed
}

std::string toString(CatmullRomMode mode) { return std::string(nameOf(kModeNames, mode, "open")); }

Expected<std::vector<std::array<int, 4>>> catmullRomQuadruples(std::size_t count, CatmullRomMode mode)
{
    const bool open = mode == CatmullRomMode::Open;
    const std::size_t needed = open ? 2 : 3;
    if (count < needed)
        return makeError(ErrorCode::TooFewPoints, "A" + std::string(open ? "n " : " ") + toString(mode) +
                                                      " Catmull-Rom curve needs at least " + std::to_string(needed) +
                                                      " points (got " + std::to_string(count) + ").");
    const int last = static_cast<int>(count) - 1; // n: the points are q_0..q_n
    const int size = static_cast<int>(count);
    // Def 2.10: segment p_i (i = 1..n) is fed by q_{i−2}, q_{i−1}, q_i, q_{i+1}.
    const auto index = [&](int j) {
        if (open) // option 2: q_{−1} := q_0 and q_{n+1} := q_n give p_1′(0) = τ(q_1 − q_0), p_n′(1) = τ(q_n − q_{n−1})
            return std::clamp(j, 0, last);
        return ((j % size) + size) % size; // option 1: q_{−1} = q_n, q_{n+1} = q_0
    };
    std::vector<std::array<int, 4>> quads;
    // Closed: the extra segment q_n → q_0 "taking the last but one as previous and the
    // second as next" (Def 2.10, option 1) is p_{n+1}, fed by q_{n−1}, q_n, q_{n+1} = q_0, q_1.
    const int segments = mode == CatmullRomMode::Closed ? last + 1 : last;
    quads.reserve(static_cast<std::size_t>(segments));
    for (int i = 1; i <= segments; ++i)
        quads.push_back({index(i - 2), index(i - 1), index(i), index(i + 1)});
    return quads;
}

namespace detail {

Error catmullRomNonFinitePoint(std::size_t index)
{
    return makeError(ErrorCode::InvalidInput, "Point q_" + std::to_string(index) + " is not a finite number (NaN or infinity).");
}

Error catmullRomNonFiniteTension() { return makeError(ErrorCode::InvalidInput, "The tension τ must be a finite number."); }

Error catmullRomOverflow()
{
    return makeError(ErrorCode::OutOfRange, "The Catmull-Rom curve overflows: the coordinates or the tension are too large.");
}

} // namespace detail

template Expected<std::vector<Vec2<Polynomial<double>>>> catmullRomSegments(const std::vector<Vec2<double>>&, const double&,
                                                                            CatmullRomMode);
template Expected<std::vector<Vec2<Polynomial<Rational>>>> catmullRomSegments(const std::vector<Vec2<Rational>>&, const Rational&,
                                                                              CatmullRomMode);

namespace {

Error alphaOutOfRange(double alpha)
{
    return makeError(ErrorCode::OutOfRange, "The parametrization exponent α must lie between 0 (uniform) and 1 (chordal); got " +
                                                formatDouble(alpha) + ".");
}

} // namespace

Expected<std::vector<Vec2<Polynomial<double>>>> catmullRomSegments(const std::vector<Point>& q, double tau, CatmullRomMode mode,
                                                                   double alpha)
{
    if (!(alpha >= 0.0 && alpha <= 1.0)) // also rejects NaN
        return alphaOutOfRange(alpha);
    if (alpha == 0.0)
        return catmullRomSegments<double>(q, tau, mode); // uniform: the thesis's curve (Lemma 2.3), bit for bit
    auto segments = catmullRomHermiteSegments(q, tau, mode, alpha);
    if (!segments)
        return segments.error();
    auto polynomials = hermitePolynomials(*segments);
    for (const auto& s : polynomials)
        for (const auto* p : {&s.x, &s.y})
            for (double c : p->coefficients())
                if (!std::isfinite(c))
                    return detail::catmullRomOverflow();
    return polynomials;
}

Expected<std::vector<HermiteSegment<double>>> catmullRomHermiteSegments(const std::vector<Point>& q, double tau,
                                                                        CatmullRomMode mode, double alpha)
{
    if (!(alpha >= 0.0 && alpha <= 1.0)) // also rejects NaN
        return alphaOutOfRange(alpha);
    if (alpha == 0.0)
        return catmullRomHermiteSegments<double>(q, tau, mode);
    for (std::size_t i = 0; i < q.size(); ++i)
        if (!isFinite(q[i]))
            return detail::catmullRomNonFinitePoint(i);
    if (!std::isfinite(tau))
        return detail::catmullRomNonFiniteTension();
    const auto quads = catmullRomQuadruples(q.size(), mode);
    if (!quads)
        return quads.error();

    const bool open = mode == CatmullRomMode::Open;
    const std::size_t count = q.size();
    const std::size_t n = count - 1;
    const auto next = [count](std::size_t i) { return (i + 1) % count; };
    const auto prev = [count](std::size_t i) { return (i + count - 1) % count; };

    // Knot spacing h_j = |q_{j+1} − q_j|^α and difference quotients d_j = (q_{j+1} − q_j)/h_j
    // (0 for coincident points); j = n is the wrap-around q_n → q_0.
    std::vector<double> h(count, 0.0);
    std::vector<Point> d(count, Point(0.0, 0.0));
    for (std::size_t j = 0; j < count; ++j) {
        const Point delta = q[next(j)] - q[j];
        const double length = norm(delta);
        h[j] = length > 0.0 ? std::pow(length, alpha) : 0.0;
        if (h[j] > 0.0)
            d[j] = Point(delta.x / h[j], delta.y / h[j]);
    }
    // Tangent m_i at the knot q_i in the global parameter: the spacing-weighted mean of the
    // two neighbouring difference quotients (for uniform spacing (q_{i+1} − q_{i−1})/2).
    const auto tangent = [&](std::size_t i) {
        const std::size_t before = prev(i);
        const double denominator = h[before] + h[i];
        if (!(denominator > 0.0))
            return Point(0.0, 0.0);
        return Point((d[before].x * h[i] + d[i].x * h[before]) / denominator,
                     (d[before].y * h[i] + d[i].y * h[before]) / denominator);
    };

    std::vector<HermiteSegment<double>> segments;
    segments.reserve(quads->size());
    for (std::size_t i = 0; i < quads->size(); ++i) {
        const Point& p0 = q[i];
        const Point& p1 = q[next(i)];
        // Local tangents: the chain rule turns the global m into 2τ m h_i on s ∈ [0, 1]
        // (2τ: the thesis's τ = 1/2 is the plain Hermite tangent).
        const double scale = 2.0 * tau * h[i];
        Point t0 = scale * tangent(i);
        Point t1 = scale * tangent(next(i));
        if (open && i == 0) // Def 2.10 option 2
            t0 = tau * (q[1] - q[0]);
        if (open && i + 1 == n)
            t1 = tau * (q[n] - q[n - 1]);
        segments.push_back({p0, p1, t0, t1});
    }
    for (const auto& g : segments)
        if (!isFinite(g.m0) || !isFinite(g.m1))
            return detail::catmullRomOverflow();
    return segments;
}

std::vector<double> catmullRomIntervals(const std::vector<Point>& q, CatmullRomMode mode, double alpha)
{
    if (!(alpha >= 0.0 && alpha <= 1.0))
        return {};
    for (const Point& p : q)
        if (!isFinite(p))
            return {};
    const auto quads = catmullRomQuadruples(q.size(), mode);
    if (!quads)
        return {};
    // Segment i runs from q_i to q_{i+1} (mod n + 1 for the closing one), as in catmullRomSegments().
    std::vector<double> h;
    h.reserve(quads->size());
    for (std::size_t i = 0; i < quads->size(); ++i) {
        if (alpha == 0.0) {
            h.push_back(1.0);
            continue;
        }
        const double length = norm(q[(i + 1) % q.size()] - q[i]);
        h.push_back(length > 0.0 ? std::pow(length, alpha) : 0.0);
    }
    return h;
}

std::vector<Point> sampleSegments(const std::vector<Vec2<Polynomial<double>>>& segments, int samplesPerSegment)
{
    assert(samplesPerSegment >= 2);
    std::vector<Point> out;
    out.reserve(segments.size() * static_cast<std::size_t>(samplesPerSegment));
    const double step = 1.0 / (samplesPerSegment - 1);
    for (const auto& segment : segments)
        for (int j = 0; j < samplesPerSegment; ++j) {
            const double s = j == samplesPerSegment - 1 ? 1.0 : j * step; // exact end
            out.emplace_back(segment.x(s), segment.y(s));
        }
    return out;
}

} // namespace granota
