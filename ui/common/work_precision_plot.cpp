#include "ui/common/work_precision_plot.h"

#include "ui/common/canvas_style.h"
#include "ui/common/plot_tick_room.h"

#include <QCoreApplication>
#include <QLocale>
#include <qcustomplot.h>

#include <cmath>

namespace granota::ui {

namespace {

QString knobLabel(double knob)
{
    if (knob < 1 && knob > 0) {
        const int e = static_cast<int>(std::lround(-std::log2(knob)));
        if (std::ldexp(1.0, -e) == knob)
            return QStringLiteral("2^-%1").arg(e);
    }
    return QLocale().toString(knob, 'g', 4); // the interface's decimal sign (C in granota-cli)
}
/// A series with more samples than this is drawn as a line without markers.
constexpr std::size_t kMostMarkers = 40;
/// English text by key, translated; `fallback` as it is for a key the table lacks.
using Texts = std::pair<const char*, const char*>;
template <std::size_t N> QString translated(const Texts (&table)[N], const std::string& key, const std::string& fallback)
{
    for (const auto& [k, text] : table)
        if (key == k)
            return QCoreApplication::translate("granota::ui::WorkPrecision", text);
    return QString::fromStdString(fallback);
}
} // namespace

QString reportTitle(const WorkPrecisionReport& r)
{
    static const Texts titles[] = {
        {"curve-sampling", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Curve sampling: polyline against curve")},
        {"catmull-rom-sampling", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Catmull-Rom sampling: polyline against curve")},
        {"bezier-evaluation", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Evaluating a Bézier curve of degree n")},
        {"least-squares", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Least-squares Bézier fit: normal equations, QR, SVD")},
        {"integrators", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Integrators: global error against run time")},
        {"energy-drift", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Energy drift: E/E₀ − 1 over 10⁵ steps of x″ = −x")},
        {"soft-body", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Soft body: constraint error against substeps")},
        {"arc-length", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Arc length: Gauss–Legendre, Simpson, polyline")},
        {"bspline-evaluation", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Evaluating a B-spline curve of degree p")},
    };
    return translated(titles, r.name, r.title);
}

QString reportLesson(const WorkPrecisionReport& r)
{
    static const Texts lessons[] = {
        {"curve-sampling",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "Against the number of points, both errors fall like 1/N² (twice the points, a quarter of "
                           "the error), and adaptive subdivision, which puts its points where the curve bends, needs "
                           "fewer for the same error. Its run time per point is higher: each point costs a flatness test.")},
        {"catmull-rom-sampling",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "The same number of points on every segment wastes them on the short, gentle ones; adaptive "
                           "subdivision of each segment puts them where the curve bends and needs fewer for the same "
                           "error. Both errors fall like 1/N².")},
        {"bezier-evaluation",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "De Casteljau and the Bernstein sum stay at rounding level at every degree; Horner on the power "
                           "basis loses digits as the degree grows, because its coefficients are huge alternating sums "
                           "that cancel.")},
        {"least-squares",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "The normal equations square the condition number of M: near degree 25 they have lost almost "
                           "every digit and by degree 30 the curve is wrong, while QR and SVD still hold about seven "
                           "digits.")},
        {"integrators",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "Halving h halves Euler's error but quarters Verlet's (order 1 against 2): at equal run time "
                           "Verlet is orders of magnitude more accurate. RK4 (order 4) costs four evaluations per step "
                           "and wins when high accuracy is needed.")},
        {"energy-drift",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "Explicit Euler multiplies the energy by 1 + h² every step: it grows without bound (×2·10⁴ "
                           "after 10³ steps). RK4 loses the same tiny fraction every step (1.4·10⁻⁸ at h = 0.1), a drift "
                           "that grows linearly (−1.39·10⁻³ after 10⁵ steps). Semi-implicit Euler and Verlet are "
                           "symplectic: each keeps a modified energy exactly (x² + v² − h x v; v² + (1 − h²/4) x²), so "
                           "their error stays bounded however long the run, about h/2 and h²/4.")},
        {"soft-body",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "XPBD's constraint error falls as the substeps grow, at a cost proportional to their number; "
                           "the seed's per-step corrections leave a lasting area deficit.")},
        {"arc-length",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "The adaptive rule, split at the cusp, reaches rounding level in about two microseconds; one "
                           "24-point Gauss rule is off by 1e-3 on the cusp and, repeated on pieces that do not end "
                           "there, gains only a factor 4 per doubling (the kink, not the rule, sets the pace); Simpson "
                           "gains 16 per halving, the polyline 4.")},
        {"bspline-evaluation",
         QT_TRANSLATE_NOOP("granota::ui::WorkPrecision",
                           "de Boor's algorithm, the Bézier segments with De Casteljau and the basis functions times the "
                           "points all stay at rounding level at every degree: each is a chain of convex combinations. "
                           "The Bézier segments, extracted once, are the quickest per point (one ratio t instead of "
                           "p(p + 1)/2 ratios of knots) but carry the rounding of their extraction, up to a few times "
                           "de Boor's error; the basis sum is the slowest.")},
    };
    return translated(lessons, r.name, r.lesson);
}

QString reportMethod(const std::string& m)
{
    static const Texts names[] = {
        {"uniform", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "uniform")},
        {"adaptive", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "adaptive")},
        {"uniform t per segment", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "uniform t per segment")},
        {"De Casteljau", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "De Casteljau")},
        {"Bernstein sum", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Bernstein sum")},
        {"Horner (power basis)", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Horner (power basis)")},
        {"normal equations", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "normal equations")},
        {"QR", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "QR")},
        {"SVD", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "SVD")},
        {"explicit Euler", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "explicit Euler")},
        {"semi-implicit Euler", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "semi-implicit Euler")},
        {"Verlet", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Verlet")},
        {"Verlet (Annex II start)", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Verlet (Annex II start)")},
        {"RK4", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "RK4")},
        {"XPBD area", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "XPBD area")},
        {"XPBD edge lengths", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "XPBD edge lengths")},
        {"seed area (Annex II)", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "seed area (Annex II)")},
        {"adaptive Gauss–Legendre", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "adaptive Gauss–Legendre")},
        {"Gauss–Legendre 24 points", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Gauss–Legendre 24 points")},
        {"Simpson", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Simpson")},
        {"polyline", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "polyline")},
        {"de Boor", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "de Boor")},
        {"Bézier extraction + De Casteljau", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "Bézier extraction + De Casteljau")},
        {"basis functions × points", QT_TRANSLATE_NOOP("granota::ui::WorkPrecision", "basis functions × points")},
    };
    return translated(names, m, m);
}

