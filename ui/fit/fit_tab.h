#pragma once
/// \file fit_tab.h
/// The Fitting tab (docs/tabs.md; thesis §2.1.3, Lemma 2.2, Prop 2.2, Ex 2.7–2.10): data
/// points Q_0..Q_k edited on a canvas and in a table (or imported from a CSV file), the
/// least-squares Bézier curve of degree n for uniform, chord-length or centripetal
/// parameters t_i (optionally corrected by re-projection), its control points and control
/// polygon, the residuals Q_i − α(t_i), the error readouts and cond₂(M), an "error against
/// degree" plot, and the exact matrices of Ex 2.7 and Ex 2.8. Every computation is the core's
/// (core/curves/fitting/least_squares_fit.h, core/curves/fitting/fit_error_by_degree.h); the tab draws and explains.

#include "ui/common/curvature_comb.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "ui/fit/fit_display.h"
#include "ui/fit/fit_drawing_panel.h"
#include "ui/fit/fit_settings.h"
#include "ui/common/curve_tab.h"

#include <cstddef>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QCPGraph;
class QCPItemText;
class QCustomPlot;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QSplitter;

namespace granota::ui {

class BackgroundFit;
class FitReadoutPanel;
class FitSettingsPanel;
class CurvatureCombScaleBox;
class Drawable;

class FitTab : public CurveTab {
    Q_OBJECT
public:
    explicit FitTab(QWidget* parent = nullptr);
    ~FitTab() override;

    void retranslate() override;
    QString hint() const override;
    bool loadExample(const granota::WorkedExample& example) override;
    QString csv() const override;

    /// Reads data points from a CSV or JSON file (core/io/point_list.h) as one undo step. On a
    /// bad file returns false with a translated message in `error` and changes nothing.
    bool importFile(const QString& path, QString* error);

    /// The settings, and changing them as one undo step.
    const FitSettings& settings() const { return m_settings; }
    void changeSettings(const FitSettings& after, const QString& undoText, int field = -1);
    /// What is drawn of the fit (fit_display.h), and changing it as one undo step (`mergeId` ≥ 0:
    /// successive changes with it merge, a spin box held down).
    const FitDisplay& display() const { return m_display; }
    void changeDisplay(const FitDisplay& after, const QString& undoText, int mergeId = -1);
    /// The fitted curve as drawn (display().samples intervals) and, while shown, the curves of
    /// the first 1, 2, …, n + 1 control points (Matlab `desglossar`).
    const std::vector<Point>& curve() const { return m_curve; }
    const std::vector<std::vector<Point>>& breakdown() const { return m_breakdown; }
    /// The degree actually fitted: min(n, k).
    int fittedDegree() const;
    /// The current fit, or nullptr when there is none (then fitError() says why, or a fit is
    /// running in the background: isFitting()).
    const FitResult* currentFit() const { return m_fit ? &*m_fit : nullptr; }

    /// A fit whose work (fitWork, least_squares_fit.h) is beyond this runs on a worker thread
    /// (background_fit.h), with its progress and a Cancel button, so that opening a document
    /// or dragging a point never waits for it: some 0.1 s on the reference machine. Below,
    /// the fit is made at once, as before (the tests and exports of small fits see it at once).
    static constexpr double kBackgroundFitWork = 2e7;
    /// Whether a fit is running in the background (the readouts say "Fitting…").
    bool isFitting() const;
    /// Waits for a fit running in the background and shows it: File ▸ Export, TikZ, CSV and
    /// `granota --screenshot` show the finished fit, never a half state.
    void finishFit() const;
    /// Stops the correction of a fit running in the background; the best fit found until then is shown.
    QPushButton* cancelButton() const;
    QProgressBar* fitProgress() const;
    QString fitError() const { return m_fitError; }
    /// The readouts (error, RMS, max, cond₂) and the warnings as shown, for tests.
    QString readoutText() const;
    QString warningText() const;

    // The parts, for the tests.
    QCustomPlot* errorPlot() const { return m_plot; }
    QSpinBox* degreeBox() const { return m_degree; }
    QComboBox* parametrizationBox() const { return m_parametrization; }
    QComboBox* solverBox() const { return m_solver; }
    QCheckBox* correctionBox() const { return m_correct; }
    QSpinBox* iterationsBox() const { return m_iterations; }
    QCheckBox* showMatricesBox() const { return m_showMatrices; }
    QCheckBox* controlPointsBox() const { return m_drawing->controlPointsBox(); }
    QCheckBox* residualsBox() const { return m_drawing->residualsBox(); }
    QCheckBox* breakdownBox() const { return m_drawing->breakdownBox(); }
    QSpinBox* samplesBox() const { return m_drawing->samplesBox(); }
    QCheckBox* allParametrizationsBox() const { return m_drawing->allParametrizationsBox(); }
    /// The error plot's line of parametrization `p`, or nullptr when it is not shown.
    QCPGraph* errorGraph(Parametrization p) const;
    /// The curvature comb of the fitted curve (ui/common/curvature_comb.h), on demand.
    QCheckBox* combBox() const { return m_combBox; }
    /// The comb's scale beside it (curvature_comb_scale_box.h: 0 is automatic); undoable, in the document.
    CurvatureCombScaleBox* combScaleBox() const { return m_combScaleBox; }
    const CurvatureComb& comb() const { return m_comb; }

