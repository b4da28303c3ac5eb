// granota-cli simulate: run a scene of chapter 4 / §5.2 headless (docs/cli.md).
#include "app/cli/command.h"
#include "app/cli/output_file.h"
#include "app/cli/scene_options.h"

#include "core/base/display_text.h"
#include "core/base/number_format.h"
#include "core/base/bounded_file.h"
#include "core/base/input_limits.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation_series.h"
#include "core/softbody/simulation_trace.h"

#include <cerrno>
#include <fstream>
#include <sstream>

namespace granota::cli {

namespace {

constexpr int kMaxSteps = 10000000;
/// The most steps × points (body vertices and chain joints) one `simulate` runs: a step
/// of the stable solver costs about 250 ns a vertex (5000 bodies of 10 sides: 12 ms), the
/// seed's less, so at most a few minutes. The frog's 600 default steps are 10 800.
constexpr long long kMaxSimulatedPoints = 1000000000;
/// The most rows `--series` writes: some 150 bytes a row, so at most about 300 MB.
constexpr long long kMaxSeriesRows = 2000000;

/// --replay F: the recording's scene, solver and steps; otherwise --scene, --solver, --set
/// and --steps. Either way the run records itself (for --record), with no snapshots but
/// the first: a headless run never goes back.
Expected<RecordedRun> runFromArguments(const Arguments& args, long* steps)
{
    constexpr int kNoSnapshots = static_cast<int>(kMaxRecordedSteps);
    if (const auto replay = args.value("replay")) {
        for (const char* other : {"scene", "solver", "set", "steps"})
            if (args.has(other))
                return makeError(ErrorCode::InvalidInput, std::string("--replay takes the scene, solver and steps from "
                                                                      "the recording: leave out --") +
                                                              other);
        auto text = readBoundedFile(*replay, kMaxFileBytes);
        if (!text)
            return text.error();
        bool notJson = false;
        auto recording = recordingFromText(*text, &notJson); // the events streamed, not held as Json
        if (!recording)
            return makeError(ErrorCode::InvalidInput,
                             quotedForDisplay(*replay) + (notJson ? " is not JSON: " : ": ") + recording.error().message);
        if (recording->steps > kMaxSteps)
            return makeError(ErrorCode::OutOfRange, "the recording has " + std::to_string(recording->steps) +
                                                        " steps, more than simulate runs (" + std::to_string(kMaxSteps) + ")");
        *steps = recording->steps;
        return RecordedRun::load(std::move(recording).value(), kNoSnapshots);
    }
    auto chosen = sceneAndSolverFromArguments(args);
    if (!chosen)
        return chosen.error();
    auto n = args.integer("steps", 0, kMaxSteps, 600);
    if (!n)
        return n.error();
    *steps = *n;
    return RecordedRun::start(chosen->first, chosen->second, kNoSnapshots);
}

Expected<CommandOutput> run(const Arguments& args)
{
    long stepCount = 0;
    auto recorded = runFromArguments(args, &stepCount);
    if (!recorded)
        return recorded.error();
    RecordedRun& runner = *recorded;
    Simulation& s = runner.simulation();
    const std::optional<long> steps = stepCount;
    const auto recordPath = args.value("record");

    const long long points = static_cast<long long>(simulationTracePoints(s));
    if (static_cast<long long>(*steps) * points > kMaxSimulatedPoints)
        return makeError(ErrorCode::OutOfRange, std::to_string(*steps) + " steps of " + std::to_string(points) +
                                                    " vertices are " + std::to_string(*steps * points) +
                                                    " vertex steps, more than " + std::to_string(kMaxSimulatedPoints) +
                                                    ": lower --steps, or bodies or sides");
    std::ofstream trace;
    const auto tracePath = args.value("trace");
    if (tracePath && recordPath && *tracePath == *recordPath)
        return makeError(ErrorCode::InvalidInput, "--trace and --record name the same file");
    const std::string traceName = "the trace to " + quotedForDisplay(tracePath.value_or(""));
    errno = 0;
    if (tracePath) {
        if ((*steps + 1LL) * points > kMaxTracePoints)
            return makeError(ErrorCode::OutOfRange, "--trace would write " + std::to_string((*steps + 1LL) * points) +
                                                        " vertex positions ((steps + 1) × " + std::to_string(points) +
                                                        " vertices), more than " + std::to_string(kMaxTracePoints) +
                                                        ": lower --steps, or bodies or sides");
        trace.open(*tracePath, std::ios::binary | std::ios::trunc);
        if (!trace)
            return writeError(traceName, errno);
        trace << simulationTraceHeader(s) << '\n' << simulationTraceRow(s) << '\n';
    }
    // The series (docs/plots-over-time.md): one row a step, the state before the first too.
    std::ofstream series;
    const auto seriesPath = args.value("series");
    const std::string seriesName = "the series to " + quotedForDisplay(seriesPath.value_or(""));
    // --series-body K: body K's own values (docs/plots-over-time.md#per-body), same columns.
    int seriesBody = -1;
    if (args.has("series-body")) {
        if (!seriesPath)
            return makeError(ErrorCode::InvalidInput, "--series-body chooses the body of --series: give --series F.csv too");
        if (s.bodyCount() == 0)
            return makeError(ErrorCode::InvalidInput, "--series-body: scene '" + s.scene().name + "' has no bodies");
        auto k = args.integer("series-body", 1, s.bodyCount(), 1);
        if (!k)
            return k.error();
        seriesBody = static_cast<int>(*k) - 1;
    }
    SeriesRecorder recorder(1, seriesBody >= 0 ? SeriesRecorder::kBodyValuesKept : 0);
    if (seriesBody >= 0)
        recorder.setBodiesAsked(true); // from the first row, however many bodies
    if (seriesPath) {
        if (*steps + 1LL > kMaxSeriesRows)
            return makeError(ErrorCode::OutOfRange, "--series would write " + std::to_string(*steps + 1LL) +
                                                        " rows (steps + 1), more than " + std::to_string(kMaxSeriesRows) +
                                                        ": lower --steps");
        if (recordPath && *seriesPath == *recordPath)
            return makeError(ErrorCode::InvalidInput, "--series and --record name the same file");
        if (tracePath && *seriesPath == *tracePath)
            return makeError(ErrorCode::InvalidInput, "--series and --trace name the same file");
        errno = 0;
        series.open(*seriesPath, std::ios::binary | std::ios::trunc);
        if (!series)
            return writeError(seriesName, errno);
        const SeriesSample& first = recorder.record(s);
        series << seriesCsvHeader(recorder.phaseLinks()) << '\n'
               << seriesCsvRow(first, recorder.phaseLinks(), seriesBody) << '\n';
    }
    for (long i = 0; i < *steps; ++i) {
        runner.step(); // a replay applies its events before their steps
        if (trace.is_open()) {
            trace << simulationTraceRow(s) << '\n';
            if (!trace) // a full disk: stop at once, with the reason
                return writeError(traceName, errno);
        }
        if (series.is_open()) {
            series << seriesCsvRow(recorder.record(s), recorder.phaseLinks(), seriesBody) << '\n';
            if (!series)
                return writeError(seriesName, errno);
        }
    }
    for (auto* file : {&trace, &series}) {
        if (!file->is_open())
            continue;
        const std::string& name = file == &trace ? traceName : seriesName;
        if (!file->flush())
            return writeError(name, errno);
        file->close();
        if (!*file)
            return writeError(name, errno);
    }
    if (recordPath) {
        const std::string name = "the recording to " + quotedForDisplay(*recordPath);
        errno = 0;
        std::ofstream file(*recordPath, std::ios::binary | std::ios::trunc);
        if (!file)
            return writeError(name, errno);
        file << recordingToJson(runner.recording()).dump(1) << '\n';
        if (!file.flush())
            return writeError(name, errno);
    }

    CommandOutput out;
    std::ostringstream txt;
    const SceneSpec& scene = s.scene();
    txt << "scene " << scene.name << " (§" << scene.section << ", " << scene.title << "), solver " << solverName(s.solver())
        << ", " << *steps << " steps\n";
    Json components = Json::array();
    std::string componentText;
    for (const auto& c : scene.components) {
        components.push(c);
        componentText += (componentText.empty() ? "" : ", ") + c;
    }
    txt << "components: " << (componentText.empty() ? "(none)" : componentText) << "\n";
    Json bodies = Json::array();
    std::vector<Point> pts;
    for (int b = 0; b < s.bodyCount(); ++b) {
        s.bodyVertices(b, pts);
        Json vertices = Json::array();
        for (const Point& p : pts)
            vertices.push(point(p));
        Json body = Json::object();
        body.set("vertices", std::move(vertices)).set("area", s.bodyArea(b)).set("target_area", s.bodyTargetArea(b));
        bodies.push(std::move(body));
        if (s.bodyCount() <= 10)
            txt << "body " << b << ": area " << formatDouble(s.bodyArea(b)) << " px² (target "
                << formatDouble(s.bodyTargetArea(b)) << ")\n";
    }
    Json chains = Json::array();
    for (int c = 0; c < s.chainCount(); ++c) {
        s.chainJoints(c, pts);
        Json joints = Json::array();
        for (const Point& p : pts)
            joints.push(point(p));
        chains.push(std::move(joints));
    }
    const Readouts r = s.readouts();
    Json readouts = Json::object();
    readouts.set("area_error_percent", r.areaErrorPercent)
        .set("max_stretch", r.maxStretch)
        .set("constraint_force", r.constraintForce)
        .set("kinetic_energy", r.kineticEnergy)
        .set("potential_energy", r.potentialEnergy)
        .set("elastic_energy", r.elasticEnergy ? Json(*r.elasticEnergy) : Json())
        .set("damping_loss", r.dampingLoss ? Json(*r.dampingLoss) : Json())
        .set("contacts", r.contacts);
    const bool finite = s.finite(), inBounds = s.inBounds();
    txt << "area error " << formatDouble(r.areaErrorPercent) << " %, max stretch " << formatDouble(r.maxStretch)
        << ", kinetic energy " << formatDouble(r.kineticEnergy) << "\n";
    txt << "finite: " << (finite ? "yes" : "no") << ", in bounds: " << (inBounds ? "yes" : "no") << "\n";
    out.json.set("scene", scene.name)
        .set("solver", solverName(s.solver()))
        .set("steps", double(*steps))
        .set("components", std::move(components))
        .set("bodies", std::move(bodies))
        .set("chains", std::move(chains))
        .set("readouts", std::move(readouts))
        .set("finite", finite)
        .set("in_bounds", inBounds);
    out.text = txt.str();
    return out;
}

} // namespace

Command simulateCommand()
{
    return {
        "simulate",
        "(--scene NAME [--solver seed|stable] [--steps N] [--set key=value …] | --replay F.json) [--trace F.csv] [--series F.csv [--series-body K]] [--record F.json] [--json]",
        "run a scene of chapter 4 or §5.2 headless; --trace writes the reference CSV layout, --series the "
        "energies, losses, area error, stretch and contacts of every step (summed, or of body K alone); --record writes the run as a recording "
        "(scene, solver, steps, events) and --replay runs one (docs/rewind.md)",
        {{"scene", "solver", "steps", "set", "trace", "series", "series-body", "record", "replay"}, {"json"}, {"set"}},
        &run};
}

} // namespace granota::cli
