// The C² cubic spline of Def 2.3 (natural ends) and the continuity check that exposes the
// slip in Ex 2.1. Expected coefficients were computed by hand (and re-checked with a
// dense Gaussian elimination in exact fractions, not with this code).
#include "core/curves/splines/continuity_check.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>

using namespace granota;

// Readable QCOMPARE failures for exact values (found by argument-dependent lookup).
static char* toString(const Rational& q) { return qstrdup(granota::toString(q).c_str()); }
namespace granota {
static char* toString(const Polynomial<Rational>& p) { return qstrdup(toText(p, "x").c_str()); }
} // namespace granota

namespace {

using RP = Polynomial<Rational>;

Rational q(long n, long d = 1)
{
    Rational v(n, d);
    v.canonicalize();
    return v;
}

/// "1 46/15 0 -16/15" → {1, 46/15, 0, −16/15}.
std::vector<Rational> values(const QString& text)
{
    std::vector<Rational> c;
    for (const QString& part : text.split(' ', Qt::SkipEmptyParts)) {
        const auto v = parseRational(part.toStdString());
        if (!v)
            qFatal("bad number in test data: %s", qPrintable(part));
        c.push_back(*v);
    }
    return c;
}
/// Ascending coefficients: "1 46/15 0 -16/15" → 1 + 46/15 x − 16/15 x³.
RP poly(const QString& text) { return RP(values(text)); }

std::vector<RPoint> ex21Points() { return {{q(0), q(1)}, {q(1), q(3)}, {q(2), q(1)}, {q(3), q(-1)}}; }

/// Ex 2.1 exactly as printed: s₂ has no constant term.
PiecewisePolynomial<Rational> ex21AsPrinted()
{
    PiecewisePolynomial<Rational> s;
    s.knots = {q(0), q(1), q(2), q(3)};
    s.pieces = {RP{q(1), q(238, 53), q(-132, 53)},            // s₁ = −132/53 x² + 238/53 x + 1
                RP{q(0), q(394, 53), q(-288, 53), q(52, 53)}, // s₂ = 52/53 x³ − 288/53 x² + 394/53 x
                RP{q(385, 53), q(-182, 53), q(0), q(4, 53)}}; // s₃ = 4/53 x³ − 182/53 x + 385/53
    return s;
}

std::vector<const ContinuityDefect<Rational>*> ofKind(const ContinuityReport<Rational>& r, DefectKind kind)
{
    std::vector<const ContinuityDefect<Rational>*> out;
    for (const auto& d : r.defects)
        if (d.kind == kind)
            out.push_back(&d);
    return out;
}

} // namespace

class TestCubicSpline : public QObject {
    Q_OBJECT
private slots:
    // Natural spline, exact, against coefficients computed by hand: M_i = s″(x_i) solve
    // h_{i−1}M_{i−1} + 2(h_{i−1}+h_i)M_i + h_iM_{i+1} = 6(Δ_i − Δ_{i−1}), M_0 = M_k = 0.
    // Ex 2.1's points: 4M_1 + M_2 = −24, M_1 + 4M_2 = 0, so M_1 = −32/5, M_2 = 8/5.
    void naturalExact_data()
    {
        QTest::addColumn<QString>("xs");
        QTest::addColumn<QString>("ys");
        QTest::addColumn<QStringList>("pieces"); // global powers of x, ascending
        QTest::newRow("Ex 2.1 points") << "0 1 2 3"
                                       << "1 3 1 -1"
                                       << QStringList{"1 46/15 0 -16/15", "-7/5 154/15 -36/5 4/3", "57/5 -134/15 12/5 -4/15"};
        // h = 1, 2: 6M_1 = 6(−1/2 − 1), M_1 = −3/2.
        QTest::newRow("uneven spacing") << "0 1 3"
                                        << "0 1 0" << QStringList{"0 5/4 0 -1/4", "-3/8 19/8 -9/8 1/8"};
        QTest::newRow("two points: the line") << "-1 3"
                                              << "2 4" << QStringList{"5/2 1/2"};
        QTest::newRow("collinear: the line") << "0 1/2 2 3"
                                             << "1 2 5 7" << QStringList{"1 2", "1 2", "1 2"};
    }
    void naturalExact()
    {
        QFETCH(QString, xs);
        QFETCH(QString, ys);
        QFETCH(QStringList, pieces);
        const std::vector<Rational> x = values(xs), y = values(ys);
        std::vector<RPoint> points;
        for (std::size_t i = 0; i < x.size(); ++i)
            points.push_back({x[i], y[i]});

        const auto spline = naturalCubicSpline(points);
        QVERIFY(spline.ok());
        QVERIFY(spline->isValid());
        QVERIFY(!spline->localOrigin); // Ex 2.1's form: powers of the global x
        QCOMPARE(spline->pieceCount(), pieces.size());
        for (int k = 0; k < pieces.size(); ++k) {
            QCOMPARE(spline->pieces[static_cast<std::size_t>(k)], poly(pieces[k]));
            QCOMPARE(spline->knots[static_cast<std::size_t>(k)], points[static_cast<std::size_t>(k)].x);
        }

        // Def 2.3: interpolates and is C² — and natural: s″ = 0 at both ends.
        const auto report = checkContinuity(*spline, 2, points);
        QVERIFY2(report.ok(), report.describe().c_str());
        QCOMPARE(report.continuityOrder(), 2);
        const auto second = spline->derivative().derivative();
        QCOMPARE(second(points.front().x), Rational(0));
        QCOMPARE(second(points.back().x), Rational(0));
    }

