#pragma once
/// \file canvas_legend.h
/// The key of a curve canvas: a small box in a corner, one line per thing drawn (a swatch in
/// its colour and line style, and what it is), and an optional note under them. By default
/// in the top-left corner; canvasLegendRect() chooses the corner that covers least of what
/// it is told to avoid (the curve's samples, the points and their labels, an inset).
/// The De Casteljau tab names its levels and step curves with it, the Catmull-Rom tab its
/// tensions and comparisons. It is drawn by a layer, so exports carry it too.

#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include <vector>

class QPainter;

namespace granota::ui {

struct CanvasLegendEntry {
    QColor color;
    Qt::PenStyle pen = Qt::SolidLine; ///< Qt::NoPen: no swatch, the text in `alertColor`
    QString text;
};

struct CanvasLegend {
    std::vector<CanvasLegendEntry> entries;
    QString note;                        ///< wrapped under the entries (e.g. an error)
    QColor alertColor{0xb0, 0x30, 0x20}; ///< the note's colour and that of entries without a swatch
};

/// What the key should not cover, in widget pixels.
struct CanvasLegendObstacles {
    /// Each one inside the key costs 1 (e.g. the curve's samples).
    std::vector<QPointF> points;
    /// Each one the key overlaps costs kKeepClearCost (handles, their labels, an inset).
    std::vector<QRectF> keepClear;
    static constexpr double kKeepClearCost = 1000.0;
};

/// What covering `box` costs (the measure canvasLegendRect() minimises): 1 a point inside it,
/// kKeepClearCost a keepClear rectangle it overlaps. The De Casteljau tab places its
/// hodograph's inset with it too.
double canvasCoverCost(const QRectF& box, const CanvasLegendObstacles& obstacles);

/// Where a key is drawn, and whether in its compact form (a smaller font, tighter lines and
/// shorter swatches: for a small canvas, where the full key would cover a point).
struct CanvasLegendBox {
    QRectF box;
    bool compact = false;
    static constexpr double kCompactFont = 0.8; ///< × the application font (the full key: 0.9 × the labels' font)
};

/// Positions tried along each edge of the canvas, between and besides its corners.
inline constexpr int kCanvasLegendEdgeSteps = 8;

/// The key's size in `view` (empty when there is nothing to show).
QSizeF canvasLegendSize(const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend, bool compact = false);
/// Where the key goes: inside the viewport (8 px in, × the style's scale), against an edge,
/// the place of least cost (above) — the four corners first (top left, top right, bottom
/// left, bottom right: the first wins a tie), then kCanvasLegendEdgeSteps − 1 places along
/// each edge; in compact form only if the full key cannot keep clear of every keepClear.
CanvasLegendBox canvasLegendRect(const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend,
                                 const CanvasLegendObstacles& obstacles);

/// Draws `legend` in the top-left corner of `view`'s viewport; returns the box (empty when
/// there is nothing to show).
QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend);
/// Draws `legend` where canvasLegendRect() put it.
QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend,
                        const CanvasLegendBox& where);

} // namespace granota::ui
