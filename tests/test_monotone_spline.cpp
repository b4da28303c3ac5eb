// Monotone cubic interpolation (monotone_spline.h): Fritsch–Carlson and Steffen on the
// d3-shape #38 data, against the natural spline of Def 2.3 that overshoots them. How the
// expected values were found, independently of this code:
//  - Steffen's slopes on the d3 data: eq. 11 and 26–27 evaluated in exact fractions by hand
//    (Python's fractions.Fraction as the calculator): 0, −12/25, 0, 0, 0, 64687/63288, 44177/63288;
//  - the natural spline's dip: scipy 1.10 CubicSpline(bc_type='natural') on the same data
//    has its minimum on [107, 502] at x ≈ 182.066, value ≈ 81.750, so 98.25 below 180 =
//    min(y(107), y(502)) (sampled at 4·10⁶ points there); here it is found from the roots of
//    the piece's derivative instead;
//  - bounds and monotonicity are properties: the exact Bernstein proof and, separately, the
//    extrema of each piece in doubles from its derivative's roots.
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/monotone_spline.h"

#include <QtTest>
#include "tests/test_main.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace granota;

Q_DECLARE_METATYPE(granota::MonotoneMethod)

namespace {

const std::vector<Point> kD3Issue38{{0, 224}, {100, 200}, {107, 180}, {502, 300}, {580, 120}, {607, 148}, {900, 400}};

/// The smallest and largest value of a cubic piece p(u) = a + b u + c u² + d u³ on [0, h]:
/// its ends and the real roots of p′ = b + 2c u + 3d u² inside.
std::pair<double, double> pieceRange(const Polynomial<double>& p, double h)
{
    std::vector<double> candidates{0.0, h};
    const double b = p.coefficient(1), c = p.coefficient(2), d = p.coefficient(3);
    if (d != 0) {
        const double disc = 4 * c * c - 12 * b * d;
        if (disc >= 0) {
            const double r = std::sqrt(disc);
            candidates.push_back((-2 * c + r) / (6 * d));
            candidates.push_back((-2 * c - r) / (6 * d));
        }
    } else if (c != 0) {
        candidates.push_back(-b / (2 * c));
    }
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (double u : candidates)
        if (u >= 0 && u <= h) {
            low = std::min(low, p(u));
            high = std::max(high, p(u));
        }
    return {low, high};
}

} // namespace

class TestMonotoneSpline : public QObject {
    Q_OBJECT

private slots:
    void methods_data()
    {
        QTest::addColumn<MonotoneMethod>("method");
        QTest::addRow("fritsch-carlson") << MonotoneMethod::FritschCarlson;
        QTest::addRow("steffen") << MonotoneMethod::Steffen;
    }

    void staysWithinNeighbouringDataValues_data() { methods_data(); }
    void staysWithinNeighbouringDataValues()
    {
        QFETCH(MonotoneMethod, method);
        const auto slopes = monotoneSlopes(kD3Issue38, method);
        QVERIFY(slopes.ok());
        const auto proofs = proveMonotone(kD3Issue38, *slopes);
        QCOMPARE(proofs.size(), kD3Issue38.size() - 1);
        for (std::size_t i = 0; i < proofs.size(); ++i) {
            const bool rising = kD3Issue38[i + 1].y > kD3Issue38[i].y;
            // Exactly, from the Bernstein coefficients: monotone in the data's direction, and
            // every coefficient between the two data values (so the piece is, by the hull).
            QCOMPARE(proofs[i].verdict, rising ? PieceMonotonicity::Increasing : PieceMonotonicity::Decreasing);
            QVERIFY(proofs[i].withinData);
        }
        // And by the extrema of the pieces in doubles.
        const auto s = monotoneSpline(kD3Issue38, method);
        QVERIFY(s.ok());
        for (int i = 0; i < s->pieceCount(); ++i) {
            const auto k = static_cast<std::size_t>(i);
            const auto [low, high] = pieceRange(s->pieces[k], kD3Issue38[k + 1].x - kD3Issue38[k].x);
            const double y0 = kD3Issue38[k].y, y1 = kD3Issue38[k + 1].y;
            QVERIFY2(low >= std::min(y0, y1) - 1e-9 && high <= std::max(y0, y1) + 1e-9, qPrintable(QString("piece %1").arg(i)));
        }
    }

    void naturalSplineDipsAbout98BelowTheData()
    {
        const auto natural = naturalCubicSpline(kD3Issue38);
        QVERIFY(natural.ok());
        // Piece 2 lives on [107, 502]; its minimum from the roots of its derivative.
        const auto [low, high] = pieceRange(natural->localPiece(2), 502.0 - 107.0);
        Q_UNUSED(high);
        const double dip = std::min(180.0, 300.0) - low;
        QVERIFY2(std::abs(dip - 98.25) < 1, qPrintable(QString::number(dip)));
        // Below every data value, too: the data's minimum is 120.
        QVERIFY(low < 120 - 38);
        // The exact proof finds the piece not monotone (it falls, then rises).
        const auto proofs = proveMonotone(kD3Issue38, [&] {
            std::vector<double> m;
            for (int i = 0; i < natural->pieceCount(); ++i)
                m.push_back(natural->localPiece(i).coefficient(1));
            m.push_back(natural->derivative()(900.0));
            return m;
        }());
        QCOMPARE(proofs[2].verdict, PieceMonotonicity::NotMonotone);
        QVERIFY(!proofs[2].withinData);
    }

