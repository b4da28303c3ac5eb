#include "ui/bsplines/bspline_basis_plot.h"

#include "core/curves/bsplines/bspline_basis.h"
#include "ui/common/canvas_style.h"
#include "ui/common/number_text.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/plot_title_room.h"

#include <QCoreApplication>
#include <QDataStream>
#include <QLabel>
#include <qcustomplot.h>

#include <algorithm>

namespace granota::ui {

namespace {
constexpr int kBasisPlotMinArea = 70;   ///< pixels between the axes, at least
constexpr int kPlotSamplesPerSpan = 24; ///< samples of each non-empty knot span, at most
constexpr int kPlotSamplesPerPixel = 3; ///< fewer per span when the spans are narrower than 8 pixels (1000 points)
constexpr int kLegendUpTo = 7;          ///< N_i in the legend up to this many functions (two rows with Σ)
constexpr int kSeriesColours = 10;      ///< CanvasStyle::series repeats after this many
constexpr int kLegendColumns = 4;       ///< a row fits the plot at 800 × 600
constexpr char kBasisPlotKeyProperty[] = "granotaBasisPlotKey"; ///< what the plot shows (knots, degree, u, style)
constexpr int kLegendMinHeight = 170; ///< a lower plot (800 × 600) has no room for the legend's rows: none
} // namespace

BasisSamples sampleBasis(const BSplineCurve<double>& curve, int samplesPerSpan)
{
    BasisSamples out;
    const int p = curve.degree, n = curve.pointCount() - 1;
    const auto& k = curve.knots;
    out.functions.resize(static_cast<std::size_t>(n + 1));
    for (auto& f : out.functions)
        f.first = -1;
    const auto record = [&](int i, double value) {
        BasisSamples::Support& f = out.functions[static_cast<std::size_t>(i)];
        if (f.first < 0)
            f.first = static_cast<int>(out.u.size()) - 1;
        f.values.push_back(value);
        out.sum.back() += value;
    };
    const int last = static_cast<int>(k.size()) - 1;
    BasisValues<double> N;
    for (int span = 0; span < last; ++span) {
        const double a = k[static_cast<std::size_t>(span)], b = k[static_cast<std::size_t>(span + 1)];
        if (!(a < b))
            continue;
        for (int j = 0; j < samplesPerSpan; ++j) {
            const double u = a + (b - a) * j / samplesPerSpan;
            out.u.push_back(u);
            out.sum.push_back(0.0);
            // Only N_{span−p..span} can be non-zero on the span (their supports [u_i, u_{i+p+1}));
            // N_{span−p−1} ends here at 0, its line's last sample.
            if (j == 0 && span - p - 1 >= 0 && span - p - 1 <= n)
                record(span - p - 1, 0.0);
            if (span >= p && span <= n) { // all p + 1 functions exist: A2.2 at once, no allocation
                basisFunctionsInto(k, p, span, u, N);
                for (int i = span - p; i <= span; ++i)
                    record(i, N[static_cast<std::size_t>(i - (span - p))]);
            } else { // outside the domain, fewer than p + 1 of them
                for (int i = std::max(0, span - p); i <= std::min(n, span); ++i)
                    record(i, basisFunction(k, i, p, u));
            }
        }
    }
    // The last knot, where the domain ends (closed there, bspline_basis.h).
    out.u.push_back(k.back());
    out.sum.push_back(0.0);
    for (int i = std::max(0, n - p); i <= n; ++i)
        if (out.functions[static_cast<std::size_t>(i)].first >= 0)
            record(i, basisFunction(k, i, p, k.back()));
    return out;
}

void setUpBSplineBasisPlot(QCustomPlot* plot)
{
    keepTickLabelsInside(plot);
    plot->legend->setVisible(true);
    // Legend items only for the few functions the legend shows: QCustomPlot's grid searches its
    // items on each addition, 1000 graphs would cost it a second.
    plot->setAutoAddPlottableToLegend(false);
    plot->legend->setBrush(QColor(255, 255, 255, 190));
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot->legend->setWrap(kLegendColumns); // rows over the plot's top, above the functions (≤ 1)
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
}

void setBSplineBasisPlotTexts(QLabel* title, QCustomPlot* plot)
{
    title->setText(QCoreApplication::translate("granota::ui::BSplineTab", "Basis functions Nᵢ,ₚ(u) (Cox–de Boor)"));
    title->setToolTip(QCoreApplication::translate(
        "granota::ui::BSplineTab", "c(u) = Σ Nᵢ,ₚ(u) Pᵢ: the weight of each control point along the curve. Nᵢ,ₚ is "
                                   "zero outside [uᵢ, uᵢ₊ₚ₊₁) (local support), the functions add up to 1 on the "
                                   "domain (the dashed line), and at a knot of multiplicity m they are Cᵖ⁻ᵐ."));
    plot->setToolTip(QCoreApplication::translate("granota::ui::BSplineTab",
                                                 "Each Nᵢ,ₚ in the colour of Pᵢ's ring; the shaded band is the domain "
                                                 "[uₚ, uₙ₊₁], the vertical line is u."));
}

void invalidateBSplineBasisPlot(QCustomPlot* plot) { plot->setProperty(kBasisPlotKeyProperty, QVariant()); }

void updateBSplineBasisPlot(QCustomPlot* plot, const QFont& font, const BSplineScene& scene, double scale)
{
    // The functions depend on the knots, the degree and u, not on the control points: a drag of
    // a point changes nothing here, and the plot keeps what it has.
    QByteArray key;
    {
        QDataStream out(&key, QIODevice::WriteOnly);
        out << scene.valid() << scene.curve.degree << toDouble(scene.u) << scale << font.toString() << plot->size();
        for (double v : scene.curve.knots)
            out << v;
    }
    if (plot->property(kBasisPlotKeyProperty).toByteArray() == key)
        return;
    plot->setProperty(kBasisPlotKeyProperty, key);
    plot->clearGraphs();
    plot->clearItems();
    QFont small = font;
    small.setPointSizeF(font.pointSizeF() * 0.85);
    plot->legend->setFont(small);
    plot->xAxis->setTickLabelFont(font);
    plot->yAxis->setTickLabelFont(font);
    plot->xAxis->setLabelFont(font);
    plot->yAxis->setLabelFont(font);
    plot->xAxis->setLabel(QStringLiteral("u"));
    plot->yAxis->setLabel(QStringLiteral("Nᵢ,ₚ(u)"));
    if (!scene.valid()) {
        plot->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    int spans = 0;
    for (std::size_t j = 0; j + 1 < scene.curve.knots.size(); ++j)
        spans += scene.curve.knots[j] < scene.curve.knots[j + 1];
    const int perSpan = std::clamp(kPlotSamplesPerPixel * plot->width() / std::max(1, spans), 2, kPlotSamplesPerSpan);
    const BasisSamples b = sampleBasis(scene.curve, perSpan);
    const int count = static_cast<int>(b.functions.size());
    const bool legend = count <= kLegendUpTo && plot->height() >= kLegendMinHeight;
    plot->legend->setVisible(legend);
    // One graph per colour once the colours repeat (CanvasStyle::series has kSeriesColours): N_i,
    // N_{i+10}, … one after the other with a gap (NaN) between, so that 1000 points cost QCustomPlot
    // 10 graphs to draw, not 1000. Their supports [u_i, u_{i+p+1}] follow one another for p ≤ 9.
    const int p = scene.curve.degree;
    const bool grouped = count > kSeriesColours && p + 1 <= kSeriesColours;
    const int graphs = grouped ? kSeriesColours : count;
    for (int c = 0; c < graphs; ++c) {
        QVector<double> u, y;
        for (int i = c; i < count; i += grouped ? kSeriesColours : count) {
            const BasisSamples::Support& f = b.functions[static_cast<std::size_t>(i)];
            if (f.values.empty())
                continue;
            if (!u.isEmpty()) { // a gap, at the key where the last function ended
                u.push_back(u.back());
                y.push_back(qQNaN());
            }
            for (std::size_t j = 0; j < f.values.size(); ++j) {
                u.push_back(b.u[static_cast<std::size_t>(f.first) + j]);
                y.push_back(f.values[j]);
            }
        }
        QCPGraph* g = plot->addGraph();
        g->setData(u, y, true);
        g->setPen(QPen(CanvasStyle::series(c), (count > 40 ? 1.0 : 2.0) * scale));
        g->setName(QStringLiteral("N") + subscriptDigits(c));
        if (legend)
            g->addToLegend();
    }
    // Σ N_{i,p} on the domain only: 1 there (partition of unity), not outside it.
    const double lo = scene.curve.domainStart(), hi = scene.curve.domainEnd();
    QVector<double> du, ds;
    for (std::size_t j = 0; j < b.u.size(); ++j)
        if (b.u[j] >= lo && b.u[j] <= hi) {
            du.push_back(b.u[j]);
            ds.push_back(b.sum[j]);
        }
    QCPGraph* total = plot->addGraph();
    total->setData(du, ds, true);
    total->setPen(QPen(QColor(0x2b, 0x2b, 0x2b), 1.2 * scale, Qt::DashLine));
    total->setName(QStringLiteral("Σ"));
    if (legend)
        total->addToLegend();

    auto* domain = new QCPItemRect(plot);
    domain->topLeft->setCoords(lo, 1.05);
    domain->bottomRight->setCoords(hi, -0.05);
    domain->setPen(Qt::NoPen);
    domain->setBrush(QColor(0x1f, 0x5f, 0xa8, 22));
    domain->setLayer(QStringLiteral("grid"));
    auto* marker = new QCPItemStraightLine(plot);
    const double at = toDouble(scene.u);
    marker->point1->setCoords(at, 0);
    marker->point2->setCoords(at, 1);
    marker->setPen(QPen(CanvasStyle().curve, 1.5 * scale));

    const int tickLabels = QFontMetrics(plot->xAxis->tickLabelFont()).height();
    const int title = QFontMetrics(plot->xAxis->labelFont()).height();
    keepAxisTitlesWhole(plot, kBasisPlotMinArea + tickLabels + title + 30);
    plot->xAxis->setRange(b.u.front(), std::max(b.u.back(), b.u.front() + 1e-9));
    plot->yAxis->setRange(-0.05, legend ? 1.7 : 1.1); // room for the legend's row
    plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace granota::ui
