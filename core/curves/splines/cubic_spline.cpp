#include "core/curves/splines/cubic_spline.h"

#include "core/base/enum_names.h"

namespace granota {

namespace {
constexpr std::array<EnumName<SplineEnds>, 4> kSplineEndsNames{{{SplineEnds::Natural, "natural"},
                                                                {SplineEnds::Clamped, "clamped"},
                                                                {SplineEnds::NotAKnot, "not-a-knot"},
                                                                {SplineEnds::AsEx21, "ex-2.1"}}};
} // namespace

std::string_view splineEndsName(SplineEnds ends) { return nameOf(kSplineEndsNames, ends, "natural"); }

std::optional<SplineEnds> parseSplineEnds(std::string_view name) { return parseName(kSplineEndsNames, name); }

// Def 2.3 with its end conditions, compiled once for doubles (drawing) and Rational (exact panels).
template Expected<PiecewisePolynomial<double>> cubicSpline(const std::vector<Vec2<double>>&, const SplineEndConditions<double>&);
template Expected<PiecewisePolynomial<Rational>> cubicSpline(const std::vector<Vec2<Rational>>&,
                                                             const SplineEndConditions<Rational>&);

} // namespace granota