    void steffenSlopesByHand()
    {
        const auto m = monotoneSlopes(kD3Issue38, MonotoneMethod::Steffen);
        QVERIFY(m.ok());
        const std::vector<double> expected{0, -12.0 / 25, 0, 0, 0, 64687.0 / 63288, 44177.0 / 63288};
        QCOMPARE(m->size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            QVERIFY2(std::abs((*m)[i] - expected[i]) <= 1e-15, qPrintable(QString("m_%1").arg(i)));
    }

    void fritschCarlsonSlopesKeepToTheCircle()
    {
        // The rule: 0 at extrema of the data, the data's sign elsewhere, and α² + β² ≤ 9.
        const std::vector<Point> data{{0, 0}, {1, 0.1}, {2, 5}, {3, 5.2}, {4, 9}, {6, 1}};
        const auto m = monotoneSlopes(data, MonotoneMethod::FritschCarlson);
        QVERIFY(m.ok());
        QCOMPARE((*m)[4], 0.0); // the maximum at x = 4
        for (std::size_t i = 0; i + 1 < data.size(); ++i) {
            const double delta = (data[i + 1].y - data[i].y) / (data[i + 1].x - data[i].x);
            const double alpha = (*m)[i] / delta, beta = (*m)[i + 1] / delta;
            QVERIFY(alpha >= 0 && beta >= 0);
            QVERIFY(alpha * alpha + beta * beta <= 9);
        }
        const auto proofs = proveMonotone(data, *m);
        for (const auto& p : proofs)
            QVERIFY(p.verdict != PieceMonotonicity::NotMonotone && p.withinData);
    }

    void interpolatesAndIsC1_data() { methods_data(); }
    void interpolatesAndIsC1()
    {
        QFETCH(MonotoneMethod, method);
        const auto s = monotoneSpline(kD3Issue38, method);
        const auto m = monotoneSlopes(kD3Issue38, method);
        QVERIFY(s.ok() && m.ok());
        for (int i = 0; i < s->pieceCount(); ++i) {
            const auto k = static_cast<std::size_t>(i);
            const double h = kD3Issue38[k + 1].x - kD3Issue38[k].x;
            const auto& p = s->pieces[k];
            const auto dp = p.derivative();
            QCOMPARE(p(0.0), kD3Issue38[k].y);
            QVERIFY(std::abs(p(h) - kD3Issue38[k + 1].y) < 1e-9);
            // p′ at both ends is the rule's slope: the neighbouring pieces share it (C¹).
            QVERIFY(std::abs(dp(0.0) - (*m)[k]) < 1e-12);
            QVERIFY(std::abs(dp(h) - (*m)[k + 1]) < 1e-9);
        }
    }

    void flatDataStayFlat_data() { methods_data(); }
    void flatDataStayFlat()
    {
        // A flat step between rises: Δ = 0 forces both slopes to 0, the piece is constant.
        QFETCH(MonotoneMethod, method);
        const std::vector<Point> data{{0, 0}, {1, 2}, {2, 2}, {4, 3}};
        const auto m = monotoneSlopes(data, method);
        QVERIFY(m.ok());
        QCOMPARE((*m)[1], 0.0);
        QCOMPARE((*m)[2], 0.0);
        QCOMPARE(proveMonotone(data, *m)[1].verdict, PieceMonotonicity::Constant);
    }

    void proofOfAHermitePiece()
    {
        // y from 0 to 1 on [0, 1]: slopes (3, 3) give b = (0, 1, 0, 1), d = (3, −3, 3):
        // d_1² = 9 ≤ d_0 d_2 = 9, monotone (the derivative touches 0 at s = 1/2), but b_1 = 1
        // and b_2 = 0 still lie within [0, 1].
        const auto edge = proveMonotonePiece(0, 1, 3, 3, 1);
        QCOMPARE(edge.verdict, PieceMonotonicity::Increasing);
        QVERIFY(!edge.byControlPolygon);
        QVERIFY(edge.withinData);
        // Slopes (4, 4): d = (4, −5, 4), 25 > 16: the cubic 4s − 6s² + 4s³... falls in between.
        QCOMPARE(proveMonotonePiece(0, 1, 4, 4, 1).verdict, PieceMonotonicity::NotMonotone);
        // Slopes (1, 1): the line, by the control polygon.
        const auto line = proveMonotonePiece(0, 1, 1, 1, 1);
        QVERIFY(line.byControlPolygon);
        QCOMPARE(line.verdict, PieceMonotonicity::Increasing);
        QCOMPARE(proveMonotonePiece(5, 2, -3, -1, 2).verdict, PieceMonotonicity::Decreasing);
    }

    void refusals()
    {
        for (MonotoneMethod method : {MonotoneMethod::FritschCarlson, MonotoneMethod::Steffen}) {
            QCOMPARE(monotoneSpline({{0, 0}}, method).error().code, ErrorCode::TooFewPoints);
            QCOMPARE(monotoneSpline({{0, 0}, {1, 1}, {1, 2}}, method).error().code, ErrorCode::NotIncreasing);
            QCOMPARE(monotoneSpline({{0, 0}, {2, 1}, {1, 2}}, method).error().code, ErrorCode::NotIncreasing);
            const double nan = std::numeric_limits<double>::quiet_NaN();
            QCOMPARE(monotoneSpline({{0, 0}, {1, nan}}, method).error().code, ErrorCode::InvalidInput);
            QCOMPARE(monotoneSpline({{0, -1e308}, {1e-300, 1e308}}, method).error().code, ErrorCode::OutOfRange);
            // Two points: the line.
            const auto line = monotoneSpline({{1, 1}, {3, 5}}, method);
            QVERIFY(line.ok());
            QCOMPARE(line->pieces[0].degree(), 1);
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestMonotoneSpline)
#include "test_monotone_spline.moc"
