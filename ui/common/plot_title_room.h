#pragma once
/// \file plot_title_room.h
/// A plot small enough for an 800×600 screen still shows its axis titles whole: its minimum
/// size leaves room along each axis for the title (centred on the axis) and the tick labels
/// across it. Called whenever a title or the font (presentation mode) changes.
#include <qcustomplot.h>

#include <algorithm>

namespace granota::ui {

/// Sets `plot`'s minimum size (nothing else may set it: this call overrides it) so that every
/// visible axis title of its main axis rect fits, and its height is at least `minimumHeight`.
inline void keepAxisTitlesWhole(QCustomPlot* plot, int minimumHeight = 0)
{
    int height = 0, width = 0;
    for (QCPAxis* axis : plot->axisRect()->axes()) {
        if (!axis->visible() || axis->label().isEmpty())
            continue;
        const QFontMetrics metrics(axis->labelFont());
        // The title along the axis, and the margins beside the axis rect (ticks, tick labels, titles).
        const int room = metrics.horizontalAdvance(axis->label()) + 3 * metrics.height();
        int& along = axis->orientation() == Qt::Vertical ? height : width;
        along = std::max(along, room);
    }
    plot->setMinimumSize(width, std::max(height, minimumHeight));
}

} // namespace granota::ui
