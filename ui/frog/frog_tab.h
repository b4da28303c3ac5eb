#pragma once
/// \file frog_tab.h
/// The soft-body lab (frog) tab (docs/scenes.md): the live canvas, the scene picker (every
/// stage of chapter 4 and the future work of §5.2), the solver, pause / step / reset, the
/// active scene's parameters applied live, and the overlays.

#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "ui/frog/frog_document.h"
#include "ui/frog/frog_overlays.h"
#include "ui/common/tab_page.h"

#include <QJsonValue>
#include <QSize>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QScrollArea;
class QSlider;
class QUndoStack;

namespace granota::ui {

class FrogCanvas;
class FrogParametersPanel;
class FrogPlotPanel;
class FrogRun;

class FrogTab : public TabPage {
    Q_OBJECT
public:
    explicit FrogTab(QWidget* parent = nullptr);

    void retranslate() override;
    QString hint() const override;
    QString keyboardHint() const override;
    QJsonObject saveState() const override;
    bool loadState(const QJsonObject& state, QString* error) override;
    QString csv() const override;
    void setPresentation(bool on) override;

    /// Opens scene `name` (docs/scenes.md) (`--scene`). False with a message for an unknown name.
    bool setScene(const QString& name, QString* error);
    /// Why the scene `name` did not load: unknown, or the core's own message for a known one.
    static QString sceneLoadError(const QString& name, const Error& coreError);
    /// Writes `frames` frames of the run as frame_0000.png … into `directory`, each `size`
    /// pixels (rounded down to even sides, as video encoders ask), exactly one fixed step
    /// apart from `firstStep` (−1: the step shown now; File ▸ Export gives the step shown when
    /// it was chosen). The run pauses while they are written; each frame is
    /// FrogCanvas::renderFrame, without the live readouts. Empty on success, else a message.
    QString exportFrames(const QString& directory, int frames, QSize size = kFrameSize, long firstStep = -1);
    /// The default size of the frames: 720p video.
    static constexpr QSize kFrameSize{1280, 720};
    /// The step of the run shown now (0 without a simulation).
    long shownStep() const;

    /// The solver (rebuilds the scene on it). False with a message when the core refuses.
    bool setSolver(SolverKind solver, QString* error);
    SolverKind solver() const;
    QString sceneName() const { return QString::fromStdString(scene().name); }
    /// The scene of the run shown (FrogRun::scene): the tab keeps no copy of its own.
    const SceneSpec& scene() const;
    /// Edits parameter `key` (docs/scenes.md name) to `value` in the scene file's form, live and
    /// undoable. False with a message when the core refuses.
    bool editParameter(const QString& key, const QJsonValue& value, QString* error);
    /// Sets `key` to `value` in the scene file's form without an undo step.
    bool applyParameter(const QString& key, const QJsonValue& value, QString* error);
    /// Edits one number of parameter `key`, live and undoable: what a tick of the parameter
    /// panel does, one call into the core (withParameter(scene, key, part, index, value),
    /// scene.h) with nothing written to JSON. False with a message when the core refuses.
    bool editParameterNumber(const QString& key, int part, int index, double value, QString* error);
    /// Builds the scene again from its parameters (Reset).
    void reset();
    /// The stable solver's knobs (docs/solvers.md#knobs): "substeps" (1–32),
    /// "edge_compliance" (0–1) or "edge_damping_ratio" (0–2), turned live as one undo step
    /// (a run of edits of one knob merges). False with a message when refused.
    bool editStableSetting(const QString& key, double value, QString* error);
    /// The speed (StepPacer::kSpeeds; others are ignored), in the canvas and the speed box.
    void setSpeed(double speed);
    /// Rewind (docs/rewind.md): the timeline under the canvas, from step 0 to the furthest
    /// recorded. Moving it pauses and goes to that step; "," steps back one step.
    QSlider* timeline() const { return m_timeline; }
    void stepBack();
    /// The stopwatch (docs/tabs.md): marks the step shown (M), or clears the mark; the
    /// timeline's label then says the steps and seconds since the mark. -1: no mark.
    void toggleMark();
    long markedStep() const { return m_mark; }
    /// A document's run is replayed up to its saved step on load when that is at most this
    /// much work (Simulation::workPerStep × steps): 600 frames' budget, about two seconds;
    /// past it, the run loads at step 0 and the tab says so.
    static const long kLoadSeekWork;
    /// The runs that changes of the scene replaced, kept for Undo, take at most this much
    /// together (FrogRun::KeptRun::bytes: as much as one run's snapshots may take); past
    /// it the oldest are let go, and their undo steps say that the scene starts again.
    static const std::size_t kKeptRunBytes;
    /// Shows the plots over time under the canvas (the canvas records the series meanwhile).
    void setPlotsShown(bool on);
    FrogPlotPanel* plotPanel() const { return m_plots; }

