#include "core/curves/splines/kochanek_bartels.h"

#include "core/base/number_format.h"

#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

namespace granota {

namespace {

template <class S> std::string valueText(const S& v)
{
    if constexpr (std::is_same_v<S, Rational>)
        return toString(v);
    else
        return formatDouble(v);
}

template <class S> bool finite(const S& v)
{
    if constexpr (std::is_floating_point_v<S>)
        return std::isfinite(v);
    else
        return true;
}

template <class S> bool finite(const Vec2<S>& v) { return finite(v.x) && finite(v.y); }

/// Refuses a triple with a value that is not finite, or C or B outside [−1, 1] (the header says why).
template <class S> Expected<bool> checkKnot(const TcbKnot<S>& k, std::size_t index, bool shared)
{
    const std::string where = shared ? std::string() : " at point " + std::to_string(index);
    const std::pair<const char*, const S*> values[] = {{"tension T", &k.tension},
                                                       {"continuity C", &k.continuity},
                                                       {"bias B", &k.bias}};
    for (const auto& [name, value] : values)
        if (!finite(*value))
            return makeError(ErrorCode::InvalidInput, std::string("The ") + name + where + " is not a finite number.");
    for (const auto& [name, value] : {values[1], values[2]})
        if (*value < S(-1) || *value > S(1))
            return makeError(ErrorCode::OutOfRange, std::string("The ") + name + where + " must lie between -1 and 1 (got " +
                                                        valueText(*value) + "): outside, a tangent points against its chord.");
    return true;
}

} // namespace

template <class S>
Expected<KochanekBartelsCurve<S>> kochanekBartels(const std::vector<Vec2<S>>& points, const std::vector<TcbKnot<S>>& perPoint,
                                                  CatmullRomMode mode, double alpha)
{
    constexpr bool exact = std::is_same_v<S, Rational>;
    if (!(alpha >= 0.0 && alpha <= 1.0)) // also rejects NaN
        return makeError(ErrorCode::OutOfRange,
                         "The parametrization exponent α must lie between 0 (uniform) and 1 (chordal); got " +
                             formatDouble(alpha) + ".");
    if (exact && alpha != 0.0)
        return makeError(ErrorCode::NotRational,
                         "An exact Kochanek–Bartels curve needs α = 0: centripetal and chordal knots are powers of distances.");
    const bool open = mode == CatmullRomMode::Open;
    const std::size_t count = points.size();
    const std::size_t needed = open ? 2 : 3;
    if (count < needed)
        return makeError(ErrorCode::TooFewPoints, "A" + std::string(open ? "n " : " ") + toString(mode) +
                                                      " Kochanek–Bartels curve needs at least " + std::to_string(needed) +
                                                      " points (got " + std::to_string(count) + ").");
    for (std::size_t i = 0; i < count; ++i)
        if (!finite(points[i]))
            return makeError(ErrorCode::InvalidInput,
                             "Point " + std::to_string(i) + " is not a finite number (NaN or infinity).");
    if (perPoint.size() != 1 && perPoint.size() != count)
        return makeError(ErrorCode::InvalidInput, "Give one tension, continuity and bias for all points or one per point (" +
                                                      std::to_string(count) + "), not " + std::to_string(perPoint.size()) + ".");
    for (std::size_t i = 0; i < perPoint.size(); ++i)
        if (auto ok = checkKnot(perPoint[i], i, perPoint.size() == 1); !ok)
            return ok.error();

    // Def 2.10's neighbours: open repeats the end points, cyclic and closed wrap around.
    const std::size_t last = count - 1;
    const auto before = [&](std::size_t i) { return i == 0 ? (open ? 0 : last) : i - 1; };
    const auto after = [&](std::size_t i) { return i == last ? (open ? last : 0) : i + 1; };
    // Knot spacing h of the step from P_i to P_j (doubles only; uniform spacing is 1).
    const auto spacing = [&](std::size_t i, std::size_t j) {
        if constexpr (exact)
            return 1.0;
        else {
            const double length = norm(points[j] - points[i]);
            return length > 0.0 ? std::pow(length, alpha) : 0.0;
        }
    };

    const S one(1), two(2);
    KochanekBartelsCurve<S> curve;
    curve.tangents.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const TcbKnot<S>& k = perPoint.size() == 1 ? perPoint.front() : perPoint[i];
        const Vec2<S> incoming = points[i] - points[before(i)]; // Δ₋
        const Vec2<S> outgoing = points[after(i)] - points[i];  // Δ₊
        const S half = S((one - k.tension) / two);
        const S plusB = S(one + k.bias), minusB = S(one - k.bias);
        const S plusC = S(one + k.continuity), minusC = S(one - k.continuity);
        KbTangents<S> t;
        t.in = half * (S(plusB * minusC) * incoming + S(minusB * plusC) * outgoing);
        t.out = half * (S(plusB * plusC) * incoming + S(minusB * minusC) * outgoing);
        if constexpr (!exact) {
            const bool end = open && (i == 0 || i == last);
            if (alpha != 0.0 && !end) { // the paper's adjustment for unequal parameter steps
                const double hBefore = spacing(before(i), i), hAfter = spacing(i, after(i));
                const double sum = hBefore + hAfter;
                t.in = sum > 0.0 ? (2.0 * hBefore / sum) * t.in : Point(0.0, 0.0);
                t.out = sum > 0.0 ? (2.0 * hAfter / sum) * t.out : Point(0.0, 0.0);
            }
            if (!finite(t.in) || !finite(t.out))
                return makeError(ErrorCode::OutOfRange,
                                 "The Kochanek–Bartels curve overflows: the coordinates or the tension are too large.");
        }
        curve.tangents.push_back(t);
    }
    const std::size_t segments = mode == CatmullRomMode::Closed ? count : last;
    curve.segments.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t j = (i + 1) % count;
        curve.segments.push_back({points[i], points[j], curve.tangents[i].out, curve.tangents[j].in});
    }
    return curve;
}

template Expected<KochanekBartelsCurve<double>> kochanekBartels(const std::vector<Point>&, const std::vector<TcbKnot<double>>&,
                                                                CatmullRomMode, double);
template Expected<KochanekBartelsCurve<Rational>> kochanekBartels(const std::vector<RPoint>&,
                                                                  const std::vector<TcbKnot<Rational>>&, CatmullRomMode, double);

} // namespace granota
