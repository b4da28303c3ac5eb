// granota-cli simulate: run a scene of chapter 4 / §5.2 headless (docs/cli.md).
#include "app/cli/command.h"
#include "app/cli/file_identity.h"
#include "app/cli/output_file.h"
#include "app/cli/run_budget.h"
#include "app/cli/scene_options.h"

#include "core/base/display_text.h"
#include "core/base/file_replacement.h"
#include "core/base/number_format.h"
#include "core/base/bounded_file.h"
#include "core/base/input_limits.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation_series.h"
#include "core/softbody/simulation_trace.h"

#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

namespace granota::cli {

namespace {

constexpr int kMaxSteps = 10000000;
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
        if (!recording) {
            std::string why = recording.error().message;
            if (notJson && why.rfind("JSON: ", 0) == 0)
                why.erase(0, 6); // "JSON: …", said once
            return makeError(ErrorCode::InvalidInput, quotedForDisplay(*replay) + (notJson ? " is not JSON: " : ": ") + why);
        }
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
    // No output may name an input or another output (file_identity.h): checked before the
    // recording is read, and every other argument before any output is opened, so that a
    // refusal leaves every file as it was.
    const auto tracePath = args.value("trace");
    const auto seriesPath = args.value("series");
    const auto recordPath = args.value("record");
    if (auto distinct = distinctFiles(
            {{"series", seriesPath}, {"trace", tracePath}, {"record", recordPath}, {"replay", args.value("replay")}});
        !distinct)
        return distinct.error();
    long stepCount = 0;
    auto recorded = runFromArguments(args, &stepCount);
    if (!recorded)
        return recorded.error();
    RecordedRun& runner = *recorded;
    Simulation& s = runner.simulation();
    const std::optional<long> steps = stepCount;

    const long long points = static_cast<long long>(simulationTracePoints(s));
    // The work budget (run_budget.h): substeps and a body's pairs of edges counted too.
    if (auto affordable = checkRunWork(s, *steps); !affordable)
        return affordable.error();
    const std::string traceName = "the trace to " + quotedForDisplay(tracePath.value_or(""));
    if (tracePath) {
        if ((*steps + 1LL) * points > kMaxTracePoints)
            return makeError(ErrorCode::OutOfRange, "--trace would write " + std::to_string((*steps + 1LL) * points) +
                                                        " vertex positions ((steps + 1) × " + std::to_string(points) +
                                                        " vertices), more than " + std::to_string(kMaxTracePoints) +
                                                        ": lower --steps, or bodies or sides");
    }
    // The series (docs/plots-over-time.md): one row a step, the state before the first too.
    const std::string seriesName = "the series to " + quotedForDisplay(seriesPath.value_or(""));
    // --series-body K: body K's own values (docs/plots-over-time.md#per-body), same columns.
    int seriesBody = -1;
    if (args.has("series-body")) {
        if (!seriesPath)
            return makeError(ErrorCode::InvalidInput, "--series-body chooses the body of --series: give --series F.csv too");
        if (s.bodyCount() == 0)
            return makeError(ErrorCode::InvalidInput,
                             "--series-body: scene " + quotedForDisplay(s.scene().name) + " has no bodies");
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
    }

    // Each output goes to a hidden file beside its target, which keeps its old content
    // until the whole run has succeeded (core/base/file_replacement.h).
    const std::string recordName = "the recording to " + quotedForDisplay(recordPath.value_or(""));
    std::optional<FileReplacement> trace, series, record;
    for (auto [path, file, name] : {std::tuple(&tracePath, &trace, &traceName), std::tuple(&seriesPath, &series, &seriesName),
                                    std::tuple(&recordPath, &record, &recordName)}) {
        if (!*path)
            continue;
        auto opened = FileReplacement::open(**path);
        if (!opened)
            return writeError(*name, opened.error().systemError);
        file->emplace(std::move(opened).value());
    }
    const auto write = [](std::optional<FileReplacement>& file, const std::string& name,
                          const std::string& bytes) -> Expected<void> {
        if (auto written = file->write(bytes); !written) // a full disk: stop at once, with the reason
            return writeError(name, written.error().systemError);
        return {};
    };
    if (trace)
        if (auto w = write(trace, traceName, simulationTraceHeader(s) + '\n' + simulationTraceRow(s) + '\n'); !w)
            return w.error();
    if (series) {
        const SeriesSample& first = recorder.record(s);
        if (auto w = write(series, seriesName,
                           seriesCsvHeader(recorder.phaseLinks()) + '\n' +
                               seriesCsvRow(first, recorder.phaseLinks(), seriesBody) + '\n');
            !w)
            return w.error();
    }
    for (long i = 0; i < *steps; ++i) {
        runner.step(); // a replay applies its events before their steps
        if (trace)
            if (auto w = write(trace, traceName, simulationTraceRow(s) + '\n'); !w)
                return w.error();
        if (series)
            if (auto w = write(series, seriesName, seriesCsvRow(recorder.record(s), recorder.phaseLinks(), seriesBody) + '\n');
                !w)
                return w.error();
    }
    if (record)
        if (auto w = write(record, recordName, recordingToJson(runner.recording()).dump(1) + '\n'); !w)
            return w.error();
    // The run has succeeded: each output now takes its target's place.
    for (auto [file, name] : {std::pair(&trace, &traceName), std::pair(&series, &seriesName), std::pair(&record, &recordName)})
        if (*file)
            if (auto committed = (*file)->commit(); !committed)
                return writeError(*name, committed.error().systemError);

    CommandOutput out;
    std::ostringstream txt;
    const SceneSpec& scene = s.scene();
    // A recording's scene is text from a file: its names are escaped (display_text.h), so an
    // ESC or a newline in a forged title cannot clear the terminal or fake a line.
    txt << "scene " << escapedForDisplay(scene.name) << " (§" << escapedForDisplay(scene.section) << ", "
        << escapedForDisplay(scene.title, 200) << "), solver " << solverName(s.solver()) << ", " << *steps << " steps\n";
    Json components = Json::array();
    std::string componentText;
    for (const SceneComponent c : scene.components) {
        const std::string name(sceneComponentName(c));
        components.push(name);
        componentText += (componentText.empty() ? "" : ", ") + name;
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
