// The cubic Hermite segment (the common form of Def 2.8's segments): on seeded random
// rational data it interpolates its two points with its two tangents exactly, its power form
// and its Bézier form (Def 2.5) are the same cubic as the Hermite basis written out by hand
// below, and each conversion has its inverse.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/hermite_segment.h"
#include "core/exact/rational.h"
#include "tests/rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;

namespace granota {
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
} // namespace granota

namespace {

/// A segment with random rational points and tangents (seeded: the same every run).
HermiteSegment<Rational> randomSegment(std::mt19937& rng)
{
    const std::vector<RPoint> v = testing::randomRational(rng, 3);
    return {v[0], v[1], v[2], v[3]};
}

/// The Hermite basis functions, written out independently of hermite_segment.h's power form:
/// h00 = (1 + 2s)(1 − s)², h10 = s(1 − s)², h01 = s²(3 − 2s), h11 = s²(s − 1).
RPoint byBasis(const HermiteSegment<Rational>& g, const Rational& s)
{
    const Rational one(1), two(2), three(3);
    const Rational u = one - s;
    const Rational h00 = (one + two * s) * u * u, h10 = s * u * u, h01 = s * s * (three - two * s), h11 = s * s * (s - one);
    return RPoint(Rational(h00 * g.p0.x + h10 * g.m0.x + h01 * g.p1.x + h11 * g.m1.x),
                  Rational(h00 * g.p0.y + h10 * g.m0.y + h01 * g.p1.y + h11 * g.m1.y));
}

} // namespace

class TestHermiteSegment : public QObject {
    Q_OBJECT
private slots:
    // p(0) = p0, p(1) = p1, p′(0) = m0, p′(1) = m1: the definition, exactly.
    void interpolatesPointsAndTangents()
    {
        std::mt19937 rng(37);
        for (int trial = 0; trial < 50; ++trial) {
            const auto g = randomSegment(rng);
            QCOMPARE(hermitePoint(g, Rational(0)), g.p0);
            QCOMPARE(hermitePoint(g, Rational(1)), g.p1);
            QCOMPARE(hermiteDerivative(g, Rational(0)), g.m0);
            QCOMPARE(hermiteDerivative(g, Rational(1)), g.m1);
        }
    }

    // The power form against the Hermite basis at rational s inside and outside [0, 1];
    // the second derivative against the difference of the first derivative's coefficients
    // read off the basis: h00″ = 12s − 6, h10″ = 6s − 4, h01″ = 6 − 12s, h11″ = 6s − 2.
    void powerFormIsTheHermiteBasis()
    {
        std::mt19937 rng(2026);
        for (int trial = 0; trial < 30; ++trial) {
            const auto g = randomSegment(rng);
            for (int j = -3; j <= 13; ++j) {
                const Rational s = frac(j, 10);
                QCOMPARE(hermitePoint(g, s), byBasis(g, s));
                const auto poly = hermitePolynomial(g);
                QCOMPARE(RPoint(poly.x(s), poly.y(s)), byBasis(g, s));
                const Rational a = 12 * s - 6, b = 6 * s - 4, c = 6 - 12 * s, d = 6 * s - 2;
                const RPoint second(Rational(a * g.p0.x + b * g.m0.x + c * g.p1.x + d * g.m1.x),
                                    Rational(a * g.p0.y + b * g.m0.y + c * g.p1.y + d * g.m1.y));
                QCOMPARE(hermiteSecondDerivative(g, s), second);
            }
        }
    }

    // Def 2.5's control points trace the same cubic (De Casteljau), agree with the power
    // form's Bézier conversion of bezier_segments.h, and convert back.
    void bezierFormIsTheSameCubic()
    {
        std::mt19937 rng(7);
        for (int trial = 0; trial < 30; ++trial) {
            const auto g = randomSegment(rng);
            const auto b = hermiteToBezier(g);
            QCOMPARE(b[1], g.p0 + RPoint(Rational(g.m0.x / 3), Rational(g.m0.y / 3)));
            QCOMPARE(b[2], g.p1 - RPoint(Rational(g.m1.x / 3), Rational(g.m1.y / 3)));
            const auto viaPower = bezierSegments(std::vector<Vec2<Polynomial<Rational>>>{hermitePolynomial(g)});
            QCOMPARE(viaPower.size(), std::size_t(1));
            for (std::size_t k = 0; k < 4; ++k)
                QCOMPARE(viaPower[0][k], b[k]);
            for (int j = 0; j <= 10; ++j) {
                const Rational s = frac(j, 10);
                QCOMPARE(deCasteljauPoint(std::vector<RPoint>(b.begin(), b.end()), s), byBasis(g, s));
            }
            QVERIFY(hermiteFromBezier(b) == g);
            QVERIFY(hermiteFromCoefficients(hermiteCoefficients(g)) == g);
            QVERIFY(hermiteFromPolynomial(hermitePolynomial(g)) == g);
        }
    }

    // A lower-degree polynomial is a Hermite segment too: the line 1 + 2s has m0 = m1 = 2.
    void lowerDegree()
    {
        const Vec2<Polynomial<Rational>> line(Polynomial<Rational>{Rational(1), Rational(2)}, Polynomial<Rational>(Rational(5)));
        const auto g = hermiteFromPolynomial(line);
        QCOMPARE(g.p0, RPoint(Rational(1), Rational(5)));
        QCOMPARE(g.p1, RPoint(Rational(3), Rational(5)));
        QCOMPARE(g.m0, RPoint(Rational(2), Rational(0)));
        QCOMPARE(g.m1, RPoint(Rational(2), Rational(0)));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestHermiteSegment)
#include "test_hermite_segment.moc"
