#pragma once
/// \file catmull_rom_tab.h
/// The Catmull-Rom tab (docs/tabs.md; thesis §2.2–2.3): points q0…qn on a canvas with one
/// Catmull-Rom curve per tension τ (Def 2.8–2.10), the end modes of Def 2.10, uniform,
/// centripetal or chordal spacing, the blending functions (Cor 2.1), the exact segment
/// polynomials (Lemma 2.3, Ex 2.11, Ex 2.13) and tangents at the knots (Prop 2.3), and the
/// comparisons of §2.3 with the Bézier curve of the same points and the C² cubic spline
/// (Def 2.3, Ex 2.1): every curve's curvature against arc length, and each segment as a cubic
/// Bézier curve with the C/G order of every knot.

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curve_tab.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPainter;
class QPushButton;
class QSlider;
class QTabWidget;

namespace granota::ui {

class FamilyPanel;
class HermiteHandles;
class KnotContinuityTable;
class ConventionsTable;
class SplineFamilyPanels;
class ViewTransform;
struct CanvasStyle;

class CatmullRomTab : public CurveTab {
    Q_OBJECT
public:
    explicit CatmullRomTab(QWidget* parent = nullptr);

    void retranslate() override;
    QString hint() const override;
    bool loadExample(const granota::WorkedExample& example) override;
    QString csv() const override;

    // The model and the views, for the main window's neighbours and for tests.
    /// The plot under the canvas: the blending functions, or κ(s) when settings().curvaturePlot.
    QCustomPlot* blendingPlot() const { return m_plot; }
    const CatmullRomSettings& settings() const { return m_settings; }
    const CatmullRomScene& scene() const { return m_scene; }
    /// The last refusal or hint sent to the status bar.
    QString lastMessage() const { return m_lastMessage; }
    FamilyPanel* familyPanel() const { return m_familyPanel; }
    HermiteHandles* hermiteHandles() const { return m_hermiteHandles; }
    /// The side panel's knot table: the curve of the family, or the selected τ's Catmull-Rom curve.
    KnotContinuityTable* knotTable() const { return m_knotTable; }
    /// The side panel's conventions table, for the τ of the curve shown.
    ConventionsTable* conventionsTable() const { return m_conventions; }
    /// The C² spline's and the function data's controls (spline_family_panels.h).
    SplineFamilyPanels* splinePanels() const { return m_splinePanels; }

