// The exact side of a Catmull-Rom comparison, computed once (catmull_rom_analysis.h).
// Expected values come from the definitions, not from the code under test: Prop 2.3 (every
// uniform Catmull-Rom curve is C¹ at its knots), Def 2.3 (a cubic spline is C² at its knots),
// the clamped ends' slopes read off the first and last Bézier control points (b1 − b0 =
// h·s′(x0)/3 for the graph (x, s(x))), the symmetric three-point spline solved by hand, and
// Ex 2.13's segment count (Def 2.10: n segments for the open or cyclic curve through q_0 … q_n).
#include "core/curves/splines/catmull_rom_analysis.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

namespace {

RPoint rpt(long x, long y) { return RPoint(Rational(x), Rational(y)); }
std::vector<RPoint> ex213() { return {rpt(3, 5), rpt(2, 2), rpt(6, 0), rpt(8, 3), rpt(7, 5)}; }

} // namespace

class TestCatmullRomAnalysis : public QObject {
    Q_OBJECT
private slots:
    // Ex 2.13: τ = 1/2 and 2 in the cyclic ends, compared with the open ones; the selected
    // curve's knots are C¹ (Prop 2.3), its Bézier segments one per segment.
    void everyTauInBothEndsAndTheSelectedKnots()
    {
        CatmullRomQuestion q;
        q.taus = {frac(1, 2), Rational(2)};
        q.selectedTau = 1;
        q.ends = CatmullRomEnds::Cyclic;
        q.compareEnds = true;
        const CatmullRomAnalysis a = analyseCatmullRom(ex213(), q);
        QVERIFY(a.exactCurves);
        QCOMPARE(int(a.ends.size()), 2);
        QVERIFY(a.ends[0].ends == CatmullRomEnds::Cyclic);
        QVERIFY(a.ends[1].ends == CatmullRomEnds::Open);
        for (const auto& e : a.ends) {
            QCOMPARE(int(e.curves.size()), 2);
            for (const auto& c : e.curves) {
                QVERIFY(c.segments.ok());
                QCOMPARE(int(c.segments->size()), 4); // Def 2.10: n segments through q_0 … q_n, cyclic or open
            }
        }
        QVERIFY(a.ends[0].curves[1].tau == Rational(2));
        QCOMPARE(int(a.selectedBezier.size()), 4);
        QCOMPARE(int(a.selectedKnots.size()), 3); // the joins of four segments, not closed
        for (const auto& k : a.selectedKnots)
            QVERIFY(k.parametricOrder() >= 1); // Prop 2.3
        QVERIFY(a.selectedOrder() >= 1);
        // The Bézier points interpolate: b0 of segment i is p_i(0) (Def 2.8: p(0) = p_1).
        const auto& segs = *a.ends[0].curves[1].segments;
        for (std::size_t i = 0; i < segs.size(); ++i) {
            QVERIFY(a.selectedBezier[i][0].x == segs[i].x(Rational(0)));
            QVERIFY(a.selectedBezier[i][3].y == segs[i].y(Rational(1)));
        }
    }

    // Not uniform: no exact Catmull-Rom side; without fractions: nothing at all.
    void nothingExactWithoutUniformSpacingOrFractions()
    {
        CatmullRomQuestion q;
        q.taus = {frac(1, 2)};
        q.selectedTau = 0;
        q.uniform = false;
        q.spline = true;
        const CatmullRomAnalysis a = analyseCatmullRom(ex213(), q);
        QVERIFY(!a.exactCurves);
        QVERIFY(a.ends.empty());
        QVERIFY(a.selectedKnots.empty());
        QCOMPARE(a.selectedOrder(), -1);
        // The spline depends on no spacing: it is solved, and refused, as Ex 2.13's abscissae
        // 3, 2, 6, 8, 7 do not increase (Def 2.3 needs a function of x).
        QVERIFY(a.spline.has_value() && !a.spline->ok());
        QVERIFY(a.spline->error().code == ErrorCode::NotIncreasing);
        const CatmullRomAnalysis none = analyseCatmullRom(std::nullopt, q);
        QVERIFY(!none.spline.has_value() && none.ends.empty());
    }

    // The spline is solved with the ends asked. Points (0,0), (1,1), (2,0), symmetric about
    // x = 1, so s′(1) = 0 with either ends. Clamped with s′(0) = 0: on [0, 1] the Hermite
    // cubic 3x² − 2x³, whose graph has b1 = (1/3, 0). Natural (s″(0) = 0): s = 3x/2 − x³/2,
    // b1 = (1/3, 1/2). Both are C² at x = 1 (Def 2.3).
    void theSplineHasTheEndsAsked()
    {
        CatmullRomQuestion q;
        q.taus = {frac(1, 2)};
        q.selectedTau = 0;
        q.spline = true;
        const std::vector<RPoint> pts{rpt(0, 0), rpt(1, 1), rpt(2, 0)};
        q.splineEnds = SplineEndConditions<Rational>{SplineEnds::Clamped, Rational(0), Rational(0)};
        const CatmullRomAnalysis clamped = analyseCatmullRom(pts, q);
        QVERIFY(clamped.spline && clamped.spline->ok());
        QCOMPARE(int(clamped.splineBezier.size()), 2);
        QVERIFY(clamped.splineBezier[0][1] == RPoint(frac(1, 3), Rational(0)));
        QVERIFY(clamped.splineBezier[0][2] == RPoint(frac(2, 3), Rational(1)));
        q.splineEnds = SplineEndConditions<Rational>{SplineEnds::Natural, Rational(0), Rational(0)};
        const CatmullRomAnalysis natural = analyseCatmullRom(pts, q);
        QVERIFY(natural.spline && natural.spline->ok());
        QVERIFY(natural.splineBezier[0][1] == RPoint(frac(1, 3), frac(1, 2)));
        for (const CatmullRomAnalysis* a : {&clamped, &natural}) {
            QCOMPARE(int(a->splineKnots.size()), 1);
            QCOMPARE(a->splineKnots[0].parametricOrder(), 2);
            QVERIFY(a->splineCheck.interpolates());
            QCOMPARE(a->splineCheck.continuityOrder(), 2); // C², and not C³ (s‴ jumps)
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestCatmullRomAnalysis)
#include "test_catmull_rom_analysis.moc"
