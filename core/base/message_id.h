#pragma once
/// \file message_id.h
/// Which sentence an Error says, and the values it quotes, so that the GUI words the same
/// facts in the interface's language (ui/common/error_text.cpp) while the CLI prints the
/// core's English message unchanged (docs/cli.md). An Error without an id keeps its English
/// for the CLI; the GUI then says what kind of error it is (ErrorCode) in its own words.
/// The arguments are listed with each id, in order, as %1, %2… of the GUI's text.

#include <optional>
#include <string>
#include <vector>

namespace granota {

enum class MessageId {
    None, ///< only the English message (the GUI words the ErrorCode)
    // Points read from a CSV file, an inline list or a JSON list (core/io/point_list.cpp).
    // Error::line holds the CSV line when there is one.
    PointNotAPair,        ///< point %1 (index) is %2 (the text), not two numbers
    CoordinateTooLong,    ///< point %1: %2 (x or y) is %3 characters long, more than %4
    CoordinateNotANumber, ///< point %1: %2 (x or y) = %3 (the text) is not a finite number
    CoordinateTooLarge,   ///< point %1: %2 = %3 has an exponent beyond the doubles' range
    CoordinateTooSmall,   ///< point %1: %2 = %3 is too close to zero to read
    NoPointsGiven,        ///< an empty inline list
    FileHoldsNoPoints,    ///< a file without a data line
    TooManyPoints,        ///< more than %1 points (kMaxDataPoints)
    JsonPointsNotJson,    ///< a JSON point list that is not JSON
    JsonPointsNotAList,   ///< a JSON point list whose value %1 is not a list
    JsonPointNotAPair,    ///< JSON point %1 is %2, not a pair [x,y]
    // A scene's parameters (core/softbody/scenes/scene.cpp, seed/stage_body.cpp). %1 is the
    // parameter's key, which the GUI shows as its panel label (scene_parameters.h).
    SceneUnknownParameter,  ///< %1 is no parameter of a scene
    SceneUnknownComponent,  ///< %1 is no component of a scene (scene_component.h); %2 lists them
    ParameterNotWhole,      ///< %1 must be a whole number
    ParameterOutOfRange,    ///< %1 must be from %2 to %3
    ParameterNotANumber,    ///< %1 must be a number
    ParameterNotAPair,      ///< %1 must be a pair x, y
    ParameterNotFinite,     ///< %1 must be a finite number (≥ 0 when %2 is "≥ 0")
    ParameterTooLarge,      ///< %1 must be at most 1e15 in magnitude
    SidesTooFew,            ///< sides %1 < 3
    SidesTooMany,           ///< sides %1 > %2
    FrameTooSmall,          ///< width or height below 1 px
    TooManyVertices,        ///< bodies × sides above %1 vertices
    BezierOutlineTooCostly, ///< a Bézier outline of degree %1 at %2 points is %3 interpolations, more than %4
    BodiesDoNotFit,         ///< %1 bodies of radius %2 do not fit a %3 × %4 frame; %5 vertices piled, at most %6
    StableKnobOutOfRange,   ///< the stable solver's knob %1 out of its range
    // A B-spline curve (core/curves/bsplines/). Knots and weights are quoted as written: a
    // number, or a fraction's text when the curve is exact.
    BSplineDegreeOutOfRange,     ///< the degree %1 is not from 1 to %2
    BSplineTooFewPoints,         ///< degree %1 needs at least %2 control points, not %3
    BSplineKnotCount,            ///< degree %1 with %2 points needs %3 knots, not %4
    BSplineWeightCount,          ///< %1 control points need %1 weights, not %2
    BSplineNotFinite,            ///< %1 (P_3, w_3 or u_3) is not finite
    BSplineKnotsDecrease,        ///< u_%1 = %2 > u_%3 = %4
    BSplineInteriorMultiplicity, ///< the knot %1 repeated %2 times inside; degree %3 allows %4
    BSplineEndMultiplicity,      ///< the knot %1 repeated %2 times at an end; degree %3 allows %4
    BSplineEmptyDomain,          ///< the domain [%1, %2] is empty
    BSplineWeightNotPositive,    ///< w_%1 = %2 is not positive
    KnotInsertionTimes,          ///< a knot inserted %1 times (at least once)
    KnotOutsideDomain,           ///< the knot %1 outside the domain [%2, %3]
    KnotInsertionMultiplicity,   ///< the knot %1 of multiplicity %2 inserted %3 more times exceeds the degree %4
    BSplineCannotUnclamp,        ///< a rational B-spline whose floating ends would need a weight ≤ 0
};

/// A value an Error's sentence quotes: a number (shown with the interface's decimal sign) or
/// a text (a key, a quoted input, "x" or "y"), shown as it is.
struct MessageArg {
    std::string text;
    std::optional<double> number;
};

inline MessageArg textArg(std::string text) { return MessageArg{std::move(text), std::nullopt}; }
inline MessageArg numberArg(double v) { return MessageArg{{}, v}; }

} // namespace granota
