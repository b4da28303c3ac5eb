// granota-cli bspline (issue 36, docs/bsplines.md): a B-spline or NURBS curve from its points,
// degree, knots and weights; de Boor's algorithm at u with every level (de_boor.h), knot
// insertion (Boehm) and removal (Tiller), and the Bézier pieces. Exact with --exact; doubles
// otherwise, the input rounded once.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_insertion.h"
#include "core/curves/bsplines/knot_removal.h"
#include "core/curves/bsplines/knot_vector.h"
#include "core/exact/exact_cost.h"

#include <algorithm>
#include <optional>
#include <sstream>
#include <type_traits>

namespace granota::cli {

namespace {

/// What was asked besides the curve, parsed before any computation.
struct Requests {
    std::optional<Rational> u;      ///< --u: de Boor at u
    std::optional<Rational> insert; ///< --insert ū
    std::optional<Rational> remove; ///< --remove ū
    int times = 1;                  ///< --times r (for --insert and --remove)
    double tolerance = 0;           ///< --tolerance (removal in doubles)
    bool toBezier = false;          ///< --to-bezier
    bool exact = false;
};

template <class S> Json num(const S& v)
{
    if constexpr (std::is_same_v<S, Rational>)
        return number(v, true);
    else
        return number(v);
}
template <class S> Json pt(const Vec2<S>& p)
{
    if constexpr (std::is_same_v<S, Rational>)
        return point(p, true);
    else
        return point(p);
}
std::string str(const Rational& v) { return toString(v); }
std::string str(double v) { return formatDouble(v); }

template <class S> Json numbers(const std::vector<S>& v)
{
    Json a = Json::array();
    for (const S& x : v)
        a.push(num(x));
    return a;
}
template <class S> Json pointList(const std::vector<Vec2<S>>& v)
{
    Json a = Json::array();
    for (const Vec2<S>& p : v)
        a.push(pt(p));
    return a;
}
template <class S> std::string numbersText(const std::vector<S>& v)
{
    std::string s;
    for (const S& x : v)
        s += (s.empty() ? "" : ", ") + str(x);
    return s;
}
template <class S> std::string pointsText(const std::vector<Vec2<S>>& v)
{
    std::string s;
    for (const Vec2<S>& p : v)
        s += "  " + text(p);
    return s;
}

/// A parameter of the command as S: itself in Rational, rounded once to a double otherwise.
template <class S> Expected<S> scalar(const Rational& q, const std::string& what)
{
    if constexpr (std::is_same_v<S, Rational>)
        return q;
    else
        return finiteDouble(q, what, true);
}

template <class S> Expected<CommandOutput> compute(BSplineCurve<S> c, const Requests& req)
{
    CommandOutput out;
    std::ostringstream txt;
    if (auto ok = checkBSpline(c); !ok)
        return ok.error();
    txt << (c.rational() ? "NURBS" : "B-spline") << " curve of degree " << c.degree << " with " << c.pointCount()
        << " control points, domain [" << str(c.domainStart()) << ", " << str(c.domainEnd()) << "]\n";
    if (req.insert) {
        auto u = scalar<S>(*req.insert, "--insert");
        if (!u)
            return u.error();
        if (auto ok = checkKnotInsertion(c, *u, req.times); !ok)
            return makeError(ok.error().code, "--insert: " + ok.error().message);
        c = insertKnot(c, *u, req.times);
        txt << "Inserted " << str(*u) << " " << req.times << " time" << (req.times == 1 ? "" : "s") << " (Boehm)\n";
    }
    if (req.remove) {
        auto u = scalar<S>(*req.remove, "--remove");
        if (!u)
            return u.error();
        if (knotMultiplicity(c.knots, *u) == 0 || !(c.domainStart() < *u && *u < c.domainEnd()))
            return makeError(ErrorCode::OutOfRange, "--remove: " + str(*u) + " is not a knot inside the domain (" +
                                                        str(c.domainStart()) + ", " + str(c.domainEnd()) + ")");
        const KnotRemoval<S> r = removeKnot(c, *u, req.times, req.tolerance);
        c = r.curve;
        txt << "Removed " << str(*u) << " " << r.removed << " of " << req.times << " time" << (req.times == 1 ? "" : "s")
            << (r.removed < req.times ? " (the curve needs the rest)" : "") << " (Tiller)";
        if (req.tolerance > 0)
            txt << ", largest error " << formatDouble(r.maxError);
        txt << "\n";
        out.json.set("removed", r.removed);
        if (req.tolerance > 0)
            out.json.set("removal_error", number(r.maxError));
    }
    txt << "knots: " << numbersText(c.knots) << "\n";
    txt << "control points:" << pointsText(c.points) << "\n";
    if (c.rational())
        txt << "weights: " << numbersText(c.weights) << "\n";
    out.json.set("degree", c.degree).set("knots", numbers(c.knots)).set("control_points", pointList(c.points));
    if (c.rational())
        out.json.set("weights", numbers(c.weights));

    if (req.u) {
        auto u = scalar<S>(*req.u, "--u");
        if (!u)
            return u.error();
        if (*u < c.domainStart() || c.domainEnd() < *u)
            return makeError(ErrorCode::OutOfRange, "--u " + str(*u) + " is outside the domain [u_p, u_{n+1}] = [" +
                                                        str(c.domainStart()) + ", " + str(c.domainEnd()) + "]");
        const DeBoorTable<S> table = deBoor(c, *u);
        txt << "de Boor at u = " << str(*u) << ", span k = " << table.span << " (u_k <= u < u_{k+1}):\n";
        Json levels = Json::array();
        for (std::size_t r = 0; r < table.levels.size(); ++r) {
            txt << "  r = " << r << ":" << pointsText(table.levels[r]);
            if (c.rational())
                txt << "  weights " << numbersText(table.weightLevels[r]);
            txt << "\n";
            levels.push(pointList(table.levels[r]));
        }
        txt << "c(u) = " << text(table.point()) << "\n";
        out.json.set("point", pt(table.point())).set("span", table.span).set("levels", std::move(levels));
        if (c.rational()) {
            Json weightLevels = Json::array();
            for (const auto& level : table.weightLevels)
                weightLevels.push(numbers(level));
            out.json.set("weight_levels", std::move(weightLevels));
        }
    }
    if (req.toBezier) {
        Json segments = Json::array(), segmentWeights = Json::array(), intervals = Json::array();
        const auto pieces = toBezierSegments(c);
        txt << "Bezier segments (" << pieces.size() << "):\n";
        for (const auto& s : pieces) {
            segments.push(pointList(s.points));
            Json interval = Json::array();
            interval.push(num(s.start)).push(num(s.end));
            intervals.push(std::move(interval));
            txt << "  [" << str(s.start) << ", " << str(s.end) << "]:" << pointsText(s.points);
            if (c.rational()) {
                segmentWeights.push(numbers(s.weights));
                txt << "  weights " << numbersText(s.weights);
            }
            txt << "\n";
        }
        out.json.set("segments", std::move(segments)).set("segment_intervals", std::move(intervals));
        if (c.rational())
            out.json.set("segment_weights", std::move(segmentWeights));
    }
    out.text = txt.str();
    return out;
}

/// The knots of --knots: "clamped" (the default), "uniform", or a comma list.
Expected<std::vector<Rational>> knotsOption(const Arguments& args, int pointCount, int degree)
{
    const std::string v = args.value("knots").value_or("clamped");
    if (v == "clamped" || v == "uniform") {
        if (pointCount < degree + 1)
            return makeError(ErrorCode::TooFewPoints, "a B-spline of degree " + std::to_string(degree) + " needs at least " +
                                                          std::to_string(degree + 1) + " control points, not " +
                                                          std::to_string(pointCount));
        return presetKnots<Rational>(v == "clamped" ? KnotPreset::Clamped : KnotPreset::Uniform, pointCount, degree);
    }
    return args.rationalList("knots");
}

/// The exact work, estimated as de Boor's p² operations per span touched (every span for
/// --to-bezier, one for --u, p per insertion or removal) on numbers of the input's bits grown
/// by the knots' at each level (as deCasteljauExactWork). --to-bezier is one pass (A5.6, about
/// p²/2 operations per knot) but counted here as p spans per point, a margin for the numbers'
/// growth along the pass: measured with 2-digit fractions, 20 000 cubic points (2.2e8) take 1.0 s,
/// 1500 points of degree 10 (6.7e8) 0.3 s; 20 000 of degree 10 (1.2e10) are refused.
double exactWork(const BSplineCurve<Rational>& c, const Requests& req)
{
    long bits = maxBitLength(c.points);
    for (const Rational& q : c.knots)
        bits = std::max(bits, bitLength(q));
    for (const Rational& q : c.weights)
        bits = std::max(bits, bitLength(q));
    const double perSpan = deCasteljauExactWork(c.degree, bits, 2 * bits);
    double spans = 1 + 2.0 * req.times * c.degree;
    if (req.toBezier)
        spans += static_cast<double>(c.pointCount()) * c.degree;
    return perSpan * spans * (c.rational() ? 3 : 1);
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    auto degree = args.integer("degree", 1, kMaxBSplineDegree, std::nullopt);
    if (!degree)
        return degree.error();
    auto knots = knotsOption(args, static_cast<int>(points->size()), *degree);
    if (!knots)
        return knots.error();
    auto weights = args.rationalList("weights");
    if (!weights)
        return weights.error();
    if (args.has("weights") && weights->empty())
        return makeError(ErrorCode::InvalidInput, "--weights needs one weight per control point");

    Requests req;
    req.exact = args.flag("exact");
    req.toBezier = args.flag("to-bezier");
    for (const char* name : {"u", "insert", "remove"}) {
        if (!args.has(name))
            continue;
        auto q = args.rational(name, std::nullopt);
        if (!q)
            return q.error();
        (std::string(name) == "u" ? req.u : std::string(name) == "insert" ? req.insert : req.remove) = *q;
    }
    if ((args.has("times") || args.has("tolerance")) && !req.insert && !req.remove)
        return makeError(ErrorCode::InvalidInput, "--times and --tolerance go with --insert or --remove");
    if (args.has("tolerance") && !req.remove)
        return makeError(ErrorCode::InvalidInput, "--tolerance goes with --remove");
    auto times = args.integer("times", 1, kMaxBSplineDegree, 1);
    if (!times)
        return times.error();
    req.times = *times;
    auto tolerance = args.rational("tolerance", Rational(0));
    if (!tolerance)
        return tolerance.error();
    if (*tolerance < 0)
        return makeError(ErrorCode::OutOfRange, "--tolerance must be 0 or more, not " + toString(*tolerance));
    if (req.exact && *tolerance != 0)
        return makeError(ErrorCode::InvalidInput, "--exact removes a knot only where the curve stays exactly the same: "
                                                  "leave out --tolerance or --exact");
    auto tol = finiteDouble(*tolerance, "--tolerance", false);
    if (!tol)
        return tol.error();
    req.tolerance = *tol;

    BSplineCurve<Rational> exact;
    exact.degree = *degree;
    exact.points = std::move(*points);
    exact.knots = std::move(*knots);
    exact.weights = std::move(*weights);
    if (auto ok = checkBSpline(exact); !ok)
        return ok.error();
    if (req.exact) {
        const double work = exactWork(exact, req);
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange,
                             exactWorkRefusal("B-spline computation", work, "the number of points or the digits of the input"));
        return compute(std::move(exact), req);
    }
    BSplineCurve<double> c;
    c.degree = exact.degree;
    auto d = finiteDoubles(exact.points, true);
    if (!d)
        return d.error();
    c.points = std::move(*d);
    for (std::size_t i = 0; i < exact.knots.size(); ++i) {
        auto k = finiteDouble(exact.knots[i], "knot u_" + std::to_string(i), true);
        if (!k)
            return k.error();
        c.knots.push_back(*k);
    }
    for (std::size_t i = 0; i < exact.weights.size(); ++i) {
        auto w = finiteDouble(exact.weights[i], "weight w_" + std::to_string(i), true);
        if (!w)
            return w.error();
        c.weights.push_back(*w);
    }
    return compute(std::move(c), req); // checkBSpline again: rounding may have merged knots or zeroed a weight
}

} // namespace

Command bsplineCommand()
{
    return {"bspline",
            "--points P | --points-file F  --degree p  [--knots K|clamped|uniform] [--weights W] [--u U] "
            "[--insert U [--times R]] [--remove U [--times R] [--tolerance E]] [--to-bezier] [--exact] [--json]",
            "a B-spline (NURBS with --weights): de Boor at u with every level, knot insertion (Boehm) and "
            "removal (Tiller), the Bezier segments",
            {{"points", "points-file", "degree", "knots", "weights", "u", "insert", "remove", "times", "tolerance"},
             {"to-bezier", "exact", "json"},
             {}},
            &run};
}

} // namespace granota::cli
