#pragma once
/// \file family_drawing.h
/// The Catmull-Rom tab's canvas for a family other than Catmull-Rom (curve_family.h): the
/// family's curve as cubic Bézier segments and, for the families set by tangents (Def 2.8),
/// the tangents at the points as arrows — incoming and outgoing as two arrows where they
/// differ. The TikZ export draws the same curve (catmull_rom_export.h).

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QColor>

class QPainter;

namespace granota::ui {

class ViewTransform;
struct CanvasStyle;

/// The colour of the family's curve (canvas, key, κ plot, TikZ).
inline const QColor kFamilyCurveColor{0x1f, 0x6f, 0xb4};
/// The tangent arrows: outgoing, and incoming where it differs.
inline const QColor kTangentOutColor{0xd9, 0x5f, 0x02};
inline const QColor kTangentInColor{0x1b, 0x9e, 0x77};

/// The family's curve and its tangents (nothing for Catmull-Rom: drawCatmullRomCurves draws it).
void drawFamilyCurve(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CatmullRomSettings& settings,
                     const CatmullRomScene& scene);

} // namespace granota::ui
