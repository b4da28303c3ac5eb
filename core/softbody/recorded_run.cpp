#include "core/softbody/recorded_run.h"

#include "core/base/enum_names.h"
#include "core/base/number_format.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace granota {

namespace {

// The knobs take the names of the scene file's "stable" keys.
constexpr std::array<EnumName<InputKind>, 8> kInputNames{
    {{InputKind::Press, "press"},
     {InputKind::Move, "move"},
     {InputKind::Release, "release"},
     {InputKind::Spawn, "spawn"},
     {InputKind::ReleaseSpawn, "release-spawn"},
     {InputKind::Substeps, stableKnobName(StableKnob::Substeps)},
     {InputKind::EdgeCompliance, stableKnobName(StableKnob::EdgeCompliance)},
     {InputKind::EdgeDampingRatio, stableKnobName(StableKnob::EdgeDampingRatio)}}};

bool hasPoint(InputKind k) { return k == InputKind::Press || k == InputKind::Move || k == InputKind::Spawn; }

/// Knob `k`'s value `v` in `s`: false (and `s` as it was) when out of range (or not a knob).
bool turnKnob(StableSettings& s, InputKind k, double v)
{
    return isKnob(k) && setStableKnob(s, std::string(nameOf(kInputNames, k, "")), v);
}

/// Why a knob event's value is refused, or empty when it is in range (or not a knob).
std::string knobValueError(InputKind k, double v)
{
    StableSettings s;
    if (!isKnob(k) || turnKnob(s, k, v))
        return {};
    const std::string key(nameOf(kInputNames, k, ""));
    return key + " must be " + stableKnobRange(key);
}

Error bad(const std::string& what) { return makeError(ErrorCode::InvalidInput, "recording: " + what); }

/// A whole number in [lo, hi] (a step), or nullopt.
std::optional<long> wholeNumber(const Json& v, long lo, long hi)
{
    const auto d = v.asNumber();
    if (!d || !(*d >= double(lo) && *d <= double(hi)) || std::floor(*d) != *d)
        return std::nullopt;
    return static_cast<long>(*d);
}

} // namespace

Json eventToJson(const InputEvent& e)
{
    Json row = Json::array();
    row.push(double(e.step)).push(std::string(nameOf(kInputNames, e.kind, "move")));
    if (hasPoint(e.kind))
        row.push(e.at.x).push(e.at.y);
    else if (isKnob(e.kind))
        row.push(e.value);
    return row;
}

Json eventsToJson(const std::vector<InputEvent>& list)
{
    Json events = Json::array();
    for (const InputEvent& e : list)
        events.push(eventToJson(e));
    return events;
}

void EventListReader::add(const Json& row)
{
    const std::size_t index = m_rows++;
    if (m_bad || m_rows > static_cast<std::size_t>(kMaxRecordedEvents))
        return;
    const long last = m_events.empty() ? 0 : m_events.back().step;
    const auto refuse = [&](std::string what) { m_bad = Bad{index, last, std::move(what)}; };
    const Json::Array* a = row.asArray();
    if (!a || a->size() < 2)
        return refuse(" must be [step, kind, …]");
    const auto step = wholeNumber((*a)[0], last, m_steps);
    if (!step)
        return refuse({}); // worded by finish(), for the steps known then
    const auto name = (*a)[1].asString();
    const auto k = name ? parseName(kInputNames, *name) : std::nullopt;
    if (!k)
        return refuse(": the kind must be press, move, release, spawn, release-spawn, substeps, edge_compliance "
                      "or edge_damping_ratio");
    InputEvent e{*step, *k, Point()};
    if (hasPoint(*k)) {
        const auto x = a->size() == 4 ? (*a)[2].asNumber() : std::nullopt;
        const auto y = a->size() == 4 ? (*a)[3].asNumber() : std::nullopt;
        if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
            return refuse(": " + *name + " needs finite x and y");
        e.at = Point(*x, *y);
    } else if (isKnob(*k)) {
        const auto v = a->size() == 3 ? (*a)[2].asNumber() : std::nullopt;
        if (!v)
            return refuse(": " + *name + " needs its value");
        if (const std::string why = knobValueError(*k, *v); !why.empty())
            return refuse(": " + why);
        e.value = *v;
    } else if (a->size() != 2) {
        return refuse(": " + *name + " takes no point");
    }
    m_events.push_back(e);
}

