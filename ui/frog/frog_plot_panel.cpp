#include "ui/frog/frog_plot_panel.h"

#include "ui/common/canvas_style.h"
#include "ui/common/number_text.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/presentation_scale.h"
#include "ui/frog/frog_run.h"
#include "ui/files/exporter.h"
#include "ui/files/file_dialogs.h"

#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QStandardItemModel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr int kEnergyGraphs = 6;       // kinetic, gravity, elastic, total, damping, other
constexpr int kMostPointsDrawn = 2400; // a longer window is drawn every few samples
constexpr int kRefreshMs = 100;

double timeOf(const SeriesSample& s) { return double(s.step) / kStepsPerSecond; }

} // namespace

FrogPlotPanel::FrogPlotPanel(QWidget* parent)
    : QWidget(parent), m_view(new QComboBox(this)), m_body(new QComboBox(this)), m_export(new QPushButton(this)),
      m_note(new QLabel(this)), m_plot(new QCustomPlot(this))
{
    setObjectName(QStringLiteral("frogPlots"));
    m_view->setObjectName(QStringLiteral("frogPlotView"));
    m_body->setObjectName(QStringLiteral("frogPlotBody"));
    m_body->addItem(QString(), -1);
    m_body->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_body->hide();
    m_export->setObjectName(QStringLiteral("frogPlotExport"));
    m_export->setFocusPolicy(Qt::TabFocus);
    for (int i = 0; i < 5; ++i)
        m_view->addItem(QString(), i);
    m_note->setWordWrap(true);
    m_note->setStyleSheet(QStringLiteral("color: #5a5a5a;"));
    m_plot->setMinimumHeight(110);
    keepTickLabelsInside(m_plot);
    m_plot->setInteractions(QCP::iRangeZoom);
    m_plot->axisRect()->setRangeZoom(Qt::Horizontal);
    m_plot->setNoAntialiasingOnDrag(true);
    for (int i = 0; i < kEnergyGraphs; ++i)
        m_plot->addGraph();
    m_plot->legend->setVisible(true);
    m_plot->legend->setFillOrder(QCPLegend::foColumnsFirst);
    m_plot->legend->setWrap(3);
    m_plot->legend->setBrush(QColor(255, 255, 255, 200));
    m_plot->legend->setBorderPen(QPen(QColor(0xcf, 0xcc, 0xc0)));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignRight | Qt::AlignTop);
    // The wheel zooms the window of seconds shown; it keeps scrolling with the run.
    connect(m_plot, &QCustomPlot::mouseWheel, this, [this](QWheelEvent*) {
        QTimer::singleShot(0, this, [this] {
            if (view() != View::Phase)
                setWindowSeconds(m_plot->xAxis->range().size());
        });
    });

    auto* top = new QHBoxLayout;
    top->setContentsMargins(0, 0, 0, 0);
    top->addWidget(m_view, 1);
    top->addWidget(m_body);
    top->addWidget(m_export);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);
    layout->addLayout(top);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_note);

    connect(m_view, &QComboBox::activated, this, [this] { refresh(true); });
    connect(m_body, &QComboBox::activated, this, [this] {
        refresh(true);
        emit bodyChosen(body());
    });
    connect(m_export, &QPushButton::clicked, this, &FrogPlotPanel::chooseExportFile);
    m_timer.setInterval(kRefreshMs);
    connect(&m_timer, &QTimer::timeout, this, [this] { refresh(); });
    retranslate();
}

void FrogPlotPanel::setRun(const FrogRun* run)
{
    m_series = run ? &run->series() : nullptr; // the same object for every run (FrogRun::restoreRun)
    m_run = run;
    refresh(true);
}

FrogPlotPanel::View FrogPlotPanel::view() const { return static_cast<View>(m_view->currentData().toInt()); }

void FrogPlotPanel::setView(View v)
{
    const int i = m_view->findData(static_cast<int>(v));
    if (i < 0 || !m_view->model()->index(i, 0).flags().testFlag(Qt::ItemIsEnabled))
        return;
    m_view->setCurrentIndex(i);
    refresh(true);
}

