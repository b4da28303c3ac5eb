// The error against degree (Prop 2.2 for every n): least-squares optimality over nested
// spaces makes it non-increasing for fixed parameters; the budget bounds the work.
#include "core/curves/fitting/fit_error_by_degree.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

std::vector<Point> samples(int count)
{
    std::vector<Point> q;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / (count - 1);
        q.emplace_back(std::cos(4 * s) + 0.3 * std::sin(37.0 * i), std::sin(5 * s) + 0.2 * std::cos(11.0 * i));
    }
    return q;
}

} // namespace

Q_DECLARE_METATYPE(granota::Parametrization)

class TestFitErrorByDegree : public QObject {
    Q_OBJECT
private slots:
    void nonIncreasing_data()
    {
        QTest::addColumn<Parametrization>("parametrization");
        QTest::addColumn<int>("count");
        for (Parametrization p : {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal}) {
            QTest::addRow("%s 5", toString(p).c_str()) << p << 5;
            QTest::addRow("%s 200", toString(p).c_str()) << p << 200;
        }
    }
    void nonIncreasing()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(int, count);
        FitOptions o;
        o.parametrization = parametrization;
        const auto errors = fitErrorByDegree(samples(count), o, 30);
        QCOMPARE(static_cast<int>(errors.size()), std::min(30, count - 1));
        for (std::size_t i = 0; i < errors.size(); ++i) {
            QCOMPARE(errors[i].degree, static_cast<int>(i) + 1);
            QVERIFY(errors[i].ok);
            QVERIFY(std::isfinite(errors[i].sse) && errors[i].sse >= 0);
            if (i > 0) // nested spaces: the best error cannot grow (up to rounding)
                QVERIFY2(errors[i].sse <= errors[i - 1].sse * (1 + 1e-9) + 1e-24,
                         qPrintable(QStringLiteral("n = %1: %2 > %3").arg(i + 1).arg(errors[i].sse).arg(errors[i - 1].sse)));
        }
        // With k + 1 points, degree k interpolates: the error vanishes.
        if (count == 5)
            QVERIFY(errors.back().sse < 1e-20);
        else
            QVERIFY(errors.back().sse < errors.front().sse);
    }
    void matchesSingleFits()
    {
        const auto q = samples(40);
        FitOptions o;
        o.parametrization = Parametrization::ChordLength;
        const auto errors = fitErrorByDegree(q, o, 10);
        QCOMPARE(errors.size(), std::size_t(10));
        for (const DegreeError& e : errors) {
            o.degree = e.degree;
            const auto fit = fitBezier(q, o);
            QVERIFY(fit.ok());
            QCOMPARE(e.sse, fit->sse);
            QCOMPARE(e.cond, fit->cond);
        }
    }
    void budgetTruncates()
    {
        bool truncated = false;
        const auto errors = fitErrorByDegree(samples(1000), FitOptions(), 30, 5000, &truncated);
        QVERIFY(truncated);
        QCOMPARE(errors.size(), std::size_t(4)); // 1000 × (n + 1) ≤ 5000 for n ≤ 4
        fitErrorByDegree(samples(10), FitOptions(), 30, 5000, &truncated);
        QVERIFY(!truncated);
        QVERIFY(fitErrorByDegree({{1, 1}}, FitOptions(), 30).empty());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestFitErrorByDegree)
#include "test_fit_error_by_degree.moc"
