#pragma once
/// \file frog_canvas.h
/// The live soft-body canvas of the frog lab (docs/scenes.md): one Simulation, stepped once per
/// frame by a 60 Hz timer as Processing's draw(), drawn in the thesis's order (background,
/// back legs, body, front legs, head) in the scene's own Processing pixels, letterboxed into
/// the widget. The mouse grabs and the space bar spawns as in Annex II; the keyboard grabs too (arrows, G
/// or Enter, Esc: docs/classroom.md), and a focus frame shows when the keys go here. Drawing reuses
/// member buffers: a frame allocates nothing in this class once warm.

#include "core/softbody/head_pose.h"
#include "core/softbody/link_angles.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_series.h"
#include "core/softbody/step_pacer.h"
#include "ui/common/canvas_style.h"
#include "ui/common/drawable.h"
#include "ui/frog/frog_art.h"
#include "ui/frog/frog_overlays.h"

#include <QElapsedTimer>
#include <QLineF>
#include <QPainterPath>
#include <QPixmap>
#include <QStaticText>
#include <QTimer>
#include <QWidget>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace granota {
class OutlineFitter;
}

namespace granota::ui {

class FrogCanvas : public QWidget, public Drawable {
    Q_OBJECT
public:
    /// What is drawn over the scene (the tab's Overlays check boxes; frog_overlays.h).
    using Overlays = FrogOverlays;
    /// §4.9/4.10: how a Bézier scene draws its body.
    enum class BezierOutline {
        Precomputed, ///< the thesis's choice: the body's vertices are the precomputed Bézier points
        Fit,         ///< the option it abandoned: a least-squares Bézier curve fitted every frame
    };

    /// Frames (and steps) per second, as Processing's default frameRate.
    static constexpr int kFramesPerSecond = kStepsPerSecond;
    /// The most counted work (Simulation::workPerStep: points × substeps) stepped in one
    /// frame: 3000 vertices on the stable solver (8 substeps), about 3 ms a step on the
    /// reference machine. A scene whose step is more work steps once every framesPerStep()
    /// frames, slower than real time, and says so, rather than blocking the event loop
    /// frame after frame (a body of 10000 sides: 39 ms a step, one step every 4 frames).
    static constexpr long kFrameWork = 24000;
    /// Scene pixels one arrow key moves the keyboard cursor (Shift: five times that).
    static constexpr double kKeyboardStep = 10.0;

    explicit FrogCanvas(QWidget* parent = nullptr);
    ~FrogCanvas() override;

    /// Takes over a freshly built simulation (the previous one, and any grab, are dropped)
    /// and records its run from here (docs/rewind.md).
    void setSimulation(std::unique_ptr<Simulation> simulation);
    /// The simulation shown. Everything that drives it goes through the recorded run, so
    /// this is read-only; a seek may replace it (do not keep the pointer across one).
    const Simulation* simulation() const { return sim(); }

