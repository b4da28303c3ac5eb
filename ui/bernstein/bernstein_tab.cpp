#include "ui/bernstein/bernstein_tab.h"
#include "ui/common/number_text.h"

#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/io/worked_examples.h"
#include "ui/common/bezier_curve_model.h"
#include "ui/common/bezier_exact_html.h"
#include "ui/common/canvas_style.h"
#include "ui/decasteljau/decasteljau_parameter_control.h"
#include "ui/common/exact_panel.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/point_editor.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/value_command.h"
#include "ui/files/tikz_writer.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonValue>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QUndoStack>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace granota::ui {

namespace {

constexpr double kCheckTolerance = 1e-12; ///< a residual below this shows ✓
constexpr int kMaxLegendEntries = 12;     ///< more graphs than this: no legend (colours repeat anyway)
constexpr int kMaxReadoutLines = 12;      ///< values listed in the hover readout
constexpr int kMaxBarLabels = 20;         ///< more bars than this: label every k-th
constexpr int kCsvSamples = 101;          ///< rows of the CSV export: t = 0, 0.01, …, 1
constexpr double kBasisWidth = 2.0;       ///< line width of the graphs B_i^n(t)
/// Their width in presentation mode: a line width of its own, thicker than kBasisWidth ×
/// kPresentationScale (3.2), so that the graphs stand out from the axes from the back of the room.
constexpr double kPresentationBasisWidth = 3.6;


/// B_i^n in plain Unicode (legend, readout): B₂⁵.
QString basisName(int i, int n) { return QStringLiteral("B") + subscriptDigits(i) + superscriptDigits(n); }

/// File ▸ Export of the basis plot: the plot as on screen, without the readout that follows the
/// mouse (it belongs to the pointer, not to the picture).
class BasisPlotExport : public Drawable {
public:
    BasisPlotExport(QCustomPlot* plot, QCPItemText* readout) : m_plot(plot), m_readout(readout) {}
    QSizeF exportSize() const override { return m_plot.exportSize(); }
    void render(QPainter& painter, const QRectF& target) override
    {
        const bool shown = m_readout->visible();
        m_readout->setVisible(false);
        m_plot.render(painter, target);
        m_readout->setVisible(shown);
    }

private:
    PlotDrawable m_plot;
    QCPItemText* m_readout;
};

QString residualText(double r) { return r == 0.0 ? QStringLiteral("0") : displayText(QString::number(r, 'e', 1).toStdString()); }


} // namespace