Expected<std::vector<InputEvent>> EventListReader::finish(long steps) &&
{
    if (m_rows > static_cast<std::size_t>(kMaxRecordedEvents))
        return bad("more than " + std::to_string(kMaxRecordedEvents) + " events");
    const auto stepError = [steps](std::size_t index, long last) {
        return bad("event " + std::to_string(index + 1) + ": its step must be a whole number from " + std::to_string(last) +
                   " (the event before) to " + std::to_string(steps) + " (the steps)");
    };
    // The events are in step order: the first beyond `steps` is the first bad one, if it
    // comes before the bad row found while reading.
    const auto beyond = std::upper_bound(m_events.begin(), m_events.end(), steps,
                                         [](long s, const InputEvent& e) { return s < e.step; });
    if (beyond != m_events.end()) {
        const auto index = static_cast<std::size_t>(beyond - m_events.begin());
        return stepError(index, index == 0 ? 0 : m_events[index - 1].step);
    }
    if (m_bad) {
        if (m_bad->what.empty())
            return stepError(m_bad->index, m_bad->last);
        return bad("event " + std::to_string(m_bad->index + 1) + m_bad->what);
    }
    return std::move(m_events);
}

Expected<std::vector<InputEvent>> eventsFromJson(const Json& events, long steps)
{
    if (!events.isArray())
        return bad("\"events\" must be an array");
    if (static_cast<long>(events.asArray()->size()) > kMaxRecordedEvents)
        return bad("more than " + std::to_string(kMaxRecordedEvents) + " events");
    EventListReader reader(steps);
    reader.reserve(events.asArray()->size());
    for (const Json& row : *events.asArray())
        reader.add(row);
    return std::move(reader).finish(steps);
}

Json documentRunToJson(const RecordedRun& run)
{
    Json doc = Json::object();
    doc.set("steps", double(run.recordedSteps()))
        .set("step", double(run.stepCount()))
        .set("events", eventsToJson(run.recording().events));
    return doc;
}

Expected<DocumentRun> documentRunFromJson(const Json& doc)
{
    if (!doc.isObject())
        return bad("not a JSON object");
    const Json* steps = doc.find("steps");
    const auto n = steps ? wholeNumber(*steps, 0, kMaxRecordedSteps) : std::nullopt;
    if (!n)
        return bad("\"steps\" must be a whole number from 0 to " + std::to_string(kMaxRecordedSteps));
    DocumentRun run;
    run.steps = *n;
    if (const Json* step = doc.find("step")) {
        const auto s = wholeNumber(*step, 0, run.steps);
        if (!s)
            return bad("\"step\" must be a whole number from 0 to " + std::to_string(run.steps) + " (the steps)");
        run.step = *s;
    }
    const Json* events = doc.find("events");
    if (!events)
        return bad("\"events\" must be an array");
    auto list = eventsFromJson(*events, run.steps);
    if (!list)
        return list.error();
    run.events = std::move(list).value();
    return run;
}

Json recordingToJson(const Recording& r)
{
    Json doc = Json::object();
    doc.set("format", "granota-recording")
        .set("version", 1)
        .set("scene", sceneToJson(r.scene))
        .set("solver", solverName(r.solver))
        .set("steps", double(r.steps))
        .set("events", eventsToJson(r.events));
    return doc;
}

namespace {

/// Everything of a recording but its events (recordingFromJson's checks, in its order).
Expected<Recording> recordingHeaderFromJson(const Json& doc)
{
    if (!doc.isObject())
        return bad("not a JSON object");
    const Json* format = doc.find("format");
    if (!format || format->asString() != std::optional<std::string>("granota-recording"))
        return bad("\"format\" must be \"granota-recording\"");
    const Json* version = doc.find("version");
    if (!version || version->asNumber() != std::optional<double>(1))
        return bad("\"version\" must be 1");
    Recording r;
    const Json* scene = doc.find("scene");
    if (!scene)
        return bad("no \"scene\"");
    auto spec = parseScene(*scene);
    if (!spec)
        return bad("its scene: " + spec.error().message);
    r.scene = std::move(spec).value();
    const Json* solver = doc.find("solver");
    const auto kind = solver && solver->asString() ? parseSolverKind(*solver->asString()) : std::nullopt;
    if (!kind)
        return bad("\"solver\" must be \"seed\" or \"stable\"");
    r.solver = *kind;
    const Json* steps = doc.find("steps");
    const auto n = steps ? wholeNumber(*steps, 0, kMaxRecordedSteps) : std::nullopt;
    if (!n)
        return bad("\"steps\" must be a whole number from 0 to " + std::to_string(kMaxRecordedSteps));
    r.steps = *n;
    return r;
}

} // namespace