    /// The table lists the points up to this many; beyond, a note says how many there are.
    static constexpr int kTableLimit = 5000;
    /// The error-against-degree plot goes up to the highest degree the tab allows,
    /// min(k, kMaxFitDegree), as long as refitting every degree on each change stays quick:
    /// Σ (k + 1)(n + 1)² over the degrees plotted (the QR factorisations' work) at most this.
    /// 60 points reach n = 59, 200 points n = 47 (docs/tabs.md).
    static constexpr double kPlotWorkBudget = 8e6;
    /// What the plot says about where it stops (empty when it reaches the highest degree).
    QString plotNote() const;

signals:
    /// A fit made in the background is shown (not one superseded by a newer request).
    void backgroundFitShown();

protected:
    void drawTikz(TikzWriter& w) const override;

private:
    // What CurveTab asks of this tab.
    PointListMessages pointMessages() const override;
    /// The document's settings: degree, parametrization, solver, corrections, showMatrices.
    void writeSettings(QJsonObject& state) const override;
    /// Applies them without an undo step: opening a document starts a new history.
    bool loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error) override;
    /// The data and the curve, and the control points unless they fly far off.
    QRectF contentBounds() const override;
    /// The plot's fonts, pens and the splitters follow the new scale.
    void presentationChanged(bool on) override;
    void buildUi();
    void addLayers();
    void applySettings(const FitSettings& s);
    void applyDisplay(const FitDisplay& d);
    /// The curve (and its breakdown) sampled again from the current fit.
    void resample();
    void updateControls();
    void onPointsChanged();
    void refit();
    /// Takes the fit (or its error) as the current one, and shows it.
    void showFit(Expected<FitResult> fit);
    /// What depends on the fit: the comb, the canvas, the readouts, the exact panel.
    void updateFitViews();
    void backgroundFitFinished();
    void updateReadouts();
    void updatePlot();
    void updateExact();
    void updateTable();
    void importDialog();

    QLabel* m_tableNote = nullptr;
    QCustomPlot* m_plot = nullptr;
    QCPItemText* m_plotText = nullptr; ///< on the plot: why it stops before the highest degree
    QString m_plotNote;
    int m_plotLastDegree = 0; ///< the error plot's degrees: 1 … this
    QSplitter* m_mainSplitter = nullptr;
    QSplitter* m_leftSplitter = nullptr;
    QSplitter* m_bottomSplitter = nullptr;

    FitSettingsPanel* m_settingsPanel = nullptr; ///< the settings' fields, kept below for the tab's use
    QSpinBox* m_degree = nullptr;
    QComboBox* m_parametrization = nullptr;
    QComboBox* m_solver = nullptr;
    QCheckBox* m_correct = nullptr;
    QSpinBox* m_iterations = nullptr;
    QCheckBox* m_showMatrices = nullptr;
    QCheckBox* m_combBox = nullptr;
    CurvatureCombScaleBox* m_combScaleBox = nullptr;
    double m_combScale = 0; ///< 0: automatic
    CurvatureComb m_comb;   ///< of the fitted curve, while the comb is shown
    void updateComb();

    FitDrawingPanel* m_drawing = nullptr;

    FitReadoutPanel* m_readouts = nullptr;
    QString m_refusal; ///< the last refused degree's reason, shown until the next fit
    BackgroundFit* m_background = nullptr;
    std::unique_ptr<Drawable> m_exportView; ///< the canvas, once the background fit is done

    FitSettings m_settings;
    FitDisplay m_display;
    std::optional<FitResult> m_fit;
    QString m_fitError;
    std::vector<Point> m_curve;                  ///< the fitted curve, sampled by De Casteljau
    std::vector<std::vector<Point>> m_breakdown; ///< breakdownCurves() of the fit, while shown
    int m_lastFittedDegree = -1;                 ///< to say when too few points lower the degree
    bool m_updatingControls = false;
    bool m_loading = false; ///< examples and documents: no "degree lowered" message
};

} // namespace granota::ui
