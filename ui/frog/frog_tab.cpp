#include "ui/frog/frog_tab.h"
#include "ui/common/error_text.h"
#include "ui/common/number_text.h"

#include "core/base/number_format.h"
#include "ui/common/value_command.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_json.h"
#include "ui/frog/frog_parameters_panel.h"
#include "ui/frog/frog_plot_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

namespace {

void setError(QString* error, const QString& text)
{
    if (error)
        *error = text;
}

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

constexpr int kParameterMergeIdBase = 0x46520000; ///< "FR": a parameter's edits merge (valueMergeId)

} // namespace

const long FrogTab::kLoadSeekWork = 600 * FrogRun::kFrameWork;
const std::size_t FrogTab::kKeptRunBytes = FrogRun::kSnapshotBytes;

struct FrogTab::KeptRun {
    std::unique_ptr<FrogRun::KeptRun> canvas;
    long mark = -1;
};

FrogTab::FrogTab(QWidget* parent)
    : TabPage(QStringLiteral("frog"), QT_TR_NOOP("Frog"), parent), m_run(new FrogRun), m_canvas(new FrogCanvas(m_run, this)),
      m_params(new FrogParametersPanel(this))
{
    m_run->setParent(this); // after the canvas: the run outlives its view
    setExportView(m_canvas);
    buildControls();
    connectControls();

    QString error;
    auto frog = loadScene("frog");
    if (frog)
        rebuild(*frog, SolverKind::Seed, &error);
    showScene();
}

// ---------------------------------------------------------------- scene and solver

bool FrogTab::rebuild(const SceneSpec& scene, SolverKind solver, QString* error)
{
    auto sim = Simulation::create(scene, solver);
    if (!sim) {
        setError(error, tr("The simulation cannot be built with these values: %1").arg(ErrorText::of(sim.error())));
        return false;
    }
    auto replaced = std::make_unique<KeptRun>();
    replaced->mark = m_mark;
    m_mark = -1; // a new run: the stopwatch's mark was of the old one
    replaced->canvas = m_run->replaceRun(std::move(sim).value());
    m_replaced.reset();
    if (replaced->canvas) {
        m_replaced = std::make_shared<RunSlot>();
        m_replaced->run = std::move(replaced);
    }
    if (m_plots)
        m_plots->refresh(true); // a new run: a new series
    updateTimeline();
    return true;
}

std::shared_ptr<FrogTab::RunSlot> FrogTab::takeReplaced()
{
    std::shared_ptr<RunSlot> slot = std::move(m_replaced);
    m_replaced.reset();
    if (!slot)
        slot = std::make_shared<RunSlot>();
    keepWithinBudget(slot);
    return slot;
}

void FrogTab::keepWithinBudget(const std::shared_ptr<RunSlot>& slot)
{
    // Newest last; the expired (steps gone from the history) and `slot`'s old place go.
    m_keptSlots.erase(std::remove_if(m_keptSlots.begin(), m_keptSlots.end(),
                                     [&slot](const std::weak_ptr<RunSlot>& w) {
                                         const auto s = w.lock();
                                         return !s || s == slot;
                                     }),
                      m_keptSlots.end());
    m_keptSlots.push_back(slot);
    std::size_t total = 0;
    for (const auto& w : m_keptSlots)
        if (const auto s = w.lock(); s && s->run)
            total += s->run->canvas->bytes();
    for (const auto& w : m_keptSlots) {
        if (total <= kKeptRunBytes)
            break;
        const auto s = w.lock();
        if (s && s->run && s != slot) {
            total -= s->run->canvas->bytes();
            s->run.reset();
            s->released = true;
        }
    }
}