Expected<Recording> recordingFromJson(const Json& doc)
{
    auto r = recordingHeaderFromJson(doc);
    if (!r)
        return r.error();
    const Json* events = doc.find("events");
    if (!events)
        return bad("\"events\" must be an array");
    auto list = eventsFromJson(*events, r->steps);
    if (!list)
        return list.error();
    r->events = std::move(list).value();
    return r;
}

Expected<Recording> recordingFromText(std::string_view text, bool* notJson)
{
    // The rows go straight into the reader: each is a small Json for a moment only. A
    // repeated "events" key starts again (the last one counts, as in Json::parse).
    std::optional<EventListReader> reader;
    reader.emplace();
    // Room for every event at once, rather than a vector growing to twice its size: each
    // row has a '[' (so does every other array, and a string may hold some: an upper bound),
    // and takes at least 13 bytes ([0,"release"]), which bounds it for text of nothing but '['.
    constexpr std::size_t kShortestRow = 13;
    reader->reserve(
        std::min(static_cast<std::size_t>(std::count(text.begin(), text.end(), '[')), text.size() / kShortestRow + 1));
    Json::ElementSink sink;
    sink.key = "events";
    bool started = false;
    sink.take = [&reader, &started](std::size_t index, Json&& row) {
        if (index == 0 && started)
            reader.emplace(); // a second "events" array: it replaces the first
        started = true;
        reader->add(row);
    };
    auto doc = Json::parse(text, sink);
    if (notJson)
        *notJson = !doc.ok();
    if (!doc)
        return doc.error();
    auto r = recordingHeaderFromJson(*doc);
    if (!r)
        return r.error();
    const Json* events = doc->find("events");
    if (!events || !events->isArray())
        return bad("\"events\" must be an array");
    auto list = std::move(*reader).finish(r->steps);
    if (!list)
        return list.error();
    r->events = std::move(list).value();
    return r;
}

// ---------------------------------------------------------------- the run

RecordedRun::RecordedRun(RecordedRun&&) noexcept = default;
RecordedRun& RecordedRun::operator=(RecordedRun&&) noexcept = default;
RecordedRun::~RecordedRun() = default;

Expected<RecordedRun> RecordedRun::start(const SceneSpec& scene, SolverKind solver, int snapshotEvery)
{
    auto sim = Simulation::create(scene, solver);
    if (!sim)
        return sim.error();
    RecordedRun run;
    run.m_sim = std::move(sim).value();
    run.m_recording.scene = scene;
    run.m_recording.solver = solver;
    run.m_every = std::max(1, snapshotEvery);
    run.takeSnapshot();
    return run;
}

Expected<RecordedRun> RecordedRun::load(Recording recording, int snapshotEvery)
{
    auto run = start(recording.scene, recording.solver, snapshotEvery);
    if (!run)
        return run.error();
    run->m_recording = std::move(recording);
    return run;
}

Expected<RecordedRun> RecordedRun::adopt(std::unique_ptr<Simulation> sim, int snapshotEvery)
{
    if (!sim || sim->stepCount() != 0)
        return makeError(ErrorCode::InvalidInput, "a recorded run starts from a simulation that has not stepped");
    RecordedRun run;
    run.m_recording.scene = sim->scene();
    run.m_recording.solver = sim->solver();
    run.m_sim = std::move(sim);
    run.m_every = std::max(1, snapshotEvery);
    run.takeSnapshot();
    return run;
}

