#include "ui/frog/frog_run.h"
#include "ui/common/error_text.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <cmath>

namespace granota::ui {

FrogRun::FrogRun(QObject* parent) : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &FrogRun::tick);
    m_clock.start();
}

FrogRun::~FrogRun() = default;

Expected<RecordedRun> FrogRun::recordRun(std::unique_ptr<Simulation> simulation, long work)
{
    auto run = RecordedRun::adopt(std::move(simulation), int(std::clamp<long>(kScrubWork / std::max(1L, work), 1, 100)));
    if (run)
        run->limitSnapshotCost(RecordedRun::kSnapshotCostShare);
    return run;
}

const SceneSpec& FrogRun::scene() const
{
    static const SceneSpec none;
    return sim() ? sim()->scene() : none;
}

SceneSpec FrogRun::sceneAsEdited() const
{
    SceneSpec spec = scene();
    if (const Simulation* s = sim(); s && spec.hasParam("radius"))
        spec.params.radius = s->mouseRadius().value_or(spec.params.radius);
    return spec;
}

SceneSpec FrogRun::sceneInForce() const
{
    SceneSpec spec = sceneAsEdited();
    if (const Simulation* s = sim())
        spec.stable = s->stableSettings();
    return spec;
}

void FrogRun::setSimulation(std::unique_ptr<Simulation> simulation)
{
    m_run.reset();
    if (simulation) {
        const long work = std::max<long>(1, simulation->workPerStep());
        const std::size_t points = std::max<std::size_t>(1, simulation->pointCount());
        auto run = recordRun(std::move(simulation), work);
        if (run) {
            m_run = std::make_unique<RecordedRun>(std::move(run).value());
            m_run->setMaxSnapshots(kSnapshotBytes / (points * kSnapshotBytesPerPoint));
        }
    }
    rebuildGhost();
    if (sim() && sim()->scene().name != m_trailScene) { // another stage: its own default point
        m_trailScene = sim()->scene().name;
        m_trailPoint.index = -1;
    }
    restartTrail();
    m_frameCount = 0;
    m_series.clear();
    if (sim() && m_recordingSeries)
        m_series.record(*sim());
    m_startAreaError = sim() && sim()->bodyCount() > 0 ? sim()->readouts().areaErrorPercent : 0;
    showRun(true);
}

std::size_t FrogRun::KeptRun::bytes() const
{
    std::size_t bytes = 0;
    for (const RecordedRun* r : {run.get(), ghost.get()})
        if (r)
            bytes += (r->snapshotCount() + 1) * r->simulation().pointCount() * kSnapshotBytesPerPoint;
    return bytes;
}

std::unique_ptr<FrogRun::KeptRun> FrogRun::takeRun()
{
    if (!m_run)
        return nullptr;
    auto kept = std::make_unique<KeptRun>();
    kept->run = std::move(m_run);
    kept->ghost = std::move(m_ghost);
    std::swap(kept->series, m_series); // the plots read m_series: its contents move, not the object
    kept->trail = std::move(m_trail);
    kept->trailPoint = m_trailPoint;
    kept->trailScene = m_trailScene;
    kept->frameCount = m_frameCount;
    kept->startAreaError = m_startAreaError;
    return kept;
}

std::unique_ptr<FrogRun::KeptRun> FrogRun::replaceRun(std::unique_ptr<Simulation> simulation)
{
    std::unique_ptr<KeptRun> kept = takeRun();
    setSimulation(std::move(simulation));
    return kept;
}

std::unique_ptr<FrogRun::KeptRun> FrogRun::restoreRun(std::unique_ptr<KeptRun> kept)
{
    if (!kept || !kept->run)
        return kept;
    std::unique_ptr<KeptRun> replaced = takeRun();
    m_run = std::move(kept->run);
    m_ghost = std::move(kept->ghost);
    if (m_ghostShown != bool(m_ghost)) // the overlay was turned since the run was set aside
        rebuildGhost();
    std::swap(m_series, kept->series);
    if (m_recordingSeries != !m_series.samples().empty()) { // the plots were shown or hidden since
        m_series.clear();
        if (m_recordingSeries)
            m_series.record(*sim());
    }
    m_trail = std::move(kept->trail);
    m_trailPoint = kept->trailPoint;
    m_trailScene = kept->trailScene;
    if (!m_trailShown || m_trail.empty()) // the overlay was turned since
        restartTrail();
    m_frameCount = kept->frameCount;
    m_startAreaError = kept->startAreaError;
    showRun(false);
    return replaced;
}

