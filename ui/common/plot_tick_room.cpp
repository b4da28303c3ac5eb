#include "ui/common/plot_tick_room.h"

#include <qcustomplot.h>

#include <QFontMetrics>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr int kSpare = 3; ///< pixels between the label's end and the widget's edge

/// How far the outermost tick labels of `axis` reach past the ends of the axis rect, in pixels,
/// at the lower and the upper end of its range (0 when they stay inside).
std::pair<int, int> overhang(QCPAxis* axis, const QRect& rect)
{
    if (!axis->visible() || !axis->tickLabels() || !axis->ticker())
        return {0, 0};
    const QCPRange range = axis->range();
    if (!(range.size() > 0) || !std::isfinite(range.lower) || !std::isfinite(range.upper))
        return {0, 0};
    QVector<double> ticks;
    QVector<QString> labels;
    const QString format = axis->numberFormat();
    axis->ticker()->generate(range, axis->parentPlot()->locale(), format.isEmpty() ? QLatin1Char('g') : format.at(0),
                             axis->numberPrecision(), ticks, nullptr, &labels);
    const QFontMetrics metrics(axis->tickLabelFont());
    const bool horizontal = axis->orientation() == Qt::Horizontal;
    const double length = horizontal ? rect.width() : rect.height();
    int lower = 0, upper = 0;
    for (int i = 0; i < ticks.size() && i < labels.size(); ++i) {
        if (ticks[i] < range.lower || ticks[i] > range.upper || labels[i].isEmpty())
            continue;
        // The tick's distance from each end of the axis, from the last layout's axis rect
        // (0 before the first: the label taken as at the end).
        double fraction = (ticks[i] - range.lower) / range.size();
        if (axis->scaleType() == QCPAxis::stLogarithmic && range.lower > 0 && ticks[i] > 0)
            fraction = std::log(ticks[i] / range.lower) / std::log(range.upper / range.lower);
        if (axis->rangeReversed())
            fraction = 1 - fraction;
        const double fromLower = std::max(0.0, fraction * length), fromUpper = std::max(0.0, (1 - fraction) * length);
        const QRect box = metrics.boundingRect(labels[i]);
        const double half = 0.5 * (horizontal ? box.width() : box.height());
        lower = std::max(lower, static_cast<int>(std::ceil(half - fromLower)));
        upper = std::max(upper, static_cast<int>(std::ceil(half - fromUpper)));
    }
    return {lower, upper};
}

/// Sets the minimum margins that `plot`'s tick labels need, never below `base` (QCustomPlot's own).
void updateMargins(QCustomPlot* plot, const QMargins& base)
{
    QCPAxisRect* axisRect = plot->axisRect();
    if (!axisRect)
        return;
    const QRect rect = axisRect->rect();
    QMargins need = base;
    for (QCPAxis* axis : axisRect->axes()) {
        const auto [lower, upper] = overhang(axis, rect);
        if (axis->orientation() == Qt::Horizontal) {
            need.setLeft(std::max(need.left(), lower > 0 ? lower + kSpare : 0));
            need.setRight(std::max(need.right(), upper > 0 ? upper + kSpare : 0));
        } else { // pixels grow downwards: the lower end of the range is at the bottom
            need.setBottom(std::max(need.bottom(), lower > 0 ? lower + kSpare : 0));
            need.setTop(std::max(need.top(), upper > 0 ? upper + kSpare : 0));
        }
    }
    if (axisRect->minimumMargins() != need)
        axisRect->setMinimumMargins(need);
}

} // namespace

void keepTickLabelsInside(QCustomPlot* plot)
{
    static const char* const kInstalled = "granotaTickLabelsInside";
    if (plot->property(kInstalled).toBool() || !plot->axisRect())
        return;
    plot->setProperty(kInstalled, true);
    const QMargins base = plot->axisRect()->minimumMargins();
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot, [plot, base] { updateMargins(plot, base); });
}

} // namespace granota::ui
