// granota-cli spline: the cubic spline of Def 2.3 through function data (x_i, y_i), with
// the end conditions that fix it (natural, clamped, not-a-knot, or as Ex 2.1), each piece
// in powers of x as Ex 2.1 prints them.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"
#include "app/cli/spline_modes.h"

#include "core/curves/splines/cubic_spline.h"
#include "core/exact/exact_cost.h"

#include <sstream>

namespace granota::cli {

namespace {

Expected<CommandOutput> run(const Arguments& args)
{
    const bool parametric = args.flag("parametric"), monotone = args.has("monotone");
    if (parametric && monotone)
        return makeError(ErrorCode::InvalidInput, "give either --parametric or --monotone, not both");
    if (parametric)
        return runParametricSpline(args);
    if (monotone)
        return runMonotoneSpline(args);
    for (const char* option : {"param", "start-tangent", "end-tangent"})
        if (args.has(option))
            return makeError(ErrorCode::InvalidInput, std::string("--") + option + " is an option of --parametric");
    auto points = args.points();
    if (!points)
        return points.error();
    auto endsName = args.choice("ends", {"natural", "clamped", "not-a-knot", "ex-2.1"}, std::string("natural"));
    if (!endsName)
        return endsName.error();
    const SplineEnds ends = *parseSplineEnds(*endsName);
    const bool slopesGiven = args.has("start-slope") || args.has("end-slope");
    if (ends != SplineEnds::Clamped && slopesGiven)
        return makeError(ErrorCode::InvalidInput, "--start-slope and --end-slope are the slopes of --ends clamped");
    if (ends == SplineEnds::Clamped && !(args.has("start-slope") && args.has("end-slope")))
        return makeError(ErrorCode::InvalidInput, "--ends clamped needs both end slopes: --start-slope A --end-slope B");
    auto start = args.rational("start-slope", Rational(0));
    if (!start)
        return start.error();
    auto end = args.rational("end-slope", Rational(0));
    if (!end)
        return end.error();
    const bool exact = args.flag("exact");

    CommandOutput out;
    std::ostringstream txt;
    txt << "Cubic spline (Def 2.3), " << *endsName << " ends; pieces in powers of x:\n";
    out.json.set("ends", *endsName);
    if (exact) {
        long xBits = 0, yBits = std::max(bitLength(*start), bitLength(*end));
        for (const RPoint& p : *points) {
            xBits = std::max(xBits, bitLength(p.x));
            yBits = std::max(yBits, bitLength(p.y));
        }
        const double work = cubicSplineExactWork(static_cast<int>(points->size()) - 1, xBits, yBits);
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange,
                             exactWorkRefusal("cubic spline", work, "the number of points or their digits"));
        auto spline = cubicSpline(*points, SplineEndConditions<Rational>{ends, *start, *end});
        if (!spline)
            return spline.error();
        describePieces(*spline, true, out, txt);
    } else {
        auto doublePoints = finiteDoubles(*points, true);
        if (!doublePoints)
            return doublePoints.error();
        auto a = finiteDouble(*start, "--start-slope " + valueText(*start), true);
        if (!a)
            return a.error();
        auto b = finiteDouble(*end, "--end-slope " + valueText(*end), true);
        if (!b)
            return b.error();
        auto spline = cubicSpline(*doublePoints, SplineEndConditions<double>{ends, *a, *b});
        if (!spline)
            return spline.error().code == ErrorCode::OutOfRange ? tooLargeForDouble("the cubic spline of these points", true)
                                                                : spline.error();
        describePieces(*spline, false, out, txt);
    }
    out.text = txt.str();
    return out;
}

} // namespace

Command splineCommand()
{
    return {"spline",
            "--points P | --points-file F  [--ends natural|clamped|not-a-knot|ex-2.1] [--start-slope A --end-slope B] "
            "[--exact] [--json]  |  --parametric [--ends natural|clamped|not-a-knot|periodic] [--start-tangent x,y "
            "--end-tangent x,y] [--param uniform|chord|centripetal] [--exact] [--json]  |  --monotone "
            "fritsch-carlson|steffen [--json]",
            "the cubic spline of Def 2.3 through (x_i, y_i) with its end conditions, each piece in powers of x (Ex 2.1: "
            "--ends ex-2.1); --parametric: the C² spline through points of the plane (Def 2.1); --monotone: a C¹ "
            "cubic that never overshoots the data",
            {{"points", "points-file", "ends", "start-slope", "end-slope", "param", "start-tangent", "end-tangent", "monotone"},
             {"exact", "json", "parametric"},
             {}},
            &run};
}

} // namespace granota::cli