void FrogRun::showRun(bool fresh)
{
    updateWork();
    m_pacer.restart();
    m_previousValid = false;
    updateBlownUp();
    emit runShown(fresh);
    updateTimer();
    if (!fresh)
        emit timelineChanged();
}

// ---------------------------------------------------------------- the clock

void FrogRun::setRunning(bool running)
{
    m_running = running;
    m_lastFrameNs = -1;
    updateTimer();
    emit changed();
}

void FrogRun::setShown(bool shown)
{
    m_shown = shown;
    updateTimer();
}

void FrogRun::updateTimer()
{
    if (m_running && sim() && m_shown) {
        if (!m_timer.isActive()) {
            m_lastFrameNs = -1;
            m_timer.start(17);
        }
    } else {
        m_timer.stop();
    }
}

void FrogRun::tick()
{
    // 17, 17, 16 ms: three frames in 50 ms, 60 frames per second on average.
    m_tick = (m_tick + 1) % 3;
    m_timer.setInterval(m_tick == 2 ? 16 : 17);
    const qint64 now = m_clock.nsecsElapsed();
    if (m_lastFrameNs >= 0) {
        m_frameNsSum += double(now - m_lastFrameNs);
        ++m_frames;
    }
    m_lastFrameNs = now;
    runFrame();
    emit frameRan();
}

void FrogRun::runFrame()
{
    ++m_frameCount;
    // Processing's draw(): one actualitza() per frame, a fixed step — slow motion waits a
    // few frames between steps, fast runs several, and a step that is more work than a frame
    // holds runs every few frames (StepPacer).
    for (int n = m_pacer.stepsThisFrame(); n > 0; --n)
        advance();
}

void FrogRun::step()
{
    advance();
    emit stepped();
}

void FrogRun::averageTimings()
{
    const auto mean = [](double& sum, int& count) {
        const double v = count > 0 ? sum / count / 1e6 : 0;
        sum = 0;
        count = 0;
        return v;
    };
    if (m_frames > 0 || !m_running)
        m_frameShownMs = mean(m_frameNsSum, m_frames);
    if (m_steps > 0)
        m_stepShownMs = mean(m_stepNsSum, m_steps);
}

QString FrogRun::speedLabel(double speed)
{
    if (speed == 0.125)
        return QStringLiteral("⅛");
    if (speed == 0.25)
        return QStringLiteral("¼");
    if (speed == 0.5)
        return QStringLiteral("½");
    return QLocale().toString(speed, 'g', 3);
}

int FrogRun::workFramesPerStep() const { return static_cast<int>(std::max<long>(1, (m_stepWork + kFrameWork - 1) / kFrameWork)); }

bool FrogRun::setSpeed(double speed)
{
    if (!m_pacer.setSpeed(speed))
        return false;
    m_pacer.restart();
    emit changed();
    return true;
}

void FrogRun::updateWork()
{
    m_stepWork = (sim() ? sim()->workPerStep() : 0) + (m_ghost ? m_ghost->simulation().workPerStep() : 0);
    m_pacer.setWork(m_stepWork, kFrameWork);
}

// ---------------------------------------------------------------- a step

void FrogRun::advance()
{
    if (!sim())
        return;
    if (m_keepsPrevious) { // keep x_prev to draw x − x_prev
        m_previous.clear();
        m_previousOffset.clear();
        for (int i = 0; i < sim()->bodyCount(); ++i) {
            sim()->bodyVertices(i, m_vertices);
            m_previousOffset.push_back(m_previous.size());
            m_previous.insert(m_previous.end(), m_vertices.begin(), m_vertices.end());
        }
        m_previousOffset.push_back(m_previous.size());
        m_previousValid = true;
    }
    const qint64 t0 = m_clock.nsecsElapsed();
    const bool replaying = m_run->playingBack();
    m_run->step();
    if (m_ghost) // in step with the run: the same events at the same steps
        while (m_ghost->stepCount() < m_run->stepCount())
            m_ghost->step();
    if (replaying) // a recorded spawn adds work
        updateWork();
    if (m_recordingSeries)
        m_series.record(*sim());
    if (m_trailShown)
        if (const auto at = trailPosition()) {
            m_trail.push_back(*at);
            while (m_trail.size() > std::size_t(kTrailSteps))
                m_trail.pop_front();
        }
    m_stepNsSum += double(m_clock.nsecsElapsed() - t0);
    ++m_steps;
    updateBlownUp();
    emit timelineChanged();
}