void FrogTab::swapRun(RunSlot& slot)
{
    std::unique_ptr<KeptRun> shown;
    if (m_replaced) // the run shown before the undo step applied its state
        shown = std::move(m_replaced->run);
    m_replaced.reset();
    if (slot.run) {
        m_run->restoreRun(std::move(slot.run->canvas)); // the run just built is let go
        m_mark = slot.run->mark;
        if (m_plots)
            m_plots->refresh(true);
        updateTimeline();
    } else if (slot.released) {
        emit statusMessage(tr("The run from before this step was not kept (too much memory): the scene starts again."));
    }
    slot.run = std::move(shown);
    slot.released = false;
    const auto kept = std::find_if(m_keptSlots.begin(), m_keptSlots.end(),
                                   [&slot](const std::weak_ptr<RunSlot>& w) { return w.lock().get() == &slot; });
    if (kept != m_keptSlots.end())
        keepWithinBudget(kept->lock()); // the newest kept now
}

void FrogTab::sayRunReplaced(const RunSlot& slot)
{
    if (!slot.run)
        return;
    const long steps = slot.run->canvas->run->recordedSteps();
    if (steps > 0)
        emit statusMessage(tr("The scene starts again; Undo brings back the run of %n step(s) it replaced.", nullptr,
                              int(std::min<long>(steps, std::numeric_limits<int>::max()))));
}

QString FrogTab::sceneLoadError(const QString& name, const Error& coreError) { return frogSceneLoadError(name, coreError); }

bool FrogTab::setScene(const QString& name, QString* error)
{
    if (!switchScene(name, error))
        return false;
    m_undo->clear(); // a scene set from outside (a document, the command line) starts a history
    m_replaced.reset();
    return true;
}

bool FrogTab::switchScene(const QString& name, QString* error)
{
    auto spec = loadScene(name.toStdString());
    if (!spec) {
        setError(error, sceneLoadError(name, spec.error()));
        return false;
    }
    // The seed never had collisions (§5.2 is future work): those scenes start on the stable
    // solver, as in granota-cli; the solver box switches back to compare.
    spec->stable = knobsInForce(); // the solver's knobs stay with the solver
    SolverKind solver = m_run->solver();
    const bool collisions = spec->has(SceneComponent::Collisions) || spec->has(SceneComponent::Obstacles);
    if (collisions)
        solver = SolverKind::Stable;
    if (!rebuild(*spec, solver, error))
        return false;
    m_note->hide();
    showScene();
    emit documentChanged();
    return true;
}

const SceneSpec& FrogTab::scene() const { return m_run->scene(); }

SolverKind FrogTab::solver() const { return m_run->solver(); }

StableSettings FrogTab::knobsInForce() const { return m_run->sceneInForce().stable; }

bool FrogTab::setSolver(SolverKind solver, QString* error)
{
    if (!rebuild(m_run->sceneInForce(), solver, error))
        return false;
    m_note->hide();
    showScene();
    emit documentChanged();
    return true;
}

QJsonObject FrogTab::sceneState() const
{
    const QJsonObject state = saveState();
    QJsonObject scene;
    for (const char* key : {"scene", "solver", "params", "stable"})
        scene.insert(QLatin1String(key), state.value(QLatin1String(key)));
    return scene;
}

void FrogTab::pushSceneStep(const QJsonObject& before, const QString& undoText)
{
    const QJsonObject after = sceneState();
    if (after == before)
        return;
    const std::shared_ptr<RunSlot> kept = takeReplaced(); // the run before the change, for Undo
    auto apply = [this, kept](const QJsonObject& state) {
        QString error;
        if (applyState(state, &error)) // states this tab wrote itself: cannot be refused
            swapRun(*kept);
        else
            showRefusal(error);
        emit documentChanged();
    };
    m_undo->push(new ValueCommand<QJsonObject>(apply, before, after, undoText, -1, {false, /*appliedAlready=*/true}));
    sayRunReplaced(*kept);
}

void FrogTab::sceneChosen(int index)
{
    const QJsonObject before = sceneState();
    QString error;
    if (!switchScene(m_sceneCombo->itemData(index).toString(), &error)) {
        showScene();
        showRefusal(error);
        return;
    }
    pushSceneStep(before, tr("Stage: %1").arg(m_sceneCombo->itemText(index)));
}

