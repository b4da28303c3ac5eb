// All roots in [0, 1] of a polynomial in Bernstein form (core/curves/bezier/bernstein_roots.h):
// polynomials built from known roots, exactly, then rounded once to doubles.
#include "core/curves/bezier/bernstein_roots.h"
#include "core/exact/rational.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>
#include <random>

using namespace granota;

namespace {

/// Bernstein coefficients of c · ∏ (t − r_i), exactly: multiplying a degree-m polynomial q by
/// (t − r) = (1 − r) t − r (1 − t) gives c_k = (1 − r) k/(m+1) q_{k−1} − r (m+1−k)/(m+1) q_k.
std::vector<double> fromRoots(const std::vector<Rational>& roots, const Rational& c = Rational(1))
{
    std::vector<Rational> q{c};
    for (const Rational& r : roots) {
        const int m = static_cast<int>(q.size()) - 1;
        std::vector<Rational> next(static_cast<std::size_t>(m + 2), Rational(0));
        for (int k = 0; k <= m + 1; ++k) {
            Rational v(0);
            if (k >= 1)
                v += (Rational(1) - r) * frac(k, m + 1) * q[static_cast<std::size_t>(k - 1)];
            if (k <= m)
                v -= r * frac(m + 1 - k, m + 1) * q[static_cast<std::size_t>(k)];
            next[static_cast<std::size_t>(k)] = v;
        }
        q = next;
    }
    std::vector<double> out;
    for (const Rational& v : q)
        out.push_back(toDouble(v));
    return out;
}

bool near(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance; }

} // namespace

class TestBernsteinRoots : public QObject {
    Q_OBJECT
private slots:
    void simpleRootsToFullPrecision()
    {
        const auto r = bernsteinRoots(fromRoots({frac(1, 5), frac(1, 2), frac(9, 10)}));
        QCOMPARE(r.roots.size(), std::size_t(3));
        QVERIFY(near(r.roots[0], 0.2, 2e-16));
        QCOMPARE(r.roots[1], 0.5);
        QVERIFY(near(r.roots[2], 0.9, 2e-16));
        for (bool c : r.crossing)
            QVERIFY(c);
        QVERIFY(!r.identicallyZero);
        // Roots outside [0, 1] are not reported; the one inside is.
        const auto outside = bernsteinRoots(fromRoots({frac(-1, 2), frac(3, 7), frac(3, 2)}));
        QCOMPARE(outside.roots.size(), std::size_t(1));
        QVERIFY(near(outside.roots[0], 3.0 / 7.0, 2e-16));
    }

    void doubleRootsFoundOnce()
    {
        // (t − 1/2)²: coefficients 1/4, −1/4, 1/4; touches 0 without crossing.
        const auto half = bernsteinRoots(fromRoots({frac(1, 2), frac(1, 2)}));
        QCOMPARE(half.roots.size(), std::size_t(1));
        QCOMPARE(half.roots[0], 0.5);
        QVERIFY(!half.crossing[0]);
        // (t − 1/3)² (t − 4/5): 1/3 is not a halving point and not a double; a double
        // root is determined only to about √ε by its values, but p′ has a simple root there.
        const auto third = bernsteinRoots(fromRoots({frac(1, 3), frac(1, 3), frac(4, 5)}));
        QCOMPARE(third.roots.size(), std::size_t(2));
        QVERIFY(near(third.roots[0], 1.0 / 3.0, 1e-7));
        QVERIFY(!third.crossing[0]);
        QVERIFY(near(third.roots[1], 0.8, 1e-15));
        QVERIFY(third.crossing[1]);
        // A triple root crosses and is found once.
        const auto triple = bernsteinRoots(fromRoots({frac(3, 10), frac(3, 10), frac(3, 10)}));
        QCOMPARE(triple.roots.size(), std::size_t(1));
        QVERIFY(near(triple.roots[0], 0.3, 1e-4));
        QVERIFY(triple.crossing[0]);
        // Two double roots and a simple one between them.
        const auto two = bernsteinRoots(fromRoots({frac(1, 7), frac(1, 7), frac(1, 2), frac(6, 7), frac(6, 7)}));
        QCOMPARE(two.roots.size(), std::size_t(3));
        QVERIFY(near(two.roots[0], 1.0 / 7.0, 1e-7));
        QCOMPARE(two.roots[1], 0.5);
        QVERIFY(near(two.roots[2], 6.0 / 7.0, 1e-7));
        QCOMPARE(two.crossing, (std::vector<bool>{false, true, false}));
    }