    /// The point the trail follows: a body's vertex or a chain's joint. By default the last
    /// joint of the first chain in the pendulum scenes (the tip), else vertex 0 of body 0.
    struct TrailPoint {
        bool joint = false; ///< a chain's joint, else a body's vertex
        int owner = 0;      ///< the body or the chain
        int index = 0;      ///< the vertex or the joint
        bool operator==(const TrailPoint& o) const { return joint == o.joint && owner == o.owner && index == o.index; }
    };
    static constexpr int kTrailSteps = 10 * kFramesPerSecond;
    const TrailPoint& trailPoint() const { return m_trailPoint; }
    /// The trail's points, oldest first (one a step while the overlay is on; a new run or a
    /// seek starts it again).
    const std::deque<Point>& trail() const { return m_trail; }
    /// The trail's segments the last paint drew: those in the frame, cut to it, the newest
    /// first up to 20 times the frame's width plus height of line (a blown-up body's trail
    /// sweeps the frame every step; frog_canvas.cpp, kTrailInkBudget).
    int trailSegmentsDrawn() const { return m_trailSegmentsDrawn; }
    /// Follows the vertex or joint nearest to `at` (scene px), within 30 px; false if none.
    bool chooseTrailPoint(Point at);
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
    HeadPose headPose(int body);
    /// The ghost (Overlays::ghost): the other solver's simulation, at the same step, or null
    /// (off, or a scene the other solver refuses).
    const Simulation* ghost() const { return m_ghost ? &m_ghost->simulation() : nullptr; }
    /// The most work (points × substeps × steps) replayed to bring a ghost turned on late up
    /// to the run's step; past it, the ghost waits for the next Reset.
    static constexpr long kGhostCatchUpWork = 60 * kFrameWork;
    /// Rewind (docs/rewind.md): the run as recorded, its mouse and key events with their steps.
    const RecordedRun* run() const { return m_run.get(); }
    /// The furthest step recorded (the timeline's end), 0 without a simulation.
    long recordedSteps() const { return m_run ? m_run->recordedSteps() : 0; }
    /// Whether the run is behind its recorded end, replaying what was recorded.
    bool playingBack() const { return m_run && m_run->playingBack(); }
    /// Goes to `step` of the recorded run, in [0, recordedSteps()] (false outside): the state
    /// the run went through there. The plots keep their samples up to it. Any grab is let go
    /// in the canvas (the recorded one goes on as recorded).
    bool seek(long step);
    /// Turns the stable solver's knobs live (docs/solvers.md#knobs), recorded at the present
    /// step and given to the ghost too; from a step gone back to it branches, as a grab does.
    /// False for values out of range (nothing changes) or without a simulation.
    bool setStableSettings(const StableSettings& settings);
    /// Replaces the recording by `events` over `steps` steps (a document's run) and goes to
    /// step 0. False with a message for events out of order or outside [0, steps].
    bool setRecording(std::vector<InputEvent> events, long steps, QString* error);
    /// The work (Simulation::workPerStep) a seek may re-simulate: snapshots are taken every
    /// kScrubWork / work steps (1 to 100), so going back answers within a few frames' time —
    /// but never so often that they take more than RecordedRun::kSnapshotCostShare of the
    /// stepping time (RecordedRun::limitSnapshotCost: a big scene's copy costs several steps).
    static constexpr long kScrubWork = 6 * kFrameWork;
    /// What the snapshots may take, counted as kSnapshotBytesPerPoint per point: a big scene
    /// keeps fewer, farther apart (RecordedRun::setMaxSnapshots).
    static constexpr std::size_t kSnapshotBytes = std::size_t(256) << 20;
    static constexpr std::size_t kSnapshotBytesPerPoint = 256;

    /// Running: the timer steps once per frame. Paused: only step() advances.
    void setRunning(bool running);
    bool running() const { return m_running; }
    /// Whether the frame timer is on (off while paused or hidden: a hidden tab costs nothing).
    bool animating() const { return m_timer.isActive(); }
    /// One fixed step (the Step button, and each exported frame).
    void step();
    /// Frames between two steps while running: 1 at real time or faster, 8 at ⅛ (slow
    /// motion), times ⌈work / kFrameWork⌉ for a step that is more work than a frame holds.
    int framesPerStep() const;
    /// The speed, a multiple of real time: one of StepPacer::kSpeeds (false for others).
    bool setSpeed(double speed);
    double speed() const { return m_pacer.speed(); }
    /// "⅛", "¼", "½", "1", "2", "4": a speed as the speed box and the text panel write it.
    static QString speedLabel(double speed);
    /// Steps per frame (1 unless fast) and the speed reached (below speed() for heavy steps).
    int stepsPerFrame() const { return m_pacer.stepsPerFrame(); }
    double effectiveSpeed() const { return m_pacer.effectiveSpeed(); }
    /// One frame of the timer: the steps the speed gives it (none in the frames slow motion
    /// waits). The timer calls it 60 times a second; tests call it to count frames exactly.
    void runFrame();
    /// Frames the timer has run since the simulation was set.
    long frameCount() const { return m_frameCount; }
    /// Whether the text panel says the body has blown up (as last refreshed).
    bool blownUpShown() const { return m_blownUp; }
    /// The lines of the text panel drawn over the scene, as last refreshed.
    QStringList textLines() const;
    /// The width the text panel takes (its widest line, wrapped to the canvas), and the most
    /// the canvas leaves it: the first never exceeds the second (presentation mode on a
    /// 1024 × 768 projector wraps the readouts instead of cutting them).
    double textPanelWidth() const;
    double textPanelRoom() const;

    /// The plots over time (docs/plots-over-time.md): while recording, every step appends a
    /// sample, up to the last kSeriesSeconds; turning it on starts the series at the state
    /// shown. Off, a step costs nothing more.
    static constexpr int kSeriesSeconds = 600;
    void setRecordingSeries(bool on);
    bool recordingSeries() const { return m_recording; }
    const SeriesRecorder& series() const { return m_series; }
    /// The body the plots show alone (FrogPlotPanel::body), outlined and numbered on the
    /// canvas so that the class sees which one it is; −1: none (the plots sum them).
    void setMarkedBody(int body);
    int markedBody() const { return m_markedBody; }

