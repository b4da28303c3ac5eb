#include "ui/bsplines/bspline_curvature_plot.h"

#include "ui/common/canvas_style.h"
#include "ui/common/curvature_plot.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>
#include <QLabel>
#include <qcustomplot.h>

namespace granota::ui {

namespace {
constexpr int kCurvaturePlotMinArea = 70; ///< pixels between the axes, at least (as the basis plot)
} // namespace

QString continuityLabel(int degree, int multiplicity)
{
    const int c = degree - multiplicity;
    return c >= 0 ? QStringLiteral("C") + superscriptDigits(c) : QCoreApplication::translate("granota::ui::BSplineTab", "broken");
}

void setBSplineCurvaturePlotTexts(QLabel* title, QCustomPlot* plot)
{
    title->setText(QCoreApplication::translate("granota::ui::BSplineTab", "Curvature κ against arc length s"));
    title->setToolTip(QCoreApplication::translate(
        "granota::ui::BSplineTab", "κ = (x′y″ − y′x″)/|c′|³, positive where the curve turns left, computed on each Bézier "
                                   "piece of the curve. At a knot of multiplicity m the curve is Cᵖ⁻ᵐ: κ is continuous "
                                   "where the curve is C², it may jump at C¹ (a break in the line), and at C⁰ the curve "
                                   "may turn a corner."));
    plot->setToolTip(QCoreApplication::translate("granota::ui::BSplineTab",
                                                 "κ(s) of the curve; the light vertical lines are its interior knots, "
                                                 "each labelled with the continuity there."));
}

void updateBSplineCurvaturePlot(QCustomPlot* plot, const QFont& font, const BSplineScene& scene, double scale)
{
    plot->clearGraphs();
    plot->clearItems();
    plot->legend->setVisible(false); // one curve, the canvas's
    plot->xAxis->setTickLabelFont(font);
    plot->yAxis->setTickLabelFont(font);
    plot->xAxis->setLabelFont(font);
    plot->yAxis->setLabelFont(font);
    std::vector<CurvaturePlotCurve> curves;
    std::vector<CurvaturePlotKnot> knots;
    if (scene.valid()) {
        curves.push_back({&scene.curvature, QPen(CanvasStyle().curve, 2.0 * scale), QString()});
        for (const BSplineScene::KnotContinuity& k : scene.curvatureKnots)
            knots.push_back({k.s, continuityLabel(scene.degree(), k.multiplicity)});
    }
    CurvaturePlotFrame frame;
    frame.xLabel = QCoreApplication::translate("granota::ui::BSplineTab", "arc length s");
    frame.yLabel = QCoreApplication::translate("granota::ui::BSplineTab", "curvature κ");
    const int tickLabels = QFontMetrics(font).height();
    frame.minimumHeight = kCurvaturePlotMinArea + 2 * tickLabels + 30;
    frame.scale = scale;
    plotCurvatureProfiles(plot, curves, knots, frame);
    plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace granota::ui