int FrogPlotPanel::body() const { return m_body->count() > 1 ? m_body->currentData().toInt() : -1; }

void FrogPlotPanel::setBody(int chosen)
{
    updateBodies();
    const int i = m_body->findData(chosen);
    if (i < 0)
        return;
    const bool changed = i != m_body->currentIndex();
    m_body->setCurrentIndex(i);
    refresh(true);
    if (changed)
        emit bodyChosen(body());
}

void FrogPlotPanel::updateBodies()
{
    // One entry a body, when there are two or more (one body's values are the scene's). A
    // series started again (a reset) keeps the choice until its first sample says otherwise.
    if (m_series && m_series->samples().empty())
        return;
    const int bodies = m_series && m_series->bodies() > 1 ? m_series->bodies() : 0;
    if (m_body->count() != bodies + 1) {
        const int chosen = m_body->currentData().toInt();
        const QSignalBlocker block(m_body);
        while (m_body->count() > bodies + 1)
            m_body->removeItem(m_body->count() - 1);
        for (int k = m_body->count() - 1; k < bodies; ++k)
            m_body->addItem(tr("Body %1").arg(k + 1), k);
        m_body->setCurrentIndex(std::max(0, m_body->findData(chosen)));
        if (m_body->currentData().toInt() != chosen)
            emit bodyChosen(body()); // that body is gone (another stage): back to the sum
    }
    m_body->setVisible(bodies > 0 && view() != View::Phase);
}

void FrogPlotPanel::setWindowSeconds(double seconds)
{
    if (!std::isfinite(seconds))
        return;
    m_window = std::clamp(seconds, 1.0, double(FrogRun::kSeriesSeconds));
    refresh(true);
}

void FrogPlotPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_timer.start();
    refresh(true);
}

void FrogPlotPanel::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_timer.stop();
}

void FrogPlotPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    if (event->type() == QEvent::FontChange)
        refresh(true);
    QWidget::changeEvent(event);
}

void FrogPlotPanel::updateViews()
{
    // The phase plot is the pendulums' only.
    const bool phase = m_series && m_series->phaseLinks() > 0;
    auto* model = qobject_cast<QStandardItemModel*>(m_view->model());
    if (QStandardItem* item = model ? model->item(m_view->findData(static_cast<int>(View::Phase))) : nullptr)
        item->setEnabled(phase);
    if (!phase && view() == View::Phase)
        m_view->setCurrentIndex(m_view->findData(static_cast<int>(View::Energy)));
}

void FrogPlotPanel::refresh(bool force)
{
    if (!m_series)
        return;
    const std::size_t size = m_series->samples().size();
    const long last = size ? m_series->samples().back().step : -1;
    if (!force && last == m_drawnStep && size == m_drawnSize && m_drawnView == int(view()))
        return; // paused, or nothing new: the plot stays as it is
    if (!isVisible() && !force)
        return;
    updateViews();
    updateBodies();
    m_drawnStep = last;
    m_drawnSize = size;
    m_drawnView = int(view());
    draw();
}

