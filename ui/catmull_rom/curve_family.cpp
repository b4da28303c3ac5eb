#include "ui/catmull_rom/curve_family.h"

namespace granota::ui {

QString curveFamilyKey(CurveFamily family)
{
    switch (family) {
    case CurveFamily::CatmullRom: return QStringLiteral("catmull-rom");
    case CurveFamily::Cardinal: return QStringLiteral("cardinal");
    case CurveFamily::KochanekBartels: return QStringLiteral("kochanek-bartels");
    case CurveFamily::Hermite: return QStringLiteral("hermite");
    case CurveFamily::PlaneSpline: return QStringLiteral("plane-spline");
    case CurveFamily::FunctionData: return QStringLiteral("function-data");
    }
    return {};
}

std::optional<CurveFamily> curveFamilyFromKey(const QString& key)
{
    for (CurveFamily f : kCurveFamilies)
        if (curveFamilyKey(f) == key)
            return f;
    return std::nullopt;
}

QString curveFamilyName(CurveFamily family)
{
    switch (family) {
    case CurveFamily::CatmullRom: return CurveFamilyNames::tr("Catmull-Rom (Def 2.10)");
    case CurveFamily::Cardinal: return CurveFamilyNames::tr("Cardinal (one tension c)");
    case CurveFamily::KochanekBartels: return CurveFamilyNames::tr("Kochanek–Bartels: T, C, B per point");
    case CurveFamily::Hermite: return CurveFamilyNames::tr("Hermite (drag the tangents)");
    case CurveFamily::PlaneSpline: return CurveFamilyNames::tr("C² spline in the plane (Def 2.1)");
    case CurveFamily::FunctionData: return CurveFamilyNames::tr("Function data y(x) (Def 2.3)");
    }
    return {};
}

bool hasPointTangents(CurveFamily family)
{
    return family == CurveFamily::Cardinal || family == CurveFamily::KochanekBartels || family == CurveFamily::Hermite;
}

} // namespace granota::ui
