#pragma once
/// \file catmull_rom_drawing.h
/// What the Catmull-Rom canvas shows besides the point editor's handles: the curves of the
/// scene (each Catmull-Rom segment and spline piece as one cubic path, the Bézier curve of
/// the same points as a polyline of its samples), their key, what the key should not cover,
/// and the box the view fits to. The TikZ export writes the same key (catmull_rom_export.h);
/// its texts keep the tab's translation context (granota::ui::CatmullRomTab).

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"
#include "ui/common/canvas_legend.h"

#include <QColor>
#include <QRectF>

#include <vector>

class QPainter;
class QPainterPath;

namespace granota::ui {

class ViewTransform;
struct CanvasStyle;

/// The comparisons of §2.3, in the same colour on the canvas, in the κ plot, the key and TikZ.
inline const QColor kCatmullRomBezierColor{0x6a, 0x3d, 0x9a};
inline const QColor kCatmullRomSplineColor{0x33, 0x33, 0x33};

/// Cubic Bézier segments as one path of cubicTo (SVG `C`, PDF `c`): the curve itself, not
/// a polyline of samples. A segment with a point that is not finite is left out.
/// Cubic Bézier segments as one path of cubicTo (SVG `C`, PDF `c`, TikZ `.. controls ..`), a
/// segment that starts where the last one ended joined to it; a segment that is not finite skipped.
QPainterPath bezierSegmentsPath(const ViewTransform& view, const std::vector<BezierSegment<double>>& segments);
void drawBezierSegments(QPainter& p, const ViewTransform& view, const std::vector<BezierSegment<double>>& segments);

/// The Bézier curve, the spline, the compared ends (dashed) and one curve per τ on top, the
/// selected τ wider; the Catmull-Rom curves only while settings.catmullRom.
void drawCatmullRomCurves(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CatmullRomSettings& settings,
                          const CatmullRomScene& scene);

/// The key: each τ's colour, the compared ends, the Bézier curve and the spline (or why there
/// is none), and a curve's refusal as its note.
CanvasLegend catmullRomLegend(const CatmullRomSettings& settings, const CatmullRomScene& scene);

/// The samples of every curve drawn, in `view`'s pixels: the key covers as few as it can.
CanvasLegendObstacles catmullRomLegendObstacles(const ViewTransform& view, const CatmullRomSettings& settings,
                                                const CatmullRomScene& scene);

/// The points' box and the curves drawn inside one box size around it (large |τ| overshoots).
QRectF catmullRomContentBounds(const std::vector<Point>& points, const CatmullRomSettings& settings,
                               const CatmullRomScene& scene);

} // namespace granota::ui
