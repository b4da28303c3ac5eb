#pragma once
/// \file decasteljau_tab.h
/// The De Casteljau tab (docs/tabs.md; thesis §2.1.1, Def 2.4, Ex 2.2, Ex 2.3): editable
/// control points, the construction of c(t) level by level at a parameter t that can be
/// animated, the Matlab Rep_Bezier "desglossar" view, the tangent, the split at t, degree
/// elevation, and beside the canvas the point table and the exact triangle of P_i^r(t).
/// Beyond the thesis (docs/tabs.md), the differential geometry of the curve as overlays,
/// each a toggle: the normal at t, the osculating circle, the curvature comb, the tight
/// bounding box with the extrema of x and y, the inflections and cusps, the hodograph c′
/// in an inset of its own with its own construction at t; the readouts s(t), L and κ(t);
/// playing at constant speed (by arc length); dragging the curve itself to mold it.
/// The Bernstein tab shows the same curve: its control points, t and history are one
/// BezierCurveModel (ui/common/bezier_curve_model.h), made here.

#include "ui/common/bezier_exact_html.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curve_tab.h"
#include "ui/decasteljau/decasteljau_scene.h"
#include "ui/decasteljau/decasteljau_view.h"

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

class BezierCurveModel;
class CurvatureCombScaleBox;
class DeCasteljauCurveDrag;
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
    /// The curve (points, t, undo history) this tab shares with the Bernstein tab.
    BezierCurveModel* curveModel() const { return m_model; }

    /// The parameter t ∈ [0, 1], shared with the Bernstein tab.
    double t() const;
    void setT(double t);

    /// What the tab shows (decasteljau_view.h): the document keeps it, a change of it is one undo step.
    const DeCasteljauView& view() const { return m_view; }
    /// Makes `view` current (clamped) without an undo step, and recomputes the scene.
    void setView(const DeCasteljauView& view);
    /// Everything drawn, computed from the points, t and the view (decasteljau_scene.h).
    const DeCasteljauScene& scene() const { return m_scene; }

    /// Sampling precision: the curve is drawn through samples() + 1 points (Matlab `part`).
    int samples() const { return m_view.samples; }
    void setSamples(int part);

    /// The control points P_i, their polygon and labels (the Matlab `puntsvis`); hidden, the
    /// curve and whatever else is shown stay (Fig 2.2 and 2.3 as printed).
    bool controlPointsVisible() const { return m_view.controlPoints; }
    void setControlPointsVisible(bool on);
    bool constructionVisible() const { return m_view.construction; }
    bool stepByStep() const { return m_view.stepByStep; }
    bool tangentVisible() const { return m_view.tangent; }
    bool splitVisible() const { return m_view.split; }
    void setConstructionVisible(bool on);
    void setStepByStep(bool on);
    void setTangentVisible(bool on);
    void setSplitVisible(bool on);

    /// The overlays beyond the thesis, each a toggle the document keeps.
    bool normalVisible() const { return m_view.normal; }
    bool osculatingCircleVisible() const { return m_view.osculatingCircle; }
    bool combVisible() const { return m_view.comb; }
    bool boundingBoxVisible() const { return m_view.boundingBox; }
    bool inflectionsVisible() const { return m_view.inflections; }
    bool hodographVisible() const { return m_view.hodograph; }
    /// Playing moves c(t) by equal steps of arc length instead of t.
    bool constantSpeed() const { return m_view.constantSpeed; }
    void setNormalVisible(bool on);
    void setOsculatingCircleVisible(bool on);
    void setCombVisible(bool on);
    void setBoundingBoxVisible(bool on);
    void setInflectionsVisible(bool on);
    void setHodographVisible(bool on);
    void setConstantSpeed(bool on);
    /// The comb's scale (curvature_comb_scale_box.h): 0 is automatic, the default.
    double combScale() const { return m_view.combScale; }
    void setCombScale(double scale);
    CurvatureCombScaleBox* combScaleBox() const { return m_combScaleBox; }

    /// κ, the normal and the osculating circle at the current t.
    const CurvatureAt& curvatureAtT() const { return m_scene.curvature; }
    /// The comb drawn (computed while it is shown).
    const CurvatureComb& comb() const { return m_scene.comb; }
    /// Extrema, box, inflections and cusps of the curve (computed while one of them is shown).
    const CurveFeatures& features() const { return m_scene.features; }
    /// s(t) and L.
    double arcLengthAtT() const;
    double totalLength() const;
    /// The readouts line under the canvas: s(t), L and κ(t).
    QString readout() const;
    /// The hodograph's control points n (P_{i+1} − P_i) and its construction at t.
    const DeCasteljauTable<double>& hodographTable() const { return m_scene.hodoLevels; }
    /// Where the hodograph's inset is drawn in a view (empty when it is hidden): the corner of
    /// the viewport that covers least of the curve, the handles, their labels and c(t) (as the
    /// key is placed; the lower right winning a tie, then lower left, upper right, upper left).
    QRectF hodographInset(const ViewTransform& view, const CanvasStyle& style) const;
    DeCasteljauCurveDrag* curveDrag() const { return m_curveDrag; }

    bool isPlaying() const;
    void setPlaying(bool on);

    /// Degree elevation: one control point more, the same curve (undoable).
    void raiseDegree();

    /// Loads a worked example's curve: its points, the view around them and t = 1/2, as one
    /// undo step named `undoText` on this tab (also when another tab loads it: Ex 2.5).
    void loadCurve(const std::vector<Point>& points, const QString& undoText);

    /// The De Casteljau table at the current t (every level P_i^r(t)).
    const DeCasteljauTable<double>& table() const { return m_scene.levels; }
    /// The sampled curve (samples() + 1 points).
    const std::vector<Point>& curve() const { return m_scene.curve; }
    /// The key in the canvas's corner: the levels', step curves' and halves' colours.
    CanvasLegend legend() const;
    /// Where the key goes in a view: the corner that covers no handle, label, c(t) or inset if
    /// one can, and the fewest samples of the curve and points of the construction.
    QRectF legendRect(const ViewTransform& view, const CanvasStyle& style) const;
    /// The same, and whether the key is compact (a small canvas).
    CanvasLegendBox legendBox(const ViewTransform& view, const CanvasStyle& style) const;
    /// What the key and the inset should not cover in a view: the curve's samples, the
    /// construction's points, the handles with their labels and c(t) with its label.
    CanvasLegendObstacles drawnObstacles(const ViewTransform& view, const CanvasStyle& style) const;
    /// The side of the squares that mark the halves' control points (over the level's dots).
    static double splitSquareSide(const CanvasStyle& style);
    /// The warning shown for high degrees; empty when there is none.
    QString warning() const { return m_warningText; }

    static constexpr int kMaxPoints = 200;                        ///< docs/extreme-cases.md: the editor refuses more
    static constexpr int kMaxExactDegree = kMaxExactBezierDegree; ///< above, the symbolic P_i^r(t) would not be readable
    static constexpr int kMaxTableDegree = kMaxTriangleDegree;    ///< above, the numeric triangle is not shown either
    static constexpr int kWarnDegree = 20;                        ///< from here on, the conditioning warning

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
    void updateReadout();
    /// The scene again from the points, t and the view (and the comb's automatic scale shown).
    void recomputeScene();
    /// The check boxes and spin boxes, the handles and snapping as m_view says.
    void showView();
    /// The user's changes (docs/tabs.md, "Undo"): each is one undo step that gives the
    /// document's value back; the programmatic setters above push nothing.
    void userMovedT(double t);
    /// A check box, the view's flag it shows and the undo step's text (the box's own).
    struct Toggle {
        QCheckBox* box;
        bool DeCasteljauView::*flag;
        const char* undoText;
    };
    std::vector<Toggle> toggles() const;
    void setFlag(bool DeCasteljauView::*flag, bool on);
    /// One undo step for any change of the view (the spin boxes merge while held, by `mergeId`).
    void userChangedView(const DeCasteljauView& after, const QString& undoText, int mergeId = -1);
    /// One undo step from `before` to the current t.
    void pushT(double before, int mergeId, const QString& undoText);

    QSplitter* m_mainSplitter = nullptr;
    QSplitter* m_sideSplitter = nullptr;

    DeCasteljauParameterControl* m_parameter = nullptr;
    QToolButton* m_play = nullptr;
    QCheckBox* m_controlPoints = nullptr;
    QCheckBox* m_construction = nullptr;
    QCheckBox* m_steps = nullptr;
    QCheckBox* m_tangent = nullptr;
    QCheckBox* m_split = nullptr;
    QCheckBox* m_snap = nullptr;
    QCheckBox* m_normal = nullptr;
    QCheckBox* m_osculating = nullptr;
    QCheckBox* m_combBox = nullptr;
    QLabel* m_combScaleLabel = nullptr;
    CurvatureCombScaleBox* m_combScaleBox = nullptr;
    QCheckBox* m_box = nullptr;
    QCheckBox* m_featuresBox = nullptr;
    QCheckBox* m_hodograph = nullptr;
    QCheckBox* m_speed = nullptr;
    QLabel* m_readout = nullptr;
    DeCasteljauCurveDrag* m_curveDrag = nullptr;
    QLabel* m_samplesLabel = nullptr;
    QSpinBox* m_samplesBox = nullptr;
    QPushButton* m_raise = nullptr;
    QLabel* m_warningLabel = nullptr;
    QTimer* m_timer = nullptr;
    QTimer* m_panelTimer = nullptr; ///< coalesces panel refreshes while dragging or playing
    void refreshPanel();
    void schedulePanel();

    BezierCurveModel* m_model = nullptr;
    double m_playStartT = 0.5; ///< where t was when Play was pressed: Pause makes one step from there
    DeCasteljauView m_view;
    DeCasteljauScene m_scene; ///< derived from the points, t and the view: recomputed on change, drawn from here
    QString m_symbolicHtml;   ///< the exact P_i^r(t) in powers of t (depends on the points only)
    QString m_warningText;
};

} // namespace granota::ui