BernsteinTab::BernsteinTab(BezierCurveModel* curve, QWidget* parent)
    : TabPage(QStringLiteral("bernstein"), QT_TR_NOOP("Bernstein"), curve->undoStack(), parent), m_curve(curve),
      m_basisPlot(new QCustomPlot(this)), m_weightsPlot(new QCustomPlot(this)), m_exact(new ExactPanel(this)),
      m_parameter(new DeCasteljauParameterControl(this)), m_degreeLabel(new QLabel(this)), m_degreeBox(new QSpinBox(this)),
      m_allBox(new QCheckBox(this)), m_markerBox(new QCheckBox(this)),
      m_checksGroup(new QGroupBox(this)), m_checkLabels{new QLabel(this), new QLabel(this), new QLabel(this)},
      m_weightsGroup(new QGroupBox(this)), m_curveLabel(new QLabel(this))
{

    m_exact->setWordWrapMode(QTextOption::WordWrap); // break between terms, never inside "t^5"
    m_degreeBox->setRange(0, kMaxDegree);
    m_degreeBox->setValue(m_degree);
    m_degreeLabel->setBuddy(m_degreeBox);

    // The basis plot: B_i^n on [0, 1], the current t as a vertical line, a hover readout.
    m_basisPlot->setMinimumHeight(200);
    keepTickLabelsInside(m_basisPlot);
    keepTickLabelsInside(m_weightsPlot);
    m_basisPlot->xAxis->setRange(0, 1);
    m_basisPlot->yAxis->setRange(-0.02, 1.05);
    m_basisPlot->xAxis->setLabel(QStringLiteral("t"));
    // The legend beside the axes, not over the curves.
    m_basisPlot->axisRect()->insetLayout()->take(m_basisPlot->legend);
    auto* legendColumn = new QCPLayoutGrid;
    m_basisPlot->plotLayout()->addElement(0, 1, legendColumn);
    m_basisPlot->plotLayout()->setColumnStretchFactor(1, 0.001);
    legendColumn->addElement(0, 0, m_basisPlot->legend);
    legendColumn->addElement(1, 0, new QCPLayoutElement(m_basisPlot)); // takes the height left below
    legendColumn->setRowStretchFactor(0, 0.001);
    legendColumn->setRowStretchFactor(1, 1);
    legendColumn->setMargins(QMargins(4, 10, 8, 4)); // the legend's frame clear of the widget's edge
    m_basisPlot->legend->setMargins(QMargins(6, 4, 6, 4));
    m_marker = new QCPItemStraightLine(m_basisPlot);
    m_marker->setPen(QPen(QColor(0x33, 0x33, 0x33), 1.5, Qt::DashLine));
    m_readout = new QCPItemText(m_basisPlot);
    m_readout->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_readout->position->setCoords(0.01, 0.02);
    m_readout->setPositionAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_readout->setTextAlignment(Qt::AlignLeft);
    m_readout->setPadding(QMargins(6, 4, 6, 4));
    m_readout->setBrush(QColor(255, 255, 255, 225));
    m_readout->setPen(QPen(QColor(0xbb, 0xbb, 0xbb)));
    m_readout->setVisible(false);
    m_drawable = std::make_unique<BasisPlotExport>(m_basisPlot, m_readout);
    setExportView(m_drawable.get());
    m_markerBox->setChecked(m_showMarker);
    m_basisPlot->setMouseTracking(true);
    connect(m_basisPlot, &QCustomPlot::mouseMove, this, &BernsteinTab::plotMouseMove);
    connect(m_basisPlot, &QCustomPlot::mousePress, this, &BernsteinTab::plotMousePress);
    connect(m_basisPlot, &QCustomPlot::mouseRelease, this, [this](QMouseEvent*) {
        m_dragging = false;
        ++m_plotDrags;
    });

    // The weights B_i^n(t) applied to the De Casteljau tab's points (Def 2.6).
    m_bars = new QCPBars(m_weightsPlot->xAxis, m_weightsPlot->yAxis);
    m_bars->setWidth(0.6);
    m_bars->setPen(QPen(CanvasStyle().curve.darker(130)));
    m_bars->setBrush(CanvasStyle().curve.lighter(140));
    m_weightsPlot->yAxis->setRange(0, 1.05);
    m_weightsPlot->yAxis->ticker()->setTickCount(3);
    m_weightsPlot->setMinimumHeight(120);
    m_curveLabel->setWordWrap(true);
    m_curveLabel->setTextFormat(Qt::RichText);
    m_curveLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* weightsLayout = new QVBoxLayout(m_weightsGroup);
    weightsLayout->addWidget(m_weightsPlot, 1);
    weightsLayout->addWidget(m_curveLabel);

    auto* checksLayout = new QVBoxLayout(m_checksGroup);
    for (QLabel* label : m_checkLabels) {
        label->setTextFormat(Qt::RichText);
        label->setWordWrap(true);
        checksLayout->addWidget(label);
    }

    auto* controls = new QHBoxLayout;
    controls->addWidget(m_degreeLabel);
    controls->addWidget(m_degreeBox);
    controls->addWidget(m_allBox);
    controls->addSpacing(12);
    controls->addWidget(m_parameter, 1);

    auto* plots = new QSplitter(Qt::Vertical, this);
    plots->addWidget(m_basisPlot);
    plots->addWidget(m_weightsGroup);
    plots->setStretchFactor(0, 3);
    plots->setStretchFactor(1, 2);
    plots->setChildrenCollapsible(false);
    plots->setSizes({430, 270});
    auto* left = new QWidget(this);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addLayout(controls);
    leftLayout->addWidget(plots, 1);

    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    // Above the checks, the plot's own choice (the row above the plot has no width to spare at 800 pixels).
    rightLayout->addWidget(m_markerBox);
    rightLayout->addWidget(m_checksGroup);
    rightLayout->addWidget(m_exact, 1);

    m_mainSplitter = new QSplitter(Qt::Horizontal, this);
    m_mainSplitter->addWidget(left);
    m_mainSplitter->addWidget(right);
    setSidePanel(right);
    m_mainSplitter->setStretchFactor(0, 3);
    m_mainSplitter->setStretchFactor(1, 2);
    m_mainSplitter->setSizes({760, 500});
    m_mainSplitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_mainSplitter);

    constexpr int kDegreeMergeId = 0x42450001; // "BE": a spin box held down is one step
    connect(m_degreeBox, &QSpinBox::valueChanged, this, [this](int n) {
        userChangedView({n, m_allDegrees, m_showMarker}, tr("Degree n = %1").arg(n), kDegreeMergeId);
    });
    connect(m_allBox, &QCheckBox::toggled, this, [this](bool on) {
        userChangedView({m_degree, on, m_showMarker}, tr("All degrees up to n"));
    });
    connect(m_markerBox, &QCheckBox::toggled, this, [this](bool on) {
        userChangedView({m_degree, m_allDegrees, on}, on ? tr("Mark t") : tr("Hide the mark at t"));
    });
    // One t for both tabs: this tab's slider moves the curve's t, and so the De Casteljau tab's.
    connect(m_parameter, &DeCasteljauParameterControl::valueChanged, this,
            [this](double t) { userMovedT(t, m_parameter->gestureMergeId()); });
    connect(m_curve, &BezierCurveModel::tChanged, this, [this](double t) {
        m_parameter->setValue(t);
        updateMarker();
        updateWeights();
        updateChecks();
    });
    connect(m_curve, &BezierCurveModel::documentChanged, this, &TabPage::documentChanged);
    connect(m_curve, &BezierCurveModel::pointsChanged, this, [this] {
        updateWeights();
        updateExactPanel();
    });

    m_parameter->setValue(t());
    rebuildBasisPlot();
    applyPlotStyle();
    retranslate();
}

