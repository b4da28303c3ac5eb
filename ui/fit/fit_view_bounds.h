#pragma once
/// \file fit_view_bounds.h
/// What the Fitting tab's view takes in (CurveTab::contentBounds): the data and the curve;
/// the fitted control points while they are drawn, unless they fly far off (high degrees put
/// them orders of magnitude away: then the data would shrink to a dot); and the curvature
/// comb's teeth while it is shown (curvature_comb.h keeps them within half the curve's size of it).

#include "core/base/vec2.h"

#include <QRectF>

#include <vector>

namespace granota::ui {

struct CurvatureComb;

/// The view takes in the fitted control points when they lie within this many times the
/// data's size of the data's box (Ex 2.8's P2 lies 1.3 sizes beyond it), so that the data keep
/// at least a seventh of the view; farther off (a high degree: × 10⁶) they are left out.
constexpr double kControlPointReach = 3.0;

/// `controlPoints` nullptr: not drawn; `comb` nullptr: not shown.
QRectF fitViewBounds(const std::vector<Point>& data, const std::vector<Point>& curve, const std::vector<Point>* controlPoints,
                     const CurvatureComb* comb);

} // namespace granota::ui
