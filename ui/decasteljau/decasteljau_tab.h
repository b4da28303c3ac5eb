#pragma once
/// \file decasteljau_tab.h
/// The De Casteljau tab (docs/tabs.md; thesis §2.1.1, Def 2.4, Ex 2.2, Ex 2.3): editable
/// control points, the construction of c(t) level by level at a parameter t that can be
/// animated, the Matlab Rep_Bezier "desglossar" view, the tangent, the split at t, degree
/// elevation, and beside the canvas the point table and the exact triangle of P_i^r(t).
/// The Bernstein tab shares this tab's control points and its t.

#include "core/curves/bezier/de_casteljau.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curve_tab.h"

#include <QString>

#include <vector>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTimer;
class QToolButton;

namespace granota::ui {

class DeCasteljauParameterControl;

class DeCasteljauTab : public CurveTab {
    Q_OBJECT
public:
    explicit DeCasteljauTab(QWidget* parent = nullptr);

    void retranslate() override;
    QString hint() const override;
    bool loadExample(const granota::WorkedExample& example) override;
    QString csv() const override;

    DeCasteljauParameterControl* parameterControl() const { return m_parameter; }

    /// The parameter t ∈ [0, 1], shared with the Bernstein tab.
    double t() const { return m_t; }
    void setT(double t);

    /// Sampling precision: the curve is drawn through samples() + 1 points (Matlab `part`).
    int samples() const { return m_samples; }
    void setSamples(int part);

    bool constructionVisible() const { return m_showConstruction; }
    bool stepByStep() const { return m_showSteps; }
    bool tangentVisible() const { return m_showTangent; }
    bool splitVisible() const { return m_showSplit; }
    void setConstructionVisible(bool on);
    void setStepByStep(bool on);
    void setTangentVisible(bool on);
    void setSplitVisible(bool on);

    bool isPlaying() const;
    void setPlaying(bool on);

    /// Degree elevation: one control point more, the same curve (undoable).
    void raiseDegree();

    /// Loads a worked example's curve: its points, the view around them and t = 1/2, as one
    /// undo step named `undoText` on this tab (also when another tab loads it: Ex 2.5).
    void loadCurve(const std::vector<Point>& points, const QString& undoText);

    /// The De Casteljau table at the current t (every level P_i^r(t)).
    const DeCasteljauTable<double>& table() const { return m_levels; }
    /// The sampled curve (samples() + 1 points).
    const std::vector<Point>& curve() const { return m_curve; }
    /// The key in the canvas's corner: the levels', step curves' and halves' colours.
    CanvasLegend legend() const;
    /// The side of the squares that mark the halves' control points (over the level's dots).
    static double splitSquareSide(const CanvasStyle& style);
    /// The warning shown for high degrees; empty when there is none.
    QString warning() const { return m_warningText; }

    static constexpr int kMaxPoints = 200;       ///< docs/extreme-cases.md: the editor refuses more
    static constexpr int kMaxExactDegree = 8;    ///< above, the symbolic P_i^r(t) would not be readable
    static constexpr int kMaxTableDegree = 20;   ///< above, the numeric triangle is not shown either
    static constexpr int kWarnDegree = 20;       ///< from here on, the conditioning warning

signals:
    void tChanged(double t);

protected:
    void drawTikz(TikzWriter& w) const override;

private:
    // What CurveTab asks of this tab.
    /// The document's t, samples and display options (CurveTab writes and checks the points).
    void writeSettings(QJsonObject& state) const override;
    bool loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error) override;
    PointListMessages pointMessages() const override;
    /// The control points with a margin of 5 % (a lone point gets a box around it).
    QRectF contentBounds() const override;
    /// The exact panel is typeset again at its new size.
    void presentationChanged(bool on) override;

    void buildLayers();
    void pointsChanged();
    void parameterChanged();
    void updateExactSymbolic();
    void updateExactPanel();
    void updateWarning();
    /// The canvas's accessible name and description: the curve, t and c(t) (screen readers).
    void updateCanvasSummary();
    void advanceAnimation();
    void setToggle(bool& flag, QCheckBox* box, bool on);
    /// The user's changes (docs/tabs.md, "Undo"): each is one undo step that gives the
    /// document's value back; the programmatic setters above push nothing.
    void userMovedT(double t);
    void userToggled(bool& flag, QCheckBox* box, bool on, const QString& undoText);
    void userSetSamples(int part);
    void pushT(double before, double after, int mergeId, const QString& undoText);

    QSplitter* m_mainSplitter = nullptr;
    QSplitter* m_sideSplitter = nullptr;

    DeCasteljauParameterControl* m_parameter = nullptr;
    QToolButton* m_play = nullptr;
    QCheckBox* m_construction = nullptr;
    QCheckBox* m_steps = nullptr;
    QCheckBox* m_tangent = nullptr;
    QCheckBox* m_split = nullptr;
    QCheckBox* m_snap = nullptr;
    QLabel* m_samplesLabel = nullptr;
    QSpinBox* m_samplesBox = nullptr;
    QPushButton* m_raise = nullptr;
    QLabel* m_warningLabel = nullptr;
    QTimer* m_timer = nullptr;
    QTimer* m_panelTimer = nullptr; ///< coalesces panel refreshes while dragging or playing
    void refreshPanel();
    void schedulePanel();

    double m_t = 0.5;
    double m_playStartT = 0.5; ///< where t was when Play was pressed: Pause makes one step from there
    int m_samples = 200;
    bool m_showConstruction = true;
    bool m_showSteps = false;
    bool m_showTangent = false;
    bool m_showSplit = false;

    // Derived from the points (and t): recomputed on change, drawn from here.
    std::vector<Point> m_curve;
    std::vector<std::vector<Point>> m_stepCurves;
    DeCasteljauTable<double> m_levels;
    QString m_symbolicHtml; ///< the exact P_i^r(t) in powers of t (depends on the points only)
    QString m_warningText;
};

} // namespace granota::ui
