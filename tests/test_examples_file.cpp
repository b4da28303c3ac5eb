// resources/examples/chapter2.json — the data behind the Examples menu — reproduces what
// the thesis prints when run through the core, example by example.
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/continuity_check.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/polynomial_text.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace granota;

namespace {

Rational rational(const QJsonValue& v)
{
    if (v.isString())
        return *parseRational(v.toString().toStdString());
    return *parseRational(QByteArray::number(v.toDouble(), 'g', 17).toStdString());
}

std::vector<RPoint> points(const QJsonObject& e)
{
    std::vector<RPoint> out;
    for (const auto& p : e["points"].toArray())
        out.emplace_back(rational(p.toArray()[0]), rational(p.toArray()[1]));
    return out;
}

Polynomial<Rational> poly(const QJsonValue& v, char var = 't')
{
    auto p = parsePolynomial(v.toString().toStdString(), var);
    if (!p)
        qFatal("unreadable polynomial %s", qPrintable(v.toString()));
    return *p;
}

} // namespace

class TestExamplesFile : public QObject {
    Q_OBJECT
    QJsonArray m_examples;

    QJsonObject example(const char* id) const
    {
        for (const auto& e : m_examples)
            if (e.toObject()["id"].toString() == QLatin1String(id))
                return e.toObject();
        return {};
    }

private slots:
    void initTestCase()
    {
        QFile f(QStringLiteral(GRANOTA_SOURCE_DIR "/resources/examples/chapter2.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonParseError error;
        const auto doc = QJsonDocument::fromJson(f.readAll(), &error);
        QCOMPARE(error.error, QJsonParseError::NoError);
        m_examples = doc.object()["examples"].toArray();
    }

    void everyExampleIsThere()
    {
        QStringList ids;
        for (const auto& e : m_examples)
            ids << e.toObject()["id"].toString();
        for (int i = 1; i <= 13; ++i)
            QVERIFY2(ids.contains(QString("2.%1").arg(i)), qPrintable(QString("Ex 2.%1 missing").arg(i)));
        for (const auto& e : m_examples) // each one names a tab of docs/classroom.md
            QVERIFY(QStringList({"decasteljau", "bernstein", "fit", "catmull-rom"}).contains(e.toObject()["tab"].toString()));
    }

    void bezierExamples()
    {
        for (const char* id : {"2.2", "2.3", "2.5", "2.6"}) {
            const QJsonObject e = example(id);
            const auto c = bezierToPowerBasis(points(e));
            QCOMPARE(c.x, poly(e["expected"].toObject()["x"]));
            QCOMPARE(c.y, poly(e["expected"].toObject()["y"]));
        }
    }

    void fitExamples()
    {
        for (const char* id : {"2.7", "2.8"}) {
            const QJsonObject e = example(id);
            auto fit = fitBezierExact(points(e), e["degree"].toInt(), Parametrization::Uniform);
            QVERIFY(fit.ok());
            const QJsonArray expected = e["expected"].toObject()["control_points"].toArray();
            QCOMPARE(fit->P.rows(), expected.size());
            for (int j = 0; j < expected.size(); ++j) {
                QCOMPARE(fit->P(j, 0), rational(expected[j].toArray()[0]));
                QCOMPARE(fit->P(j, 1), rational(expected[j].toArray()[1]));
            }
        }
        // Ex 2.9/2.10: chord parameters are irrational, so no exact fit — but a numerical one.
        const QJsonObject e = example("2.9");
        QVERIFY(!fitBezierExact(points(e), 2, Parametrization::ChordLength).ok());
        FitOptions o;
        o.degree = 2;
        o.parametrization = Parametrization::ChordLength;
        QVERIFY(fitBezier(toDouble(points(e)), o).ok());
    }

    void catmullRomExamples()
    {
        const QJsonObject e11 = example("2.11");
        const auto p = points(e11);
        for (const auto& tau : e11["taus"].toArray()) {
            const auto seg = catmullRomSegment(p[0], p[1], p[2], p[3], rational(tau));
            const QJsonObject want = e11["expected"].toObject()[tau.toString()].toObject();
            QCOMPARE(seg.x, poly(want["x"]));
            QCOMPARE(seg.y, poly(want["y"]));
        }
        const QJsonObject e13 = example("2.13");
        for (const auto& mode : e13["modes"].toArray()) {
            auto segs = catmullRomSegments(points(e13), rational(e13["tau"]),
                                           *parseCatmullRomMode(mode.toString().toStdString()));
            QVERIFY(segs.ok());
            const QJsonArray want = e13["expected"].toObject()[mode.toString()].toArray();
            QCOMPARE(int(segs->size()), want.size());
            for (int i = 0; i < want.size(); ++i) {
                QCOMPARE((*segs)[i].x, poly(want[i].toObject()["x"]));
                QCOMPARE((*segs)[i].y, poly(want[i].toObject()["y"]));
            }
        }
    }

    void example21AsPrintedFailsWhereTheNoteSays()
    {
        const QJsonObject e = example("2.1");
        PiecewisePolynomial<Rational> s;
        for (int k = 0; k <= 3; ++k)
            s.knots.push_back(Rational(k));
        for (const auto& piece : e["pieces_as_printed"].toArray())
            s.pieces.push_back(poly(piece, 'x'));
        const auto report = checkContinuity(s, 2, points(e));
        QVERIFY(!report.ok());
        QStringList where;
        for (const auto& d : report.defects)
            where << QString::fromStdString(d.describe());
        QCOMPARE(where.filter("discontinuous at x = 1:").size(), 1);
        QCOMPARE(where.filter("discontinuous at x = 2:").size(), 1);
        QCOMPARE(where.filter("s_2 does not interpolate").size(), 2);
        QCOMPARE(int(report.defects.size()), 4); // first and second derivatives are fine
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestExamplesFile)
#include "test_examples_file.moc"