BernsteinTab::~BernsteinTab() = default;

// ---------------------------------------------------------------- settings

double BernsteinTab::t() const { return m_curve->t(); }

void BernsteinTab::setT(double t)
{
    m_curve->setT(t); // comes back through tChanged
    m_parameter->setValue(m_curve->t());
}

int BernsteinTab::plotDragMergeId() const
{
    constexpr int kBase = 0x42500000; // "BP": far from the slider's gesture ids
    return kBase + (m_plotDrags & 0xffff);
}

void BernsteinTab::userMovedT(double t, int mergeId)
{
    const double before = this->t();
    setT(t);
    if (this->t() == before)
        return;
    m_curve->pushT(before, mergeId, tr("Move t"));
    emit documentChanged();
}

void BernsteinTab::applyView(const View& v)
{
    setAllDegrees(v.allDegrees);
    setDegree(v.degree);
    setTMarkerVisible(v.marker);
}

void BernsteinTab::setTMarkerVisible(bool on)
{
    if (m_markerBox->isChecked() != on) {
        const QSignalBlocker block(m_markerBox);
        m_markerBox->setChecked(on);
    }
    if (on == m_showMarker)
        return;
    m_showMarker = on;
    m_marker->setVisible(on);
    m_basisPlot->replot(QCustomPlot::rpQueuedReplot);
    emit documentChanged();
}

