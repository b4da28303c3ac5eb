#include "ui/common/work_precision_panel.h"

#include "ui/common/presentation_scale.h"
#include "ui/common/work_precision_plot.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace granota::ui {

WorkPrecisionPanel::WorkPrecisionPanel(std::vector<std::string> reports, QWidget* parent)
    : QWidget(parent), m_names(std::move(reports)), m_choice(new QComboBox(this)), m_axis(new QComboBox(this)),
      m_measure(new QPushButton(this)), m_cancel(new QPushButton(this)), m_progress(new QProgressBar(this)),
      m_lesson(new QLabel(this)), m_plot(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4); // its row of choices fits an 800×600 screen in Catalan
    auto* row = new QHBoxLayout;
    row->addWidget(m_choice, 1);
    row->addWidget(m_axis);
    if (m_names.size() <= 1)
        row->addStretch(1); // the choice is hidden: keep the axis box its own width
    row->addWidget(m_measure);
    row->addWidget(m_cancel);
    layout->addLayout(row);
    layout->addWidget(m_progress);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_lesson);
    m_lesson->setWordWrap(true);
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_progress->setVisible(false);
    m_cancel->setEnabled(false);
    m_choice->setVisible(m_names.size() > 1);
    m_plot->setMinimumHeight(180);
    connect(m_measure, &QPushButton::clicked, this, &WorkPrecisionPanel::measure);
    connect(m_cancel, &QPushButton::clicked, this, &WorkPrecisionPanel::cancel);
    connect(m_axis, &QComboBox::activated, this, [this] { showReport(); });
    connect(m_choice, &QComboBox::currentIndexChanged, this, [this] {
        if (m_report && m_choice->currentIndex() >= 0 &&
            m_report->name != m_names[static_cast<std::size_t>(m_choice->currentIndex())]) {
            m_report.reset();
            showReport();
        }
    });
    retranslate();
    showReport();
}

WorkPrecisionPanel::~WorkPrecisionPanel()
{
    if (m_thread) {
        m_cancelRequested = true;
        m_thread->wait();
        delete m_thread;
    }
}

std::string WorkPrecisionPanel::selectedReport() const
{
    const int i = m_choice->currentIndex();
    return i >= 0 && std::size_t(i) < m_names.size() ? m_names[std::size_t(i)] : std::string();
}

void WorkPrecisionPanel::selectReport(const std::string& name)
{
    for (std::size_t i = 0; i < m_names.size(); ++i)
        if (m_names[i] == name)
            m_choice->setCurrentIndex(static_cast<int>(i));
}

WorkPrecisionAxis WorkPrecisionPanel::axis() const { return static_cast<WorkPrecisionAxis>(m_axis->currentData().toInt()); }

void WorkPrecisionPanel::setAxis(WorkPrecisionAxis axis)
{
    m_axis->setCurrentIndex(std::max(0, m_axis->findData(static_cast<int>(axis))));
    showReport();
}

void WorkPrecisionPanel::measure()
{
    if (m_thread || m_choice->currentIndex() < 0)
        return;
    const std::string name = m_names[static_cast<std::size_t>(m_choice->currentIndex())];
    m_cancelRequested = false;
    m_permille = 0;
    m_result.reset();
    WorkPrecisionOptions options;
    options.quick = m_quick;
    if (m_quick)
        options.minSecondsPerPoint = 1e-6;
    options.progress = [this](double fraction) {
        m_permille = static_cast<int>(fraction * 1000);
        return !m_cancelRequested.load();
    };
    m_thread = QThread::create([this, name, options] { m_result = runWorkPrecisionReport(name, options); });
    auto* poll = new QTimer(this);
    connect(poll, &QTimer::timeout, this, [this] { m_progress->setValue(m_permille.load()); });
    poll->start(50);
    connect(m_thread, &QThread::finished, this, [this, poll] {
        poll->deleteLater();
        m_thread->deleteLater();
        m_thread = nullptr;
        const bool ok = m_result && m_result->ok();
        if (ok) {
            m_report = m_result->value();
            m_axis->setCurrentIndex(std::max(0, m_axis->findData(static_cast<int>(m_report->xAxis))));
        }
        m_measure->setEnabled(true);
        m_cancel->setEnabled(false);
        m_progress->setVisible(false);
        showReport();
        emit finished(ok);
    });
    m_measure->setEnabled(false);
    m_cancel->setEnabled(true);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_thread->start(QThread::LowPriority);
}

void WorkPrecisionPanel::cancel() { m_cancelRequested = true; }

void WorkPrecisionPanel::showReport()
{
    // An untimed report (energy-drift: the energy step by step) has only its knob for an x axis.
    m_axis->setEnabled(m_report.has_value() && m_report->timed);
    if (m_report) {
        // The knob's own name in the choice ("against points", "against degree").
        m_axis->setItemText(1, tr("against %1").arg(reportKnob(*m_report)));
        plotWorkPrecision(m_plot, *m_report, m_styleScale, axis());
        m_lesson->setText(reportLesson(*m_report));
    } else {
        m_axis->setItemText(1, tr("against the setting"));
        clearWorkPrecisionPlot(m_plot);
        m_lesson->setText(m_result && !m_result->ok() && m_result->error().code == ErrorCode::Cancelled
                              ? tr("Cancelled. Press Measure to start again.")
                              : tr("Press Measure: each method runs over a range of its setting, and the plot "
                                   "shows its error against its run time or against the setting itself (lower "
                                   "left is better)."));
    }
}

void WorkPrecisionPanel::setPresentation(bool on)
{
    m_styleScale = presentationScale(on);
    showReport();
}

void WorkPrecisionPanel::retranslate()
{
    const int current = m_choice->currentIndex();
    m_choice->clear();
    for (const auto& name : m_names) {
        WorkPrecisionReport r;
        r.name = name;
        m_choice->addItem(reportTitle(r));
    }
    m_choice->setCurrentIndex(current < 0 ? 0 : current);
    const int axis = m_axis->currentIndex();
    m_axis->clear();
    m_axis->addItem(tr("against run time"), static_cast<int>(WorkPrecisionAxis::Seconds));
    m_axis->addItem(QString(), static_cast<int>(WorkPrecisionAxis::Knob)); // named by showReport()
    m_axis->setCurrentIndex(axis < 0 ? 0 : axis);
    m_axis->setToolTip(tr("The x axis: the run time per call, or the method's setting itself (the number of "
                          "points, the degree, the step…), which counts the cost without the clock."));
    m_choice->setToolTip(tr("Which numerical method to measure: its error against its run time."));
    m_measure->setText(tr("Measure"));
    m_measure->setToolTip(tr("Run every method over a range of its setting and plot error against run time."));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop the measurement."));
    m_progress->setToolTip(tr("Measuring…"));
    m_plot->setToolTip(tr("Work-precision plot: each marker is one setting of a method; lower is more accurate, "
                          "left is cheaper (faster, or fewer points)."));
    showReport();
}

void WorkPrecisionPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace granota::ui
