#pragma once
/// \file plane_spline_settings.h
/// The settings of the Catmull-Rom tab's "C² spline in the plane" family (Def 2.1 in full,
/// core/curves/splines/parametric_spline.h): the end conditions, the parameters and, for
/// clamped ends, the two end tangents as exact numbers. A plain value (undo steps hold it,
/// the document saves it).

#include "core/curves/splines/parametric_spline.h"
#include "core/exact/rational.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace granota::ui {

struct PlaneSplineSettings {
    /// docs/extreme-cases.md: a typed tangent component is at most this in absolute value.
    static constexpr int kMaxTangentAbs = 1000000;

    ParametricEnds ends = ParametricEnds::Natural;
    SplineParameters parameters = SplineParameters::Uniform;
    RPoint startTangent{Rational(1), Rational(0)}; ///< p′(u_0) of clamped ends (in the global u)
    RPoint endTangent{Rational(1), Rational(0)};   ///< p′(u_n) of clamped ends
    bool catmullRomToo = true;                     ///< the Catmull-Rom curve (τ = 1/2) of the same points, for comparison

    bool operator==(const PlaneSplineSettings& o) const;
    bool operator!=(const PlaneSplineSettings& o) const { return !(*this == o); }
};

/// "x, y" with exact components ("1/2, −3", "0.25,1"; Unicode minus too); nullopt when it is
/// not two numbers or a component is beyond kMaxTangentAbs.
std::optional<RPoint> parseTangent(const QString& text);
/// The tangent as parseTangent reads it: "1/2, -3".
QString tangentText(const RPoint& tangent);

/// The settings as JSON: {"ends": "natural", "parameters": "uniform", "start_tangent": "1, 0",
/// "end_tangent": "1, 0", "catmull_rom_too": true}, and back. readPlaneSplineSettings checks
/// every key it knows (a missing key keeps its default) and returns nullopt with `problem` set
/// to the offending key on bad data.
void writePlaneSplineSettings(const PlaneSplineSettings& s, QJsonObject& json);
std::optional<PlaneSplineSettings> readPlaneSplineSettings(const QJsonObject& json, QString* problem);

} // namespace granota::ui