void BernsteinTab::userChangedView(const View& after, const QString& undoText, int mergeId)
{
    const View before = view();
    applyView(after);
    if (view() == before)
        return;
    m_undo->push(
        new ValueCommand<View>([this](const View& v) { applyView(v); }, before, view(), undoText, mergeId, {true, true}));
}

void BernsteinTab::setDegree(int n)
{
    n = std::clamp(n, 0, kMaxDegree);
    if (m_degreeBox->value() != n) {
        const QSignalBlocker block(m_degreeBox);
        m_degreeBox->setValue(n);
    }
    if (n == m_degree)
        return;
    m_degree = n;
    rebuildBasisPlot();
    updateChecks();
    updateExactPanel();
    emit documentChanged();
}

void BernsteinTab::setAllDegrees(bool on)
{
    if (m_allBox->isChecked() != on) {
        const QSignalBlocker block(m_allBox);
        m_allBox->setChecked(on);
    }
    if (on == m_allDegrees)
        return;
    m_allDegrees = on;
    rebuildBasisPlot();
    updateExactPanel();
    emit documentChanged();
}

// ---------------------------------------------------------------- plots

void BernsteinTab::rebuildBasisPlot()
{
    m_basisPlot->clearGraphs();
    QVector<double> ts(kPlotSamples);
    for (int j = 0; j < kPlotSamples; ++j)
        ts[j] = static_cast<double>(j) / (kPlotSamples - 1);
    const int first = m_allDegrees ? 0 : m_degree;
    const double width = m_presentation ? kPresentationBasisWidth : kBasisWidth;
    int legendEntries = 0;
    for (int n = first; n <= m_degree; ++n) {
        // Every graph of one degree at once through Lemma 2.1 (core/curves/bezier/bernstein.h).
        std::vector<QVector<double>> values(static_cast<std::size_t>(n + 1), QVector<double>(kPlotSamples));
        for (int j = 0; j < kPlotSamples; ++j) {
            const auto b = bernsteinAll(n, ts[j]);
            for (int i = 0; i <= n; ++i)
                values[static_cast<std::size_t>(i)][j] = b[static_cast<std::size_t>(i)];
        }
        for (int i = 0; i <= n; ++i) {
            QCPGraph* g = m_basisPlot->addGraph();
            g->setData(ts, values[static_cast<std::size_t>(i)], true);
            if (m_allDegrees) {
                // One colour per degree; the largest degree drawn boldest.
                g->setPen(QPen(CanvasStyle::series(n), n == m_degree ? width : width * 0.6));
                g->setName(QStringLiteral("n = %1").arg(n));
                if (i == 0)
                    ++legendEntries;
                else
                    g->removeFromLegend();
            } else {
                g->setPen(QPen(CanvasStyle::series(i), width));
                g->setName(basisName(i, n));
                ++legendEntries;
            }
        }
    }
    m_basisPlot->legend->setVisible(legendEntries <= kMaxLegendEntries);
    updateMarker();
}

void BernsteinTab::updateMarker()
{
    m_readout->setVisible(false); // it named the t under the mouse; the next move shows it again
    const double tt = t();
    m_marker->point1->setCoords(tt, 0);
    m_marker->point2->setCoords(tt, 1);
    m_basisPlot->replot(QCustomPlot::rpQueuedReplot);
}

bool BernsteinTab::readoutShown() const { return m_readout->visible(); }

double BernsteinTab::markerT() const { return m_marker->point1->coords().x(); }

