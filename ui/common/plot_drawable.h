#pragma once
/// \file plot_drawable.h
/// A QCustomPlot as a Drawable, so plots export through the same code as canvases: the
/// plot paints itself into a QPicture (vector operations), which is replayed into any
/// painter — PNG, SVG or PDF.

#include "ui/common/drawable.h"

class QCustomPlot;

namespace granota::ui {

class PlotDrawable : public Drawable {
public:
    explicit PlotDrawable(QCustomPlot* plot) : m_plot(plot) {}
    QSizeF exportSize() const override;
    void render(QPainter& painter, const QRectF& target) override;

private:
    QCustomPlot* m_plot;
};

} // namespace granota::ui