void FrogTab::solverChosen(int index)
{
    const QJsonObject before = sceneState();
    QString error;
    if (!setSolver(index == 1 ? SolverKind::Stable : SolverKind::Seed, &error)) {
        showScene();
        showRefusal(error);
        return;
    }
    pushSceneStep(before, tr("Solver: %1").arg(m_solverCombo->itemText(index)));
}

void FrogTab::reset()
{
    QString error;
    if (!rebuild(m_run->sceneInForce(), m_run->solver(), &error)) // a new run with the knobs as they are
        showRefusal(error);
    else
        emit statusMessage(tr("The scene starts again."));
    m_replaced.reset(); // Reset lets the run go
}

void FrogTab::showScene()
{
    const SceneSpec& scene = m_run->scene();
    const QString name = fromStd(scene.name);
    const QSignalBlocker b1(m_sceneCombo), b2(m_solverCombo);
    m_sceneCombo->setCurrentIndex(std::max(0, m_sceneCombo->findData(name)));
    m_solverCombo->setCurrentIndex(m_run->solver() == SolverKind::Stable ? 1 : 0);
    m_params->setScene(m_run->sceneAsEdited());
    m_bezierBox->setVisible(scene.has(SceneComponent::OutlineBezier));
    retranslate();
    fitSidePanel();
}

void FrogTab::fitSidePanel()
{
    // Wide enough for the parameters' rows (they change with the scene and the font), so
    // that nothing is clipped; the canvas takes the rest.
    if (!m_scroll)
        return;
    const int comfortable = m_side->fontMetrics().averageCharWidth() * 50;
    const int needed = m_side->minimumSizeHint().width() + m_scroll->verticalScrollBar()->sizeHint().width() + 4;
    m_scroll->setMinimumWidth(std::max(comfortable, needed));
}

bool FrogTab::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_side && event->type() == QEvent::LayoutRequest)
        QMetaObject::invokeMethod(this, &FrogTab::fitSidePanel, Qt::QueuedConnection);
    return TabPage::eventFilter(watched, event);
}

void FrogTab::changeEvent(QEvent* event)
{
    TabPage::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        fitSidePanel();
}

void FrogTab::showRefusal(const QString& message)
{
    m_note->setText(message);
    m_note->show();
    emit statusMessage(message);
}

// ---------------------------------------------------------------- parameters

bool FrogTab::applyParameter(const QString& key, const QJsonValue& value, QString* error)
{
    if (!scene().hasParam(key.toStdString())) {
        setError(error, tr("Scene “%1” has no parameter “%2”.").arg(fromStd(scene().name), key));
        return false;
    }
    // The scene file's form of the value (a document's, a test's): read as the file reader reads it.
    return showParameter(withParameter(m_run->sceneAsEdited(), key.toStdString(), fromQJson(value)), error);
}

bool FrogTab::showParameter(const Expected<SceneSpec>& spec, QString* error)
{
    if (!spec) {
        setError(error, tr("This value was refused: %1").arg(ErrorText::of(spec.error())));
        return false;
    }
    // The core has no setter on a running Simulation: the scene is built again with the new
    // value (the bodies start again; pause, overlays, solver and outline stay).
    if (!rebuild(*spec, m_run->solver(), error))
        return false;
    m_params->setValues(m_run->sceneAsEdited());
    m_note->hide();
    emit documentChanged();
    return true;
}

bool FrogTab::editParameter(const QString& key, const QJsonValue& value, QString* error)
{
    auto before = std::make_shared<const SceneSpec>(m_run->sceneAsEdited());
    if (!applyParameter(key, value, error))
        return false;
    pushParameterStep(key, std::move(before));
    return true;
}

