#pragma once
/// \file frog_run.h
/// The frog's run as a model, with no widget (docs/design.md, "A scene's run"): one
/// Simulation recorded as a RecordedRun (docs/rewind.md), its ghost on the other solver, the
/// 60 Hz clock that steps it as Processing's draw() (Annex II) at the pace of a StepPacer, the
/// plots' series, the trail, the stable solver's knobs and the speed, and whether the seed's
/// body has blown up (decided at each step). The Frog tab owns it; the canvas draws it and
/// feeds it the mouse and the keys, and the plot panel reads its series.

#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_series.h"
#include "core/softbody/step_pacer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace granota::ui {

class FrogRun : public QObject {
    Q_OBJECT
public:
    /// Frames (and steps) per second, as Processing's default frameRate.
    static constexpr int kFramesPerSecond = kStepsPerSecond;
    /// The most counted work (Simulation::workPerStep: points × substeps) stepped in one
    /// frame: 3000 vertices on the stable solver (8 substeps), about 3 ms a step on the
    /// reference machine. A scene whose step is more work steps once every framesPerStep()
    /// frames, slower than real time, and says so, rather than blocking the event loop
    /// frame after frame (a body of 10000 sides: 39 ms a step, one step every 4 frames).
    static constexpr long kFrameWork = 24000;
    /// The most work (points × substeps × steps) replayed to bring a ghost turned on late up
    /// to the run's step; past it, the ghost waits for the next Reset.
    static constexpr long kGhostCatchUpWork = 60 * kFrameWork;
    /// The work (Simulation::workPerStep) a seek may re-simulate: snapshots are taken every
    /// kScrubWork / work steps (1 to 100), so going back answers within a few frames' time —
    /// but never so often that they take more than RecordedRun::kSnapshotCostShare of the
    /// stepping time (RecordedRun::limitSnapshotCost: a big scene's copy costs several steps).
    static constexpr long kScrubWork = 6 * kFrameWork;
    /// What the snapshots may take, counted as kSnapshotBytesPerPoint per point: a big scene
    /// keeps fewer, farther apart (RecordedRun::setMaxSnapshots).
    static constexpr std::size_t kSnapshotBytes = std::size_t(256) << 20;
    static constexpr std::size_t kSnapshotBytesPerPoint = 256;
    /// The plots over time (docs/plots-over-time.md) keep the last kSeriesSeconds.
    static constexpr int kSeriesSeconds = 600;
    /// The trail keeps the last kTrailSteps steps.
    static constexpr int kTrailSteps = 10 * kFramesPerSecond;

    /// The point the trail follows: a body's vertex or a chain's joint. By default the last
    /// joint of the first chain in the pendulum scenes (the tip), else vertex 0 of body 0.
    struct TrailPoint {
        bool joint = false; ///< a chain's joint, else a body's vertex
        int owner = 0;      ///< the body or the chain
        int index = 0;      ///< the vertex or the joint
        bool operator==(const TrailPoint& o) const { return joint == o.joint && owner == o.owner && index == o.index; }
    };

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

    explicit FrogRun(QObject* parent = nullptr);
    ~FrogRun() override;