    /// Undoable edits of the settings. addTension refuses garbage, values outside [−10, 10],
    /// duplicates and an 11th tension with a message (statusMessage) and returns false.
    bool addTension(const QString& text);
    bool removeTension(int index);
    void setSelectedTension(int index);
    /// The family selector (curve_family.h): one undo step.
    void setFamily(CurveFamily family);
    /// The cardinal tension c ∈ [−1, 1] (slider moves merge into one undo step).
    void setCardinalTension(const Rational& c);
    /// T (0), C (1) or B (2) ∈ [−1, 1] of the point selected in the editor, or of every point
    /// when the panel says "All points" or none is selected.
    void setTcb(int which, const Rational& value);
    /// The Hermite family's tangent of point `index` (one undo step).
    void setHermiteTangent(int index, Point tangent);
    /// Every Hermite tangent back to the Catmull-Rom rule's (one undo step).
    void resetHermiteTangents();
    void setEnds(CatmullRomEnds ends);
    void setSpacing(CatmullRomSpacing spacing);
    void setBezierVisible(bool on);
    void setSplineVisible(bool on);
    /// The cubic spline's end conditions (Def 2.3; cubic_spline.h), and the end slopes of
    /// clamped ends.
    void setSplineEnds(SplineEnds ends);
    void setSplineSlopes(const Rational& start, const Rational& end);
    /// The Catmull-Rom curves of the tensions shown or hidden (Fig 2.1 shows the spline alone).
    void setCatmullRomVisible(bool on);
    /// The points q_i, their labels and polygon (the Matlab Rep_CatmullRom `puntvis`); hidden,
    /// the canvas no longer picks them (the table still edits them).
    void setControlPointsVisible(bool on);
    void setCompareEnds(bool on);
    void setAllTausInPlot(bool on);
    void setCurvaturePlot(bool on);
    /// The key in the canvas's corner (and in the TikZ picture): each τ's colour, the compared
    /// ends, the Bézier curve and the spline, and a refusal as its note.
    CanvasLegend legend() const;
    /// Where the key is drawn in `view`: where it covers least of the curves, clear of the
    /// points and their labels (canvasLegendRect()).
    QRectF legendRect(const ViewTransform& view, const CanvasStyle& style) const;

protected:
    void drawTikz(TikzWriter& w) const override;
    void changeEvent(QEvent* event) override;

private:
    // What CurveTab asks of this tab: the settings of the document (catmull_rom_settings.h),
    // its refusals of the points, the view's box, presentation mode (controls and plot).
    bool loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error) override;
    void writeSettings(QJsonObject& state) const override;
    PointListMessages pointMessages() const override;
    void presentationChanged(bool on) override;
    /// The points' box and the curves drawn inside one box size around it (large |τ| overshoots).
    QRectF contentBounds() const override;
    void buildUi();
    /// Pushes an undo step from the current settings to `after` (nothing if equal).
    void changeSettings(const CatmullRomSettings& after, const QString& undoText, bool mergeable = false, int familyMergeId = -1);
    // The family selector's part of the tab (catmull_rom_tab_families.cpp).
    void buildFamilyControls();
    void addFamilySideTabs();
    void retranslateFamilyControls();
    /// The Hermite handles and the knot table, after every recompute.
    void updateFamilyViews();
    void hermiteTangentDragged(int index, Point tangent);
    void hermiteDragFinished(int index, Point startTangent);
    /// T, C, B and the Hermite tangents follow their points: a point inserted at `index` gets
    /// (0, 0, 0) and the Catmull-Rom tangent there, a removed point's values go with it (part
    /// of the editor's undo step).
    void pointInserted(int index);
    void pointRemoved(int index);
    /// Points and settings as one undo step (a worked example, a family's example).
    void loadPointsAndSettings(const std::vector<Point>& points, const CatmullRomSettings& settings, const QString& undoText);
    /// Makes `s` current (undo/redo, loading): controls, curves, panel, plot.
    void applySettings(const CatmullRomSettings& s);
    void pointsEdited();
    void recompute();
    /// The canvas's accessible name and description: the tensions and the points (screen readers).
    void updateCanvasSummary();
    void syncControls();
    /// The plot under the canvas for the current settings and scene (catmull_rom_plot.h).
    void updatePlot();
    void updateContentBounds(bool force);
    void sliderMoved(int value);
    void refuse(const QString& message);
    void drawLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style) const;
    CanvasLegendBox legendBox(const ViewTransform& view, const CanvasStyle& style) const;
    QString tensionItemText(const Rational& tau) const;

    QCustomPlot* m_plot = nullptr;
    FamilyPanel* m_familyPanel = nullptr;
    HermiteHandles* m_hermiteHandles = nullptr;
    KnotContinuityTable* m_knotTable = nullptr;
    ConventionsTable* m_conventions = nullptr;
    SplineFamilyPanels* m_splinePanels = nullptr;
    QTabWidget* m_sideTabs = nullptr;
    QGroupBox* m_tensionBox = nullptr;
    QListWidget* m_tauList = nullptr;
    QLineEdit* m_tauEdit = nullptr;
    QPushButton* m_addTau = nullptr;
    QPushButton* m_removeTau = nullptr;
    QSlider* m_tauSlider = nullptr;
    QLabel* m_sliderLabel = nullptr;
    QGroupBox* m_curveBox = nullptr;
    QLabel* m_endsLabel = nullptr;
    QComboBox* m_endsCombo = nullptr;
    QLabel* m_spacingLabel = nullptr;
    QComboBox* m_spacingCombo = nullptr;
    QCheckBox* m_bezierCheck = nullptr;
    QCheckBox* m_pointsCheck = nullptr;
    QCheckBox* m_splineCheck = nullptr;
    QCheckBox* m_catmullRomCheck = nullptr;
    QLabel* m_splineEndsLabel = nullptr;
    QComboBox* m_splineEndsCombo = nullptr;
    QLabel* m_slopesLabel = nullptr;
    QLineEdit* m_startSlopeEdit = nullptr;
    QLineEdit* m_endSlopeEdit = nullptr;
    QCheckBox* m_compareCheck = nullptr;
    QCheckBox* m_allTausCheck = nullptr;
    QCheckBox* m_curvatureCheck = nullptr;
    QLabel* m_plotTitle = nullptr;

    CatmullRomSettings m_settings;
    CatmullRomScene m_scene;
    QString m_lastMessage;
    bool m_syncing = false;
};

} // namespace granota::ui