    void rootsAtTheEnds()
    {
        const auto r = bernsteinRoots(fromRoots({Rational(0), frac(1, 2), Rational(1)}));
        QCOMPARE(r.roots, (std::vector<double>{0.0, 0.5, 1.0}));
        // t² (1 − t): a double root at 0, a simple one at 1; each once.
        const auto ends = bernsteinRoots(fromRoots({Rational(0), Rational(0), Rational(1)}));
        QCOMPARE(ends.roots, (std::vector<double>{0.0, 1.0}));
        // A degree-1 polynomial with its root at 1.
        QCOMPARE(bernsteinRoots({1.0, 0.0}).roots, std::vector<double>{1.0});
    }

    void clusteredRootsResolved()
    {
        // 1e-6 apart: |p| between them is 2.5e-13, far above rounding (~1e-16).
        const Rational a = frac(2, 5);
        const Rational b = a + frac(1, 1000000);
        const auto r = bernsteinRoots(fromRoots({a, b, frac(7, 10)}));
        QCOMPARE(r.roots.size(), std::size_t(3));
        QVERIFY(near(r.roots[0], 0.4, 1e-10));
        QVERIFY(near(r.roots[1], 0.4 + 1e-6, 1e-10));
        QVERIFY(r.roots[0] < r.roots[1]);
        QVERIFY(near(r.roots[2], 0.7, 1e-15));
    }

    void wilkinsonLike()
    {
        // Farouki & Rajan's example: Wilkinson's ∏_{k=1}^{20} (t − k/20), hopeless in the
        // power basis, well conditioned enough in the Bernstein form.
        std::vector<Rational> twenty;
        for (int k = 1; k <= 20; ++k)
            twenty.push_back(frac(k, 20));
        const auto r20 = bernsteinRoots(fromRoots(twenty));
        QCOMPARE(r20.roots.size(), std::size_t(20));
        for (int k = 1; k <= 20; ++k)
            QVERIFY(near(r20.roots[static_cast<std::size_t>(k - 1)], k / 20.0, 1e-9));
        QCOMPARE(r20.roots.back(), 1.0); // b_n = 0 exactly

        // Degree 60: thirty roots k/30 in (0, 1] and thirty outside [0, 1].
        std::vector<Rational> sixty;
        for (int k = 1; k <= 30; ++k)
            sixty.push_back(frac(k, 30));
        for (int e = 0; e < 30; ++e)
            sixty.push_back(e % 2 ? frac(-1 - e, 4) : frac(5 + e, 4));
        const auto r60 = bernsteinRoots(fromRoots(sixty));
        QCOMPARE(r60.roots.size(), std::size_t(30));
        for (int k = 1; k <= 30; ++k)
            QVERIFY(near(r60.roots[static_cast<std::size_t>(k - 1)], k / 30.0, 1e-11));

        // Sixty roots (2k − 1)/120 spread over [0, 1] are beyond doubles: between the middle
        // roots |p| ≈ 1e-35 while the coefficients (up to 1e-18) are rounded by ~1e-34. Then
        // the outer roots are still found, and whatever is reported is a zero within rounding.
        std::vector<Rational> dense;
        for (int k = 1; k <= 60; ++k)
            dense.push_back(frac(2 * k - 1, 120));
        const auto b = fromRoots(dense);
        double scale = 0;
        for (double c : b)
            scale = std::max(scale, std::fabs(c));
        const auto r = bernsteinRoots(b);
        QVERIFY(r.roots.size() >= 10);
        for (int k = 1; k <= 5; ++k) {
            QVERIFY(near(r.roots[static_cast<std::size_t>(k - 1)], (2 * k - 1) / 120.0, 1e-9));
            QVERIFY(near(r.roots[r.roots.size() - static_cast<std::size_t>(k)], (121 - 2 * k) / 120.0, 1e-9));
        }
        for (double t : r.roots)
            QVERIFY(std::fabs(bernsteinValue(b, t)) <= 1e-15 * scale);
    }

    void noSpuriousRoots()
    {
        QVERIFY(bernsteinRoots({1.0}).roots.empty());
        QVERIFY(bernsteinRoots({1.0, 2.0, 3.0, 0.5}).roots.empty());
        // (t − 1/2)² + 10⁻⁶: the control polygon dips below 0, the polynomial does not.
        QVERIFY(bernsteinRoots({0.25 + 1e-6, -0.25 + 1e-6, 0.25 + 1e-6}).roots.empty());
        // Roots only outside [0, 1].
        QVERIFY(bernsteinRoots(fromRoots({frac(-1, 2), frac(3, 2), Rational(2)})).roots.empty());
        // A non-finite coefficient: nothing can be said.
        const double inf = std::numeric_limits<double>::infinity();
        QVERIFY(bernsteinRoots({1.0, inf, -1.0}).roots.empty());
        QVERIFY(bernsteinRoots({1.0, std::nan(""), -1.0}).roots.empty());
    }