void FrogPlotPanel::draw()
{
    m_plot->clearItems();
    for (int i = m_plot->plottableCount() - 1; i >= 0; --i)
        if (qobject_cast<QCPCurve*>(m_plot->plottable(i)))
            m_plot->removePlottable(i);
    // The window's font, which presentation mode enlarges; ticks and legend a little smaller.
    const QFont font = this->font();
    QFont small = font;
    small.setPointSizeF(font.pointSizeF() * 0.9);
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        axis->setLabelFont(font);
        axis->setTickLabelFont(small);
    }
    m_plot->legend->setFont(small);
    if (view() == View::Phase)
        drawPhase();
    else
        drawTime();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void FrogPlotPanel::drawTime()
{
    const auto& samples = m_series->samples();
    const View v = view();
    const double end = samples.empty() ? 0 : timeOf(samples.back());
    const double start = std::max(0.0, end - m_window);
    // The samples in the window (consecutive steps: found by bisection), thinned out to
    // kMostPointsDrawn so that a long window costs no more to draw than a short one.
    const auto first = std::lower_bound(samples.begin(), samples.end(), start,
                                        [](const SeriesSample& s, double t) { return timeOf(s) < t; });
    const std::size_t from = std::size_t(first - samples.begin());
    const std::size_t count = samples.size() - from;
    const std::size_t stride = std::max<std::size_t>(1, (count + kMostPointsDrawn - 1) / kMostPointsDrawn);

    const bool energy = v == View::Energy;
    const bool stable = !samples.empty() && samples.back().elastic.has_value();
    const int chosen = body();
    const QString names[kEnergyGraphs] = {tr("kinetic"), tr("gravitational"), tr("elastic"),
                                          tr("total"),   tr("damping"),       tr("other losses")};
    const int graphs = energy ? kEnergyGraphs : 1;
    QVector<double> keys;
    QVector<double> values[kEnergyGraphs];
    keys.reserve(int(count / stride + 1));
    for (std::size_t i = from; i < samples.size(); i += stride) {
        const SeriesValues* of = seriesValuesOf(samples[i], chosen);
        if (!of)
            continue; // older than the body's values are kept
        const SeriesValues& s = *of;
        keys << timeOf(samples[i]);
        if (energy) {
            const double e[kEnergyGraphs] = {
                s.kinetic, s.gravity, s.elastic.value_or(0), s.total, s.dampingLoss.value_or(0), s.otherLoss.value_or(0)};
            for (int g = 0; g < kEnergyGraphs; ++g)
                values[g] << e[g];
        } else {
            values[0] << (v == View::AreaError ? s.areaErrorPercent : v == View::Stretch ? s.maxStretch : double(s.contacts));
        }
    }
    m_plot->legend->clearItems();
    for (int g = 0; g < kEnergyGraphs; ++g) {
        QCPGraph* graph = m_plot->graph(g);
        const bool shown = g < graphs && (stable || !energy || g == 0 || g == 1 || g == 3);
        graph->setVisible(shown);
        if (!shown) {
            graph->data()->clear();
            continue;
        }
        graph->setData(keys, values[g], true);
        graph->setLineStyle(v == View::Contacts ? QCPGraph::lsStepLeft : QCPGraph::lsLine);
        QPen pen(CanvasStyle::series(energy ? g : int(v) + 5), (energy && g == 3 ? 2.5 : 1.5) * m_scale);
        if (energy && g >= 4)
            pen.setStyle(Qt::DashLine);
        graph->setPen(pen);
        graph->setName(energy                 ? names[g]
                       : v == View::AreaError ? tr("area error")
                       : v == View::Stretch   ? tr("largest stretch")
                                              : tr("contacts"));
        graph->addToLegend();
    }
    m_plot->legend->setVisible(energy);
    // Three columns where they fit (two rows), else two: the legend never runs off the plot.
    m_plot->legend->setWrap(3);
    m_plot->legend->setIconSize(QSize(int(18 * m_scale), int(10 * m_scale)));
    if (energy && m_plot->legend->minimumOuterSizeHint().width() > 0.9 * m_plot->axisRect()->width())
        m_plot->legend->setWrap(2);
    // A legend that would hide most of the curves (the splitter dragged low) stays off.
    if (energy && m_plot->legend->minimumOuterSizeHint().height() > 0.6 * m_plot->axisRect()->height())
        m_plot->legend->setVisible(false);
    m_plot->xAxis->setLabel(tr("time (s)"));
    m_plot->yAxis->setLabel(energy                 ? tr("energy")
                            : v == View::AreaError ? tr("area error (%)")
                            : v == View::Stretch   ? tr("|L/L₀ − 1|")
                                                   : tr("contacts"));
    m_plot->xAxis->setRange(start, std::max(start + m_window, end));
    bool found = false;
    QCPRange range;
    for (int g = 0; g < graphs; ++g) {
        if (!m_plot->graph(g)->visible())
            continue;
        bool ok = false;
        const QCPRange r = m_plot->graph(g)->getValueRange(ok);
        if (ok)
            range = found ? QCPRange(std::min(range.lower, r.lower), std::max(range.upper, r.upper)) : r;
        found = found || ok;
    }
    if (!found)
        range = QCPRange(0, 1);
    if (v == View::AreaError) { // the target, 0 %, always in view
        range.lower = std::min(range.lower, 0.0);
        range.upper = std::max(range.upper, 0.0);
    }
    const double pad = std::max(0.05 * range.size(), 1e-9 + 1e-6 * std::abs(range.upper));
    m_plot->yAxis->setRange(range.lower - pad, range.upper + pad);
    if (v == View::AreaError) {
        auto* zero = new QCPItemStraightLine(m_plot);
        zero->point1->setCoords(0, 0);
        zero->point2->setCoords(1, 0);
        zero->setPen(QPen(QColor(0x8a, 0x86, 0x7a), 1, Qt::DotLine));
    }
    // One body's values are kept in the last samples only, or from when it was chosen.
    QString kept;
    if (chosen >= 0 && !m_series->keepsBodies())
        kept = tr("Body %1 alone: its values are kept from the next step on.").arg(chosen + 1);
    const auto keptFrom = std::partition_point(samples.begin(), samples.end(),
                                               [](const SeriesSample& s) { return s.bodies.empty(); });
    if (chosen >= 0 && m_series->keepsBodies() && keptFrom != samples.begin() && keptFrom != samples.end())
        kept = tr("Body %1 alone: its values are kept from %2 s on.").arg(chosen + 1).arg(displayFixed(timeOf(*keptFrom), 1));
    if (!kept.isEmpty())
        kept += QLatin1Char(' ');
    if (energy && !stable)
        m_note->setText(kept + tr("Energies in px²/step², unit masses. The seed's springs and area are corrections, not "
                                  "forces: it stores no elastic energy and books no losses; total = kinetic + gravitational."));
    else if (energy)
        m_note->setText(kept + tr("Energies in mass·px²/step². Other losses: hits and friction at walls and between bodies, "
                                  "and the solver's own dissipation, less what the mouse put in."));
    else
        m_note->setText(kept.trimmed());
    m_note->setVisible(!m_note->text().isEmpty());
}