    FrogCanvas* canvas() const { return m_canvas; }
    FrogRun* frogRun() const { return m_run; }
    FrogParametersPanel* parametersPanel() const { return m_params; }

protected:
    void drawTikz(TikzWriter& w) const override;
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// The side panel and the stage, built (frog_tab_controls.cpp); their signals, wired.
    void buildControls();
    void connectControls();
    /// Shows the scene `spec` (a new run with it) or says why the core refused it.
    bool showParameter(const Expected<SceneSpec>& spec, QString* error);
    /// The undo step of an edit of `key`, from the scene `before` to the one shown.
    void pushParameterStep(const QString& key, std::shared_ptr<const SceneSpec> before);
    /// The tab's part of a document as it stands (saveState, and what applyState keeps).
    FrogDocument document() const;
    /// The frog's head in the TikZ picture, over the body (issue 34, item 10).
    void drawTikzHead(TikzWriter& w) const;
    void fitSidePanel();
    /// A new run of `scene` on `solver`; the run it replaces waits in m_replaced for the undo
    /// step of the change (takeReplaced), until the next rebuild.
    bool rebuild(const SceneSpec& scene, SolverKind solver, QString* error);
    /// A run a change of the scene replaced (its scene and solver are its simulation's), with the stopwatch mark it had
    /// (docs/rewind.md, "A change of the scene"); `released` when it was let go to stay within
    /// kKeptRunBytes. The undo step of the change holds it and swaps it with the run shown.
    struct KeptRun;
    struct RunSlot {
        std::unique_ptr<KeptRun> run;
        bool released = false;
    };
    std::shared_ptr<RunSlot> takeReplaced();
    /// What an undo or redo of a change of the scene does once it has applied its state: shows
    /// the run `slot` keeps, and keeps in its place the run that was shown.
    void swapRun(RunSlot& slot);
    /// Keeps `slot` as the newest of the runs kept, letting the oldest go past kKeptRunBytes.
    void keepWithinBudget(const std::shared_ptr<RunSlot>& slot);
    /// The status bar's word on a change of the scene: the run it replaced, and that Undo brings it back.
    void sayRunReplaced(const RunSlot& slot);
    void showScene();
    void sceneChosen(int index);
    void solverChosen(int index);
    void overlaysChanged();
    /// loadState without clearing the undo history: what an undo step of the stage or the
    /// solver applies. Keys the state lacks keep their current values.
    bool applyState(const QJsonObject& state, QString* error);
    /// The stage, the solver and the stage's parameters: what choosing a stage or a solver
    /// changes, and one undo step gives back.
    QJsonObject sceneState() const;
    void pushSceneStep(const QJsonObject& before, const QString& undoText);
    /// The scene `name` on the current solver (or the stable one, for collisions).
    bool switchScene(const QString& name, QString* error);
    /// The overlays the boxes show; showOverlays sets the boxes (without signals) and the canvas.
    FrogOverlays overlaysChecked() const;
    void showOverlays(const FrogOverlays& overlays);
    void setPaused(bool paused);
    void updateTimeline();
    void showExplosion(bool blownUp);
    bool applyStableSettings(const StableSettings& settings, QString* error);
    /// The stable solver's knobs as the run has them now (turned live since its start).
    StableSettings knobsInForce() const;
    void showStableSettings();
    void timelineMoved(int step);
    void stepOnce();
    void showRefusal(const QString& message);
    QString sceneTitle(const QString& name) const;
    QString sceneDescription(const QString& name) const;
    QString sceneHint() const;

    FrogRun* m_run; // the run the canvas shows and the plots read
    FrogCanvas* m_canvas;
    FrogParametersPanel* m_params;
    FrogPlotPanel* m_plots = nullptr;
    QCheckBox* m_showPlots = nullptr;

    QScrollArea* m_scroll = nullptr;
    QWidget* m_side = nullptr;
    QGroupBox *m_sceneBox, *m_bezierBox, *m_paramBox, *m_overlayBox;
    QLabel *m_sceneLabel, *m_description, *m_solverLabel, *m_hint, *m_note, *m_fitCost;
    QLabel* m_solverNote; ///< what the chosen solver cannot show of this scene (seedRoundsShapes)
    QComboBox *m_sceneCombo, *m_solverCombo, *m_speedCombo;
    QLabel* m_speedLabel;
    QGroupBox* m_stableBox = nullptr;
    QLabel *m_substepsLabel = nullptr, *m_complianceLabel = nullptr, *m_stableNote = nullptr;
    QSpinBox* m_substeps = nullptr;
    StableSettings m_knobsShown; ///< what the knob boxes show (showStableSettings)
    QDoubleSpinBox* m_compliance = nullptr;
    QLabel *m_hertzLabel = nullptr, *m_dampingLabel = nullptr;
    QDoubleSpinBox* m_hertz = nullptr;   ///< the compliance as the frequency an edge rings at
    QDoubleSpinBox* m_damping = nullptr; ///< ζ
    static constexpr double kMostEdgeHertz = 999.99;
    /// The first body's first edge, whose ring the note and the frequency box state.
    std::optional<Simulation::EdgeSpring> edgeSpringShown() const;
    QPushButton* m_softBodyReport = nullptr;
    QWidget* m_explosion = nullptr; ///< "the body has blown up", with Reset and the stable solver
    QLabel* m_explosionText = nullptr;
    QPushButton *m_explosionReset = nullptr, *m_explosionStable = nullptr;
    QSlider* m_timeline = nullptr;
    QLabel* m_timelineLabel = nullptr;
    int m_timelineDigits = -1; ///< digits of the recorded steps the label's width was set for
    QPushButton* m_markButton = nullptr;
    long m_mark = -1;
    std::shared_ptr<RunSlot> m_replaced;             ///< the run the last rebuild replaced (rebuild)
    std::vector<std::weak_ptr<RunSlot>> m_keptSlots; ///< the undo steps' kept runs, oldest first
    std::weak_ptr<RunSlot> m_lastParameterSlot;      ///< the kept run of the last parameter step (merges)
    QPushButton *m_pause, *m_step, *m_reset;
    QRadioButton *m_precomputed, *m_fit;
    std::array<QCheckBox*, kFrogOverlayCount> m_overlayBoxes{}; ///< one per row of frogOverlays(), in its order
};

} // namespace granota::ui
