// Catmull-Rom and cardinal curves as Hermite segments (issue 37): the Hermite form of every
// τ and mode is, exactly in Rational, the segment computed by Lemma 2.3's matrix M(τ)
// (catmullRomSegments, an independent computation), and its Bézier points those of
// bezier_segments.h's power-to-Bernstein change; the non-uniform curve is its Hermite
// segments' power form bit for bit; a cardinal tension c is τ = (1 − c)/2.
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/cardinal_spline.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/exact/rational.h"
#include "tests/rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cstring>
#include <random>

using namespace granota;

namespace granota {
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
} // namespace granota

Q_DECLARE_METATYPE(granota::CatmullRomMode)

class TestCatmullRomHermite : public QObject {
    Q_OBJECT
private slots:
    void sameCurveExactly_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<QString>("tau");
        for (CatmullRomMode mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (const char* tau : {"0", "1/2", "1", "-1/3", "5/7"})
                QTest::addRow("%s tau=%s", toString(mode).c_str(), tau) << mode << QString(tau);
    }
    void sameCurveExactly()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(QString, tau);
        const Rational t = *parseRational(tau.toStdString());
        std::mt19937 rng(11);
        for (int n : {2, 3, 7}) {
            const auto q = testing::randomRational(rng, n);
            const auto hermite = catmullRomHermiteSegments(q, t, mode);
            const auto lemma23 = catmullRomSegments(q, t, mode);
            QVERIFY(hermite.ok() && lemma23.ok());
            QCOMPARE(hermite->size(), lemma23->size());
            const auto viaHermite = hermitePolynomials(*hermite);
            const auto bezier = bezierSegments(*lemma23);
            for (std::size_t i = 0; i < hermite->size(); ++i) {
                QVERIFY(viaHermite[i].x == (*lemma23)[i].x);
                QVERIFY(viaHermite[i].y == (*lemma23)[i].y);
                const auto b = hermiteToBezier((*hermite)[i]);
                for (std::size_t k = 0; k < 4; ++k)
                    QCOMPARE(b[k], bezier[i][k]);
            }
            // A cardinal tension c is τ = (1 − c)/2.
            const auto cardinal = cardinalHermiteSegments(q, tauToCardinal(t), mode);
            QVERIFY(cardinal.ok());
            QVERIFY(*cardinal == *hermite);
        }
    }

    // The non-uniform curve is hermitePolynomial() of its Hermite segments, bit for bit, and
    // the uniform one in doubles agrees with Lemma 2.3's product to rounding.
    void doublesThroughHermite()
    {
        std::mt19937 rng(3);
        const auto q = toDouble(testing::randomRational(rng, 8));
        for (CatmullRomMode mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (double alpha : {0.0, 0.5, 1.0}) {
                const auto segments = catmullRomSegments(q, 0.4, mode, alpha);
                const auto hermite = catmullRomHermiteSegments(q, 0.4, mode, alpha);
                QVERIFY(segments.ok() && hermite.ok());
                const auto viaHermite = hermitePolynomials(*hermite);
                QCOMPARE(viaHermite.size(), segments->size());
                for (std::size_t i = 0; i < viaHermite.size(); ++i)
                    for (int k = 0; k < 4; ++k) {
                        const double a = viaHermite[i].x.coefficient(k), b = (*segments)[i].x.coefficient(k);
                        const double c = viaHermite[i].y.coefficient(k), d = (*segments)[i].y.coefficient(k);
                        if (alpha != 0.0) {
                            QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
                            QVERIFY(std::memcmp(&c, &d, sizeof c) == 0);
                        } else {
                            QVERIFY(std::abs(a - b) <= 1e-12 * (1 + std::abs(b)));
                            QVERIFY(std::abs(c - d) <= 1e-12 * (1 + std::abs(d)));
                        }
                    }
            }
        QCOMPARE(catmullRomHermiteSegments(q, 0.5, CatmullRomMode::Open, 1.5).error().code, ErrorCode::OutOfRange);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCatmullRomHermite)
#include "test_catmull_rom_hermite.moc"