void FrogPlotPanel::drawPhase()
{
    for (int g = 0; g < kEnergyGraphs; ++g) {
        m_plot->graph(g)->setVisible(false);
        m_plot->graph(g)->data()->clear();
    }
    m_plot->legend->clearItems();
    const auto& samples = m_series->samples();
    const int links = m_series->phaseLinks();
    const double end = samples.empty() ? 0 : timeOf(samples.back());
    const double start = std::max(0.0, end - m_window);
    QCPRange x(-0.1, 0.1), y(-0.01, 0.01);
    for (int k = 0; k < links; ++k) {
        QVector<double> t, theta, omega;
        for (const SeriesSample& s : samples) {
            if (timeOf(s) < start || std::size_t(k) >= s.angularVelocities.size())
                continue;
            t << double(t.size());
            theta << s.angles[std::size_t(k)];
            omega << s.angularVelocities[std::size_t(k)];
            x.lower = std::min(x.lower, theta.back()), x.upper = std::max(x.upper, theta.back());
            y.lower = std::min(y.lower, omega.back()), y.upper = std::max(y.upper, omega.back());
        }
        auto* curve = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
        curve->setData(t, theta, omega, true);
        curve->setPen(QPen(CanvasStyle::series(k), 1.5 * m_scale));
        curve->setName(tr("link %1").arg(k + 1));
    }
    // §4.15: the first link's angle is limited from the vertical on both solvers; an orbit
    // that reaches a limit is cut off there.
    if (m_run && m_run->scene().has(SceneComponent::AngleLimits) && links > 0)
        for (double limit : {m_run->scene().chainShoulderMin, m_run->scene().chainShoulderMax}) {
            auto* line = new QCPItemStraightLine(m_plot);
            line->point1->setCoords(limit, 0);
            line->point2->setCoords(limit, 1);
            line->setPen(QPen(QColor(0xa4, 0x43, 0x1b), 1.5 * m_scale, Qt::DashLine));
            x.lower = std::min(x.lower, limit - 0.05), x.upper = std::max(x.upper, limit + 0.05);
        }
    m_plot->legend->setVisible(links > 1);
    m_plot->xAxis->setLabel(tr("angle θ from the vertical (rad)"));
    m_plot->yAxis->setLabel(tr("dθ/dt (rad/step)"));
    const double px = 0.05 * x.size(), py = 0.05 * y.size();
    m_plot->xAxis->setRange(x.lower - px, x.upper + px);
    m_plot->yAxis->setRange(y.lower - py, y.upper + py);
    m_note->setText(m_run && m_run->scene().has(SceneComponent::AngleLimits)
                        ? tr("Phase plot of the last %1 s: each link's orbit. The dashed lines are the first link's "
                             "limits (§4.15): an orbit that reaches one is cut off.")
                              .arg(displayFixed(m_window, m_window < 10 ? 1 : 0))
                        : tr("Phase plot of the last %1 s: each link's orbit; a small swing of a free link is an "
                             "ellipse, with the period 2π√(L/g).")
                              .arg(displayFixed(m_window, m_window < 10 ? 1 : 0)));
    m_note->setVisible(true);
}