    void identicallyZeroFlagged()
    {
        const auto z = bernsteinRoots({0.0, 0.0, 0.0, 0.0});
        QVERIFY(z.identicallyZero);
        QVERIFY(z.roots.empty());
        QVERIFY(bernsteinRoots({0.0}).identicallyZero);
        QVERIFY(!bernsteinRoots({0.0, 1e-300}).identicallyZero);
    }

    void productFormula()
    {
        // (t − 1/4)(t − 3/4) from two linear factors equals the exact quadratic.
        const auto p = bernsteinProduct({-0.25, 0.75}, {-0.75, 0.25});
        const auto q = fromRoots({frac(1, 4), frac(3, 4)});
        QCOMPARE(p.size(), q.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            QVERIFY(near(p[i], q[i], 1e-16));
        for (double t : {0.0, 0.1, 0.5, 0.77, 1.0})
            QVERIFY(near(bernsteinValue(p, t), (t - 0.25) * (t - 0.75), 1e-16));
    }

    // Known random roots, at least 10⁻³ apart, degree up to 120: every one found, nothing else.
    void randomKnownRoots()
    {
        std::mt19937 rng(15);
        std::uniform_int_distribution<int> grid(1, 999);
        for (int trial = 0; trial < 200; ++trial) {
            const int k = 1 + trial % 12;
            std::vector<int> chosen;
            while (static_cast<int>(chosen.size()) < k) {
                const int g = grid(rng);
                if (std::find(chosen.begin(), chosen.end(), g) == chosen.end())
                    chosen.push_back(g);
            }
            std::sort(chosen.begin(), chosen.end());
            std::vector<Rational> roots;
            for (int g : chosen)
                roots.push_back(frac(g, 1000));
            // Extra factors with no root in [0, 1] raise the degree.
            const int extra = (trial * 7) % (trial < 190 ? 20 : 108);
            for (int e = 0; e < extra; ++e)
                roots.push_back(e % 2 ? frac(-(e + 1), 3) : frac(e + 4, 3));
            const auto r = bernsteinRoots(fromRoots(roots));
            QVERIFY2(r.roots.size() == chosen.size(),
                     qPrintable(QString("trial %1: %2 roots, expected %3").arg(trial).arg(r.roots.size()).arg(k)));
            for (std::size_t i = 0; i < chosen.size(); ++i)
                QVERIFY2(near(r.roots[i], chosen[i] / 1000.0, 1e-10), qPrintable(QString("trial %1").arg(trial)));
        }
    }

    // Random coefficients (small integers: many exact zeros and ties): a dense sign scan's
    // every sign change holds a found root, and every found root is a zero of p within
    // rounding.
    void randomAgainstSignScan()
    {
        std::mt19937 rng(2026);
        std::uniform_int_distribution<int> coefficient(-4, 4);
        const int m = 4000;
        for (int trial = 0; trial < 400; ++trial) {
            const int n = 1 + trial % 25;
            std::vector<double> b(static_cast<std::size_t>(n + 1));
            double scale = 0;
            for (double& c : b) {
                c = coefficient(rng) * (trial % 2 ? 1.0 : 0.37);
                scale = std::max(scale, std::fabs(c));
            }
            const auto r = bernsteinRoots(b);
            if (r.identicallyZero)
                continue;
            QVERIFY(std::is_sorted(r.roots.begin(), r.roots.end()));
            for (double t : r.roots) {
                QVERIFY(t >= 0.0 && t <= 1.0);
                QVERIFY2(std::fabs(bernsteinValue(b, t)) <= 1e-9 * scale, qPrintable(QString("trial %1").arg(trial)));
            }
            double previous = bernsteinValue(b, 0.0);
            for (int j = 1; j <= m; ++j) {
                const double t0 = (j - 1) / double(m), t1 = j / double(m);
                const double value = bernsteinValue(b, t1);
                if (previous * value < 0) {
                    const bool inside = std::any_of(r.roots.begin(), r.roots.end(), [&](double t) { return t >= t0 && t <= t1; });
                    QVERIFY2(inside, qPrintable(QString("trial %1: sign change in [%2, %3] missed").arg(trial).arg(t0).arg(t1)));
                }
                if (value != 0)
                    previous = value;
            }
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestBernsteinRoots)
#include "test_bernstein_roots.moc"
