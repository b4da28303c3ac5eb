// granota-cli spline --parametric: the C² spline through points of the plane (Def 2.1 in
// full, core/curves/splines/parametric_spline.h), each segment in powers of its local s.
#include "app/cli/finite_doubles.h"
#include "app/cli/spline_modes.h"

#include "core/curves/splines/parametric_spline.h"
#include "core/exact/exact_cost.h"
#include "core/io/point_list.h"

#include <algorithm>
#include <optional>

namespace granota::cli {

namespace {

/// --start-tangent / --end-tangent "x,y": one point of the --points syntax.
Expected<std::optional<RPoint>> tangentOption(const Arguments& args, const std::string& name)
{
    const auto text = args.value(name);
    if (!text)
        return std::optional<RPoint>();
    auto parsed = parsePointList(*text);
    if (!parsed || parsed->size() != 1)
        return makeError(ErrorCode::InvalidInput,
                         "--" + name + " takes one vector \"x,y\"" + (parsed ? std::string() : ": " + parsed.error().message));
    return std::optional<RPoint>(parsed->front());
}

template <class S> void describe(const ParametricSpline<S>& spline, bool exact, CommandOutput& out, std::ostringstream& txt)
{
    Json segments = Json::array();
    for (std::size_t i = 0; i < spline.segments.size(); ++i) {
        const auto& c = spline.segments[i];
        const Polynomial<S> x(std::vector<S>{c[0].x, c[1].x, c[2].x, c[3].x}), y(std::vector<S>{c[0].y, c[1].y, c[2].y, c[3].y});
        Json segment = Json::object();
        segment.set("x", cubicCoefficients(x, exact)).set("y", cubicCoefficients(y, exact));
        segments.push(std::move(segment));
        txt << "  p_" << i + 1 << "(s) = (" << toText(x, "s") << ", " << toText(y, "s") << ")   u ∈ ["
            << knotText(spline.knots[i]) << ", " << knotText(spline.knots[i + 1]) << "]\n";
    }
    Json knots = Json::array();
    for (const S& u : spline.knots)
        knots.push(knotNumber(u, exact));
    out.json.set("segments", std::move(segments)).set("knots", std::move(knots));
}

} // namespace

Expected<CommandOutput> runParametricSpline(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    auto endsName = args.choice("ends", {"natural", "clamped", "not-a-knot", "periodic"}, std::string("natural"));
    if (!endsName)
        return endsName.error();
    const ParametricEnds ends = *parseParametricEnds(*endsName);
    auto paramName = args.choice("param", {"uniform", "chord", "centripetal"}, std::string("uniform"));
    if (!paramName)
        return paramName.error();
    const SplineParameters parameters = *parseSplineParameters(*paramName);
    if (args.has("start-slope") || args.has("end-slope"))
        return makeError(ErrorCode::InvalidInput, "--parametric takes end tangents: --start-tangent x,y --end-tangent x,y");
    const bool tangentsGiven = args.has("start-tangent") || args.has("end-tangent");
    if (ends != ParametricEnds::Clamped && tangentsGiven)
        return makeError(ErrorCode::InvalidInput, "--start-tangent and --end-tangent are the tangents of --ends clamped");
    if (ends == ParametricEnds::Clamped && !(args.has("start-tangent") && args.has("end-tangent")))
        return makeError(ErrorCode::InvalidInput,
                         "--ends clamped needs both end tangents: --start-tangent x,y --end-tangent x,y");
    auto start = tangentOption(args, "start-tangent");
    if (!start)
        return start.error();
    auto end = tangentOption(args, "end-tangent");
    if (!end)
        return end.error();
    const bool exact = args.flag("exact");

    CommandOutput out;
    std::ostringstream txt;
    txt << "C² spline through points of the plane (Def 2.1), " << *endsName << " ends, " << *paramName
        << " parameters; segments in powers of the local s ∈ [0, 1]:\n";
    out.json.set("ends", *endsName).set("param", *paramName);
    if (exact) {
        // Each coordinate is a spline of Def 2.3 on the knots (closed: two banded solves
        // each): four times the function spline's work, a bound of the same shape.
        long bits = 0;
        for (const RPoint& p : *points)
            bits = std::max({bits, bitLength(p.x), bitLength(p.y)});
        for (const auto* t : {&*start, &*end})
            if (t->has_value())
                bits = std::max({bits, bitLength((*t)->x), bitLength((*t)->y)});
        const double work = 4 * cubicSplineExactWork(static_cast<int>(points->size()),
                                                     parameters == SplineParameters::Uniform ? 1 : bits, bits);
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange,
                             exactWorkRefusal("parametric spline", work, "the number of points or their digits"));
        auto spline = parametricSpline(*points, ends, parameters, *start, *end);
        if (!spline)
            return spline.error();
        describe(*spline, true, out, txt);
    } else {
        auto doublePoints = finiteDoubles(*points, true);
        if (!doublePoints)
            return doublePoints.error();
        std::optional<Point> a, b;
        for (auto [from, to, name] : {std::tuple{&*start, &a, "--start-tangent"}, std::tuple{&*end, &b, "--end-tangent"}})
            if (from->has_value()) {
                auto tx = finiteDouble((*from)->x, std::string(name) + " x", true);
                if (!tx)
                    return tx.error();
                auto ty = finiteDouble((*from)->y, std::string(name) + " y", true);
                if (!ty)
                    return ty.error();
                *to = Point(*tx, *ty);
            }
        auto spline = parametricSpline(*doublePoints, ends, parameters, a, b);
        if (!spline)
            return spline.error().code == ErrorCode::OutOfRange ? tooLargeForDouble("the spline of these points", true)
                                                                : spline.error();
        describe(*spline, false, out, txt);
    }
    out.text = txt.str();
    return out;
}

} // namespace granota::cli
