#pragma once
/// \file recorded_run.h
/// Rewind (docs/rewind.md): a run of a scene that records what drives it — the scene as
/// run, the solver, and every mouse and key event with the step it came before — so that it
/// replays identically (both solvers are deterministic: same input, same bits) and can go
/// back to any step it has been through. Going back restores the snapshot taken at or
/// before that step (one every `snapshotEvery` steps) and steps forward from it, applying
/// the recorded events again; running on from a step it has been through plays the
/// recording back until a new event is made there, which cuts the recorded future off.

#include "core/base/expected.h"
#include "core/io/json.h"
#include "core/softbody/simulation.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granota {

/// Annex II's input: the left button's press, move and release, and the space bar's
/// spawn (a new body at the mouse) and its release; and the stable solver's knobs turned
/// live (Simulation::setStableSettings): its substeps and its edges' compliance.
enum class InputKind { Press, Move, Release, Spawn, ReleaseSpawn, Substeps, EdgeCompliance, EdgeDampingRatio };

struct InputEvent {
    long step = 0; ///< applied once the run has made this many steps, before the next
    InputKind kind = InputKind::Move;
    Point at;         ///< scene px (Press, Move, Spawn)
    double value = 0; ///< the knob's new value (Substeps, EdgeCompliance, EdgeDampingRatio)
    bool operator==(const InputEvent& o) const { return step == o.step && kind == o.kind && at == o.at && value == o.value; }
};
/// Whether an event turns a knob (it changes how the run steps, not where anything is).
inline bool isKnob(InputKind k)
{
    return k == InputKind::Substeps || k == InputKind::EdgeCompliance || k == InputKind::EdgeDampingRatio;
}

struct Recording {
    SceneSpec scene;
    SolverKind solver = SolverKind::Seed;
    long steps = 0; ///< how far the run went
    std::vector<InputEvent> events;
};

/// The most events and steps a recording may hold (a bound on what a file can ask for):
/// ten events a step for a day of 60 steps a second is far below either.
inline constexpr long kMaxRecordedEvents = 10000000;
inline constexpr long kMaxRecordedSteps = 100000000;

/// {"format": "granota-recording", "version": 1, "scene": {…scene file…}, "solver": …,
///  "steps": N, "events": [[step, "press", x, y], [step, "release"], [step, "substeps", n], …]}
/// (docs/file-formats.md).
Json recordingToJson(const Recording& recording);
/// Rejects a malformed recording with a message naming what is wrong: the scene as a scene
/// file is checked, events in step order, inside [0, steps], finite coordinates, knobs in
/// their ranges (StableSettings::valid).
Expected<Recording> recordingFromJson(const Json& doc);
/// The "events" array alone, as the recording file writes it, and read back with the same checks.
Json eventsToJson(const std::vector<InputEvent>& events);
Expected<std::vector<InputEvent>> eventsFromJson(const Json& events, long steps);
/// One row of it, [step, kind, …].
Json eventToJson(const InputEvent& event);

/// Reads the rows of an "events" array one at a time, with eventsFromJson's checks and
/// messages, so that a reader never holds all the rows as Json at once (2.4 million events
/// are some 500 MB as a Json tree, 96 MB as InputEvents): recordingFromText streams the
/// file's rows here, and the Frog tab its document's.
class EventListReader {
public:
    /// The run's steps when known; a streaming reader learns them after the events, and gives them to finish().
    explicit EventListReader(long steps = kMaxRecordedSteps) : m_steps(steps) {}
    void reserve(std::size_t count) { m_events.reserve(std::min<std::size_t>(count, kMaxRecordedEvents)); }
    /// The next row; after the first bad one the rest are only counted.
    void add(const Json& row);
    /// The events, or the first error as eventsFromJson words it, for a run of `steps` steps
    /// (at most the constructor's): an event beyond them is an error in its place.
    Expected<std::vector<InputEvent>> finish(long steps) &&;

private:
    long m_steps;
    std::size_t m_rows = 0;
    std::vector<InputEvent> m_events;
    /// The first bad row: its index, the step of the event before it, and what is wrong
    /// (empty: its step, worded by finish() for the steps known then).
    struct Bad {
        std::size_t index = 0;
        long last = 0;
        std::string what;
    };
    std::optional<Bad> m_bad;
};

/// recordingFromJson(Json::parse(text)), with the events streamed (Json::ElementSink) rather
/// than held as a Json tree. `notJson`, when given, is set when the text is no JSON (the
/// error is then Json::parse's), so that a caller can word the two kinds apart.
Expected<Recording> recordingFromText(std::string_view text, bool* notJson = nullptr);

/// A run as a document keeps it beside the scene it already holds (the Frog tab's
/// "recording"): {"steps": N, "step": s, "events": […]}, "step" the step shown (optional, 0).
struct DocumentRun {
    long steps = 0;
    long step = 0;
    std::vector<InputEvent> events;
};
class RecordedRun;
Json documentRunToJson(const RecordedRun& run);
/// Errors name what is wrong: steps outside [0, 10⁸], a step outside [0, steps], an event as
/// recordingFromJson says.
Expected<DocumentRun> documentRunFromJson(const Json& doc);

