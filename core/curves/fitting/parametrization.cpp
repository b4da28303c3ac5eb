#include "core/curves/fitting/parametrization.h"

#include "core/base/enum_names.h"
#include "core/exact/square_root.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace granota {

namespace {

constexpr std::array<EnumName<Parametrization>, 4> kParametrizationNames{{
    {Parametrization::Uniform, "uniform"},
    {Parametrization::ChordLength, "chord"},
    {Parametrization::Centripetal, "centripetal"},
    {Parametrization::AnnexIII, "annex-iii"},
}};

std::vector<double> uniformParameters(std::size_t count)
{
    std::vector<double> t(count, 0.0);
    if (count < 2)
        return t;
    const double k = static_cast<double>(count - 1);
    for (std::size_t i = 0; i < count; ++i)
        t[i] = static_cast<double>(i) / k; // t_i = i/k, exactly 1 at i = k
    return t;
}

std::vector<Rational> uniformExact(std::size_t count)
{
    std::vector<Rational> t(count, Rational(0));
    if (count < 2)
        return t;
    const long k = static_cast<long>(count - 1);
    for (std::size_t i = 0; i < count; ++i) {
        t[i] = Rational(static_cast<long>(i), k);
        t[i].canonicalize();
    }
    return t;
}

} // namespace

std::optional<Parametrization> parseParametrization(std::string_view text)
{
    return parseName(kParametrizationNames, text, NameMatch::IgnoreCase);
}

std::string toString(Parametrization p) { return std::string(nameOf(kParametrizationNames, p, "uniform")); }

std::vector<double> parameters(const std::vector<Point>& q, Parametrization p, bool* fellBackToUniform)
{
    if (fellBackToUniform)
        *fellBackToUniform = false;
    if (p == Parametrization::Uniform || q.size() < 2)
        return uniformParameters(q.size());

    // Scale by a power of two (exact, so the ratios are unchanged) so that neither the
    // differences nor the sum of up to millions of distances can overflow or underflow.
    double largest = 0.0;
    for (const Point& point : q)
        largest = std::max({largest, std::fabs(point.x), std::fabs(point.y)});
    const int exponent = (std::isfinite(largest) && largest > 0.0) ? std::ilogb(largest) : 0;
    const auto scaled = [exponent](double v) { return std::ldexp(v, -exponent); };

    // d_j = dist(Q_{j−1}, Q_j) (§2.1.3), or √d_j for centripetal, or |Q_{j−1}| as Annex III
    // computes it; t_i = Σ_{j≤i} d_j / Σ d_j.
    std::vector<double> t(q.size(), 0.0);
    double total = 0.0;
    for (std::size_t j = 1; j < q.size(); ++j) {
        double d = p == Parametrization::AnnexIII
                       ? std::hypot(scaled(q[j - 1].x), scaled(q[j - 1].y))
                       : std::hypot(scaled(q[j].x) - scaled(q[j - 1].x), scaled(q[j].y) - scaled(q[j - 1].y));
        if (std::isnan(d)) // Q contains NaN; inf differences of huge points are caught below
            d = std::numeric_limits<double>::infinity();
        if (p == Parametrization::Centripetal)
            d = std::sqrt(d);
        total += d;
        t[j] = total;
    }
    if (!(total > 0.0) || !std::isfinite(total)) {
        if (fellBackToUniform)
            *fellBackToUniform = true;
        return uniformParameters(q.size());
    }
    for (std::size_t i = 1; i + 1 < q.size(); ++i)
        t[i] = std::min(t[i] / total, 1.0);
    t.back() = 1.0;
    return t;
}

std::optional<std::vector<Rational>> exactParameters(const std::vector<RPoint>& q, Parametrization p, bool* fellBackToUniform)
{
    if (fellBackToUniform)
        *fellBackToUniform = false;
    if (p == Parametrization::Uniform || q.size() < 2)
        return uniformExact(q.size());

    std::vector<Rational> t(q.size(), Rational(0));
    Rational total(0);
    for (std::size_t j = 1; j < q.size(); ++j) {
        const bool annex = p == Parametrization::AnnexIII; // |Q_{j−1}|, as BezParamProp
        const Rational dx = annex ? q[j - 1].x : Rational(q[j].x - q[j - 1].x);
        const Rational dy = annex ? q[j - 1].y : Rational(q[j].y - q[j - 1].y);
        std::optional<Rational> d = exactSqrt(Rational(dx * dx + dy * dy));
        if (d && p == Parametrization::Centripetal)
            d = exactSqrt(*d);
        if (!d)
            return std::nullopt; // an irrational distance (or square root of one)
        total += *d;
        t[j] = total;
    }
    if (sgn(total) == 0) {
        if (fellBackToUniform)
            *fellBackToUniform = true;
        return uniformExact(q.size());
    }
    for (std::size_t i = 1; i < q.size(); ++i)
        t[i] /= total;
    return t;
}

std::optional<std::vector<RadicalQuotient>> radicalParameters(const std::vector<RPoint>& q, Parametrization p)
{
    if ((p != Parametrization::ChordLength && p != Parametrization::AnnexIII) || q.size() < 2 || q.size() > kMaxRadicalPoints)
        return std::nullopt;
    std::vector<RadicalSum> partial(q.size()); // S_i = d_1 + … + d_i, S_0 = 0
    for (std::size_t j = 1; j < q.size(); ++j) {
        const bool annex = p == Parametrization::AnnexIII; // |Q_{j−1}|, as BezParamProp
        const Rational dx = annex ? q[j - 1].x : Rational(q[j].x - q[j - 1].x);
        const Rational dy = annex ? q[j - 1].y : Rational(q[j].y - q[j - 1].y);
        const std::optional<SimplifiedSquareRoot> d = simplifySquareRoot(Rational(dx * dx + dy * dy));
        if (!d)
            return std::nullopt; // too large to simplify quickly
        partial[j] = partial[j - 1] + RadicalSum(*d);
    }
    const RadicalSum& total = partial.back();
    if (total.isZero())
        return std::nullopt; // all coincide: parameters() falls back to uniform
    std::vector<RadicalQuotient> t;
    for (const RadicalSum& s : partial)
        t.push_back(*divide(s, total)); // total ≠ 0
    return t;
}

} // namespace granota