void BernsteinTab::updateWeights()
{
    const auto& points = m_curve->points();
    if (points.empty())
        return;
    const int n = static_cast<int>(points.size()) - 1;
    const double tt = t();
    const std::vector<double> w = bernsteinAll(n, tt);
    QVector<double> keys(n + 1), values(n + 1);
    for (int i = 0; i <= n; ++i) {
        keys[i] = i;
        values[i] = w[static_cast<std::size_t>(i)];
    }
    m_bars->setData(keys, values, true);
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    const int every = n + 1 > kMaxBarLabels ? (n + kMaxBarLabels) / kMaxBarLabels : 1;
    for (int i = 0; i <= n; i += every)
        ticker->addTick(i, QStringLiteral("P%1").arg(i));
    m_weightsPlot->xAxis->setTicker(ticker);
    m_weightsPlot->xAxis->setRange(-0.7, n + 0.7);
    m_weightsPlot->replot(QCustomPlot::rpQueuedReplot);

    // Def 2.6 against De Casteljau (Prop 2.1): the same point.
    const Point viaBernstein = bezierBernstein(points, tt);
    const Point viaDeCasteljau = deCasteljauPoint(points, tt);
    double sum = 0.0;
    for (double v : w)
        sum += v;
    m_curveLabel->setText(tr("At t = %1 the weights sum to %2.<br>Def 2.6: %3 = %4<br>De Casteljau: %5 = %6 (difference %7)")
                              .arg(panelNumber(tt), displaySignificant(sum, 17),
                                   QStringLiteral("Σ %1 P<sub>i</sub>").arg(basisHtml(QStringLiteral("i"), QString::number(n))),
                                   panelPointText(viaBernstein), levelHtml(QStringLiteral("0"), QString::number(n)),
                                   panelPointText(viaDeCasteljau), residualText(distance(viaBernstein, viaDeCasteljau))));
    m_weightsGroup->setTitle(tr("Weights of the %n control points of the De Casteljau tab at t (Def 2.6)", nullptr, n + 1));
}

void BernsteinTab::plotMouseMove(QMouseEvent* event)
{
    const double tt = std::clamp(m_basisPlot->xAxis->pixelToCoord(event->position().x()), 0.0, 1.0);
    if (m_dragging && (event->buttons() & Qt::LeftButton)) {
        userMovedT(tt, plotDragMergeId());
        return;
    }
    m_readout->setText(readout(tt));
    m_readout->setVisible(true);
    m_basisPlot->replot(QCustomPlot::rpQueuedReplot);
    emit statusMessage(readout(tt).replace(QLatin1Char('\n'), QStringLiteral("   ")));
}

void BernsteinTab::plotMousePress(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton)
        return;
    m_dragging = true;
    userMovedT(std::clamp(m_basisPlot->xAxis->pixelToCoord(event->position().x()), 0.0, 1.0), plotDragMergeId());
}

QString BernsteinTab::readout(double tt) const
{
    // The values at the t the readout names: t to three decimals, as shown, so that
    // "t = 0.300" comes with B₀⁴ = 0.7⁴ = 0.2401, not the values a fraction of a pixel away.
    const double shown = std::round(tt * 1000) / 1000;
    const std::vector<double> b = bernsteinAll(m_degree, shown);
    // With more than kMaxReadoutLines polynomials, the ones that matter: B_i^n(t) is unimodal
    // in i with its peak at i ≈ n t (Def 2.5: the ratio B_{i+1}/B_i = (n − i) t / ((i + 1)(1 − t))
    // falls through 1 there), so the kMaxReadoutLines largest are consecutive around the peak.
    const int peak = static_cast<int>(std::max_element(b.begin(), b.end()) - b.begin());
    const int first = std::clamp(peak - kMaxReadoutLines / 2, 0, std::max(0, m_degree + 1 - kMaxReadoutLines));
    const int last = std::min(m_degree, first + kMaxReadoutLines - 1);
    QStringList lines{QStringLiteral("t = %1").arg(displayFixed(shown, 3))};
    if (first > 0)
        lines << QStringLiteral("…");
    for (int i = first; i <= last; ++i)
        lines << QStringLiteral("%1 = %2").arg(basisName(i, m_degree)).arg(displayFixed(b[static_cast<std::size_t>(i)], 4));
    if (last < m_degree)
        lines << QStringLiteral("…");
    return lines.join(QLatin1Char('\n'));
}

