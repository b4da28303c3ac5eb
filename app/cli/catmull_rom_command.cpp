// granota-cli catmull-rom: the segment polynomials of a Catmull-Rom curve (§2.2,
// Lemma 2.3, Def 2.10; Ex 2.11, Ex 2.13) in powers of the local s, and samples.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/input_limits.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/catmull_rom_analysis.h"
#include "core/exact/exact_cost.h"
#include "core/exact/polynomial_text.h"

#include <sstream>

namespace granota::cli {

namespace {

constexpr int kMaxSamples = 100000;
constexpr int kDefaultSamples = 11; // s = 0, 0.1, …, 1

/// Each segment's cubic Bézier control points b_0..b_3 (bezier_segments.h), segment order.
Json bezierJson(const std::vector<Vec2<Polynomial<Rational>>>& segments)
{
    Json all = Json::array();
    for (const auto& b : bezierSegments(segments)) {
        Json controls = Json::array();
        for (const RPoint& p : b)
            controls.push(point(p, true));
        all.push(std::move(controls));
    }
    return all;
}
Json bezierJson(const std::vector<Vec2<Polynomial<double>>>& segments)
{
    Json all = Json::array();
    for (const auto& b : bezierSegments(segments)) {
        Json controls = Json::array();
        for (const Point& p : b)
            controls.push(point(p));
        all.push(std::move(controls));
    }
    return all;
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    auto tau = args.rational("tau", frac(1, 2));
    if (!tau)
        return tau.error();
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
    // The samples are written only with --json: the text form never computes them.
    const bool withSamples = args.flag("json");
    // Bounded before any work (too few points: the curve below says so).
    if (const auto quads = catmullRomQuadruples(points->size(), mode)) {
        const long segmentCount = static_cast<long>(quads->size());
        if (segmentCount * *samples > kMaxCurveSamples)
            return makeError(ErrorCode::OutOfRange,
                             std::to_string(*samples) + " samples on each of " + std::to_string(segmentCount) + " segments are " +
                                 std::to_string(segmentCount * *samples) + ", more than " + std::to_string(kMaxCurveSamples) +
                                 " in all: lower --samples, or the number of points");
        if (exact) {
            const double work = catmullRomExactWork(quads->size(), maxBitLength(*points), bitLength(*tau),
                                                    withSamples ? *samples : 0);
            if (!exactWorkAllowed(work))
                return makeError(ErrorCode::OutOfRange,
                                 exactWorkRefusal("Catmull-Rom curve", work,
                                                  std::string(withSamples ? "--samples, " : "") +
                                                      "the number of points or the digits of their coordinates"));
        }
    }

    CommandOutput out;
    std::ostringstream txt;
    txt << "Catmull-Rom curve (Def 2.10), " << *modeName << ", τ = " << toString(*tau);
    if (*alpha != 0)
        txt << ", α = " << toString(*alpha);
    txt << "; segments in powers of s ∈ [0,1]:\n";
    Json segments = Json::array(), sampleJson = Json::array(), bezier = Json::array();
    Json knots = Json::array();
    if (exact) {
        // The segments and their knots as the Catmull-Rom tab's side panel shows them (§2.3, Prop 2.3).
        CatmullRomQuestion question;
        question.taus = {*tau};
        question.selectedTau = 0;
        question.ends = mode == CatmullRomMode::Cyclic   ? CatmullRomEnds::Cyclic
                        : mode == CatmullRomMode::Closed ? CatmullRomEnds::Closed
                                                         : CatmullRomEnds::Open;
        const CatmullRomAnalysis analysis = analyseCatmullRom(*points, question);
        const auto& segs = analysis.ends.front().curves.front().segments;
        if (!segs)
            return segs.error();
        for (std::size_t i = 0; i < segs->size(); ++i) {
            const auto& s = (*segs)[i];
            Json seg = Json::object();
            seg.set("x", cubicCoefficients(s.x, true)).set("y", cubicCoefficients(s.y, true));
            segments.push(std::move(seg));
            txt << "  p_" << i + 1 << "(s) = " << toText(s, "s") << "\n";
            for (int j = 0; withSamples && j < *samples; ++j) {
                const Rational u = frac(j, *samples - 1);
                sampleJson.push(point(RPoint(s.x(u), s.y(u)), true));
            }
        }
        bezier = bezierJson(*segs);
        if (!analysis.selectedKnots.empty())
            txt << "knots (C^k: derivatives equal up to order k; G^k: tangent direction, curvature):\n";
        for (const auto& k : analysis.selectedKnots) {
            const std::size_t at = (static_cast<std::size_t>(k.fromSegment) + 1) % points->size();
            const std::string name = "q_" + std::to_string(at);
            txt << "  " << name << ": C^" << k.parametricOrder() << ", G^" << k.geometricOrder() << "\n";
            Json knot = Json::object();
            knot.set("knot", Json(static_cast<int>(at))).set("C", Json(k.parametricOrder())).set("G", Json(k.geometricOrder()));
            knots.push(std::move(knot));
        }
    } else {
        // Exact coordinates beyond the doubles are named here; an overflow while computing
        // is the core's OutOfRange (it checks every coefficient, like fitting does).
        auto doublePoints = finiteDoubles(*points, *alpha == 0);
        if (!doublePoints)
            return doublePoints.error();
        auto doubleTau = finiteDouble(*tau, "--tau " + valueText(*tau), *alpha == 0);
        if (!doubleTau)
            return doubleTau.error();
        auto segs = catmullRomSegments(*doublePoints, *doubleTau, mode, toDouble(*alpha));
        if (!segs)
            return segs.error().code == ErrorCode::OutOfRange
                       ? tooLargeForDouble("the Catmull-Rom curve of these points", *alpha == 0)
                       : segs.error();
        for (std::size_t i = 0; i < segs->size(); ++i) {
            const auto& s = (*segs)[i];
            Json seg = Json::object();
            seg.set("x", cubicCoefficients(s.x, false)).set("y", cubicCoefficients(s.y, false));
            segments.push(std::move(seg));
            txt << "  p_" << i + 1 << "(s) = " << toText(s, "s") << "\n";
        }
        if (withSamples)
            for (const Point& p : sampleSegments(*segs, *samples))
                sampleJson.push(point(p));
        bezier = bezierJson(*segs);
    }
    txt << "(" << *samples << " samples per segment with --json)\n";
    out.json.set("segments", std::move(segments)).set("samples", std::move(sampleJson)).set("bezier", std::move(bezier));
    if (exact)
        out.json.set("knots", std::move(knots));
    out.text = txt.str();
    return out;
}

} // namespace

Command catmullRomCommand()
{
    return {"catmull-rom",
            "--points P | --points-file F  [--tau TAU] [--mode open|cyclic|closed] [--alpha A] [--samples S] [--exact] [--json]",
            "Catmull-Rom segments in powers of s (Lemma 2.3, Def 2.10) and S samples per segment; τ = 1/2 and open by default",
            {{"points", "points-file", "tau", "mode", "alpha", "samples"}, {"exact", "json"}, {}},
            &run};
}

} // namespace granota::cli