QString reportKnob(const WorkPrecisionReport& r)
{
    if (r.knob == "points")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "points");
    if (r.knob == "degree")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "degree");
    if (r.knob == "step h")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "step h");
    if (r.knob == "step")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "step n");
    if (r.knob == "substeps")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "substeps");
    if (r.knob == "setting")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "setting (tolerance, pieces, intervals or segments)");
    return QString::fromStdString(r.knob);
}

QString reportError(const WorkPrecisionReport& r)
{
    if (r.name == "curve-sampling" || r.name == "catmull-rom-sampling")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "max distance between curve and polyline");
    if (r.name == "bezier-evaluation")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "max |c(t) − exact| / max |Pᵢ|");
    if (r.name == "least-squares")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "max |Pⱼ − Pⱼ(true)| / max |Pⱼ(true)|");
    if (r.name == "integrators")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "|x(T) − exact| at T = 10");
    if (r.name == "energy-drift")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "|E/E₀ − 1|, E = (v² + x²)/2");
    if (r.name == "soft-body")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "RMS relative constraint violation");
    if (r.name == "arc-length")
        return QCoreApplication::translate("granota::ui::WorkPrecision",
                                           "max relative error of L over four curves, one with a cusp");
    if (r.name == "bspline-evaluation")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "max |c(u) − exact| / max |Pᵢ|");
    return QString::fromStdString(r.error);
}

QString reportAxisTitle(const WorkPrecisionReport& r, WorkPrecisionAxis axis)
{
    if (axis == WorkPrecisionAxis::Seconds)
        return QCoreApplication::translate("granota::ui::WorkPrecision", "run time per call (s)");
    if (r.knob == "points")
        return QCoreApplication::translate("granota::ui::WorkPrecision", "points of the polyline (evaluations of the curve)");
    return reportKnob(r);
}