void BernsteinTab::applyPlotStyle()
{
    // Fonts follow the application font (the main window enlarges it in presentation
    // mode); lines are thickened here.
    const double s = presentationScale(m_presentation);
    QFont tickFont;
    tickFont.setPointSizeF(tickFont.pointSizeF() * 0.9);
    const QFont labelFont;
    for (QCustomPlot* plot : {m_basisPlot, m_weightsPlot}) {
        for (QCPAxis* axis : {plot->xAxis, plot->yAxis}) {
            axis->setTickLabelFont(tickFont);
            axis->setLabelFont(labelFont);
        }
        plot->legend->setFont(tickFont);
    }
    m_readout->setFont(tickFont);
    m_marker->setPen(QPen(QColor(0x33, 0x33, 0x33), 1.5 * s, Qt::DashLine));
    rebuildBasisPlot();
    m_weightsPlot->replot(QCustomPlot::rpQueuedReplot);
}

// ---------------------------------------------------------------- checks and exact panel

void BernsteinTab::updateChecks()
{
    m_checks = checkBernsteinProperties(m_degree, t());
    const QString n = QString::number(m_degree);
    const QString verdictYes = tr("yes");
    auto line = [&](const QString& name, const QString& formula, const BernsteinPropertyCheck& c) {
        return tr("%1 %2 %3 — residual at t: %4; exact as polynomials: %5")
            .arg(ExactPanel::checkMark(c.exact && c.residual < kCheckTolerance), name, formula, residualText(c.residual),
                 c.exact ? verdictYes : tr("no"));
    };
    m_checkLabels[0]->setText(line(tr("Partition of unity:"),
                                   QStringLiteral("Σ<sub>i</sub> %1 = 1").arg(basisHtml(QStringLiteral("i"), n)),
                                   m_checks.partitionOfUnity));
    m_checkLabels[1]->setText(line(tr("Symmetry:"),
                                   QStringLiteral("%1 = %2").arg(basisHtml(QStringLiteral("i"), n),
                                                                 basisHtml(QStringLiteral("n−i"), n, QStringLiteral("1 − t"))),
                                   m_checks.symmetry));
    if (m_checks.recursion.applies)
        m_checkLabels[2]->setText(
            line(tr("Recursion (Lemma 2.1):"),
                 QStringLiteral("%1 = (1 − t) %2 + t %3")
                     .arg(basisHtml(QStringLiteral("i"), n), basisHtml(QStringLiteral("i"), QString::number(m_degree - 1)),
                          basisHtml(QStringLiteral("i−1"), QString::number(m_degree - 1))),
                 m_checks.recursion));
    else
        m_checkLabels[2]->setText(tr("Recursion (Lemma 2.1): needs n ≥ 1."));
}

QStringList BernsteinTab::checkTexts() const
{
    return {m_checkLabels[0]->text(), m_checkLabels[1]->text(), m_checkLabels[2]->text()};
}

QString BernsteinTab::curvePointText() const { return m_curveLabel->text(); }

void BernsteinTab::updateExactPanel()
{
    m_exact->setContent(bernsteinPanelHtml(m_degree, m_allDegrees, m_curve->points(), m_curve->pointEditor()->allExactPoints()));
}

// ---------------------------------------------------------------- TabPage

