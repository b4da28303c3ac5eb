#include "core/curves/splines/parametric_spline.h"

#include "core/base/enum_names.h"

namespace granota {

namespace {
constexpr std::array<EnumName<ParametricEnds>, 4> kParametricEndsNames{{{ParametricEnds::Natural, "natural"},
                                                                        {ParametricEnds::Clamped, "clamped"},
                                                                        {ParametricEnds::NotAKnot, "not-a-knot"},
                                                                        {ParametricEnds::Periodic, "periodic"}}};
constexpr std::array<EnumName<SplineParameters>, 3> kSplineParametersNames{
    {{SplineParameters::Uniform, "uniform"}, {SplineParameters::Chord, "chord"}, {SplineParameters::Centripetal, "centripetal"}}};
} // namespace

std::string_view parametricEndsName(ParametricEnds ends) { return nameOf(kParametricEndsNames, ends, "natural"); }
std::optional<ParametricEnds> parseParametricEnds(std::string_view name) { return parseName(kParametricEndsNames, name); }
std::string_view splineParametersName(SplineParameters parameters)
{
    return nameOf(kSplineParametersNames, parameters, "uniform");
}
std::optional<SplineParameters> parseSplineParameters(std::string_view name) { return parseName(kSplineParametersNames, name); }

namespace detail {

Error parametricNonFinitePoint(std::size_t index)
{
    return makeError(ErrorCode::InvalidInput, "Point P_" + std::to_string(index) + " is not a finite number (NaN or infinity).");
}

Error parametricNonFiniteTangent()
{
    return makeError(ErrorCode::InvalidInput, "An end tangent is not a finite number (NaN or infinity).");
}

Error parametricMissingTangent()
{
    return makeError(ErrorCode::InvalidInput, "Clamped ends need both end tangents (a start tangent and an end tangent).");
}

Error parametricTooFewPoints(ParametricEnds ends, std::size_t count)
{
    return makeError(ErrorCode::TooFewPoints, std::string(ends == ParametricEnds::Periodic ? "A closed" : "An open") +
                                                  " C² spline with " + std::string(parametricEndsName(ends)) +
                                                  " ends needs at least " + std::to_string(parametricSplineMinimumPoints(ends)) +
                                                  " points (got " + std::to_string(count) + ").");
}

Error parametricRepeatedPoint(std::size_t index, std::size_t next, SplineParameters parameters)
{
    return makeError(ErrorCode::InvalidInput, "Points P_" + std::to_string(index) + " and P_" + std::to_string(next) +
                                                  " coincide: " + std::string(splineParametersName(parameters)) +
                                                  " parameters need distinct consecutive points.");
}

Error parametricIrrationalLength(std::size_t index, std::size_t next, SplineParameters parameters)
{
    return makeError(ErrorCode::NotRational, "The " + std::string(splineParametersName(parameters)) + " parameter step from P_" +
                                                 std::to_string(index) + " to P_" + std::to_string(next) +
                                                 " is not a rational number: exact values need uniform parameters here.");
}

Error parametricSingular() { return makeError(ErrorCode::Singular, "No unique closed C² spline through these points."); }

Error parametricOverflow()
{
    return makeError(ErrorCode::OutOfRange, "The spline overflows: the coordinates are too large or too close together.");
}

} // namespace detail

// Def 2.1 in the plane, compiled once for doubles (drawing) and Rational (exact panels).
template Expected<ParametricSpline<double>> parametricSpline(const std::vector<Vec2<double>>&, ParametricEnds, SplineParameters,
                                                             std::optional<Vec2<double>>, std::optional<Vec2<double>>);
template Expected<ParametricSpline<Rational>> parametricSpline(const std::vector<Vec2<Rational>>&, ParametricEnds,
                                                               SplineParameters, std::optional<Vec2<Rational>>,
                                                               std::optional<Vec2<Rational>>);

} // namespace granota