bool FrogTab::editParameterNumber(const QString& key, int part, int index, double value, QString* error)
{
    if (!scene().hasParam(key.toStdString())) {
        setError(error, tr("Scene “%1” has no parameter “%2”.").arg(fromStd(scene().name), key));
        return false;
    }
    auto before = std::make_shared<const SceneSpec>(m_run->sceneAsEdited());
    // One number set through the core's table and the scene checked: nothing is written to JSON (issue 35).
    if (!showParameter(withParameter(m_run->sceneAsEdited(), key.toStdString(), part, index, value), error))
        return false;
    pushParameterStep(key, std::move(before));
    return true;
}

void FrogTab::pushParameterStep(const QString& key, std::shared_ptr<const SceneSpec> before)
{
    // The run the value replaced goes with the step: Undo brings it back as it was.
    const std::shared_ptr<RunSlot> kept = takeReplaced();
    // Undo and redo give `key` the value the scene they hold has, and only that parameter.
    auto apply = [this, key, kept](const std::shared_ptr<const SceneSpec>& scene) {
        if (showParameter(withParameterOf(m_run->sceneAsEdited(), *scene, key.toStdString()), nullptr))
            swapRun(*kept);
    };
    // Consecutive edits of the same parameter merge, so that spinning an arrow is one step:
    // the step keeps the run from before the first of them.
    const int index = m_undo->index();
    m_undo->push(new ValueCommand<std::shared_ptr<const SceneSpec>>(
        apply, std::move(before), std::make_shared<const SceneSpec>(m_run->sceneAsEdited()),
        tr("Change %1").arg(ErrorText::parameterLabel(key.toStdString())), valueMergeId(kParameterMergeIdBase, key),
        {/*dropWhenUnchanged=*/false, /*appliedAlready=*/true}));
    const bool merged = m_undo->index() == index;
    if (!merged)
        m_lastParameterSlot = kept;
    if (const auto shown = merged ? m_lastParameterSlot.lock() : kept)
        sayRunReplaced(*shown);
}

// ---------------------------------------------------------------- run controls

void FrogTab::setPaused(bool paused)
{
    m_run->setRunning(!paused);
    retranslate();
}

void FrogTab::stepOnce()
{
    if (!m_pause->isChecked())
        m_pause->setChecked(true); // a single step pauses first
    m_run->step();
}

FrogOverlays FrogTab::overlaysChecked() const
{
    FrogOverlays checked;
    for (std::size_t i = 0; i < m_overlayBoxes.size(); ++i)
        checked.*frogOverlays()[i].flag = m_overlayBoxes[i]->isChecked();
    return checked;
}

void FrogTab::showOverlays(const FrogOverlays& overlays)
{
    for (std::size_t i = 0; i < m_overlayBoxes.size(); ++i) {
        const QSignalBlocker block(m_overlayBoxes[i]);
        m_overlayBoxes[i]->setChecked(overlays.*frogOverlays()[i].flag);
    }
    m_canvas->setOverlays(overlays);
}

void FrogTab::overlaysChanged()
{
    auto* box = qobject_cast<QCheckBox*>(sender());
    FrogOverlays before = overlaysChecked();
    for (std::size_t i = 0; i < m_overlayBoxes.size(); ++i)
        if (m_overlayBoxes[i] == box)
            before.*frogOverlays()[i].flag = !(before.*frogOverlays()[i].flag); // the box has toggled already
    const auto apply = [this](const FrogOverlays& overlays) {
        showOverlays(overlays);
        emit documentChanged();
    };
    m_undo->push(new ValueCommand<FrogOverlays>(apply, before, overlaysChecked(),
                                                box ? box->text().remove(QLatin1Char('&')) : tr("Overlays")));
}

void FrogTab::setPresentation(bool on)
{
    m_canvas->setPresentation(on);
    m_plots->setPresentation(on);
}

void FrogTab::setPlotsShown(bool on)
{
    if (m_showPlots->isChecked() != on) {
        const QSignalBlocker block(m_showPlots);
        m_showPlots->setChecked(on);
    }
    m_run->setRecordingSeries(on);
    m_plots->setRun(m_run);
    m_plots->setVisible(on); // at the height it asks for (FrogPlotPanel::sizeHint), the canvas the rest
    m_canvas->setMarkedBody(on ? m_plots->body() : -1);
}