    void notC3()
    {
        // A cubic spline is C², not C³ in general: s‴ jumps (−16/15·6 → 4/3·6 at x = 1).
        const auto spline = naturalCubicSpline(ex21Points());
        QVERIFY(spline.ok());
        const auto report = checkContinuity(*spline, 3, ex21Points());
        QCOMPARE(report.continuityOrder(), 2);
        QCOMPARE(static_cast<int>(report.defects.size()), 2);
        QCOMPARE(report.defects[0].order, 3);
        QCOMPARE(report.defects[0].left, q(-32, 5));
        QCOMPARE(report.defects[0].right, q(8));
    }

    void doublesMatchExact()
    {
        const auto exact = naturalCubicSpline(ex21Points());
        const std::vector<Point> points = toDouble(ex21Points());
        const auto fast = naturalCubicSpline(points);
        QVERIFY(exact.ok() && fast.ok());
        QVERIFY(fast->localOrigin); // numerically sound form for doubles
        for (int j = 0; j <= 60; ++j) {
            const double x = j / 20.0;
            QVERIFY(std::fabs((*fast)(x) - (*exact)(exactRational(x)).get_d()) < 1e-13);
        }
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k <= 3; ++k)
                QVERIFY(std::fabs(fast->globalPiece(i).coefficient(k) - exact->pieces[i].coefficient(k).get_d()) < 1e-12);
        const auto report = checkContinuity(*fast, 2, points, 1e-12);
        QVERIFY2(report.ok(), report.describe().c_str());
    }

    void farFromOrigin()
    {
        // x around 1e6 with unit spacing: the local form keeps full accuracy.
        std::vector<Point> points;
        for (int i = 0; i < 6; ++i)
            points.push_back({1e6 + i, (i % 2) ? 1.0 : -1.0});
        const auto spline = naturalCubicSpline(points);
        QVERIFY(spline.ok());
        for (const auto& p : points)
            QVERIFY(std::fabs((*spline)(p.x) - p.y) < 1e-12);
        QVERIFY(checkContinuity(*spline, 2, points, 1e-9).ok());
    }

    void rejects_data()
    {
        QTest::addColumn<QString>("xs");
        QTest::addColumn<int>("code");
        QTest::newRow("equal x") << "0 1 1 2" << int(ErrorCode::NotIncreasing);
        QTest::newRow("decreasing x") << "0 2 1" << int(ErrorCode::NotIncreasing);
        QTest::newRow("one point") << "0" << int(ErrorCode::TooFewPoints);
        QTest::newRow("no points") << "" << int(ErrorCode::TooFewPoints);
    }
    void rejects()
    {
        QFETCH(QString, xs);
        QFETCH(int, code);
        std::vector<RPoint> exact;
        std::vector<Point> fast;
        for (const QString& x : xs.split(' ', Qt::SkipEmptyParts)) {
            exact.push_back({*parseRational(x.toStdString()), Rational(1)});
            fast.push_back({exact.back().x.get_d(), 1.0});
        }
        const auto a = naturalCubicSpline(exact);
        const auto b = naturalCubicSpline(fast);
        QVERIFY(!a.ok() && !b.ok());
        QCOMPARE(int(a.error().code), code);
        QCOMPARE(int(b.error().code), code);
        QVERIFY(!a.error().message.empty());
    }
    void rejectsNonFinite()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        for (const std::vector<Point>& bad :
             {std::vector<Point>{{0, 1}, {1, nan}, {2, 0}}, std::vector<Point>{{0, 1}, {inf, 2}}}) {
            const auto s = naturalCubicSpline(bad);
            QVERIFY(!s.ok());
            QCOMPARE(s.error().code, ErrorCode::InvalidInput);
            QVERIFY(s.error().message.find("Point 1") != std::string::npos);
        }
    }

    // Ex 2.1 as printed: s₂ lacks +1/53. The check must report exactly the value jumps at
    // x = 1 and x = 2 and s₂ missing (1, 3) and (2, 1) — s′ and s″ do match.
    void ex21AsPrintedFails()
    {
        const auto report = checkContinuity(ex21AsPrinted(), 2, ex21Points());
        QVERIFY(!report.ok());
        QCOMPARE(report.continuityOrder(), -1);
        QVERIFY(!report.interpolates());
        QCOMPARE(static_cast<int>(report.defects.size()), 4);

        const auto jumps = ofKind(report, DefectKind::Jump);
        QCOMPARE(static_cast<int>(jumps.size()), 2);
        QCOMPARE(jumps[0]->knot, 1);
        QCOMPARE(jumps[0]->order, 0);
        QCOMPARE(jumps[0]->x, q(1));
        QCOMPARE(jumps[0]->left, q(3));        // s₁(1) = −132/53 + 238/53 + 1
        QCOMPARE(jumps[0]->right, q(158, 53)); // s₂(1) = (52 − 288 + 394)/53
        QCOMPARE(jumps[0]->jump(), q(-1, 53));
        QCOMPARE(jumps[1]->knot, 2);
        QCOMPARE(jumps[1]->order, 0);
        QCOMPARE(jumps[1]->x, q(2));
        QCOMPARE(jumps[1]->left, q(52, 53)); // s₂(2) = (416 − 1152 + 788)/53
        QCOMPARE(jumps[1]->right, q(1));     // s₃(2) = (32 − 364 + 385)/53

        const auto misses = ofKind(report, DefectKind::NotInterpolated);
        QCOMPARE(static_cast<int>(misses.size()), 2);
        QCOMPARE(misses[0]->point, 1);
        QCOMPARE(misses[0]->piece, 1); // s₂
        QCOMPARE(misses[0]->expected, q(3));
        QCOMPARE(misses[0]->got, q(158, 53));
        QCOMPARE(misses[1]->point, 2);
        QCOMPARE(misses[1]->piece, 1);
        QCOMPARE(misses[1]->expected, q(1));
        QCOMPARE(misses[1]->got, q(52, 53));

        const QString text = QString::fromStdString(report.describe());
        QVERIFY2(text.contains("s is discontinuous at x = 1: left 3, right 158/53 (jump -1/53)"), qPrintable(text));
        QVERIFY2(text.contains("s is discontinuous at x = 2: left 52/53, right 1 (jump 1/53)"), qPrintable(text));
        QVERIFY2(text.contains("s_2 does not interpolate (1, 3): s_2(1) = 158/53"), qPrintable(text));
        QVERIFY2(text.contains("s_2 does not interpolate (2, 1): s_2(2) = 52/53"), qPrintable(text));
    }

    void ex21CorrectedPasses()
    {
        auto s = ex21AsPrinted();
        s.pieces[1] += RP(q(1, 53));
        const auto report = checkContinuity(s, 2, ex21Points());
        QVERIFY2(report.ok(), report.describe().c_str());
        QCOMPARE(report.continuityOrder(), 2);
        // A cubic spline (Def 2.3) — but not the natural one: its ends are not s″ = 0.
        const auto second = s.derivative().derivative();
        QCOMPARE(second(q(0)), q(-264, 53));
        QCOMPARE(second(q(3)), q(72, 53));
        const auto natural = naturalCubicSpline(ex21Points());
        QVERIFY(natural.ok());
        QVERIFY(natural->pieces != s.pieces);
    }

    void firstDerivativeJump()
    {
        // x² then 3x − 2: continuous at x = 1 (both 1), slopes 2 and 3.
        PiecewisePolynomial<Rational> s{{q(0), q(1), q(2)}, {RP{q(0), q(0), q(1)}, RP{q(-2), q(3)}}, false};
        const auto report = checkContinuity(s, 2);
        QCOMPARE(report.continuityOrder(), 0);
        QCOMPARE(static_cast<int>(report.defects.size()), 2); // s′ and s″ (2 → 0)
        const auto& d = report.defects[0];
        QCOMPARE(d.kind, DefectKind::Jump);
        QCOMPARE(d.knot, 1);
        QCOMPARE(d.order, 1);
        QCOMPARE(d.left, q(2));
        QCOMPARE(d.right, q(3));
        QCOMPARE(QString::fromStdString(d.describe()), QString("s' is discontinuous at x = 1: left 2, right 3 (jump 1)"));
        QCOMPARE(report.defects[1].order, 2);
    }

    void secondDerivativeJump()
    {
        // Local form: x³ on [0, 1] and [1, 2] (written around each knot), then at x = 2 a
        // quadratic with the right value 8 and slope 12 but s″ = 10 instead of 12.
        PiecewisePolynomial<Rational> s{{q(0), q(1), q(2), q(4)},
                                        {RP{q(0), q(0), q(0), q(1)}, RP{q(1), q(3), q(3), q(1)}, RP{q(8), q(12), q(5)}},
                                        true};
        QCOMPARE(s(q(3, 2)), q(27, 8));
        QCOMPARE(s.globalPiece(1), (RP{q(0), q(0), q(0), q(1)})); // (u + 1)³ = x³
        const auto report = checkContinuity(s, 2);
        QCOMPARE(report.continuityOrder(), 1);
        QCOMPARE(static_cast<int>(report.defects.size()), 1);
        const auto& d = report.defects[0];
        QCOMPARE(d.knot, 2);
        QCOMPARE(d.order, 2);
        QCOMPARE(d.x, q(2));
        QCOMPARE(d.left, q(12));
        QCOMPARE(d.right, q(10));
        QVERIFY(checkContinuity(s, 1).ok()); // C¹ is all that was asked
    }

    void toleranceForDoubles()
    {
        PiecewisePolynomial<double> s{{0.0, 1.0, 2.0}, {Polynomial<double>{0.0, 1.0}, Polynomial<double>{1e-13, 1.0}}, false};
        const auto strict = checkContinuity(s, 1);
        QCOMPARE(static_cast<int>(strict.defects.size()), 1);
        QCOMPARE(strict.defects[0].order, 0);
        QVERIFY(checkContinuity(s, 1, {}, 1e-9).ok());
    }

    void pointOutsideDomain()
    {
        const auto report = checkContinuity(ex21AsPrinted(), 0, {{q(5), q(1)}});
        QCOMPARE(static_cast<int>(ofKind(report, DefectKind::OutsideDomain).size()), 1);
    }

    void evaluationConvention()
    {
        // Ex 2.1's intervals are [0,1), [1,2), [2,3]: s(1) comes from s₂, s(3) from s₃.
        const auto s = ex21AsPrinted();
        QCOMPARE(s.pieceIndex(q(1)), 1);
        QCOMPARE(s.pieceIndex(q(3)), 2);
        QCOMPARE(s(q(1)), q(158, 53));
        QCOMPARE(s(q(3)), q(-1));
        QCOMPARE(s.order(), 3);
        // Local and global forms describe the same function.
        const auto local = s.toLocal();
        QVERIFY(local.localOrigin);
        for (int j = 0; j <= 12; ++j)
            QCOMPARE(local(q(j, 4)), s(q(j, 4)));
        QCOMPARE(local.toGlobal().pieces, s.pieces);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCubicSpline)
#include "test_cubic_spline.moc"
