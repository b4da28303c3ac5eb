#pragma once
/// \file curve_family.h
/// The Catmull-Rom tab's family selector (issue 37): which curves the tab draws through its
/// points. Def 2.8 builds a segment from two points and two tangents; the families differ only
/// in how they choose the tangents (hermite_segment.h), except the last two, which solve for
/// them (Def 2.1, Def 2.3):
///  - Catmull-Rom: τ(q_{i+1} − q_{i−1}), one curve per tension of the list (today's tab);
///  - cardinal: the same rule with the graphics texts' tension c, τ = (1 − c)/2 (cardinal_spline.h);
///  - Kochanek–Bartels: tension, continuity and bias per point (kochanek_bartels.h);
///  - Hermite: every tangent a handle the student drags;
///  - the C² spline through points in the plane (parametric_spline.h);
///  - function data y(x) and its monotone interpolants (monotone_spline.h).

#include <QCoreApplication>
#include <QString>

#include <array>
#include <optional>

namespace granota::ui {

enum class CurveFamily { CatmullRom, Cardinal, KochanekBartels, Hermite, PlaneSpline, FunctionData };

/// Every family, in the selector's order.
inline constexpr std::array<CurveFamily, 6> kCurveFamilies{CurveFamily::CatmullRom,      CurveFamily::Cardinal,
                                                           CurveFamily::KochanekBartels, CurveFamily::Hermite,
                                                           CurveFamily::PlaneSpline,     CurveFamily::FunctionData};

/// "catmull-rom", "cardinal", "kochanek-bartels", "hermite", "plane-spline", "function-data":
/// the document's (JSON) key.
QString curveFamilyKey(CurveFamily family);
std::optional<CurveFamily> curveFamilyFromKey(const QString& key);

/// The family's name in the user's language (the selector's items).
QString curveFamilyName(CurveFamily family);

/// True for the families whose tangents a rule or the student sets at each point (Def 2.8's
/// Hermite segments): their tangents are drawn at the points.
bool hasPointTangents(CurveFamily family);

class CurveFamilyNames {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::CurveFamilyNames)
};

} // namespace granota::ui
