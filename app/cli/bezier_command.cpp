// granota-cli bezier: De Casteljau's construction (Def 2.4) at one t, every level, and
// the curve in powers of t (Ex 2.2, Ex 2.3).
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/exact/exact_cost.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/polynomial_text.h"

#include <sstream>

namespace granota::cli {

namespace {

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    if (static_cast<int>(points->size()) > kMaxDegree + 1)
        return makeError(ErrorCode::DegreeTooHigh,
                         "at most " + std::to_string(kMaxDegree + 1) + " control points (degree " + std::to_string(kMaxDegree) + ")");
    auto t = args.rational("t", std::nullopt);
    if (!t)
        return t.error();
    const bool exact = args.flag("exact");
    const int n = static_cast<int>(points->size()) - 1;
    if (exact) {
        const double work = deCasteljauExactWork(n, maxBitLength(*points), bitLength(*t));
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange,
                             exactWorkRefusal("De Casteljau triangle", work, "the number of points or the digits of --t and the points"));
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
    out.text = txt.str();
    return out;
}

} // namespace

Command bezierCommand()
{
    return {"bezier", "--points P | --points-file F  --t T  [--exact] [--json]",
            "De Casteljau's construction at t: every level P_i^r(t), c(t), c'(t), c(t) in powers of t",
            {{"points", "points-file", "t"}, {"exact", "json"}, {}}, &run};
}

} // namespace granota::cli
