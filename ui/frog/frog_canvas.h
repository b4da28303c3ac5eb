#pragma once
/// \file frog_canvas.h
/// The live soft-body canvas of the frog lab (docs/scenes.md): the view of a FrogRun (the run,
/// its clock and its recording: frog_run.h), repainted as it steps, drawn in the thesis's order
/// (background, back legs, body, front legs, head) in the scene's own Processing pixels,
/// letterboxed into the widget. The mouse grabs and the space bar spawns as in Annex II; the keyboard grabs too (arrows, G
/// or Enter, Esc: docs/classroom.md), and a focus frame shows when the keys go here. Drawing reuses
/// member buffers: a frame allocates nothing in this class once warm.

#include "core/softbody/head_pose.h"
#include "core/softbody/link_angles.h"
#include "ui/common/canvas_style.h"
#include "ui/common/drawable.h"
#include "ui/frog/frog_overlay_painter.h"
#include "ui/frog/frog_run.h"
#include "ui/frog/frog_scene_painter.h"

#include <QElapsedTimer>
#include <QWidget>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace granota::ui {

class FrogCanvas : public QWidget, public Drawable {
    Q_OBJECT
public:
    /// What is drawn over the scene (the tab's Overlays checkboxes) and how a Bézier scene
    /// draws its body (the painters', frog_overlay_painter.h and frog_scene_painter.h).
    using Overlays = FrogOverlayPainter::Overlays;
    using BezierOutline = FrogScenePainter::BezierOutline;

    using TrailPoint = FrogRun::TrailPoint;
    /// Scene pixels one arrow key moves the keyboard cursor (Shift: five times that).
    static constexpr double kKeyboardStep = 10.0;

    /// The view of `run` (not owned; it outlives the canvas).
    explicit FrogCanvas(FrogRun* run, QWidget* parent = nullptr);
    /// The view of a run of its own (a canvas alone, as the benchmarks use it).
    explicit FrogCanvas(QWidget* parent = nullptr);
    ~FrogCanvas() override;
    FrogRun* frogRun() const { return m_run; }

    // The run itself (its state, its clock, its recording) is read and driven through
    // frogRun(): the canvas draws it, repaints as it tells, and feeds it the mouse and keys.
    /// The trail's segments the last paint drew: those in the frame, cut to it, the newest
    /// first up to 20 times the frame's width plus height of line (a blown-up body's trail
    /// sweeps the frame every step; frog_overlay_painter.cpp, kTrailInkBudget).
    int trailSegmentsDrawn() const { return m_overlayPainter.trailSegmentsDrawn(); }
    /// The ruler: a measure in scene px between two points the user set, dragged with the
    /// right button (or Ctrl and the left), or placed from the keyboard with L at the cursor,
    /// the arrows, and L again; Esc or a right click clears it. Nothing is recorded; a document
    /// saved keeps it, and it is not an edit (no undo step).
    const std::optional<std::pair<Point, Point>>& ruler() const { return m_ruler; }
    /// The keyboard cursor (the simulation's mouse, scene px): on the body nearest the view's
    /// middle from the canvas's first focus on.
    Point keyboardCursor() const { return m_mouse; }
    /// Sets or clears the ruler (a document's).
    void setRuler(const std::optional<std::pair<Point, Point>>& ruler);
    /// What the ruler says: its length and its run and rise, in px.
    QString rulerText() const;
    /// §4.15, the protractor (Overlays::protractor): each limited link's angle and range,
    /// drawn at its joint; the text panel counts the joints held at a limit.
    std::vector<LinkAngleReading> linkAngles(int chain) const;
    /// Where the head of `body` is drawn (core/softbody/head_pose.h): on the seed solver as
    /// Annex II draws it, upright, its 138 × 93 box at vertex 0 − (69, 46); on the stable
    /// solver Granota's head, turned with the body.
    HeadPose headPose(int body) { return m_scenePainter.headPose(*sim(), body); }
    /// The lines of the text panel drawn over the scene, as last refreshed.
    QStringList textLines() const;
    /// The width the text panel takes (its widest line, wrapped to the canvas), and the most
    /// the canvas leaves it: the first never exceeds the second (presentation mode on a
    /// 1024 × 768 projector wraps the readouts instead of cutting them).
    double textPanelWidth() const;
    double textPanelRoom() const;

    /// The body the plots show alone (FrogPlotPanel::body), outlined and numbered on the
    /// canvas so that the class sees which one it is; −1: none (the plots sum them).
    void setMarkedBody(int body);
    int markedBody() const { return m_markedBody; }

    void setOverlays(const Overlays& overlays);
    const Overlays& overlays() const { return m_overlays; }
    void setBezierOutline(BezierOutline mode);
    BezierOutline bezierOutline() const { return m_scenePainter.bezierOutline(); }
    /// Average cost of the per-frame least-squares fit and its sampling, µs (0 before any).
    double fitMicroseconds() const { return m_scenePainter.fitMicroseconds(); }

    void setPresentation(bool on);
    /// What the canvas shows, for screen readers (the tab gives the scene and the solver): its
    /// accessible description is this and the area error, refreshed with the text panel.
    void setSceneSummary(const QString& summary);