    /// A run set aside whole, as a change of the scene (a parameter, the stage, the solver)
    /// replaced it: its simulation and recording, its ghost, the plots' series and the trail.
    /// The Frog tab keeps it with the undo step of the change, so that Undo brings it back
    /// (docs/rewind.md, "A change of the scene").
    struct KeptRun {
        std::unique_ptr<RecordedRun> run;
        std::unique_ptr<RecordedRun> ghost;
        SeriesRecorder series{std::size_t(kSeriesSeconds) * kFramesPerSecond};
        std::deque<Point> trail;
        TrailPoint trailPoint;
        std::string trailScene;
        long frameCount = 0;
        double startAreaError = 0;
        /// What it holds, counted as kSnapshotBytes counts a run: kSnapshotBytesPerPoint a
        /// point for its state and each snapshot, the ghost's too.
        std::size_t bytes() const;
    };
    /// setSimulation(), handing back the run it replaces (null when there was none).
    std::unique_ptr<KeptRun> replaceRun(std::unique_ptr<Simulation> simulation);
    /// Shows `kept` again, at the step it was left at, and hands back the run it replaces (or
    /// `kept` itself, unchanged, when it holds no run).
    std::unique_ptr<KeptRun> restoreRun(std::unique_ptr<KeptRun> kept);

    void setOverlays(const Overlays& overlays);
    const Overlays& overlays() const { return m_overlays; }
    void setBezierOutline(BezierOutline mode);
    BezierOutline bezierOutline() const { return m_bezier; }
    /// Average cost of the per-frame least-squares fit and its sampling, µs (0 before any).
    double fitMicroseconds() const { return m_fitShownUs; }

    void setPresentation(bool on);
    /// What the canvas shows, for screen readers (the tab gives the scene and the solver): its
    /// accessible description is this and the area error, refreshed with the text panel.
    void setSceneSummary(const QString& summary);

    /// The outline drawn for body `body`, in scene pixels: the polygon, the seed's
    /// curveVertex outline, the closed Catmull-Rom curve or the fitted Bézier curve, as the
    /// scene's components say. Valid until the next call.
    const std::vector<Point>& bodyOutline(int body);
    /// The art the canvas paints with (its colours and the feet), for the TikZ picture.
    const FrogArt& art() const { return m_art; }
    /// The head of body `index` as the canvas paints it (FrogArt::paintHead at its pose), in
    /// scene coordinates: for the TikZ export, which records it as paths (path_recorder.h).
    void paintHeadOf(QPainter& p, int index);
    /// The half width of a leg's outline (Annex II, Pota.dibuixar: the factor 7).
    static constexpr double kLegHalfWidth = 7;

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
    /// The run has stepped, gone back or forth, or branched: the timeline moves.
    void timelineChanged();
    /// The seed's body has blown up (blownUp in core/softbody/simulation.h), or is whole again
    /// (a reset, a step back): the tab offers Reset and the stable solver.
    void blownUpChanged(bool blownUp);

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
    Simulation* sim() const { return m_run ? &m_run->simulation() : nullptr; }
    void tick();
    void advance();
    void updateWork();                  ///< m_stepWork and the pacer, after a spawn (live, replayed or sought)
    std::unique_ptr<KeptRun> takeRun(); ///< the run shown, set aside (null without one)
    /// After a new run or one restored: the pacing, the grab and the texts start afresh.
    /// `fresh`: a new run, which takes the mouse's position as Processing's mouseX does.
    void runShown(bool fresh);
    /// Whether a press at `at` would grab: asked of a copy, so that going back in a run, a
    /// click that grabs nothing does not cut off the recorded future.
    bool wouldGrab(Point at) const;
    /// Live input, to the run and to its ghost; a press returns whether the run grabbed.
    bool send(InputKind kind, Point at = Point());
    void rebuildGhost();
    /// `simulation` recorded with the snapshots spaced as kScrubWork says for steps of `work`,
    /// within RecordedRun::kSnapshotCostShare of the stepping time (the run and its ghost).
    static Expected<RecordedRun> recordRun(std::unique_ptr<Simulation> simulation, long work);
    void restartTrail();
    std::optional<Point> trailPosition(); ///< where the trail's point is now
    void drawTrail(QPainter& p);
    void drawMarkedBody(QPainter& p, double pixel);
    void drawPairs(QPainter& p);
    void drawProtractor(QPainter& p, double pixel);
    void drawRuler(QPainter& p, double pixel);
    std::vector<std::pair<int, int>> m_pairs; // drawPairs' buffer
    std::vector<LinkAngleReading> m_angles;   // drawProtractor's buffer
    // The ruler (scene px): its two ends, while dragged (right button or Ctrl+left) or
    // placed from the keyboard (L, then the arrows, then L).
    std::optional<std::pair<Point, Point>> m_ruler;
    bool m_rulerDragging = false;
    bool m_rulerPlacing = false;
    void drawGhost(QPainter& p);
    int workFramesPerStep() const; ///< ⌈work / kFrameWork⌉: how much a heavy step slows real time
    void updateTimer();
    void refreshTexts();
    void updateAccessibleDescription();
    void reportMouseRadius();
    QRectF sceneRectIn(const QRectF& target) const;
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

