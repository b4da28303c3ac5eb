#include "ui/catmull_rom/catmull_rom_plot.h"

#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/catmull_rom_report.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/canvas_style.h"
#include "ui/catmull_rom/family_drawing.h"
#include "ui/common/curvature_plot.h"
#include "ui/common/number_text.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/plot_title_room.h"

#include <QCoreApplication>
#include <QLabel>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

namespace {

/// Pixels between the plot's axes, at least: on an 800×600 screen the blending plot kept 52.
constexpr int kMinPlotArea = 100;
constexpr int kPlotSamples = 101; ///< t = 0, 0.01, …, 1 (the Matlab linspace(0,1))

/// The height that leaves kMinPlotArea between the axes: below them the x axis's tick labels
/// and title (a line each, with QCustomPlot's paddings), above them its 15 px margin.
int minimumPlotHeight(const QCustomPlot* plot)
{
    const int tickLabels = QFontMetrics(plot->xAxis->tickLabelFont()).height();
    const int title = QFontMetrics(plot->xAxis->labelFont()).height();
    return kMinPlotArea + tickLabels + title + 15 + 3 * 5;
}

Qt::PenStyle tauPenStyle(int i)
{
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine, Qt::DashDotDotLine};
    return styles[i % 5];
}

/// Cor 2.1's w₀…w₃ on t ∈ [0, 1] for the selected τ, or every τ (Ex 2.12) in one line style each.
void plotBlendingFunctions(QCustomPlot* plot, const CatmullRomSettings& settings, double scale)
{
    plot->xAxis->setLabel(QStringLiteral("t"));
    plot->yAxis->setLabel(QStringLiteral("wⱼ(t, τ)"));
    std::vector<int> shown;
    if (settings.allTausInPlot) {
        for (int i = 0; i < static_cast<int>(settings.taus.size()); ++i)
            shown.push_back(i);
    } else if (settings.selectedTau >= 0 && settings.selectedTau < static_cast<int>(settings.taus.size())) {
        shown.push_back(settings.selectedTau);
    }
    // Two columns of legend entries: w0…w3 (and a τ per line style) stay short in a low plot.
    plot->legend->setWrap(shown.size() > 1 ? 4 : 2);
    QVector<double> t(kPlotSamples);
    for (int k = 0; k < kPlotSamples; ++k)
        t[k] = static_cast<double>(k) / (kPlotSamples - 1);
    double lo = 0, hi = 1;
    for (std::size_t n = 0; n < shown.size(); ++n) {
        const int i = shown[n];
        const auto w = blendingFunctions(toDouble(settings.taus[static_cast<std::size_t>(i)]));
        for (int j = 0; j < 4; ++j) {
            QVector<double> y(kPlotSamples);
            for (int k = 0; k < kPlotSamples; ++k) {
                y[k] = w[static_cast<std::size_t>(j)](t[k]);
                lo = std::min(lo, y[k]);
                hi = std::max(hi, y[k]);
            }
            QCPGraph* g = plot->addGraph();
            g->setData(t, y, true);
            g->setPen(
                QPen(CanvasStyle::series(j), 2.0 * scale, shown.size() > 1 ? tauPenStyle(static_cast<int>(n)) : Qt::SolidLine));
            g->setName(QStringLiteral("w") + subscriptDigits(j));
            if (n > 0)
                g->removeFromLegend();
        }
    }
    // With several τ, one legend entry per line style.
    if (shown.size() > 1)
        for (std::size_t n = 0; n < shown.size(); ++n) {
            QCPGraph* key = plot->addGraph();
            key->setPen(QPen(QColor(0x55, 0x55, 0x55), 1.5 * scale, tauPenStyle(static_cast<int>(n))));
            key->setName(QStringLiteral("τ = %1").arg(tensionText(settings.taus[static_cast<std::size_t>(shown[n])])));
        }
    if (shown.size() == 1) // the plot alone tells which tension it shows
        plot->yAxis->setLabel(QStringLiteral("wⱼ(t, %1)").arg(tensionText(settings.taus[static_cast<std::size_t>(shown[0])])));
    keepAxisTitlesWhole(plot, minimumPlotHeight(plot));
    const double pad = (hi - lo) * 0.05;
    plot->xAxis->setRange(0, 1);
    plot->yAxis->setRange(lo - pad, hi + pad);
}

