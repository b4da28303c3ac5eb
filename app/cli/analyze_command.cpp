// granota-cli analyze: the differential geometry of a Bézier curve (beyond the thesis):
// hodograph, length, extrema, tight box, inflections, cusps, and at one t the curvature,
// normal and osculating circle; with --length-at the parameter at an arc length.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/hodograph.h"

#include <sstream>

namespace granota::cli {

namespace {

Json list(const std::vector<double>& values)
{
    Json a = Json::array();
    for (double v : values)
        a.push(v);
    return a;
}

std::string listText(const std::vector<double>& values)
{
    if (values.empty())
        return "none";
    std::string s;
    for (double v : values)
        s += (s.empty() ? "" : ", ") + formatDouble(v);
    return s;
}

template <class T, class F> Json orNull(const std::optional<T>& v, F make) { return v ? make(*v) : Json(); }

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = controlPoints(args);
    if (!points)
        return points.error();
    if (points->size() < 2)
        return makeError(ErrorCode::TooFewPoints, "analyze needs at least 2 control points (a curve of degree ≥ 1)");
    auto P = finiteDoubles(*points, false);
    if (!P)
        return P.error();
    std::optional<double> t, s;
    if (args.has("t")) {
        auto q = args.rational("t", std::nullopt);
        if (!q)
            return q.error();
        if (*q < 0 || *q > 1)
            return makeError(ErrorCode::OutOfRange, "--t " + valueText(*q) + " is outside [0, 1]");
        t = toDouble(*q);
    }
    if (args.has("length-at")) {
        auto q = args.rational("length-at", std::nullopt);
        if (!q)
            return q.error();
        auto d = finiteDouble(*q, "--length-at " + valueText(*q), false);
        if (!d)
            return d.error();
        s = *d;
    }

    const int n = static_cast<int>(P->size()) - 1;
    const ArcLengthParametrization arc(*P);
    const double L = arc.total();
    if (s && (*s < 0 || *s > L))
        return makeError(ErrorCode::OutOfRange,
                         "--length-at " + formatDouble(*s) + " is outside [0, L] = [0, " + formatDouble(L) + "]");
    const CurveFeatures f = curveFeatures(*P);
    const std::vector<Point> H = hodograph(*P);

    CommandOutput out;
    Json hodographJson = Json::array();
    for (const Point& h : H)
        hodographJson.push(point(h));
    Json extrema = Json::object();
    extrema.set("x", list(f.extremaX)).set("y", list(f.extremaY));
    Json bbox = Json::array();
    bbox.push(point(f.bbox.minCorner()));
    bbox.push(point(f.bbox.maxCorner()));
    out.json.set("degree", n)
        .set("hodograph", std::move(hodographJson))
        .set("length", L)
        .set("extrema", std::move(extrema))
        .set("bbox", std::move(bbox))
        .set("inflections", list(f.inflections))
        .set("cusps", list(f.cusps));

    std::ostringstream txt;
    txt << "Bézier curve of degree " << n << "\n"
        << "  length L = " << formatDouble(L) << "\n"
        << "  extrema of x at t = " << listText(f.extremaX) << "; of y at t = " << listText(f.extremaY) << "\n"
        << "  bounding box " << text(f.bbox.minCorner()) << " – " << text(f.bbox.maxCorner()) << "\n"
        << "  inflections at t = " << listText(f.inflections) << (f.straight ? " (the curve is straight)" : "") << "\n"
        << "  cusps (c' = 0) at t = " << listText(f.cusps)
        << (f.stationary ? " (every control point is the same point: c' = 0 everywhere)" : "") << "\n";
    if (t) {
        const CurvatureAt c = curvatureAt(*P, *t);
        const auto pointJson = [](const Point& p) { return point(p); };
        const auto numberJson = [](double v) { return Json(v); };
        Json at = Json::object();
        at.set("t", *t)
            .set("point", point(c.point))
            .set("tangent", point(c.tangent))
            .set("normal", orNull(c.normal, pointJson))
            .set("curvature", orNull(c.curvature, numberJson))
            .set("radius", orNull(c.radius, numberJson))
            .set("center", orNull(c.center, pointJson))
            .set("arc_length", arc.lengthAt(*t));
        out.json.set("at", std::move(at));
        txt << "At t = " << formatDouble(*t) << ": c(t) = " << text(c.point) << ", c'(t) = " << text(c.tangent) << "\n"
            << "  curvature = " << (c.curvature ? formatDouble(*c.curvature) : std::string("undefined (c' = 0)"))
            << ", radius = " << (c.radius ? formatDouble(*c.radius) : std::string("none"))
            << ", s(t) = " << formatDouble(arc.lengthAt(*t)) << "\n";
    }
    if (s) {
        const double ts = arc.parameterAt(*s);
        out.json.set("t_at_length", ts);
        txt << "t at arc length " << formatDouble(*s) << " = " << formatDouble(ts) << "\n";
    }
    out.text = txt.str();
    return out;
}

} // namespace

Command analyzeCommand()
{
    return {"analyze",
            "--points P | --points-file F  [--t T] [--length-at S] [--json]",
            "hodograph, arc length, extrema, tight box, inflections, cusps; curvature at T; t at arc length S",
            {{"points", "points-file", "t", "length-at"}, {"json"}, {}},
            &run};
}

} // namespace granota::cli
