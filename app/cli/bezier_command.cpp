// granota-cli bezier: De Casteljau's construction (Def 2.4) at one t, every level, and
// the curve in powers of t (Ex 2.2, Ex 2.3); with --reduce, the L²-closest curve of one degree
// less (degree_reduction.h).
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/degree_reduction.h"
#include "core/exact/exact_cost.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/polynomial_text.h"

#include <sstream>

namespace granota::cli {

namespace {

/// The largest degree --reduce takes: the exact normal equations grow like n³ in size of
/// numbers, and the double operator loses digits beyond (degree_reduction.h).
constexpr int kMaxReductionDegree = 40;

/// --reduce: "reduced" (n control points) and "reduction_error" (the L² distance), and the
/// same as text.
Expected<void> addReduction(const std::vector<RPoint>& points, bool exact, Json& json, std::ostringstream& txt)
{
    const int n = static_cast<int>(points.size()) - 1;
    if (n < 1)
        return makeError(ErrorCode::TooFewPoints, "--reduce needs at least two control points (degree 0 has nothing to reduce)");
    if (n > kMaxReductionDegree)
        return makeError(ErrorCode::DegreeTooHigh, "--reduce takes at most degree " + std::to_string(kMaxReductionDegree));
    Json reduced = Json::array();
    std::string line;
    double error = 0;
    if (exact) {
        auto r = reduceDegree(points);
        if (!r)
            return r.error();
        for (const RPoint& q : r->points) {
            reduced.push(point(q, true));
            line += "  " + text(q);
        }
        error = r->error;
    } else {
        auto d = finiteDoubles(points, true);
        if (!d)
            return d.error();
        auto r = reduceDegree(*d);
        if (!r)
            return r.error();
        for (const Point& q : r->points) {
            reduced.push(point(q));
            line += "  " + text(q);
        }
        error = r->error;
    }
    txt << "Reduced to degree " << n - 1 << " (closest in L2[0,1]):" << line << "\n";
    txt << "L2 distance: " << formatDouble(error) << "\n";
    json.set("reduced", std::move(reduced)).set("reduction_error", number(error));
    return {};
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = controlPoints(args);
    if (!points)
        return points.error();
    if (args.flag("reduce") && !args.has("t")) {
        // Only the reduction: no De Casteljau construction was asked for.
        CommandOutput out;
        std::ostringstream txt;
        const int n = static_cast<int>(points->size()) - 1;
        txt << "Bézier curve of degree " << n << "\n";
        out.json.set("degree", n);
        auto r = addReduction(*points, args.flag("exact"), out.json, txt);
        if (!r)
            return r.error();
        out.text = txt.str();
        return out;
    }
    auto t = args.rational("t", std::nullopt);
    if (!t)
        return t.error();
    const bool exact = args.flag("exact");
    const int n = static_cast<int>(points->size()) - 1;
    if (exact) {
        const double work = deCasteljauExactWork(n, maxBitLength(*points), bitLength(*t));
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange, exactWorkRefusal("De Casteljau triangle", work,
                                                                     "the number of points or the digits of --t and the points"));
    }

    // The power basis is converted exactly and rounded once, so its coefficients are right
    // to the last digit even where evaluating them in floating point would not be.
    const Vec2<Polynomial<Rational>> poly = bezierToPowerBasis(*points);
    // Without --exact every number is a double, the input's too: checked before computing.
    std::vector<Point> doublePoints;
    double doubleT = 0;
    if (!exact) {
        auto d = finiteDoubles(*points, true);
        if (!d)
            return d.error();
        doublePoints = std::move(*d);
        auto dt = finiteDouble(*t, "--t " + valueText(*t), true);
        if (!dt)
            return dt.error();
        doubleT = *dt;
    }

    CommandOutput out;
    std::ostringstream txt;
    txt << "Bézier curve of degree " << n << " (De Casteljau, Def 2.4) at t = " << toString(*t) << "\n";
    Json levels = Json::array();
    Json pointJson, tangentJson;
    std::string pointText, tangentText;
    if (exact) {
        const auto table = deCasteljau(*points, *t);
        for (int r = 0; r <= n; ++r) {
            Json level = Json::array();
            txt << "  r = " << r << ":";
            for (const auto& p : table.levels[r]) {
                level.push(point(p, true));
                txt << "  " << text(p);
            }
            txt << "\n";
            levels.push(std::move(level));
        }
        pointJson = point(table.point(), true);
        tangentJson = point(table.tangent(), true);
        pointText = text(table.point());
        tangentText = text(table.tangent());
    } else {
        const auto table = deCasteljau(doublePoints, doubleT);
        for (int r = 0; r <= n; ++r) {
            Json level = Json::array();
            txt << "  r = " << r << ":";
            for (const auto& p : table.levels[r]) {
                level.push(point(p));
                txt << "  " << text(p);
            }
            txt << "\n";
            levels.push(std::move(level));
        }
        pointJson = point(table.point());
        tangentJson = point(table.tangent());
        pointText = text(table.point());
        tangentText = text(table.tangent());
    }
    txt << "c(t)  = P_0^" << n << "(t) = " << pointText << "\n";
    txt << "c'(t) = " << tangentText << "\n";
    if (exact) {
        txt << "c(t) in powers of t: " << toText(poly) << "\n";
    } else {
        // Rounded once from the exact coefficients, the numbers --json prints.
        const auto rounded = [](const Polynomial<Rational>& p) {
            std::vector<double> c;
            for (const Rational& q : p.coefficients())
                c.push_back(toDouble(q));
            return Polynomial<double>(std::move(c));
        };
        const Vec2<Polynomial<double>> doublePoly(rounded(poly.x), rounded(poly.y));
        txt << "c(t) in powers of t: " << toText(doublePoly) << "\n";
    }

    Json px = Json::array(), py = Json::array();
    for (const Rational& c : poly.x.coefficients(n))
        px.push(number(c, exact));
    for (const Rational& c : poly.y.coefficients(n))
        py.push(number(c, exact));
    Json polyJson = Json::object();
    polyJson.set("x", std::move(px)).set("y", std::move(py));

    out.json.set("point", std::move(pointJson))
        .set("levels", std::move(levels))
        .set("poly", std::move(polyJson))
        .set("tangent", std::move(tangentJson))
        .set("degree", n);
    if (args.flag("reduce")) {
        auto r = addReduction(*points, exact, out.json, txt);
        if (!r)
            return r.error();
    }
    out.text = txt.str();
    return out;
}

} // namespace

Command bezierCommand()
{
    return {"bezier",
            "--points P | --points-file F  --t T  [--reduce] [--exact] [--json]",
            "De Casteljau's construction at t: every level P_i^r(t), c(t), c'(t), c(t) in powers of t; "
            "--reduce: the closest curve of one degree less (--t then optional)",
            {{"points", "points-file", "t"}, {"exact", "json", "reduce"}, {}},
            &run};
}

} // namespace granota::cli
