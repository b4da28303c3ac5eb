#pragma once
/// \file frog_plot_panel.h
/// The plots over time under the Frog canvas (docs/plots-over-time.md): the run's series
/// drawn as a scrolling window of the last seconds — energies and what damping and the rest
/// took, the area error, the largest stretch, the contacts — or, for the pendulums, the phase
/// plot (each link's angle against its angular velocity, with §4.15's limits); summed over
/// the bodies or of one body alone, marked on the canvas. The wheel
/// zooms the window, a drag moves it; pause freezes it. The series export as CSV, in the
/// columns of `granota-cli simulate --series`.

#include "core/softbody/simulation_series.h"
#include "core/softbody/scenes/scene.h"

#include <QTimer>
#include <QWidget>

class QComboBox;
class QCustomPlot;
class QLabel;
class QPushButton;

namespace granota::ui {

class FrogRun;

class FrogPlotPanel : public QWidget {
    Q_OBJECT
public:
    enum class View { Energy, AreaError, Stretch, Contacts, Phase };

    explicit FrogPlotPanel(QWidget* parent = nullptr);

    /// The run whose series is drawn (frog_run.h), and the scene it comes from (its angle limits).
    void setRun(const FrogRun* run);
    /// Draws the series again if it has grown (a timer does so ten times a second while the
    /// panel is shown; the tab calls it after a single step or a new run).
    void refresh(bool force = false);

    View view() const;
    void setView(View view);
    /// Whose values the time plots show and the CSV holds: −1 the scene's (summed over its
    /// bodies), or body k's alone (0-based; its values are kept for the last
    /// SeriesRecorder::bodySamplesKept() samples). The list is shown when there are two or more.
    int body() const;
    void setBody(int chosen);
    /// The width of the scrolling window, seconds (the wheel changes it): 1 … kSeriesSeconds.
    double windowSeconds() const { return m_window; }
    void setWindowSeconds(double seconds);
    QCustomPlot* plot() const { return m_plot; }
    /// The whole series kept, as `simulate --series` writes it.
    QString csv() const;
    /// Writes csv() to `path`; false with a message when it cannot be written.
    bool exportCsv(const QString& path, QString* error) const;

    void retranslate();
    void setPresentation(bool on);
    /// A third of a 1280 × 800 window's canvas column; the splitter gives the canvas the rest.
    QSize sizeHint() const override { return {480, int(230 * m_scale)}; }

signals:
    void statusMessage(const QString& text);
    /// The user chose whose values to plot (body()).
    void bodyChosen(int body);

protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void draw();
    void drawTime();
    void drawPhase();
    void chooseExportFile();
    void updateViews();
    void updateBodies();

    const SeriesRecorder* m_series = nullptr;
    const FrogRun* m_run = nullptr;
    QComboBox* m_view;
    QComboBox* m_body;
    QPushButton* m_export;
    QLabel* m_note;
    QCustomPlot* m_plot;
    QTimer m_timer;
    double m_window = 10;
    long m_drawnStep = -1;
    std::size_t m_drawnSize = 0;
    int m_drawnView = -1;
    double m_scale = 1;
};

} // namespace granota::ui