QString FrogPlotPanel::csv() const
{
    if (!m_series)
        return QString();
    const int links = m_series->phaseLinks();
    const int chosen = body();
    std::string out = seriesCsvHeader(links) + "\n";
    for (const SeriesSample& s : m_series->samples())
        if (seriesValuesOf(s, chosen))
            out += seriesCsvRow(s, links, chosen) + "\n";
    return QString::fromStdString(out);
}

bool FrogPlotPanel::exportCsv(const QString& path, QString* error) const
{
    const QString message = writeTextFile(path, csv());
    if (error)
        *error = message;
    return message.isEmpty();
}

void FrogPlotPanel::chooseExportFile()
{
    const QString file = saveFileName(this, tr("Export the series"), QStringLiteral("series.csv"), tr("CSV files (*.csv)"));
    if (file.isEmpty())
        return;
    QString error;
    if (exportCsv(file, &error))
        emit statusMessage(tr("Exported %1").arg(QFileInfo(file).fileName()));
    else
        emit statusMessage(error);
}

void FrogPlotPanel::retranslate()
{
    const QString texts[5] = {tr("Energy"), tr("Area error"), tr("Largest stretch"), tr("Contacts"),
                              tr("Phase plot (pendulums)")};
    for (int i = 0; i < 5; ++i)
        m_view->setItemText(m_view->findData(i), texts[i]);
    m_view->setToolTip(tr("What to plot against time: the energies and what damping and the rest took, the area "
                          "error, the largest stretch, the contacts; or, for the pendulums, each link's angle "
                          "against its angular velocity. The wheel zooms the window of seconds."));
    m_body->setItemText(0, tr("All bodies"));
    for (int k = 1; k < m_body->count(); ++k)
        m_body->setItemText(k, tr("Body %1").arg(k));
    m_body->setToolTip(tr("Whose values to plot: all the bodies summed (the area error: their mean; the stretch: "
                          "the largest), or one body alone, with the legs that hang from it. The canvas marks the "
                          "body chosen. The CSV holds what is plotted."));
    m_export->setText(tr("Export CSV…"));
    m_export->setToolTip(tr("Every step kept (the last %1 minutes), in the columns of granota-cli simulate --series.")
                             .arg(FrogRun::kSeriesSeconds / 60));
    m_plot->setAccessibleName(tr("Plots over time"));
    refresh(true);
}

void FrogPlotPanel::setPresentation(bool on)
{
    m_scale = presentationScale(on);
    updateGeometry(); // a taller panel in presentation mode
    refresh(true);
}

} // namespace granota::ui
