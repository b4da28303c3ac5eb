// granota-cli bezier: De Casteljau's construction (Def 2.4) at one t, every level, and
// the curve in powers of t (Ex 2.2, Ex 2.3); with --weights, the rational curve
// (rational_bezier.h); with --reduce, the L²-closest curve of one degree less
// (degree_reduction.h).
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/degree_reduction.h"
#include "core/exact/exact_cost.h"
#include "core/curves/bezier/power_basis.h"
#include "core/curves/bezier/rational_bezier.h"
#include "core/exact/polynomial_text.h"

#include <algorithm>
#include <sstream>
#include <type_traits>

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

/// The levels of a De Casteljau table with weights as JSON and as text lines (projected
/// points, then their weights w_i^r).
template <class S>
void writeRationalLevels(const RationalDeCasteljauTable<S>& table, bool exact, Json& levels, Json& weightLevels,
                         std::ostringstream& txt)
{
    for (std::size_t r = 0; r < table.levels.size(); ++r) {
        Json level = Json::array(), weights = Json::array();
        txt << "  r = " << r << ":";
        for (std::size_t i = 0; i < table.levels[r].size(); ++i) {
            const auto& p = table.levels[r][i];
            const auto& w = table.weights[r][i];
            if constexpr (std::is_same_v<S, Rational>) {
                level.push(point(p, exact));
                weights.push(number(w, exact));
                txt << "  " << text(p) << " w " << toString(w);
            } else {
                level.push(point(p));
                weights.push(number(w));
                txt << "  " << text(p) << " w " << formatDouble(w);
            }
        }
        txt << "\n";
        levels.push(std::move(level));
        weightLevels.push(std::move(weights));
    }
}

/// --weights: the rational Bézier curve (rational_bezier.h), De Casteljau in homogeneous
/// coordinates at t ∈ [0, 1]. The keys of the polynomial curve, "poly" holding the numerator
/// and the denominator of c(t) = (x(t), y(t)) / w(t) in powers of t, and "weights" and
/// "weight_levels" beside them.
Expected<CommandOutput> runRational(const Arguments& args, const std::vector<RPoint>& points)
{
    if (args.flag("reduce"))
        return makeError(ErrorCode::InvalidInput, "--reduce is for polynomial curves: leave out --weights or --reduce");
    auto weights = args.rationalList("weights");
    if (!weights)
        return weights.error();
    if (auto ok = checkRationalBezier(points.size(), *weights); !ok)
        return makeError(ok.error().code, "--weights: " + ok.error().message);
    auto t = args.rational("t", std::nullopt);
    if (!t)
        return t.error();
    if (*t < 0 || *t > 1)
        return makeError(ErrorCode::OutOfRange, "--t " + valueText(*t) +
                                                    " is outside [0, 1]: with --weights the curve is evaluated inside its "
                                                    "interval only (outside it the weights' sum can vanish)");
    const bool exact = args.flag("exact");
    const int n = static_cast<int>(points.size()) - 1;
    if (exact) {
        long weightBits = 0;
        for (const Rational& w : *weights)
            weightBits = std::max(weightBits, bitLength(w));
        const double work = rationalDeCasteljauExactWork(n, maxBitLength(points), weightBits, bitLength(*t));
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange,
                             exactWorkRefusal("De Casteljau triangle with weights", work,
                                              "the number of points or the digits of --t, --weights and the points"));
    }
    // c(t) = p(t)/w(t): p from the homogeneous points w_i P_i, w from the weights alone.
    std::vector<RPoint> homogeneous, weightPoints;
    for (std::size_t i = 0; i < points.size(); ++i) {
        homogeneous.push_back((*weights)[i] * points[i]);
        weightPoints.emplace_back((*weights)[i], Rational(0));
    }
    const Vec2<Polynomial<Rational>> numerator = bezierToPowerBasis(homogeneous);
    const Polynomial<Rational> denominator = bezierToPowerBasis(weightPoints).x;

    CommandOutput out;
    std::ostringstream txt;
    txt << "Rational Bézier curve of degree " << n << " (De Casteljau with weights) at t = " << toString(*t) << "\n";
    Json levels = Json::array(), weightLevels = Json::array(), weightsJson = Json::array();
    Json pointJson, tangentJson;
    std::string pointText, tangentText;
    if (exact) {
        const auto table = rationalDeCasteljau(points, *weights, *t);
        writeRationalLevels(table, true, levels, weightLevels, txt);
        pointJson = point(table.point(), true);
        tangentJson = point(table.tangent(), true);
        pointText = text(table.point());
        tangentText = text(table.tangent());
        for (const Rational& w : *weights)
            weightsJson.push(number(w, true));
    } else {
        auto d = finiteDoubles(points, true);
        if (!d)
            return d.error();
        std::vector<double> w;
        for (std::size_t i = 0; i < weights->size(); ++i) {
            auto wi = finiteDouble((*weights)[i], "weight " + std::to_string(i + 1), true);
            if (!wi)
                return wi.error();
            if (!(*wi > 0))
                return makeError(ErrorCode::OutOfRange, "--weights: weight " + std::to_string(i + 1) +
                                                            " is too small for a double (below 1e-308): use --exact");
            w.push_back(*wi);
            weightsJson.push(number(*wi));
        }
        const auto table = rationalDeCasteljau(*d, w, toDouble(*t));
        writeRationalLevels(table, false, levels, weightLevels, txt);
        pointJson = point(table.point());
        tangentJson = point(table.tangent());
        pointText = text(table.point());
        tangentText = text(table.tangent());
    }
    txt << "c(t)  = P_0^" << n << "(t) = " << pointText << "\n";
    txt << "c'(t) = " << tangentText << "\n";
    const auto polyText = [&](const Polynomial<Rational>& p) {
        if (exact)
            return toText(p);
        std::vector<double> c;
        for (const Rational& q : p.coefficients())
            c.push_back(toDouble(q));
        return toText(Polynomial<double>(std::move(c)));
    };
    txt << "c(t) = (x(t), y(t)) / w(t) in powers of t:\n  x(t) = " << polyText(numerator.x)
        << "\n  y(t) = " << polyText(numerator.y) << "\n  w(t) = " << polyText(denominator) << "\n";

    Json polyJson = Json::object();
    const auto coefficients = [&](const Polynomial<Rational>& p) {
        Json a = Json::array();
        for (const Rational& c : p.coefficients(n))
            a.push(number(c, exact));
        return a;
    };
    polyJson.set("x", coefficients(numerator.x)).set("y", coefficients(numerator.y)).set("w", coefficients(denominator));
    out.json.set("point", std::move(pointJson))
        .set("levels", std::move(levels))
        .set("weight_levels", std::move(weightLevels))
        .set("poly", std::move(polyJson))
        .set("tangent", std::move(tangentJson))
        .set("weights", std::move(weightsJson))
        .set("degree", n);
    out.text = txt.str();
    return out;
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = controlPoints(args);
    if (!points)
        return points.error();
    if (args.has("weights"))
        return runRational(args, *points);
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
            "--points P | --points-file F  --t T  [--weights W] [--reduce] [--exact] [--json]",
            "De Casteljau's construction at t: every level P_i^r(t), c(t), c'(t), c(t) in powers of t; "
            "--weights w0,w1,…: the rational curve (weights > 0, t in [0, 1]); "
            "--reduce: the closest curve of one degree less (--t then optional)",
            {{"points", "points-file", "t", "weights"}, {"exact", "json", "reduce"}, {}},
            &run};
}

} // namespace granota::cli