void clearWorkPrecisionPlot(QCustomPlot* plot)
{
    plot->clearGraphs();
    plot->clearItems();
    plot->xAxis->setLabel(QString());
    plot->yAxis->setLabel(QString());
    plot->legend->setVisible(false);
    plot->replot();
}

void plotWorkPrecision(QCustomPlot* plot, const WorkPrecisionReport& report, double styleScale,
                       std::optional<WorkPrecisionAxis> axis)
{
    // An untimed report (energy-drift) has only its knob to plot against.
    const WorkPrecisionAxis xAxis = report.timed ? axis.value_or(report.xAxis) : WorkPrecisionAxis::Knob;
    const bool againstKnob = xAxis == WorkPrecisionAxis::Knob;
    plot->clearGraphs();
    plot->clearItems();
    plot->plotLayout()->setAutoMargins(QCP::msAll);
    keepTickLabelsInside(plot);
    QSharedPointer<QCPAxisTickerLog> logTicker(new QCPAxisTickerLog);
    for (QCPAxis* axis : {plot->xAxis, plot->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(logTicker);
        axis->setNumberFormat(QStringLiteral("eb"));
        axis->setNumberPrecision(0);
        QFont f = axis->labelFont();
        f.setPointSizeF(QFont().pointSizeF() * styleScale);
        axis->setLabelFont(f);
        axis->setTickLabelFont(f);
    }
    plot->xAxis->setLabel(reportAxisTitle(report, xAxis));
    plot->yAxis->setLabel(reportError(report));
    double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
    int index = 0;
    const QCPScatterStyle::ScatterShape shapes[] = {QCPScatterStyle::ssCircle, QCPScatterStyle::ssSquare,
                                                    QCPScatterStyle::ssTriangle, QCPScatterStyle::ssDiamond,
                                                    QCPScatterStyle::ssCross};
    for (const auto& series : report.series) {
        QCPGraph* graph = plot->addGraph();
        graph->setName(reportMethod(series.method));
        const QColor colour = CanvasStyle::series(index);
        graph->setPen(QPen(colour, 2.0 * styleScale));
        // A long series (energy-drift's steps) is a curve, not a handful of settings: no markers.
        if (series.samples.size() <= kMostMarkers)
            graph->setScatterStyle(QCPScatterStyle(shapes[index % 5], colour, colour.lighter(150), 7 * styleScale));
        QVector<double> x, y;
        for (const auto& p : series.samples) {
            const double px = againstKnob ? p.knob : p.seconds;
            const double error = std::fabs(p.error); // signed only in energy-drift (E/E0 − 1)
            if (!(px > 0) || !(error > 0))
                continue;
            x << px;
            y << error;
            xmin = std::min(xmin, px);
            xmax = std::max(xmax, px);
            ymin = std::min(ymin, error);
            ymax = std::max(ymax, error);
        }
        graph->setData(x, y, true);
        // Against run time, the knob at the first and last marker: which end is coarse, which
        // is fine. (Against the knob the axis says it.)
        for (std::size_t k : {std::size_t(0), series.samples.size() - 1}) {
            if (againstKnob || series.samples.empty() || (k > 0 && series.samples.size() < 2))
                continue;
            const auto& p = series.samples[k];
            auto* label = new QCPItemText(plot);
            label->position->setCoords(p.seconds, p.error);
            label->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
            label->setText(QStringLiteral(" %1 = %2").arg(reportKnob(report), knobLabel(p.knob)));
            label->setColor(colour.darker(130));
            QFont f = label->font();
            f.setPointSizeF(QFont().pointSizeF() * 0.85 * styleScale);
            label->setFont(f);
        }
        ++index;
    }
    if (xmax > 0) {
        plot->xAxis->setRange(xmin / 2, xmax * 4);
        const double top = ymax * 10;
        plot->yAxis->setRange(ymin / 10, report.plotErrorCeiling > 0 ? std::min(top, report.plotErrorCeiling) : top);
    }
    plot->legend->setVisible(true);
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    QFont lf = plot->legend->font();
    lf.setPointSizeF(QFont().pointSizeF() * styleScale);
    plot->legend->setFont(lf);
    plot->replot();
}

} // namespace granota::ui
