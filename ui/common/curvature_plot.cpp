#include "ui/common/curvature_plot.h"

#include "ui/common/plot_title_room.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

void plotCurvatureProfiles(QCustomPlot* plot, const std::vector<CurvaturePlotCurve>& curves,
                           const std::vector<CurvaturePlotKnot>& knots, const CurvaturePlotFrame& frame)
{
    plot->xAxis->setLabel(frame.xLabel);
    plot->yAxis->setLabel(frame.yLabel);
    std::vector<double> values; // every κ shown, for the range
    double length = 0;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const CurvaturePlotCurve& curve : curves) {
        if (!curve.profile || curve.profile->samples.empty())
            continue;
        const CurvatureProfile& profile = *curve.profile;
        QVector<double> s, kappa;
        for (std::size_t i = 0; i < profile.samples.size(); ++i) {
            if (i > 0 && !profile.samples[i].empty()) { // a gap between segments: a jump of κ is a break, not a slope
                s << profile.samples[i].front().s;
                kappa << nan;
            }
            for (const CurvatureSample& sample : profile.samples[i]) {
                s << sample.s;
                kappa << (sample.kappa ? *sample.kappa : nan); // undefined (a cusp): a gap, never 0
                if (sample.kappa)
                    values.push_back(*sample.kappa);
            }
        }
        length = std::max(length, profile.length());
        QCPGraph* g = plot->addGraph();
        g->setData(s, kappa, true); // in order: the two samples of a knot keep their sides
        g->setPen(curve.pen);
        g->setName(curve.name);
    }

    // The range of most values: a near-cusp's spike would flatten every other curve.
    double lo = -1, hi = 1;
    if (!values.empty()) {
        std::sort(values.begin(), values.end());
        const auto at = [&values](double q) {
            return values[static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)))];
        };
        lo = std::min(0.0, at(0.01));
        hi = std::max(0.0, at(0.99));
        const double spread = hi - lo;
        if (!(spread > 0) || !std::isfinite(spread)) {
            lo -= 1;
            hi += 1;
        } else {
            lo -= 0.08 * spread;
            hi += 0.08 * spread;
        }
    }

    for (const CurvaturePlotKnot& knot : knots) {
        auto* line = new QCPItemStraightLine(plot);
        line->point1->setCoords(knot.s, 0);
        line->point2->setCoords(knot.s, 1);
        line->setPen(QPen(QColor(0x60, 0x60, 0x60, 170), frame.scale, Qt::DashLine));
        line->setLayer(QStringLiteral("grid"));
        if (!knot.label.isEmpty()) {
            auto* text = new QCPItemText(plot);
            text->position->setTypeX(QCPItemPosition::ptPlotCoords);
            text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
            text->position->setCoords(knot.s, 0.0); // the top of the axis rectangle
            text->setPositionAlignment(Qt::AlignTop | Qt::AlignHCenter);
            text->setFont(plot->xAxis->tickLabelFont());
            text->setColor(QColor(0x40, 0x40, 0x40));
            text->setBrush(QColor(255, 255, 255, 200));
            text->setPadding(QMargins(2, 0, 2, 0));
            text->setText(knot.label);
        }
    }

    keepAxisTitlesWhole(plot, frame.minimumHeight);
    plot->xAxis->setRange(0, length > 0 && std::isfinite(length) ? length : 1.0);
    plot->yAxis->setRange(lo, hi);
}

} // namespace granota::ui