void FrogTab::showExplosion(bool blownUp)
{
    m_explosion->setVisible(blownUp);
    m_explosionStable->setVisible(m_run->solver() == SolverKind::Seed);
}

void FrogTab::timelineMoved(int step)
{
    // Scrubbing is looking: the run pauses there (P runs on, replaying what was recorded).
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    m_run->seek(step);
    m_plots->refresh(true);
}

void FrogTab::toggleMark()
{
    const Simulation* sim = m_run->simulation();
    m_mark = m_mark >= 0 || !sim ? -1 : sim->stepCount();
    if (m_mark >= 0)
        emit statusMessage(tr("Stopwatch: marked step %1; M again clears the mark.").arg(m_mark));
    updateTimeline();
}

void FrogTab::stepBack()
{
    const Simulation* sim = m_run->simulation();
    if (!sim)
        return;
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    if (sim->stepCount() == 0) {
        emit statusMessage(tr("Step 0: the run starts here."));
        return;
    }
    m_run->seek(sim->stepCount() - 1);
    m_plots->refresh(true);
}

void FrogTab::setSpeed(double speed)
{
    if (!m_run->setSpeed(speed))
        return;
    const QSignalBlocker block(m_speedCombo);
    m_speedCombo->setCurrentIndex(m_speedCombo->findData(speed));
}

// ---------------------------------------------------------------- document

FrogDocument FrogTab::document() const
{
    FrogDocument doc;
    doc.scene = m_run->sceneAsEdited();
    doc.solver = m_run->solver();
    doc.overlays = m_canvas->overlays();
    doc.fitOutline = m_fit->isChecked();
    doc.paused = !m_run->running();
    doc.speed = m_run->speed();
    doc.ruler = m_canvas->ruler();
    return doc;
}

QJsonObject FrogTab::saveState() const { return document().toJson(m_run->recorded()); }

bool FrogTab::loadState(const QJsonObject& state, QString* error)
{
    if (state.isEmpty())
        return true; // a document without the frog's state: keep the tab as it is
    if (!applyState(state, error))
        return false;
    m_undo->clear();
    m_replaced.reset();
    return true;
}

bool FrogTab::applyState(const QJsonObject& state, QString* error)
{
    FrogDocument current = document();
    current.paused = m_pause->isChecked(); // what the Pause button says, where the state says nothing
    auto doc = FrogDocument::fromJson(state, current, error);
    if (!doc)
        return false;
    if (!rebuild(doc->scene, doc->solver, error))
        return false;
    if (doc->recording) {
        QString refused;
        if (!m_run->setRecording(std::move(doc->recording->events), doc->recording->steps, &refused))
            showRefusal(refused); // checked by FrogDocument: cannot happen
        const long step = doc->recording->step;
        const long work = m_run->simulation()->workPerStep() * step;
        if (work <= kLoadSeekWork)
            m_run->seek(step);
        else
            emit statusMessage(
                tr("The run was saved at step %1: drag the timeline to go there (it is long to replay).").arg(step));
    }
    setSpeed(doc->speed);
    m_canvas->setRuler(doc->ruler);
    // Everything is valid: show it.
    showOverlays(doc->overlays);
    {
        const QSignalBlocker b1(m_fit), b2(m_precomputed);
        (doc->fitOutline ? m_fit : m_precomputed)->setChecked(true);
        m_canvas->setBezierOutline(doc->fitOutline ? FrogCanvas::BezierOutline::Fit : FrogCanvas::BezierOutline::Precomputed);
        const QSignalBlocker b3(m_pause);
        m_pause->setChecked(doc->paused);
        m_run->setRunning(!doc->paused);
    }
    m_note->hide();
    showScene();
    return true;
}

} // namespace granota::ui
