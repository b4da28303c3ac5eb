#pragma once
/// \file bspline_tab.h
/// The B-spline tab (docs/tabs.md; beyond the thesis, issue 36: the answer to §2.3's dilemma,
/// a curve both local and C^{p−1}): control points edited as in the other curve tabs, the
/// degree p, the knot vector on a ruler under the canvas (drag a knot, double-click to insert
/// one, presets), de Boor's algorithm at u step by step (the net level by level in the De
/// Casteljau tab's colours, the span's p + 1 points ringed), the basis functions N_{i,p}(u)
/// plotted under the ruler, and the actions on the curve: knot insertion (the new polygon drawn
/// over the old one, the curve unchanged), exact knot removal, the Bézier segments, degree
/// elevation, weights (NURBS). Every change is one undo step; the points are the CurveTab's
/// editor's, the rest is one BSplineModel.

#include "ui/bsplines/bspline_examples.h"
#include "ui/bsplines/bspline_model.h"
#include "ui/bsplines/bspline_scene.h"
#include "ui/common/curve_tab.h"

#include <optional>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;
class QSpinBox;
class QTabWidget;
class QTimer;
class QToolButton;

namespace granota::ui {

class KnotRuler;
class WeightGesture;

class BSplineTab : public CurveTab {
    Q_OBJECT
public:
    explicit BSplineTab(QWidget* parent = nullptr);

    void retranslate() override;
    QString hint() const override;
    QString keyboardHint() const override;
    bool loadExample(const granota::WorkedExample& example) override;
    QString csv() const override;

    // The model and the views, for tests.
    const BSplineModel& model() const { return m_model; }
    const BSplineScene& scene() const { return m_scene; }
    KnotRuler* knotRuler() const { return m_ruler; }
    QCustomPlot* basisPlot() const { return m_plot; }
    /// The knots in force (the model's for the points there are).
    std::vector<Rational> knots() const;
    /// The polygon before the last knot insertion, drawn under the new one until the next edit.
    const std::vector<Point>& previousPolygon() const { return m_previousPolygon; }
    /// The last refusal or note sent to the status bar.
    QString lastMessage() const { return m_lastMessage; }

    /// Undoable edits; each refuses with a message (statusMessage) and returns false when it
    /// cannot be done.
    bool setDegree(int degree);
    bool setPreset(KnotPreset preset);
    void setU(const Rational& u, int mergeId = -1);
    /// Moves knot `index` to `value` (rounded to the ruler's step, bounded by its neighbours);
    /// moves with the same `mergeId` (≥ 0) are one undo step.
    bool moveKnot(int index, const Rational& value, int mergeId = -1);
    /// Boehm's knot insertion at `value` (inside the domain; the knot's multiplicity stays ≤ p).
    bool insertKnot(const Rational& value);
    /// Removes knot `index` if the curve stays exactly the same (exact knot removal); else says
    /// the curve needs it.
    bool removeKnot(int index);
    /// Raises the degree by one, the curve unchanged (p < kMaxBSplineDegree).
    bool elevateDegree();
    /// The weights (n + 1 of them, each > 0), or none (polynomial).
    bool setWeights(const std::vector<Rational>& weights);
    /// Point `index`'s weight as typed in the table's w column (> 0); the other weights stay
    /// (1 each if there were none). Each change is one undo step.
    bool setWeight(int index, const Rational& weight);
    /// The weight of point `index` in force (1 on a polynomial curve).
    Rational weightOf(int index) const;
    /// Point `index`'s weight by `steps` notches (weight_gesture.h: ×2^(±1/4) each, two
    /// significant digits, exact); the other weights stay (1 each if there were none).
    /// Consecutive changes of one point are one undo step.
    bool stepWeight(int index, int steps);
    void setNetVisible(bool on);
    void setBezierSegmentsVisible(bool on);
    /// The cubic Bézier quarter circle beside (the quarter-circle example turns it on).
    void setCubicCircleVisible(bool on);
    /// The plot under the canvas: κ(s) with the knots' continuity (on) or the basis functions.
    void setCurvaturePlot(bool on);
    /// The inset of the curve in (wx, wy, w) and its rays down to w = 1.
    void setHomogeneousCurveVisible(bool on);
    /// Where the inset is drawn on the canvas (widget pixels; empty while hidden).
    QRectF homogeneousInset() const;
    /// Loads one of the tab's examples (bspline_examples.h) as one undo step.
    void loadBSplineExample(BSplineExampleId id);
    bool isPlaying() const;
    void setPlaying(bool on);

protected:
    void drawTikz(TikzWriter& w) const override;
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    bool loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error) override;
    void writeSettings(QJsonObject& state) const override;
    PointListMessages pointMessages() const override;
    void presentationChanged(bool on) override;
    QRectF contentBounds() const override;
    void buildUi();
    /// One undo step from the current model to `after` (nothing if equal).
    void changeModel(const BSplineModel& after, const QString& undoText, int mergeId = -1);
    /// Points and model changed together (insertion, removal, elevation, examples): one undo step.
    void changeCurve(const BSplineCurve<Rational>& curve, const BSplineModel& after, const QString& undoText);
    /// Makes `m` current (undo/redo, loading): controls, scene, views.
    void applyModel(const BSplineModel& m);
    void pointsEdited();
    void recompute();
    void syncControls();
    void refuse(const QString& message);
    /// The points exactly: their exact forms, or their doubles' values.
    std::vector<RPoint> exactValues() const;
    /// A value from the ruler (a double) as the round fraction of its step.
    Rational rulerValue(double value) const;
    void advanceAnimation();
    void updateContentBounds(bool force);
    /// Redraws the plot under the canvas: the basis functions or κ(s), as the model asks.
    void updatePlot();

    KnotRuler* m_ruler = nullptr;
    WeightGesture* m_weightGesture = nullptr;
    QCustomPlot* m_plot = nullptr;
    QLabel* m_plotTitle = nullptr;
    QTabWidget* m_sideTabs = nullptr;
    QGroupBox* m_curveBox = nullptr;
    QLabel* m_degreeLabel = nullptr;
    QSpinBox* m_degreeSpin = nullptr;
    QLabel* m_presetLabel = nullptr;
    QComboBox* m_presetCombo = nullptr;
    QLabel* m_weightsLabel = nullptr;
    QLineEdit* m_weightsEdit = nullptr;
    QCheckBox* m_netCheck = nullptr;
    QCheckBox* m_bezierCheck = nullptr;
    QCheckBox* m_cubicCircleCheck = nullptr;
    QCheckBox* m_curvatureCheck = nullptr;
    QCheckBox* m_homogeneousCheck = nullptr;
    QGroupBox* m_actionsBox = nullptr;
    QPushButton* m_insertButton = nullptr;
    QPushButton* m_removeButton = nullptr;
    QPushButton* m_elevateButton = nullptr;
    QLabel* m_uLabel = nullptr;
    QSlider* m_uSlider = nullptr;
    QToolButton* m_play = nullptr;
    QComboBox* m_examplesCombo = nullptr;
    QTimer* m_timer = nullptr;
    QTimer* m_panelTimer = nullptr; ///< coalesces exact panel refreshes while a point is dragged

    BSplineModel m_model;
    BSplineScene m_scene;
    std::vector<Point> m_previousPolygon;
    std::optional<Rational> m_playU; ///< u while Play runs (the model's u changes only at Pause)
    QString m_lastMessage;
    bool m_syncing = false;
    int m_knotGesture = 0; ///< the merge id of a knot drag: one undo step each
    int m_uGesture = 0;    ///< the same for the u slider
};

} // namespace granota::ui