void BernsteinTab::retranslate()
{
    m_parameter->retranslate();
    m_degreeLabel->setText(tr("Degree n:"));
    const QString degreeTip = tr("The degree n of the Bernstein polynomials Bᵢⁿ(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ (Def 2.5).");
    m_degreeLabel->setToolTip(degreeTip);
    m_degreeBox->setToolTip(degreeTip);
    m_allBox->setText(tr("All degrees up to n"));
    m_markerBox->setText(tr("Mark t"));
    m_markerBox->setToolTip(tr("The dashed vertical line at the current t, shared with the De Casteljau tab. Off, the "
                               "plot and its exports show the polynomials alone, as Figure 2.4 does."));
    m_allBox->setToolTip(tr("Overlay the polynomials of every degree 0…n, one colour per degree, like the tots option "
                            "of the thesis's Matlab Rep_Pol_Bernstein (Ex 2.4, Figure 2.4)."));
    m_basisPlot->yAxis->setLabel(tr("value"));
    m_basisPlot->setToolTip(tr("The Bernstein polynomials on [0, 1] (Def 2.5). Move the mouse to read their values; "
                               "click or drag to move t, shared with the De Casteljau tab."));
    m_weightsGroup->setToolTip(tr("Def 2.6: c(t) = Σ Bᵢⁿ(t) Pᵢ. Each bar is the weight of one control point of the "
                                  "De Casteljau tab at the current t; they sum to 1 (partition of unity)."));
    m_weightsPlot->yAxis->setLabel(tr("weight"));
    m_curveLabel->setToolTip(tr("The point c(t) from the Bernstein sum (Def 2.6) and from De Casteljau's algorithm "
                                "(Def 2.4): equal by Prop 2.1."));
    m_checksGroup->setTitle(tr("Properties at the current n and t"));
    m_checksGroup->setToolTip(tr("Each property is checked twice: in floating point at t (the residual) and exactly, "
                                 "as polynomials with rational coefficients."));
    m_checkLabels[0]->setToolTip(tr("Partition of unity: the Bernstein polynomials of one degree sum to 1."));
    m_checkLabels[1]->setToolTip(tr("Symmetry: Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t)."));
    m_checkLabels[2]->setToolTip(tr("Lemma 2.1: Bᵢⁿ = (1 − t) Bᵢⁿ⁻¹ + t Bᵢ₋₁ⁿ⁻¹."));
    m_exact->setToolTip(tr("The Bernstein polynomials expanded in powers of t (Ex 2.4) and the De Casteljau tab's curve "
                           "written in the Bernstein basis (Ex 2.5, Ex 2.6)."));
    updateWeights();
    updateChecks();
    updateExactPanel();
    m_basisPlot->replot(QCustomPlot::rpQueuedReplot); // the axis label
}

QJsonObject BernsteinTab::saveState() const
{
    QJsonObject state;
    state.insert(QStringLiteral("degree"), m_degree);
    state.insert(QStringLiteral("mode"), m_allDegrees ? QStringLiteral("all") : QStringLiteral("single"));
    state.insert(QStringLiteral("t"), t());
    state.insert(QStringLiteral("t_marker"), m_showMarker);
    return state;
}

bool BernsteinTab::loadState(const QJsonObject& state, QString* error)
{
    auto fail = [error](const QString& message) {
        if (error)
            *error = message;
        return false;
    };
    int degree = 3;
    if (const QJsonValue v = state.value(QStringLiteral("degree")); !v.isUndefined()) {
        const double d = v.toDouble(-1);
        if (!v.isDouble() || d != std::floor(d) || d < 0 || d > kMaxDegree)
            return fail(tr("The Bernstein degree must be a whole number from 0 to %1.").arg(kMaxDegree));
        degree = static_cast<int>(d);
    }
    bool all = false;
    if (const QJsonValue v = state.value(QStringLiteral("mode")); !v.isUndefined()) {
        if (v.toString() != QLatin1String("single") && v.toString() != QLatin1String("all"))
            return fail(tr("The Bernstein mode must be \"single\" or \"all\"."));
        all = v.toString() == QLatin1String("all");
    }
    bool marker = true; // older documents: shown
    if (const QJsonValue v = state.value(QStringLiteral("t_marker")); !v.isUndefined()) {
        if (!v.isBool())
            return fail(tr("The Bernstein tab's “t_marker” must be true or false."));
        marker = v.toBool();
    }
    std::optional<double> tt;
    if (const QJsonValue v = state.value(QStringLiteral("t")); !v.isUndefined()) {
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < 0 || v.toDouble() > 1)
            return fail(tr("The parameter t must be a number between 0 and 1."));
        tt = v.toDouble();
    }
    setAllDegrees(all);
    setDegree(degree);
    setTMarkerVisible(marker);
    if (tt)
        setT(*tt);
    return true;
}