void FrogRun::updateBlownUp()
{
    bool now = false;
    if (sim() && sim()->solver() == SolverKind::Seed && sim()->bodyCount() > 0)
        now = granota::blownUp(sim()->readouts().areaErrorPercent, m_startAreaError);
    if (now != m_blownUp) {
        m_blownUp = now;
        emit blownUpChanged(m_blownUp);
    }
}

// ---------------------------------------------------------------- the trail

void FrogRun::setTrailShown(bool on)
{
    if (on == m_trailShown)
        return;
    m_trailShown = on;
    restartTrail();
}

void FrogRun::restartTrail()
{
    m_trail.clear();
    const Simulation* s = sim();
    if (s && !trailPosition()) { // none chosen in this scene: the pendulum's tip, else the first body's vertex 0
        m_trailPoint = TrailPoint{};
        if (s->bodyCount() == 0 && s->chainCount() > 0) {
            s->chainJoints(0, m_work);
            m_trailPoint = {true, 0, std::max(0, int(m_work.size()) - 1)};
        }
    }
    if (m_trailShown)
        if (const auto at = trailPosition())
            m_trail.push_back(*at);
}

std::optional<Point> FrogRun::trailPosition()
{
    const Simulation* s = sim();
    if (!s)
        return std::nullopt;
    std::vector<Point>& points = m_trailBuffer; // reused: this runs every step
    points.clear();
    if (m_trailPoint.joint && m_trailPoint.owner < s->chainCount())
        s->chainJoints(m_trailPoint.owner, points);
    else if (!m_trailPoint.joint && m_trailPoint.owner < s->bodyCount())
        s->bodyVertices(m_trailPoint.owner, points);
    if (m_trailPoint.index < 0 || m_trailPoint.index >= int(points.size()))
        return std::nullopt;
    return points[std::size_t(m_trailPoint.index)];
}

bool FrogRun::chooseTrailPoint(Point at)
{
    const Simulation* s = sim();
    if (!s)
        return false;
    double best = 30;
    std::optional<TrailPoint> chosen;
    const auto consider = [&](bool joint, int owner) {
        for (std::size_t k = 0; k < m_work.size(); ++k)
            if (const double d = std::hypot(m_work[k].x - at.x, m_work[k].y - at.y); d <= best) {
                best = d;
                chosen = TrailPoint{joint, owner, int(k)};
            }
    };
    for (int i = 0; i < s->bodyCount(); ++i) {
        s->bodyVertices(i, m_work);
        consider(false, i);
    }
    for (int c = 0; c < s->chainCount(); ++c) {
        s->chainJoints(c, m_work);
        consider(true, c);
    }
    if (!chosen)
        return false;
    m_trailPoint = *chosen;
    restartTrail();
    emit changed();
    return true;
}

void FrogRun::setKeepsPrevious(bool on)
{
    m_keepsPrevious = on;
    if (!on)
        m_previousValid = false;
}

void FrogRun::setRecordingSeries(bool on)
{
    if (on == m_recordingSeries)
        return;
    m_recordingSeries = on;
    m_series.clear();
    if (on && sim())
        m_series.record(*sim());
}

void FrogRun::restartSeries()
{
    if (m_recordingSeries) {
        m_series.clear();
        m_series.record(*sim());
    }
}

// ---------------------------------------------------------------- input and the recording

