#pragma once
/// \file canvas_legend.h
/// The key of a curve canvas: a small box in its top-left corner, one line per thing drawn
/// (a swatch in its colour and line style, and what it is), and an optional note under them.
/// The De Casteljau tab names its levels and step curves with it, the Catmull-Rom tab its
/// tensions and comparisons. It is drawn by a layer, so exports carry it too.

#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QColor>
#include <QRectF>
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

/// Draws `legend` in the top-left corner of `view`'s viewport; returns the box (empty when
/// there is nothing to show).
QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend);

} // namespace granota::ui