bool BernsteinTab::loadExample(const granota::WorkedExample& example)
{
    const QString id = QString::fromStdString(example.id);
    if (example.kind == "bernstein" && example.degree >= 0 && example.degree <= kMaxDegree) {
        // Ex 2.4: every degree up to 5, as the thesis lists them.
        userChangedView({example.degree, true, m_showMarker}, tr("Load Ex %1").arg(id));
        emit statusMessage(tr("Ex %1: the Bernstein polynomials of every degree up to %2.").arg(id).arg(example.degree));
        return true;
    }
    if (example.kind == "bezier" && !example.points.empty() && static_cast<int>(example.points.size()) <= kMaxDegree + 1) {
        // Ex 2.5, Ex 2.6: the curves of Ex 2.2 and Ex 2.3 through Def 2.6.
        // The points and t are the De Casteljau tab's (one history for both tabs): the status
        // bar says so, as for every example that changes another tab than the one shown.
        m_undo->beginMacro(tr("Load Ex %1").arg(id));
        m_curve->loadCurve(example.points, tr("Load Ex %1").arg(id));
        userChangedView({static_cast<int>(example.points.size()) - 1, false, m_showMarker}, tr("Load Ex %1").arg(id));
        m_undo->endMacro();
        emit statusMessage(tr("Ex %1: the curve written in the Bernstein basis is in the panel on the right. Its "
                              "control points are now the De Casteljau tab's too (Ctrl+Z on either tab gives the old ones back).")
                               .arg(id));
        return true;
    }
    return false;
}

QString BernsteinTab::csv() const
{
    QStringList header{QStringLiteral("t")};
    for (int i = 0; i <= m_degree; ++i)
        header << QStringLiteral("B_%1^%2").arg(i).arg(m_degree);
    QString out = header.join(QLatin1Char(',')) + QLatin1Char('\n');
    for (int j = 0; j < kCsvSamples; ++j) {
        const double tt = static_cast<double>(j) / (kCsvSamples - 1);
        QStringList row{QString::fromStdString(formatReadable(tt))};
        for (double b : bernsteinAll(m_degree, tt))
            row << QString::fromStdString(formatReadable(b));
        out += row.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

void BernsteinTab::drawTikz(TikzWriter& w) const
{
    w.comment(QStringLiteral("Bernstein polynomials of degree %1 (Def 2.5) on [0, 1]").arg(m_degree));
    w.polyline({{0, 0}, {1, 0}}, Qt::black, 0.6);
    w.polyline({{0, 0}, {0, 1}}, Qt::black, 0.6);
    for (int n = m_allDegrees ? 0 : m_degree; n <= m_degree; ++n) {
        std::vector<std::vector<Point>> curves(static_cast<std::size_t>(n + 1));
        for (int j = 0; j < kPlotSamples; ++j) {
            const double tt = static_cast<double>(j) / (kPlotSamples - 1);
            const auto b = bernsteinAll(n, tt);
            for (int i = 0; i <= n; ++i)
                curves[static_cast<std::size_t>(i)].push_back({tt, b[static_cast<std::size_t>(i)]});
        }
        for (int i = 0; i <= n; ++i)
            w.polyline(curves[static_cast<std::size_t>(i)], CanvasStyle::series(m_allDegrees ? n : i), 1.0);
    }
    if (m_showMarker)
        w.polyline({{t(), 0}, {t(), 1}}, QColor(0x33, 0x33, 0x33), 0.6, true);
}

void BernsteinTab::setPresentation(bool on)
{
    m_presentation = on;
    m_exact->setPresentation(on);
    applyPlotStyle();
    updateExactPanel();
}

QString BernsteinTab::hint() const { return tr("Move the mouse over the plot to read Bᵢⁿ(t); click or drag to move t."); }

} // namespace granota::ui