    void drawScene(QPainter& p, double pixel);
    void drawBody(QPainter& p, int body, double pixel);
    void drawHead(QPainter& p, int body);
    HeadPose headPose(const std::vector<Point>& vertices) const;
    void drawLeg(QPainter& p, int chain, double pixel);
    void drawPendulum(QPainter& p, double pixel);
    void drawObstacles(QPainter& p);
    void drawOverlays(QPainter& p, double pixel);
    void drawTextPanel(QPainter& p, const QRectF& sceneRect);
    void renderScene(QPainter& p, const QRectF& target, bool textPanel);
    void fillPath(const std::vector<Point>& points, bool close);

    std::unique_ptr<RecordedRun> m_run;
    std::unique_ptr<RecordedRun> m_ghost; // Overlays::ghost: the other solver, fed the same input
    TrailPoint m_trailPoint;
    int m_markedBody = -1;
    struct ProtractorLabel {
        QPointF at;
        QString text;
        bool atLimit = false;
    };
    std::vector<ProtractorLabel> m_protractorLabels; // drawProtractor's, kept for their capacity
    std::vector<QRectF> m_protractorBoxes;
    std::deque<Point> m_trail;
    int m_trailSegmentsDrawn = 0;
    std::vector<QLineF> m_trailLines; ///< reused by drawTrail: a frame allocates nothing
    std::string m_trailScene;         // the stage m_trailPoint was chosen in
    std::vector<Point> m_trailBuffer;
    FrogArt m_art;
    CanvasStyle m_style;
    Overlays m_overlays;
    BezierOutline m_bezier = BezierOutline::Precomputed;

    QTimer m_timer;
    int m_tick = 0;
    long m_stepWork = 0; // m_sim->workPerStep(), again after a spawn
    long m_frameCount = 0;
    StepPacer m_pacer;
    SeriesRecorder m_series{std::size_t(kSeriesSeconds) * kFramesPerSecond};
    bool m_recording = false;
    bool m_running = true;

    // Interaction (Annex II: mousePressed, mouseReleased, keyPressed, keyReleased).
    Point m_mouse{0, 0};
    bool m_mouseKnown = false;
    bool m_pressed = false;
    bool m_spawnHeld = false;
    bool m_keyboardHeld = false;  // the grab was made with G or Enter
    QString m_sceneSummary;       // setSceneSummary
    double m_reportedRadius = -1; // last mouseRadiusChanged, −1 before any
    double m_startAreaError = 0;  // the area error the simulation started with (blownUp)
    bool m_blownUp = false;       // as last said by blownUpChanged

    // Buffers reused every frame.
    std::vector<Point> m_vertices, m_outline, m_joints, m_previous, m_fitControl, m_fitCurve, m_work;
    std::vector<std::size_t> m_previousOffset;
    QPainterPath m_path;
    std::unique_ptr<OutlineFitter> m_fitter;
    bool m_previousValid = false;

    // Background art, cached for the screen at the size last drawn.
    QPixmap m_background;
    QSize m_backgroundSize;

    // Timing, averaged and shown a few times a second.
    QElapsedTimer m_clock, m_textClock;
    qint64 m_lastFrameNs = -1;
    double m_frameNsSum = 0, m_stepNsSum = 0, m_drawNsSum = 0, m_fitNsSum = 0;
    int m_frames = 0, m_steps = 0, m_draws = 0, m_fits = 0;
    double m_frameShownMs = 0, m_stepShownMs = 0, m_drawShownMs = 0, m_fitShownUs = 0;
    std::vector<QStaticText> m_lines;
    std::vector<QString> m_numbers;
    // Pens, brushes and fonts of the overlays, made once per presentation scale.
    QPen m_framePen, m_edgePen, m_velocityPen, m_ringPen, m_numberPen, m_markPen;
    QBrush m_panelBrush, m_trackBrush, m_goodBrush, m_offBrush, m_jointDotBrush;
    QFont m_font, m_numberFont;
    void buildPens(); ///< "0", "1", … for the vertex overlay, made once
};

} // namespace granota::ui
