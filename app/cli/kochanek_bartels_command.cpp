// granota-cli kochanek-bartels: the Hermite segments of a Kochanek–Bartels (TCB) curve
// (kochanek_bartels.h; Def 2.8's segments with tangents set by tension, continuity and bias)
// in powers of the local s, their Bézier points, samples and each point's two tangents.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/display_text.h"
#include "core/base/input_limits.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/curves/splines/kochanek_bartels.h"
#include "core/exact/exact_cost.h"
#include "core/exact/polynomial_text.h"

#include <algorithm>
#include <sstream>

namespace granota::cli {

namespace {

constexpr int kMaxSamples = 100000;
constexpr int kDefaultSamples = 11; // s = 0, 0.1, …, 1, as catmull-rom

std::string trimmed(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

/// --tcb "T,C,B" or "T,C,B;T,C,B;…" (one triple for all points, or one per point; a
/// trailing ";" tolerated). C and B must lie in [−1, 1] (kochanek_bartels.h says why).
Expected<std::vector<TcbKnot<Rational>>> parseTcb(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream all(text);
    for (std::string item; std::getline(all, item, ';');)
        items.push_back(trimmed(item));
    if (!items.empty() && items.back().empty() && items.size() > 1)
        items.pop_back();
    std::vector<TcbKnot<Rational>> knots;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string where = "--tcb item " + std::to_string(i + 1);
        std::vector<std::string> fields;
        std::stringstream one(items[i]);
        for (std::string field; std::getline(one, field, ',');)
            fields.push_back(trimmed(field));
        if (fields.size() != 3)
            return makeError(ErrorCode::InvalidInput, where + " is " + quotedForDisplay(items[i]) +
                                                          ": write tension, continuity and bias as T,C,B (e.g. 0,1/2,0)");
        Rational values[3];
        const char* names[3] = {"tension T", "continuity C", "bias B"};
        for (std::size_t k = 0; k < 3; ++k) {
            const auto v = parseRational(fields[k]);
            if (!v)
                return makeError(ErrorCode::InvalidInput, where + ": the " + names[k] + " " + quotedForDisplay(fields[k]) +
                                                              " is not a number (integer, decimal or fraction p/q)");
            values[k] = *v;
        }
        for (std::size_t k = 1; k < 3; ++k)
            if (values[k] < -1 || values[k] > 1)
                return makeError(ErrorCode::OutOfRange,
                                 where + ": the " + names[k] + " " + toString(values[k]) + " must lie between -1 and 1");
        knots.push_back({values[0], values[1], values[2]});
    }
    return knots;
}

/// Each segment's cubic Bézier control points b_0..b_3 (hermiteToBezier), segment order.
template <class S> Json bezierJson(const std::vector<HermiteSegment<S>>& segments, bool exact)
{
    Json all = Json::array();
    for (const auto& b : hermiteToBezier(segments)) {
        Json controls = Json::array();
        for (const auto& p : b) {
            if constexpr (std::is_same_v<S, Rational>)
                controls.push(point(p, exact));
            else
                controls.push(point(p));
        }
        all.push(std::move(controls));
    }
    return all;
}

template <class S> Json pointJson(const Vec2<S>& p, bool exact)
{
    if constexpr (std::is_same_v<S, Rational>)
        return point(p, exact);
    else
        return point(p);
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    const auto tcbText = args.value("tcb");
    if (!tcbText)
        return makeError(ErrorCode::InvalidInput,
                         "--tcb T,C,B is required (one triple for all points, or \"T,C,B;T,C,B;…\" one per point)");
    auto tcb = parseTcb(*tcbText);
    if (!tcb)
        return tcb.error();
    if (tcb->size() != 1 && tcb->size() != points->size())
        return makeError(ErrorCode::InvalidInput, "--tcb gives " + std::to_string(tcb->size()) + " triples for " +
                                                      std::to_string(points->size()) +
                                                      " points: give one for all points or one per point");
    auto modeName = args.choice("mode", {"open", "cyclic", "closed"}, std::string("open"));
    if (!modeName)
        return modeName.error();
    auto alpha = args.rational("alpha", Rational(0));
    if (!alpha)
        return alpha.error();
    if (*alpha < 0 || *alpha > 1)
        return makeError(ErrorCode::OutOfRange, "--alpha must be between 0 and 1 (0 uniform, 1/2 centripetal, 1 chordal)");
    auto samples = args.integer("samples", 2, kMaxSamples, kDefaultSamples);
    if (!samples)
        return samples.error();
    const bool exact = args.flag("exact");
    if (exact && *alpha != 0)
        return makeError(ErrorCode::NotRational,
                         "--exact needs --alpha 0: centripetal and chordal knots are powers of distances, not fractions");
    const CatmullRomMode mode = *parseCatmullRomMode(*modeName);
    const bool withSamples = args.flag("json"); // the text form computes no samples
    // Bounded before any work (too few points: the curve below says so).
    if (const auto quads = catmullRomQuadruples(points->size(), mode)) {
        const long segmentCount = static_cast<long>(quads->size());
        if (segmentCount * *samples > kMaxCurveSamples)
            return makeError(ErrorCode::OutOfRange,
                             std::to_string(*samples) + " samples on each of " + std::to_string(segmentCount) + " segments are " +
                                 std::to_string(segmentCount * *samples) + ", more than " + std::to_string(kMaxCurveSamples) +
                                 " in all: lower --samples, or the number of points");
        if (exact) {
            long tcbBits = 0; // a tangent multiplies T, C and B: their bits add up
            for (const auto& k : *tcb)
                tcbBits = std::max(tcbBits, bitLength(k.tension) + bitLength(k.continuity) + bitLength(k.bias));
            const double work = catmullRomExactWork(quads->size(), maxBitLength(*points), tcbBits, withSamples ? *samples : 0);
            if (!exactWorkAllowed(work))
                return makeError(ErrorCode::OutOfRange,
                                 exactWorkRefusal("Kochanek–Bartels curve", work,
                                                  std::string(withSamples ? "--samples, " : "") +
                                                      "the number of points or the digits of their coordinates"));
        }
    }

    CommandOutput out;
    std::ostringstream txt;
    txt << "Kochanek–Bartels curve, " << *modeName << ", T,C,B = ";
    for (std::size_t i = 0; i < tcb->size(); ++i)
        txt << (i ? "; " : "") << toString((*tcb)[i].tension) << "," << toString((*tcb)[i].continuity) << ","
            << toString((*tcb)[i].bias);
    if (*alpha != 0)
        txt << ", α = " << toString(*alpha);
    txt << "; segments in powers of s ∈ [0,1]:\n";

    Json segments = Json::array(), sampleJson = Json::array(), bezier = Json::array(), tangents = Json::array();
    Json knots = Json::array();
    const auto write = [&](const auto& curve) {
        using S = std::decay_t<decltype(curve.segments.front().p0.x)>;
        const auto polys = hermitePolynomials(curve.segments);
        for (std::size_t i = 0; i < polys.size(); ++i) {
            const auto& s = polys[i];
            Json seg = Json::object();
            seg.set("x", cubicCoefficients(s.x, exact)).set("y", cubicCoefficients(s.y, exact));
            segments.push(std::move(seg));
            txt << "  p_" << i + 1 << "(s) = " << toText(s, "s") << "\n";
        }
        if constexpr (std::is_same_v<S, Rational>) {
            for (std::size_t i = 0; withSamples && i < polys.size(); ++i)
                for (int j = 0; j < *samples; ++j) {
                    const Rational u = frac(j, *samples - 1);
                    sampleJson.push(point(RPoint(polys[i].x(u), polys[i].y(u)), exact));
                }
        } else if (withSamples) {
            for (const Point& p : sampleSegments(polys, *samples))
                sampleJson.push(point(p));
        }
        bezier = bezierJson(curve.segments, exact);
        txt << "tangents (in: ending the segment into q_i; out: starting the segment out of q_i):\n";
        for (std::size_t i = 0; i < curve.tangents.size(); ++i) {
            const auto& t = curve.tangents[i];
            Json one = Json::object();
            one.set("in", pointJson(t.in, exact)).set("out", pointJson(t.out, exact));
            tangents.push(std::move(one));
            txt << "  q_" << i << ": in " << text(t.in) << ", out " << text(t.out) << "\n";
        }
        if constexpr (std::is_same_v<S, Rational>) {
            // Each knot's continuity (knot_continuity.h), as catmull-rom --exact names it.
            const auto analysis = knotContinuity(polys, {}, mode == CatmullRomMode::Closed);
            if (!analysis.empty())
                txt << "knots (C^k: derivatives equal up to order k; G^k: tangent direction, curvature):\n";
            for (const auto& k : analysis) {
                const std::size_t at = (static_cast<std::size_t>(k.fromSegment) + 1) % points->size();
                txt << "  q_" << at << ": C^" << k.parametricOrder() << ", G^" << k.geometricOrder() << "\n";
                Json knot = Json::object();
                knot.set("knot", Json(static_cast<int>(at)))
                    .set("C", Json(k.parametricOrder()))
                    .set("G", Json(k.geometricOrder()));
                knots.push(std::move(knot));
            }
        }
    };
    if (exact) {
        const auto curve = kochanekBartels(*points, *tcb, mode);
        if (!curve)
            return curve.error();
        write(*curve);
    } else {
        auto doublePoints = finiteDoubles(*points, *alpha == 0);
        if (!doublePoints)
            return doublePoints.error();
        std::vector<TcbKnot<double>> doubleTcb;
        for (const auto& k : *tcb) {
            auto t = finiteDouble(k.tension, "the tension T " + valueText(k.tension), *alpha == 0);
            if (!t)
                return t.error();
            doubleTcb.push_back({*t, toDouble(k.continuity), toDouble(k.bias)});
        }
        const auto curve = kochanekBartels(*doublePoints, doubleTcb, mode, toDouble(*alpha));
        if (!curve)
            return curve.error().code == ErrorCode::OutOfRange
                       ? tooLargeForDouble("the Kochanek–Bartels curve of these points", *alpha == 0)
                       : curve.error();
        write(*curve);
    }
    txt << "(" << *samples << " samples per segment with --json)\n";
    out.json.set("segments", std::move(segments))
        .set("samples", std::move(sampleJson))
        .set("bezier", std::move(bezier))
        .set("tangents", std::move(tangents));
    if (exact)
        out.json.set("knots", std::move(knots));
    out.text = txt.str();
    return out;
}

} // namespace

Command kochanekBartelsCommand()
{
    return {"kochanek-bartels",
            "--points P | --points-file F  --tcb T,C,B | --tcb \"T,C,B;T,C,B;…\"  [--mode open|cyclic|closed] [--alpha A] "
            "[--samples S] [--exact] [--json]",
            "Kochanek–Bartels (TCB) segments in powers of s, samples and each point's in and out tangents; open by default",
            {{"points", "points-file", "tcb", "mode", "alpha", "samples"}, {"exact", "json"}, {}},
            &run};
}

} // namespace granota::cli