    /// Takes over a freshly built simulation (the previous one is dropped) and records its
    /// run from here (docs/rewind.md).
    void setSimulation(std::unique_ptr<Simulation> simulation);
    /// setSimulation(), handing back the run it replaces (null when there was none).
    std::unique_ptr<KeptRun> replaceRun(std::unique_ptr<Simulation> simulation);
    /// Shows `kept` again, at the step it was left at, and hands back the run it replaces (or
    /// `kept` itself, unchanged, when it holds no run).
    std::unique_ptr<KeptRun> restoreRun(std::unique_ptr<KeptRun> kept);
    /// The simulation. Everything that drives it goes through the recorded run, so this is
    /// read-only; a seek may replace it (do not keep the pointer across one).
    const Simulation* simulation() const { return sim(); }
    /// The scene the run was built from, with the stable knobs it started with
    /// (Simulation::scene): the one copy of the scene the Frog tab, its plots and its exports
    /// read. An empty scene without a simulation.
    const SceneSpec& scene() const;
    /// The solver it runs on (the seed without a simulation).
    SolverKind solver() const { return sim() ? sim()->solver() : SolverKind::Seed; }
    /// scene() as the user has it at the step shown: with the radius the mouse has set in
    /// §4.1's polygon (Simulation::mouseRadius). What the parameters panel shows, an edit of a
    /// parameter starts from and a document saves.
    SceneSpec sceneAsEdited() const;
    /// sceneAsEdited() with the stable knobs as turned live since the start
    /// (Simulation::stableSettings): what Reset, a stage or a solver starts the next run with.
    SceneSpec sceneInForce() const;
    /// The run as recorded, its mouse and key events with their steps (null without one).
    const RecordedRun* recorded() const { return m_run.get(); }
    /// The furthest step recorded (the timeline's end), 0 without a simulation.
    long recordedSteps() const { return m_run ? m_run->recordedSteps() : 0; }
    /// Whether the run is behind its recorded end, replaying what was recorded.
    bool playingBack() const { return m_run && m_run->playingBack(); }
    /// Goes to `step` of the recorded run, in [0, recordedSteps()] (false outside): the state
    /// the run went through there. The plots keep their samples up to it; the view lets go of
    /// any grab (grabLost; the recorded one goes on as recorded).
    bool seek(long step);
    /// Turns the stable solver's knobs live (docs/solvers.md#knobs), recorded at the present
    /// step and given to the ghost too; from a step gone back to it branches, as a grab does.
    /// False for values out of range (nothing changes) or without a simulation.
    bool setStableSettings(const StableSettings& settings);
    /// Replaces the recording by `events` over `steps` steps (a document's run) and goes to
    /// step 0. False with a message for events out of order or outside [0, steps].
    bool setRecording(std::vector<InputEvent> events, long steps, QString* error);

    /// Live input, to the run and to its ghost; a press returns whether the run grabbed. A
    /// spawn adds work; input that cuts off the recorded future moves the timeline.
    bool send(InputKind kind, Point at = Point());
    /// Whether a press at `at` would grab: asked of a copy, so that going back in a run, a
    /// click that grabs nothing does not cut off the recorded future.
    bool wouldGrab(Point at) const;

    /// Both solvers at once (docs/solvers.md#both-at-once): the other solver's run of the
    /// same scene, fed the same input. ghost() is its simulation, at the same step, or null
    /// (off, or a scene the other solver refuses).
    void setGhostShown(bool on);
    const Simulation* ghost() const { return m_ghost ? &m_ghost->simulation() : nullptr; }

    /// The trail: while shown, the path of trailPoint() over the last kTrailSteps steps,
    /// oldest first (a new run or a seek starts it again).
    void setTrailShown(bool on);
    const TrailPoint& trailPoint() const { return m_trailPoint; }
    const std::deque<Point>& trail() const { return m_trail; }
    /// Follows the vertex or joint nearest to `at` (scene px), within 30 px; false if none.
    bool chooseTrailPoint(Point at);

    /// While kept, each step keeps the bodies' vertices before it (Verlet's x_prev), for the
    /// velocity overlay: previous() holds them body after body, body i's from
    /// previousOffset()[i]; valid only after a step (not after a new run or a seek).
    void setKeepsPrevious(bool on);
    bool previousValid() const { return m_previousValid; }
    const std::vector<Point>& previous() const { return m_previous; }
    const std::vector<std::size_t>& previousOffset() const { return m_previousOffset; }

    /// Running: the clock steps once per frame while the view is shown. Paused: only step().
    void setRunning(bool running);
    bool running() const { return m_running; }
    /// Whether the view is shown: a hidden tab's clock stops (it costs nothing).
    void setShown(bool shown);
    /// Whether the frame timer is on.
    bool animating() const { return m_timer.isActive(); }
    /// One fixed step (the Step button, and each exported frame).
    void step();
    /// One frame of the clock: the steps the speed gives it (none in the frames slow motion
    /// waits). The timer calls it 60 times a second; tests call it to count frames exactly.
    void runFrame();
    /// Frames run since the simulation was set.
    long frameCount() const { return m_frameCount; }
    /// Frames between two steps while running: 1 at real time or faster, 8 at ⅛ (slow
    /// motion), times ⌈work / kFrameWork⌉ for a step that is more work than a frame holds.
    int framesPerStep() const { return m_pacer.framesPerStep(); }
    /// ⌈work / kFrameWork⌉: how much a heavy step slows real time.
    int workFramesPerStep() const;
    /// The speed, a multiple of real time: one of StepPacer::kSpeeds (false for others).
    bool setSpeed(double speed);
    double speed() const { return m_pacer.speed(); }
    /// "⅛", "¼", "½", "1", "2", "4": a speed as the speed box and the text panel write it.
    static QString speedLabel(double speed);
    /// Steps per frame (1 unless fast) and the speed reached (below speed() for heavy steps).
    int stepsPerFrame() const { return m_pacer.stepsPerFrame(); }
    double effectiveSpeed() const { return m_pacer.effectiveSpeed(); }
    /// The frame and step times measured since the last call, averaged (ms); each keeps its
    /// last value when nothing was measured (the frame time goes to 0 while paused).
    void averageTimings();
    double frameMs() const { return m_frameShownMs; }
    double stepMs() const { return m_stepShownMs; }

