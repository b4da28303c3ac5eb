// Ex 2.1's slip: s₂ as printed lacks +1/53. The correction finds exactly that constant, and
// the corrected spline passes the continuity check of Def 2.3; nothing else is "corrected".
#include "core/curves/splines/continuity_check.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/spline_offset_correction.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

namespace {

using RP = Polynomial<Rational>;
Rational q(long n, long d = 1) { return frac(n, d); }

std::vector<RPoint> ex21Points() { return {{q(0), q(1)}, {q(1), q(3)}, {q(2), q(1)}, {q(3), q(-1)}}; }

PiecewisePolynomial<Rational> ex21AsPrinted()
{
    PiecewisePolynomial<Rational> s;
    s.knots = {q(0), q(1), q(2), q(3)};
    s.pieces = {RP{q(1), q(238, 53), q(-132, 53)}, RP{q(0), q(394, 53), q(-288, 53), q(52, 53)},
                RP{q(385, 53), q(-182, 53), q(0), q(4, 53)}};
    return s;
}

} // namespace

class TestSplineOffsetCorrection : public QObject {
    Q_OBJECT
private slots:
    void ex21()
    {
        const auto result = correctConstantOffsets(ex21AsPrinted(), ex21Points());
        QCOMPARE(int(result.corrections.size()), 1);
        QCOMPARE(result.corrections[0].piece, 1);
        QVERIFY(result.corrections[0].offset == q(1, 53));
        QVERIFY(result.corrected.pieces[1] == (RP{q(1, 53), q(394, 53), q(-288, 53), q(52, 53)}));
        QVERIFY(result.corrected.pieces[0] == ex21AsPrinted().pieces[0]);
        QVERIFY(result.corrected.pieces[2] == ex21AsPrinted().pieces[2]);
        const auto report = checkContinuity(result.corrected, 2, ex21Points());
        QVERIFY2(report.ok(), report.describe().c_str());
    }

    void correctSplineIsLeftAlone()
    {
        const auto natural = naturalCubicSpline(ex21Points());
        QVERIFY(natural.ok());
        const auto result = correctConstantOffsets(*natural, ex21Points());
        QVERIFY(result.corrections.empty());
        QVERIFY(result.corrected.pieces == natural->pieces);
    }

    void unequalMissesAreNotAConstant()
    {
        auto s = ex21AsPrinted();
        s.pieces[1] += RP{q(1, 53), q(1, 7)}; // now off by 1/7·x − 1/7, not a constant
        s.pieces[1] -= RP{q(1, 7)};
        const auto result = correctConstantOffsets(s, ex21Points());
        QVERIFY(result.corrections.empty());
    }

    void dataOffTheKnots()
    {
        auto pts = ex21Points();
        pts[1].x = q(3, 2);
        QVERIFY(correctConstantOffsets(ex21AsPrinted(), pts).corrections.empty());
        pts.pop_back();
        QVERIFY(correctConstantOffsets(ex21AsPrinted(), pts).corrections.empty());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestSplineOffsetCorrection)
#include "test_spline_offset_correction.moc"
