#pragma once
/// \file bspline_report.h
/// The B-spline tab's exact panel: de Boor's net at u level by level (exact when the points
/// are), the span and the p + 1 points acting there, the basis functions at u with their sum
/// (the partition of unity), each N_{i,p}'s support [u_i, u_{i+p+1}), and each distinct knot
/// with its multiplicity m and the continuity C^{p−m} of the curve there. It only formats the
/// scene and the core's values (bspline_basis.h); its texts keep the tab's translation
/// context (granota::ui::BSplineTab).

#include "ui/bsplines/bspline_scene.h"

#include <QString>

namespace granota::ui {

QString bsplineReportHtml(const BSplineScene& scene);

} // namespace granota::ui