class RecordedRun {
public:
    /// A new run of `scene` on `solver`, recording from step 0.
    static Expected<RecordedRun> start(const SceneSpec& scene, SolverKind solver, int snapshotEvery = 100);
    /// The recording ready to play back from step 0 (run() or seek() to go through it).
    static Expected<RecordedRun> load(Recording recording, int snapshotEvery = 100);
    /// Records a simulation already built (the Frog tab builds its own, and checks it):
    /// the scene and solver are its own. Errors: one that has already stepped (its start
    /// could not be replayed from the scene).
    static Expected<RecordedRun> adopt(std::unique_ptr<Simulation> sim, int snapshotEvery = 100);
    /// Replaces what is recorded by `steps` steps of `events` (a document's run), and goes
    /// back to step 0 to play them. Errors: events out of step order or outside [0, steps],
    /// or not finite; the run is then unchanged.
    Expected<void> setRecording(std::vector<InputEvent> events, long steps);

    RecordedRun(RecordedRun&&) noexcept;
    RecordedRun& operator=(RecordedRun&&) noexcept;
    ~RecordedRun();

    Simulation& simulation() { return *m_sim; }
    const Simulation& simulation() const { return *m_sim; }
    long stepCount() const { return m_sim->stepCount(); }
    /// The furthest step recorded: seek() reaches any step in [0, recordedSteps()].
    long recordedSteps() const { return m_recording.steps; }
    /// Whether step() will replay recorded steps (the run is behind its recorded end).
    bool playingBack() const { return stepCount() < m_recording.steps; }
    const Recording& recording() const { return m_recording; }

    /// Live input: applied now and recorded at the present step. Made while playing back, it
    /// cuts the recorded future off first (a new branch from here). A point that is not
    /// finite is neither applied nor recorded (press returns false). Moves made within one
    /// step are kept as the last of them (a move only sets where the mouse is), so a mouse
    /// that sends a hundred events a second records at most one a step.
    bool press(Point p);
    void move(Point p);
    void release();
    void spawn(Point p);
    void releaseSpawn();
    /// The stable solver's knobs, turned live and recorded as one event for each that
    /// changes (a run of changes within one step keeps the last). Out of range: false, and
    /// nothing is applied or recorded.
    bool setStableSettings(const StableSettings& settings);

    /// One step: first the recorded events of this step (while playing back), then the step;
    /// then the knobs recorded at the step reached, which were in force from there.
    void step();
    /// Steps until the recorded end (replays the whole recording from where it is).
    void runToEnd();
    /// Goes to `step`, in [0, recordedSteps()]: the state after that many steps, as the run
    /// first went through it, with the knobs turned at that step in force (as they were once
    /// turned). Errors: a step outside that range.
    Expected<void> seek(long step);
    /// Snapshots held, and the steps between them: as asked, doubled when there would be more
    /// than maxSnapshots() (so memory stays bounded on long runs), and no fewer than
    /// limitSnapshotCost allows.
    std::size_t snapshotCount() const { return m_snapshots.size(); }
    int snapshotEvery() const { return std::max(m_every, m_costEvery); }
    /// Keeps the snapshots within `share` of the time spent stepping (docs/rewind.md#what-a-snapshot-costs):
    /// each snapshot and one step in kTimedStepEvery are timed with `nowNs` (the steady clock
    /// when empty; a test gives its own), and the steps between snapshots become at least
    /// snapshotSpacing(snapshot ns, step ns, share). A copy of the simulation costs the
    /// same whether it comes every step or every thousand; only the spacing bounds its
    /// share. A share ≤ 0 turns the floor off.
    void limitSnapshotCost(double share, std::function<double()> nowNs = {});
    /// The share of stepping time the Frog tab lets the snapshots take (issue 16: recording,
    /// the series and the plots together at most 5 % of a step of 1000 bodies).
    static constexpr double kSnapshotCostShare = 0.01;
    static constexpr int kTimedStepEvery = 8;
    /// The fewest steps between two snapshots that keep `snapshotNs` a copy within `share` of
    /// steps of `stepNs` each: ⌈snapshotNs / (share · stepNs)⌉, at least 1, and 1 while either
    /// time is unknown (≤ 0 or not a number); at most kMaxSnapshotSpacing.
    static int snapshotSpacing(double snapshotNs, double stepNs, double share);
    static constexpr int kMaxSnapshotSpacing = 1 << 20;
    static constexpr std::size_t kMaxSnapshots = 256;
    /// Fewer snapshots, for a big scene whose copies are large (at least 2, at most
    /// kMaxSnapshots): thins those held at once if there are more.
    void setMaxSnapshots(std::size_t n);
    std::size_t maxSnapshots() const { return m_maxSnapshots; }

private:
    RecordedRun() = default;
    struct Snapshot {
        std::unique_ptr<Simulation> sim;
        std::size_t nextEvent = 0;
    };
    void live(const InputEvent& e);
    void apply(const InputEvent& e);
    void applyPendingKnobs();
    void takeSnapshot();
    void thinSnapshots();

    std::unique_ptr<Simulation> m_sim;
    Recording m_recording;
    std::size_t m_nextEvent = 0;       // the first recorded event not yet applied
    std::vector<Snapshot> m_snapshots; // in step order; the first at step 0
    int m_every = 100;                 // as asked, doubled by thinning
    int m_costEvery = 0;               // the floor limitSnapshotCost measures (0: none)
    double m_costShare = 0;            // limitSnapshotCost's share, 0 when off
    std::function<double()> m_nowNs;
    double m_stepNs = 0;     // a step's time, a running mean of the timed ones
    double m_snapshotNs = 0; // the last snapshot's time
    std::size_t m_maxSnapshots = kMaxSnapshots;
};

} // namespace granota
