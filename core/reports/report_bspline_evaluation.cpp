// docs/work-precision.md, B-spline evaluation at degree p (issue 36): de Boor's algorithm (de_boor.h)
// against the Bézier extraction followed by De Casteljau (Def 2.4) on the segment, and against the
// basis-matrix sum Σ N_{i,p}(u) P_i (Cox–de Boor basis functions times the points), each against
// exact rational de Boor.
#include "core/base/stopwatch.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/bspline_basis.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_vector.h"
#include "core/exact/rational.h"
#include "core/reports/work_precision_reports.h"

#include <algorithm>
#include <cmath>

namespace granota::reports {

namespace {

/// The report's curve of degree p: 3p + 1 control points with small integer coordinates and a
/// clamped knot vector whose interior knots are reproducible multiples of 1/1024 (exact in
/// binary, so the exact reference sees the same knots) at random, so spans of very different
/// lengths, one of them doubled from degree 2 on.
BSplineCurve<double> reportCurve(int degree)
{
    BSplineCurve<double> c;
    c.degree = degree;
    const int count = 3 * degree + 1;
    c.points = reportControlPoints(count, 3600u + static_cast<unsigned>(degree));
    unsigned s = 77u + static_cast<unsigned>(degree);
    std::vector<double> interior;
    const int inner = count - degree - 1; // n − p
    while (static_cast<int>(interior.size()) < inner) {
        s = s * 1664525u + 1013904223u;
        const double knot = (1 + (s >> 8) % 1023) / 1024.0; // in (0, 1)
        if (std::find(interior.begin(), interior.end(), knot) != interior.end())
            continue;
        interior.push_back(knot);
        if (degree >= 2 && interior.size() == 2 && static_cast<int>(interior.size()) < inner)
            interior.push_back(knot); // one knot of multiplicity 2
    }
    std::sort(interior.begin(), interior.end());
    c.knots.assign(static_cast<std::size_t>(degree) + 1, 0.0);
    c.knots.insert(c.knots.end(), interior.begin(), interior.end());
    c.knots.insert(c.knots.end(), static_cast<std::size_t>(degree) + 1, 1.0);
    return c;
}

BSplineCurve<Rational> exactCopy(const BSplineCurve<double>& c)
{
    BSplineCurve<Rational> e;
    e.degree = c.degree;
    e.points = toRational(c.points);
    for (double k : c.knots)
        e.knots.push_back(exactRational(k));
    return e;
}

/// The Bézier segments of `c`, extracted once; evaluating at u finds u's segment (by bisection,
/// as findSpan does) and runs De Casteljau at t = (u − start)/(end − start).
struct ExtractedCurve {
    std::vector<RationalBezierSegment<double>> segments;
    std::vector<double> ends; ///< each segment's end, increasing

    explicit ExtractedCurve(const BSplineCurve<double>& c) : segments(toBezierSegments(c))
    {
        for (const auto& s : segments)
            ends.push_back(s.end);
    }
    Point operator()(double u, std::vector<Point>& work) const
    {
        // The first segment that ends after u; the last one for u at the domain's end.
        const auto j = static_cast<std::size_t>(std::upper_bound(ends.begin(), ends.end() - 1, u) - ends.begin());
        const auto& s = segments[j];
        work.assign(s.points.begin(), s.points.end());
        return deCasteljauInPlace(work, (u - s.start) / (s.end - s.start));
    }
};

/// Σ N_{i,p}(u) P_i over the p + 1 basis functions that are non-zero on u's span.
Point basisSum(const BSplineCurve<double>& c, double u)
{
    const int span = findSpan(c.knots, c.degree, c.pointCount(), u);
    BasisValues<double> N;
    basisFunctionsInto(c.knots, c.degree, span, u, N);
    Point sum(0, 0);
    for (int i = 0; i <= c.degree; ++i) {
        const double n = N[static_cast<std::size_t>(i)];
        const Point& p = c.points[static_cast<std::size_t>(span - c.degree + i)];
        sum += Point(n * p.x, n * p.y);
    }
    return sum;
}

} // namespace

Expected<WorkPrecisionReport> bsplineEvaluation(const WorkPrecisionOptions& options)
{
    WorkPrecisionReport r;
    r.name = "bspline-evaluation";
    r.title = "Evaluating a B-spline curve of degree p";
    r.knob = "degree";
    r.error = "max |c(u) - exact| / max |P_i| over 129 values of u";
    r.reference = "exact rational de Boor (GMP)";
    r.lesson = "de Boor's algorithm, the Bézier segments with De Casteljau and the basis functions times the "
               "points all stay at rounding level at every degree: each is a chain of convex combinations. "
               "The Bézier segments, extracted once, are the quickest per point (one ratio t instead of "
               "p(p + 1)/2 ratios of knots) but carry the rounding of their extraction, up to a few times "
               "de Boor's error; the basis sum is the slowest.";
    const Progress progress(options);
    const int maxDegree = kMaxBSplineDegree;
    constexpr int kValues = 129; // u = j/128: exact in binary, so the reference sees the same u
    WorkPrecisionSeries deBoorSeries{"de Boor", {}}, extraction{"Bézier extraction + De Casteljau", {}},
        basis{"basis functions × points", {}};
    double sink = 0;
    for (int p = 1; p <= maxDegree; ++p) {
        const BSplineCurve<double> curve = reportCurve(p);
        const BSplineCurve<Rational> exact = exactCopy(curve);
        const ExtractedCurve bezier(curve);
        double scale = 0;
        for (const Point& q : curve.points)
            scale = std::max(scale, norm(q));
        std::vector<Point> work;
        double eDeBoor = 0, eExtraction = 0, eBasis = 0;
        for (int j = 0; j < kValues; ++j) {
            const double u = j / double(kValues - 1);
            const RPoint e = bsplinePoint(exact, exactRational(u));
            const Point ref(toDouble(e.x), toDouble(e.y));
            eDeBoor = std::max(eDeBoor, distance(bsplinePoint(curve, u), ref));
            eExtraction = std::max(eExtraction, distance(bezier(u, work), ref));
            eBasis = std::max(eBasis, distance(basisSum(curve, u), ref));
        }
        auto timeOf = [&](auto&& evaluate) {
            return secondsPerCall(
                       [&] {
                           double acc = 0;
                           for (int j = 0; j < kValues; ++j)
                               acc += evaluate(j / double(kValues - 1)).x;
                           return acc;
                       },
                       options.minSecondsPerPoint, &sink) /
                   kValues;
        };
        const double tDeBoor = timeOf([&](double u) { return bsplinePoint(curve, u); });
        const double tExtraction = timeOf([&](double u) { return bezier(u, work); });
        const double tBasis = timeOf([&](double u) { return basisSum(curve, u); });
        deBoorSeries.samples.push_back({double(p), std::max(eDeBoor / scale, kErrorFloor), tDeBoor});
        extraction.samples.push_back({double(p), std::max(eExtraction / scale, kErrorFloor), tExtraction});
        basis.samples.push_back({double(p), std::max(eBasis / scale, kErrorFloor), tBasis});
        if (!progress.tick(p, maxDegree))
            return cancelled();
    }
    r.series = {std::move(deBoorSeries), std::move(extraction), std::move(basis)};
    return r;
}

} // namespace granota::reports