Expected<void> RecordedRun::setRecording(std::vector<InputEvent> events, long steps)
{
    if (steps < 0 || steps > kMaxRecordedSteps)
        return bad("the steps must be a whole number from 0 to " + std::to_string(kMaxRecordedSteps));
    long last = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const InputEvent& e = events[i];
        if (e.step < last || e.step > steps)
            return bad("event " + std::to_string(i + 1) + ": its step must be from " + std::to_string(last) + " to " +
                       std::to_string(steps));
        if (!std::isfinite(e.at.x) || !std::isfinite(e.at.y))
            return bad("event " + std::to_string(i + 1) + " needs finite x and y");
        if (const std::string why = knobValueError(e.kind, e.value); !why.empty())
            return bad("event " + std::to_string(i + 1) + ": " + why);
        last = e.step;
    }
    m_snapshots.resize(1); // the one at step 0: the rest belonged to the old recording
    m_sim = m_snapshots.front().sim->clone();
    m_snapshots.front().nextEvent = 0;
    m_nextEvent = 0;
    m_recording.events = std::move(events);
    m_recording.steps = steps;
    applyPendingKnobs();
    return {};
}

void RecordedRun::setMaxSnapshots(std::size_t n)
{
    m_maxSnapshots = std::clamp<std::size_t>(n, 2, kMaxSnapshots);
    thinSnapshots();
}

void RecordedRun::takeSnapshot()
{
    const double t0 = m_costShare > 0 ? m_nowNs() : 0;
    m_snapshots.push_back({m_sim->clone(), m_nextEvent});
    if (m_costShare > 0) {
        m_snapshotNs = m_nowNs() - t0;
        m_costEvery = snapshotSpacing(m_snapshotNs, m_stepNs, m_costShare);
    }
    thinSnapshots();
}

void RecordedRun::thinSnapshots()
{
    // Twice the steps between snapshots: every other one goes (the first, at step 0, stays).
    // They were taken one interval apart, so those kept are twice that apart.
    while (m_snapshots.size() > m_maxSnapshots) {
        m_every = std::min(kMaxSnapshotSpacing, 2 * snapshotEvery());
        std::vector<Snapshot> kept;
        for (std::size_t i = 0; i < m_snapshots.size(); i += 2)
            kept.push_back(std::move(m_snapshots[i]));
        m_snapshots = std::move(kept);
    }
}

int RecordedRun::snapshotSpacing(double snapshotNs, double stepNs, double share)
{
    if (!(snapshotNs > 0) || !(stepNs > 0) || !(share > 0))
        return 1;
    const double steps = std::ceil(snapshotNs / (share * stepNs));
    return steps >= kMaxSnapshotSpacing ? kMaxSnapshotSpacing : std::max(1, static_cast<int>(steps));
}

void RecordedRun::limitSnapshotCost(double share, std::function<double()> nowNs)
{
    m_costShare = share > 0 ? share : 0;
    m_costEvery = 0;
    m_stepNs = m_snapshotNs = 0;
    m_nowNs = nowNs ? std::move(nowNs) : [] {
        return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
}

void RecordedRun::apply(const InputEvent& e)
{
    switch (e.kind) {
    case InputKind::Press: m_sim->press(e.at); break;
    case InputKind::Move: m_sim->move(e.at); break;
    case InputKind::Release: m_sim->release(); break;
    case InputKind::Spawn: m_sim->spawn(e.at); break;
    case InputKind::ReleaseSpawn: m_sim->releaseSpawn(); break;
    case InputKind::Substeps:
    case InputKind::EdgeCompliance:
    case InputKind::EdgeDampingRatio: {
        StableSettings s = m_sim->stableSettings();
        turnKnob(s, e.kind, e.value); // checked when recorded or read
        m_sim->setStableSettings(s);
        break;
    }
    }
}

void RecordedRun::applyPendingKnobs()
{
    // The knobs turned at the present step, before it is made: a knob was in force from the
    // moment it was turned, and setting it again when step() applies it changes nothing.
    const auto& events = m_recording.events;
    for (std::size_t i = m_nextEvent; i < events.size() && events[i].step <= stepCount(); ++i)
        if (isKnob(events[i].kind))
            apply(events[i]);
}

void RecordedRun::live(const InputEvent& e)
{
    const long now = stepCount();
    if (m_nextEvent < m_recording.events.size() || now < m_recording.steps) {
        // A new branch from here: the recorded future is gone, and its snapshots.
        m_recording.events.resize(m_nextEvent);
        m_recording.steps = now;
        while (!m_snapshots.empty() && m_snapshots.back().sim->stepCount() > now)
            m_snapshots.pop_back();
    }
    auto& events = m_recording.events;
    // A move sets where the mouse is, a knob its value: the last one of a step is the one that
    // counts. A knob's turn does not depend on the mouse's events of its step, so it replaces
    // the same knob's turn anywhere in the step; a move only the move just before it.
    auto same = events.end();
    for (auto it = events.end(); it != events.begin() && (it - 1)->step == e.step;) {
        --it;
        if (it->kind == e.kind && (isKnob(e.kind) || e.kind == InputKind::Move))
            same = it;
        if (!isKnob(e.kind) || same != events.end())
            break;
    }
    if (same != events.end())
        *same = e;
    else
        events.push_back(e);
    m_nextEvent = events.size();
}

bool RecordedRun::press(Point p)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return false;
    live({stepCount(), InputKind::Press, p});
    return m_sim->press(p);
}
void RecordedRun::move(Point p)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return;
    live({stepCount(), InputKind::Move, p});
    m_sim->move(p);
}
void RecordedRun::release()
{
    live({stepCount(), InputKind::Release, Point()});
    m_sim->release();
}
void RecordedRun::spawn(Point p)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return;
    live({stepCount(), InputKind::Spawn, p});
    m_sim->spawn(p);
}
void RecordedRun::releaseSpawn()
{
    live({stepCount(), InputKind::ReleaseSpawn, Point()});
    m_sim->releaseSpawn();
}