/// §2.3 made visible (curvature_plot.h): signed κ against arc length s of every curve drawn,
/// a gap at each knot (so a jump of κ shows as a break) and the selected τ's knots marked.
void plotCurvature(QCustomPlot* plot, const CatmullRomSettings& settings, const CatmullRomScene& scene, double scale)
{
    std::vector<CurvaturePlotCurve> curves;
    const double width = 2.0 * scale;
    // The family's curve instead of the τ curves when it is not Catmull-Rom (as on the canvas).
    const bool catmullRom = settings.family == CurveFamily::CatmullRom;
    if (!catmullRom)
        curves.push_back({&scene.family.curvature, QPen(kFamilyCurveColor, 1.5 * width), curveFamilyName(settings.family)});
    for (std::size_t i = 0; catmullRom && i < scene.curves.size(); ++i) {
        const bool selected = static_cast<int>(i) == settings.selectedTau;
        curves.push_back({&scene.curves[i].curvature, QPen(tensionColour(scene.curves[i].tau), selected ? 1.5 * width : width),
                          QStringLiteral("τ = %1").arg(tensionText(scene.curves[i].tau))});
    }
    for (std::size_t i = 0; catmullRom && i < scene.otherEnds.size(); ++i)
        curves.push_back({&scene.otherEnds[i].curvature, QPen(tensionColour(scene.otherEnds[i].tau), 0.75 * width, Qt::DashLine),
                          QCoreApplication::translate("granota::ui::CatmullRomTab", "τ = %1, %2 ends")
                              .arg(tensionText(scene.otherEnds[i].tau), CatmullRomReport::endsName(scene.otherEnds[i].ends))});
    curves.push_back({&scene.bezierCurvature, QPen(kCatmullRomBezierColor, width, Qt::DashDotLine),
                      QCoreApplication::translate("granota::ui::CatmullRomTab", "Bézier")});
    curves.push_back({&scene.splineCurvature, QPen(kCatmullRomSplineColor, width),
                      QCoreApplication::translate("granota::ui::CatmullRomTab", "cubic spline C²")});
    // The families of issue 37 with curves of their own: the C² spline in the plane and its
    // Catmull-Rom comparison; the curves on function data, each in its colour.
    curves.push_back(
        {&scene.planeSpline.spline.curvature, QPen(kCatmullRomSplineColor, 1.25 * width), PlaneSplineCurves::tr("C² spline")});
    curves.push_back({&scene.planeSpline.catmullRom.curvature, QPen(tensionColour(0.5), width, Qt::DashLine),
                      QStringLiteral("Catmull-Rom τ = 1/2")});
    for (const FunctionDataCurveShape& shape : scene.functionData.curves)
        curves.push_back(
            {&shape.curvature, QPen(functionDataCurveColour(shape.curve), width), functionDataCurveLabel(shape.curve)});

    // The knots of the selected τ, where its κ may jump.
    std::vector<CurvaturePlotKnot> knots;
    if (!catmullRom || (settings.selectedTau >= 0 && settings.selectedTau < static_cast<int>(scene.curves.size()))) {
        const CurvatureProfile& profile = catmullRom ? scene.curves[static_cast<std::size_t>(settings.selectedTau)].curvature
                                                     : scene.family.curvature;
        const bool closed = settings.ends == CatmullRomEnds::Closed;
        for (std::size_t k = 0; k < profile.knots.size(); ++k)
            if (closed || (k > 0 && k + 1 < profile.knots.size())) // the ends of an open curve are no knots
                knots.push_back({profile.knots[k], QString()});
    }

    CurvaturePlotFrame frame;
    frame.xLabel = QCoreApplication::translate("granota::ui::CatmullRomTab", "arc length s");
    frame.yLabel = QCoreApplication::translate("granota::ui::CatmullRomTab", "curvature κ");
    frame.minimumHeight = minimumPlotHeight(plot);
    frame.scale = scale;
    plotCurvatureProfiles(plot, curves, knots, frame);
}

} // namespace

void setUpCatmullRomPlot(QCustomPlot* plot)
{
    keepTickLabelsInside(plot);
    plot->legend->setVisible(true);
    plot->legend->setBrush(QColor(255, 255, 255, 190));
    plot->legend->setFillOrder(QCPLayoutGrid::foRowsFirst);
    plot->legend->setWrap(4); // w0…w3 in one column, the line style of each τ in the next
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    plot->xAxis->setRange(0, 1);
}

void setCatmullRomPlotTexts(QLabel* title, QCustomPlot* plot, bool curvature)
{
    if (curvature) {
        title->setText(QCoreApplication::translate("granota::ui::CatmullRomTab", "Curvature κ against arc length s (§2.3)"));
        title->setToolTip(QCoreApplication::translate(
            "granota::ui::CatmullRomTab", "κ = (x′y″ − y′x″)/|p′|³, positive where the curve turns left. A Catmull-Rom "
                                          "curve is C¹ but not C²: p″ jumps at its knots and so does κ (a break in the "
                                          "line). The C² cubic spline's κ is continuous, and the Bézier curve is one "
                                          "polynomial (C^∞)."));
        plot->setToolTip(QCoreApplication::translate("granota::ui::CatmullRomTab",
                                                     "κ(s) of every curve drawn, in its colour and line style as on the "
                                                     "canvas; the light vertical lines are the knots of the selected τ."));
    } else {
        title->setText(
            QCoreApplication::translate("granota::ui::CatmullRomTab", "Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)"));
        title->setToolTip(QCoreApplication::translate("granota::ui::CatmullRomTab",
                                                      "p(t) = Σ wⱼ(t, τ) pⱼ: the weight of each of the four points along a "
                                                      "segment. They always add up to 1."));
        plot->setToolTip(
            QCoreApplication::translate("granota::ui::CatmullRomTab", "The blending functions w₀…w₃ of Cor 2.1 on t ∈ [0, 1]."));
    }
}

void updateCatmullRomPlot(QCustomPlot* plot, const QFont& font, const CatmullRomSettings& settings, const CatmullRomScene& scene,
                          double scale)
{
    plot->clearGraphs();
    plot->legend->setFont(font);
    plot->xAxis->setTickLabelFont(font);
    plot->yAxis->setTickLabelFont(font);
    plot->xAxis->setLabelFont(font);
    plot->yAxis->setLabelFont(font);
    plot->clearItems(); // the knot marks of the κ plot
    // κ(s) has the colours and line styles of the canvas, whose legend names them.
    plot->legend->setVisible(!settings.curvaturePlot);
    if (settings.curvaturePlot)
        plotCurvature(plot, settings, scene, scale);
    else
        plotBlendingFunctions(plot, settings, scale);
    plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace granota::ui
