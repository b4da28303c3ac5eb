#pragma once
/// \file bezier_exact_html.h
/// The exact panels of the two Bézier tabs as HTML, apart from their widgets: De Casteljau's
/// triangle at t (Def 2.4, Ex 2.2, Ex 2.3), every level in powers of t, the exact arc length and
/// curvature at t, and the Bernstein tab's polynomials (Def 2.5, Ex 2.4) and curve in the
/// Bernstein basis (Def 2.6, Ex 2.5, Ex 2.6). The texts keep their tabs' translation contexts.

#include "core/base/vec2.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bezier/de_casteljau.h"

#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

/// Above this degree the levels in powers of t (and the curve in the Bernstein basis) would
/// not be readable, and the triangle at t is not written in fractions.
constexpr int kMaxExactBezierDegree = 8;
/// Above this degree the numeric triangle is not shown either.
constexpr int kMaxTriangleDegree = 20;

/// Whether every level P_i^r(t) and c′(t) fits in a double (Def 2.4): control points
/// near ±1e308 make n (P_1 − P_0) or a level overflow to inf, or inf − inf to NaN.
bool triangleFitsInDoubles(const DeCasteljauTable<double>& table);

/// P_i^r(t) as HTML.
QString levelHtml(const QString& i, const QString& r);
/// B_i^n(arg) as HTML.
QString basisHtml(const QString& i, const QString& n, const QString& arg = QStringLiteral("t"));

/// Def 2.4 run on polynomials: every P_i^r(t) in powers of t, or a note saying why not
/// (points without an exact form, a degree above kMaxExactBezierDegree). `exact`: the points
/// as the point editor keeps them exactly (PointEditor::allExactPoints), nullopt if some has none.
QString deCasteljauSymbolicHtml(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exact);

/// What the De Casteljau tab's exact panel shows, computed by the tab.
struct DeCasteljauPanelInput {
    DeCasteljauPanelInput(const std::vector<Point>& p, double at, const DeCasteljauTable<double>& l, const CurvatureAt& k)
        : points(p), t(at), levels(l), curvature(k)
    {
    }
    const std::vector<Point>& points;
    std::optional<std::vector<RPoint>> exactPoints; ///< PointEditor::allExactPoints(): nullopt if some point has no exact form
    double t = 0;
    const DeCasteljauTable<double>& levels; ///< the triangle at t in doubles
    const CurvatureAt& curvature;           ///< κ, and c′(t) where the doubles lose it
    bool showSplit = false;                 ///< the halves' control points too
    std::optional<double> arcLength;        ///< s(t) (none: no lengths were computed)
    double totalLength = 0;                 ///< L
    QString curvatureReadout;               ///< the κ(t) readout, where κ is not exact
    QString symbolicHtml;                   ///< deCasteljauSymbolicHtml() of the points
    QString warning;                        ///< the high-degree warning, empty if none
};
/// The triangle at t (in fractions for small fractions at t = p/q, q ≤ 16), c(t), c′(t), the
/// split, the exact curvature, the levels in powers of t and the warning.
QString deCasteljauPanelHtml(const DeCasteljauPanelInput& in);

/// The Bernstein tab's panel: B_i^n in powers of t for n (or every degree up to n), then the
/// curve of `points` written with Def 2.6, term by term (with `exact`, the points as the point
/// editor keeps them exactly).
QString bernsteinPanelHtml(int degree, bool allDegrees, const std::vector<Point>& points,
                           const std::optional<std::vector<RPoint>>& exact);

} // namespace granota::ui
