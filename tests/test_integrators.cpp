// The integrators of chapter 3 and §4.2 against problems with known solutions: constant
// gravity (exact for Verlet and the MRUA update up to the start) and the harmonic
// oscillator (orders of convergence: Euler 1, Verlet 2, RK4 4; energy behaviour).
#include "core/softbody/integrators.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;
Q_DECLARE_METATYPE(Integrator)

namespace {

/// x'' = −x from (1, 0): x(t) = cos t. Global error at t = T after T/h steps.
double oscillatorError(Integrator method, double h, double T = 2.0)
{
    const auto a = [](Point x, Point) { return Point(-x.x, -x.y); };
    ParticleState s = startParticle(Point(1, 0), Point(0, 0), h, a);
    const int steps = static_cast<int>(std::lround(T / h));
    for (int i = 0; i < steps; ++i)
        integrate(method, s, h, a);
    return std::abs(s.position.x - std::cos(steps * h));
}

} // namespace

class TestIntegrators : public QObject {
    Q_OBJECT
private slots:
    void orderOfConvergence_data()
    {
        QTest::addColumn<Integrator>("method");
        QTest::addColumn<double>("order");
        QTest::newRow("explicit Euler") << Integrator::ExplicitEuler << 1.0;
        QTest::newRow("semi-implicit Euler") << Integrator::SemiImplicitEuler << 1.0;
        QTest::newRow("Verlet") << Integrator::Verlet << 2.0;
        QTest::newRow("RK4") << Integrator::Rk4 << 4.0;
    }
    void orderOfConvergence()
    {
        QFETCH(Integrator, method);
        QFETCH(double, order);
        // Halving h divides the global error by about 2^order.
        const double e1 = oscillatorError(method, 0.02), e2 = oscillatorError(method, 0.01);
        const double observed = std::log2(e1 / e2);
        qInfo("%s: error %.3g at h = 0.02, %.3g at h = 0.01, observed order %.2f", integratorName(method).c_str(), e1, e2,
              observed);
        QVERIFY(std::abs(observed - order) < 0.25);
    }

    void verletBeatsEulerAtEqualCost()
    {
        // Same number of acceleration evaluations: Verlet's error is far smaller.
        QVERIFY(oscillatorError(Integrator::Verlet, 0.01) * 100 < oscillatorError(Integrator::ExplicitEuler, 0.01));
    }

    void energy()
    {
        // Explicit Euler spirals outwards (energy grows), Verlet's energy stays bounded.
        const auto a = [](Point x, Point) { return Point(-x.x, -x.y); };
        const auto energyAfter = [&](Integrator m) {
            ParticleState s = startParticle(Point(1, 0), Point(0, 0), 0.1, a);
            double worst = 0;
            for (int i = 0; i < 5000; ++i) {
                integrate(m, s, 0.1, a);
                worst = std::max(worst, std::abs(0.5 * (dot(s.velocity, s.velocity) + dot(s.position, s.position)) - 0.5));
            }
            return worst;
        };
        QVERIFY(energyAfter(Integrator::ExplicitEuler) > 1.0);
        QVERIFY(energyAfter(Integrator::Verlet) < 0.01);
        QVERIFY(energyAfter(Integrator::SemiImplicitEuler) < 0.06);
    }

    void mruaIsSemiImplicitEuler()
    {
        // §4.2 with h = 1: v(t) = v(t−1) + g, X(t) = X(t−1) + v(t).
        const Point g(0, 0.75);
        ParticleState s{Point(640, 360), Point(0, -5), Point(640, 360)};
        Point x(640, 360), v(0, -5);
        for (int t = 1; t <= 50; ++t) {
            integrate(Integrator::SemiImplicitEuler, s, 1.0, [&](Point, Point) { return g; });
            v = Point(v.x + g.x, v.y + g.y);
            x = Point(x.x + v.x, x.y + v.y);
            QCOMPARE(s.position, x);
        }
        // Closed form: X(t) = X0 + t v0 + g t(t+1)/2.
        QCOMPARE(s.position.y, 360 - 5 * 50 + 0.75 * 50 * 51 / 2);
    }

    void verletIsExactUnderConstantGravity()
    {
        const Point g(0, 9.81);
        const double h = 0.1;
        const auto a = [&](Point, Point) { return g; };
        ParticleState s = startParticle(Point(0, 0), Point(3, -20), h, a);
        for (int i = 1; i <= 100; ++i) {
            integrate(Integrator::Verlet, s, h, a);
            const double t = i * h;
            QVERIFY(std::abs(s.position.x - 3 * t) < 1e-9);
            QVERIFY(std::abs(s.position.y - (-20 * t + 0.5 * 9.81 * t * t)) < 1e-9);
        }
    }

    void names()
    {
        for (Integrator m : {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler, Integrator::Verlet, Integrator::Rk4})
            QCOMPARE(*parseIntegrator(integratorName(m)), m);
        QVERIFY(!parseIntegrator("leapfrog"));
        QCOMPARE(evaluationsPerStep(Integrator::Rk4), 4);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestIntegrators)
#include "test_integrators.moc"