bool FrogRun::send(InputKind kind, Point at)
{
    const bool wasPlayingBack = playingBack();
    bool held = false;
    for (RecordedRun* run : {m_run.get(), m_ghost.get()}) {
        if (!run)
            continue;
        bool h = false;
        switch (kind) {
        case InputKind::Press: h = run->press(at); break;
        case InputKind::Move: run->move(at); break;
        case InputKind::Release: run->release(); break;
        case InputKind::Spawn: run->spawn(at); break;
        case InputKind::ReleaseSpawn: run->releaseSpawn(); break;
        case InputKind::Substeps:
        case InputKind::EdgeCompliance:
        case InputKind::EdgeDampingRatio: break; // setStableSettings
        }
        if (run == m_run.get())
            held = h;
    }
    if (kind == InputKind::Spawn)
        updateWork();
    if (wasPlayingBack && !playingBack()) // the recorded future is cut off here
        emit timelineChanged();
    return held;
}

bool FrogRun::wouldGrab(Point at) const
{
    const std::unique_ptr<Simulation> copy = sim()->clone();
    copy->move(at);
    return copy->press(at);
}

bool FrogRun::setStableSettings(const StableSettings& settings)
{
    if (!m_run || !m_run->setStableSettings(settings))
        return false;
    if (m_ghost) // the seed keeps them and steps as before; a stable ghost takes them
        m_ghost->setStableSettings(settings);
    updateWork();
    emit changed();
    emit timelineChanged(); // the recording has a new end
    return true;
}

void FrogRun::setGhostShown(bool on)
{
    if (on == m_ghostShown)
        return;
    m_ghostShown = on;
    rebuildGhost();
    updateWork();
}

void FrogRun::rebuildGhost()
{
    m_ghost.reset();
    if (!m_ghostShown || !m_run)
        return;
    const SolverKind other = sim()->solver() == SolverKind::Seed ? SolverKind::Stable : SolverKind::Seed;
    auto built = Simulation::create(sim()->scene(), other);
    if (!built) {
        emit statusMessage(QCoreApplication::translate("granota::ui::FrogCanvas", "The other solver cannot run this scene: %1")
                               .arg(ErrorText::of(built.error())));
        return;
    }
    const long catchUp = (*built)->workPerStep() * sim()->stepCount();
    if (catchUp > kGhostCatchUpWork) {
        emit statusMessage(QCoreApplication::translate(
            "granota::ui::FrogCanvas", "The ghost starts with the next Reset: the run so far is too long to replay for it."));
        return;
    }
    auto ghost = recordRun(std::move(built).value(), m_stepWork);
    if (!ghost || !ghost->setRecording(m_run->recording().events, m_run->recordedSteps()).ok() ||
        !ghost->seek(sim()->stepCount()).ok())
        return;
    m_ghost = std::make_unique<RecordedRun>(std::move(ghost).value());
}

bool FrogRun::seek(long step)
{
    if (!m_run || step < 0 || step > m_run->recordedSteps())
        return false;
    const long from = sim()->stepCount();
    if (step != from) {
        // Forward by a little with the plots shown: step through, so that each step is
        // sampled; else restore a snapshot, and the plots keep the samples up to it.
        if (m_recordingSeries && step > from && (step - from) * std::max(1L, m_stepWork) <= 4 * kScrubWork) {
            while (sim()->stepCount() < step)
                advance();
        } else {
            (void)m_run->seek(step); // inside the range: cannot fail
            if (m_ghost && !m_ghost->seek(step).ok())
                rebuildGhost();
            if (m_recordingSeries) {
                m_series.truncateAfter(step);
                if (m_series.samples().empty() || m_series.samples().back().step != step)
                    restartSeries();
            }
        }
    }
    updateWork();
    restartTrail(); // the path so far belongs to where the run was
    m_previousValid = false;
    updateBlownUp();
    emit grabLost();
    emit changed();
    emit timelineChanged();
    return true;
}

bool FrogRun::setRecording(std::vector<InputEvent> events, long steps, QString* error)
{
    if (!m_run)
        return false;
    auto ok = m_run->setRecording(std::move(events), steps);
    if (!ok) {
        if (error)
            *error = ErrorText::of(ok.error());
        return false;
    }
    restartSeries();
    rebuildGhost();
    updateWork();
    restartTrail();
    m_previousValid = false;
    updateBlownUp();
    emit changed();
    emit timelineChanged();
    return true;
}

} // namespace granota::ui