    /// The outline drawn for body `body`, in scene pixels: the polygon, the seed's
    /// curveVertex outline, the closed Catmull-Rom curve or the fitted Bézier curve, as the
    /// scene's components say. Valid until the next call.
    const std::vector<Point>& bodyOutline(int body) { return m_scenePainter.bodyOutline(*sim(), body); }
    /// The art the canvas paints with (its colours and the feet), for the TikZ picture.
    const FrogArt& art() const { return m_scenePainter.art(); }
    /// The head of body `index` as the canvas paints it (FrogArt::paintHead at its pose), in
    /// scene coordinates: for the TikZ export, which records it as paths (path_recorder.h).
    void paintHeadOf(QPainter& p, int index);
    /// The half width of a leg's outline (Annex II, Pota.dibuixar: the factor 7).
    static constexpr double kLegHalfWidth = FrogScenePainter::kLegHalfWidth;

    /// The letterbox transform of the widget: scene pixels ↔ widget pixels.
    QPointF toWidget(const Point& scenePoint) const;
    Point toScene(const QPointF& widgetPoint) const;

    QSizeF exportSize() const override { return size(); }
    void render(QPainter& painter, const QRectF& target) override;
    /// The scene and its overlays as render() draws them, without the text panel: a frame of
    /// an animation carries no live readout (frame time, energies) that would be stale in it.
    void renderFrame(QPainter& painter, const QRectF& target);

    QSize sizeHint() const override { return {960, 540}; }
    QSize minimumSizeHint() const override { return {80, 45}; }
    /// The caption of the thin line drawn along the frame's top edge (the scene's upper wall),
    /// and where it is drawn in `target` (the widget's rect on screen).
    QString frameCaption() const;
    QRectF frameCaptionRect(const QRectF& target) const;

signals:
    /// About four times a second: the fit cost (µs) for the side panel.
    void fitCostChanged(double microseconds);
    /// Hints for the status bar.
    void statusMessage(const QString& text);
    /// §4.1's polygon: the mouse has set the radius to `radius` px (Simulation::mouseRadius).
    void mouseRadiusChanged(double radius);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void enterEvent(QEnterEvent* event) override;
    void showEvent(QShowEvent* event) override;
    /// The text panel wraps to the new width at once, not at the next refresh.
    void resizeEvent(QResizeEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    const Simulation* sim() const { return m_run->simulation(); }
    void observe(); ///< connects to m_run's signals
    /// After a new run or one restored: the grab and the texts start afresh. `fresh`: a new
    /// run, which takes the mouse's position as Processing's mouseX does.
    void runShown(bool fresh);
    void letGo(); ///< the run went to another step: the canvas's grab ends
    void refreshTexts();
    QStringList composeTexts(bool blownUpLine); ///< the text panel's lines (frog_canvas_texts.cpp)
    void updateAccessibleDescription();
    void reportMouseRadius();
    QRectF sceneRectIn(const QRectF& target) const;
    void renderScene(QPainter& p, const QRectF& target, bool textPanel);
    /// The keyboard's grab: the cursor (the simulation's mouse) moved by the arrows, drawn
    /// while the canvas has the focus; G or Enter grabs at it, again or Esc lets go.
    void moveKeyboardCursor(double dx, double dy);
    /// Where the keyboard cursor starts: on the body nearest the view's middle.
    Point keyboardCursorStart();
    bool keyboardGrab();
    void keyboardRelease();
    int nearestBody(Point at);
    /// The mean of body `body`'s vertices.
    Point bodyCentre(int body);
    /// Before the keyboard first uses the cursor: on the body nearest the view's middle.
    void placeKeyboardCursor();
    bool insideABody(Point at); ///< inside the polygon of some body (reuses m_vertices)
    void drawKeyboardCursor(QPainter& p) const;
    void buildPens(); ///< the painters' pens and fonts at the presentation scale

    FrogRun* m_run;
    FrogScenePainter m_scenePainter;
    FrogOverlayPainter m_overlayPainter;
    int m_markedBody = -1;
    // The ruler (scene px): its two ends, while dragged (right button or Ctrl+left) or
    // placed from the keyboard (L, then the arrows, then L).
    std::optional<std::pair<Point, Point>> m_ruler;
    bool m_rulerDragging = false;
    bool m_rulerPlacing = false;
    CanvasStyle m_style;
    Overlays m_overlays;

    // Interaction (Annex II: mousePressed, mouseReleased, keyPressed, keyReleased).
    Point m_mouse{0, 0};
    bool m_mouseKnown = false;
    bool m_pressed = false;
    bool m_spawnHeld = false;
    bool m_keyboardHeld = false;  // the grab was made with G or Enter
    QString m_sceneSummary;       // setSceneSummary
    double m_reportedRadius = -1; // last mouseRadiusChanged, −1 before any

    // Buffers reused by the text panel and the keyboard's grab.
    std::vector<Point> m_vertices, m_joints;
    std::vector<std::pair<int, int>> m_pairs;
    std::vector<LinkAngleReading> m_angles;

    // Drawing time, averaged and shown a few times a second.
    QElapsedTimer m_clock, m_textClock;
    double m_drawNsSum = 0;
    int m_draws = 0;
    double m_drawShownMs = 0;
    QPen m_framePen;
};

} // namespace granota::ui
