#pragma once
/// \file work_precision_panel.h
/// The work-precision section of a tab (docs/work-precision.md): pick a report, Measure, watch the
/// progress, Cancel at any time; the plot (error against run time or against the knob — the
/// number of points, the degree… —, log–log; the report chooses, the user may switch) and the
/// lesson it teaches. The measurement runs in a worker thread, so the window never freezes.

#include "core/reports/work_precision.h"

#include <QWidget>

#include <atomic>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QCustomPlot;
class QLabel;
class QProgressBar;
class QPushButton;
class QThread;

namespace granota::ui {

class WorkPrecisionPanel : public QWidget {
    Q_OBJECT
public:
    /// `reports`: the names of the reports this tab shows (work_precision.h).
    explicit WorkPrecisionPanel(std::vector<std::string> reports, QWidget* parent = nullptr);
    ~WorkPrecisionPanel() override;

    /// Starts measuring the selected report (no-op while one runs).
    void measure();
    void cancel();
    bool running() const { return m_thread != nullptr; }
    /// The last report measured, if any.
    const std::optional<WorkPrecisionReport>& report() const { return m_report; }
    QCustomPlot* plot() const { return m_plot; }
    /// The names of the reports offered, in the order of the choice box.
    const std::vector<std::string>& reportNames() const { return m_names; }
    /// The report chosen (selectReport), "" if none.
    std::string selectedReport() const;
    /// What the x axis shows: run time or the knob. A new report starts with its own choice.
    WorkPrecisionAxis axis() const;
    void setAxis(WorkPrecisionAxis axis);
    void selectReport(const std::string& name);
    void setPresentation(bool on);
    /// Tests: measure with the quick settings and no repetition of the timings.
    void setQuick(bool quick) { m_quick = quick; }

signals:
    void finished(bool ok);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void showReport();

    std::vector<std::string> m_names;
    QComboBox* m_choice;
    QComboBox* m_axis; ///< data: WorkPrecisionAxis
    QPushButton* m_measure;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_lesson;
    QCustomPlot* m_plot;
    QThread* m_thread = nullptr;
    std::atomic<bool> m_cancelRequested{false};
    std::atomic<int> m_permille{0};
    std::optional<WorkPrecisionReport> m_report;
    std::optional<Expected<WorkPrecisionReport>> m_result; ///< written by the worker, read after it ends
    double m_styleScale = 1.0;
    bool m_quick = false;
};

} // namespace granota::ui
