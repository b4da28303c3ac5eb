#pragma once
/// \file decasteljau_construction_drawing.h
/// The drawing of De Casteljau's construction (Def 2.4): every level r ≥ 1 of a table, its
/// points and the segments between them, one colour per level; and a polyline as a path.
/// The tab's canvas draws the curve's construction with it, and the hodograph's inset the
/// hodograph's own construction at the same t (a Bézier curve of degree n − 1).

#include "core/base/vec2.h"
#include "core/curves/bezier/de_casteljau.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QPainterPath>

#include <vector>

class QPainter;

namespace granota::ui {

/// The finite points of `points` joined in screen coordinates.
QPainterPath polylinePath(const std::vector<Point>& points, const ViewTransform& view);

/// Levels 1 … n − 1 of `table` (level 0 is the control polygon, level n the point c(t)),
/// with dots of `dotScale` × the handle radius (none when `dotScale` ≤ 0).
void drawDeCasteljauConstruction(QPainter& p, const ViewTransform& view, const CanvasStyle& style,
                                 const DeCasteljauTable<double>& table, double dotScale = 0.6);

} // namespace granota::ui