bool RecordedRun::setStableSettings(const StableSettings& settings)
{
    if (!settings.valid())
        return false;
    const StableSettings now = m_sim->stableSettings();
    if (settings.substeps != now.substeps)
        live({stepCount(), InputKind::Substeps, Point(), double(settings.substeps)});
    if (settings.edgeCompliance != now.edgeCompliance)
        live({stepCount(), InputKind::EdgeCompliance, Point(), settings.edgeCompliance});
    if (settings.edgeDampingRatio != now.edgeDampingRatio)
        live({stepCount(), InputKind::EdgeDampingRatio, Point(), settings.edgeDampingRatio});
    m_sim->setStableSettings(settings);
    return true;
}

void RecordedRun::step()
{
    const auto& events = m_recording.events;
    while (m_nextEvent < events.size() && events[m_nextEvent].step <= stepCount())
        apply(events[m_nextEvent++]);
    // One step in kTimedStepEvery timed, when the snapshots' cost is limited: two clock
    // readings a step would cost more than the seed's frog step itself.
    const bool timed = m_costShare > 0 && stepCount() % kTimedStepEvery == 0;
    const double t0 = timed ? m_nowNs() : 0;
    m_sim->step();
    if (timed) {
        const double ns = m_nowNs() - t0;
        m_stepNs = m_stepNs > 0 ? 0.75 * m_stepNs + 0.25 * ns : ns;
        m_costEvery = snapshotSpacing(m_snapshotNs, m_stepNs, m_costShare);
    }
    applyPendingKnobs(); // the knobs turned at the step reached are in force there
    const long now = stepCount();
    m_recording.steps = std::max(m_recording.steps, now);
    if (m_snapshots.empty() || now - m_snapshots.back().sim->stepCount() >= snapshotEvery())
        takeSnapshot();
}

void RecordedRun::runToEnd()
{
    while (stepCount() < m_recording.steps)
        step();
}

Expected<void> RecordedRun::seek(long target)
{
    if (target < 0 || target > m_recording.steps)
        return makeError(ErrorCode::OutOfRange, "step " + std::to_string(target) + " is outside the recording (0 to " +
                                                    std::to_string(m_recording.steps) + ")");
    // The latest snapshot at or before the target; from the present state instead when that
    // is nearer (between the snapshot and the target).
    const auto after = std::upper_bound(m_snapshots.begin(), m_snapshots.end(), target,
                                        [](long t, const Snapshot& s) { return t < s.sim->stepCount(); });
    const Snapshot& from = *(after - 1); // the one at step 0 is always there
    if (!(stepCount() >= from.sim->stepCount() && stepCount() <= target)) {
        m_sim = from.sim->clone();
        m_nextEvent = from.nextEvent;
    }
    while (stepCount() < target)
        step();
    applyPendingKnobs();
    return {};
}

} // namespace granota