    /// Whether the seed's body has blown up (blownUp in core/softbody/simulation.h), as
    /// decided at the last step, seek or new run.
    bool blownUp() const { return m_blownUp; }

    /// The plots over time: while recording, every step appends a sample, up to the last
    /// kSeriesSeconds; turning it on starts the series at the state shown. Off, a step costs
    /// nothing more.
    void setRecordingSeries(bool on);
    bool recordingSeries() const { return m_recordingSeries; }
    const SeriesRecorder& series() const { return m_series; }
    /// A scene of many bodies keeps each body's values only while the plots ask for one.
    void setSeriesBodiesAsked(bool asked) { m_series.setBodiesAsked(asked); }

signals:
    /// One step by step() (the Step button, an exported frame).
    void stepped();
    /// One frame of the clock, with the steps it ran.
    void frameRan();
    /// Something else the view shows changed: the speed, the knobs, the running state, the
    /// trail's point, a seek or a new recording.
    void changed();
    /// A new run (`fresh`) or one restored is shown: the view starts its input afresh.
    void runShown(bool fresh);
    /// The run went to another step: the view lets go of its grab.
    void grabLost();
    /// The run has stepped, gone back or forth, or branched: the timeline moves.
    void timelineChanged();
    /// The seed's body has blown up, or is whole again (a reset, a step back): the tab offers
    /// Reset and the stable solver.
    void blownUpChanged(bool blownUp);
    /// Hints for the status bar.
    void statusMessage(const QString& text);

private:
    Simulation* sim() const { return m_run ? &m_run->simulation() : nullptr; }
    void tick();
    void advance();
    void updateWork(); ///< m_stepWork and the pacer, after a spawn (live, replayed or sought)
    void updateTimer();
    void updateBlownUp();
    std::unique_ptr<KeptRun> takeRun(); ///< the run shown, set aside (null without one)
    /// After a new run or one restored: the pacing starts afresh and the view is told.
    void showRun(bool fresh);
    void rebuildGhost();
    /// `simulation` recorded with the snapshots spaced as kScrubWork says for steps of `work`,
    /// within RecordedRun::kSnapshotCostShare of the stepping time (the run and its ghost).
    static Expected<RecordedRun> recordRun(std::unique_ptr<Simulation> simulation, long work);
    void restartTrail();
    std::optional<Point> trailPosition(); ///< where the trail's point is now
    void restartSeries();                 ///< the series from the state shown, when recording

    std::unique_ptr<RecordedRun> m_run;
    std::unique_ptr<RecordedRun> m_ghost; // the other solver, fed the same input
    bool m_ghostShown = false;
    TrailPoint m_trailPoint;
    bool m_trailShown = false;
    std::deque<Point> m_trail;
    std::string m_trailScene; // the stage m_trailPoint was chosen in
    std::vector<Point> m_trailBuffer, m_work;
    bool m_keepsPrevious = false;
    bool m_previousValid = false;
    std::vector<Point> m_previous, m_vertices;
    std::vector<std::size_t> m_previousOffset;

    QTimer m_timer;
    int m_tick = 0;
    long m_stepWork = 0; // the run's and the ghost's workPerStep(), again after a spawn
    long m_frameCount = 0;
    StepPacer m_pacer;
    SeriesRecorder m_series{std::size_t(kSeriesSeconds) * kFramesPerSecond};
    bool m_recordingSeries = false;
    bool m_running = true;
    bool m_shown = false;
    double m_startAreaError = 0; // the area error the simulation started with (blownUp)
    bool m_blownUp = false;      // as last said by blownUpChanged

    // Timing, averaged by averageTimings().
    QElapsedTimer m_clock;
    qint64 m_lastFrameNs = -1;
    double m_frameNsSum = 0, m_stepNsSum = 0;
    int m_frames = 0, m_steps = 0;
    double m_frameShownMs = 0, m_stepShownMs = 0;
};

} // namespace granota::ui
