// The Frog tab's part of a document, read and written by FrogDocument (ui/frog/frog_document.h)
// without a window: what it writes it reads back the same; a key the document lacks keeps the
// current value (or the scene file's, for parameters); a bad value is refused with its message.
#include "core/softbody/scenes/scene.h"
#include "ui/frog/frog_document.h"
#include "ui/frog/frog_overlays.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include "tests/test_main.h"

using namespace granota;
using granota::ui::FrogDocument;
using granota::ui::FrogOverlays;

namespace {

/// A document far from the defaults: the stable solver, a changed parameter and knob, two
/// overlays, the fitted outline, paused at half speed, a ruler.
FrogDocument sample()
{
    FrogDocument doc;
    doc.scene = *withParameter(*loadScene("frog"), "gravity", 0, 1, 0.5);
    doc.scene.stable.substeps = 12;
    doc.solver = SolverKind::Stable;
    doc.overlays.ghost = true;
    doc.overlays.frameTime = true;
    doc.fitOutline = true;
    doc.paused = true;
    doc.speed = 0.5;
    doc.ruler = std::pair{Point(1, 2), Point(30, 40)};
    return doc;
}

} // namespace

class TestGuiFrogDocument : public QObject {
    Q_OBJECT
private slots:
    void roundTrip()
    {
        const FrogDocument doc = sample();
        const QJsonObject written = doc.toJson(nullptr);
        QString error;
        const auto read = FrogDocument::fromJson(written, FrogDocument(), &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(read->toJson(nullptr), written);
        // Field by field, against the values sample() set.
        QCOMPARE(read->scene.params.gravity.y, 0.5);
        QCOMPARE(read->scene.stable.substeps, 12);
        QCOMPARE(read->solver, SolverKind::Stable);
        QVERIFY(read->overlays == doc.overlays);
        QVERIFY(read->fitOutline && read->paused);
        QCOMPARE(read->speed, 0.5);
        QVERIFY(read->ruler && read->ruler->second.y == 40);
        QVERIFY(!read->recording);
        // The overlays by their document keys, one per row of the table.
        const QJsonObject overlays = written.value("overlays").toObject();
        QCOMPARE(overlays.size(), int(ui::kFrogOverlayCount));
        QCOMPARE(overlays.value("ghost"), QJsonValue(true));
        QCOMPARE(overlays.value("frame_time"), QJsonValue(true));
        QCOMPARE(overlays.value("vertices"), QJsonValue(false));
    }

    // Only "scene" is needed: the rest is the current state's, or the scene file's.
    void aMissingKeyKeepsTheCurrentValue()
    {
        const FrogDocument current = sample();
        QString error;
        const auto read = FrogDocument::fromJson(QJsonObject{{"scene", "frog"}}, current, &error);
        QVERIFY2(read, qPrintable(error));
        QVERIFY(read->overlays == current.overlays);
        QCOMPARE(read->speed, current.speed);
        QVERIFY(read->paused && read->fitOutline);
        QCOMPARE(read->scene.stable.substeps, 12);                                   // the knobs in force
        QCOMPARE(read->scene.params.gravity.y, loadScene("frog")->params.gravity.y); // the file's
        QCOMPARE(read->solver, SolverKind::Seed);                                    // a document that names no solver: the seed
        QVERIFY(!read->ruler);
        const auto none = FrogDocument::fromJson(QJsonObject(), current, &error);
        QVERIFY(!none);
        QVERIFY2(error.startsWith("Unknown scene “”"), qPrintable(error));
    }

    void aBadValueIsRefused_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("overlay") << QByteArray(R"({"scene": "frog", "overlays": {"ghost": 1}})")
                                 << "The overlay “ghost” must be true or false.";
        QTest::newRow("speed") << QByteArray(R"({"scene": "frog", "speed": 3})")
                               << "The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4.";
        QTest::newRow("solver") << QByteArray(R"({"scene": "frog", "solver": "euler"})")
                                << "Unknown solver “euler” (seed or stable).";
        QTest::newRow("parameter") << QByteArray(R"({"scene": "frog", "params": {"chain": [1]}})")
                                   << "Scene “frog” has no parameter “chain”.";
        QTest::newRow("outline") << QByteArray(R"({"scene": "frog", "bezier_outline": "spline"})")
                                 << "The Bézier outline must be “precomputed” or “fit”, not “spline”.";
        QTest::newRow("ruler") << QByteArray(R"({"scene": "frog", "ruler": [1, 2, 3]})")
                               << "The ruler must be four numbers: x and y of each end, in px.";
    }
    void aBadValueIsRefused()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QString error;
        const auto read = FrogDocument::fromJson(QJsonDocument::fromJson(json).object(), sample(), &error);
        QVERIFY(!read);
        QCOMPARE(error, message);
    }

    // Parameters that only fit together are read together, in any order: 200 bodies need the
    // wider frame, and "bodies" comes before "width" in a QJsonObject.
    void parametersAreCheckedTogether()
    {
        const auto many = loadScene("many-bodies");
        const auto wide = withBodies(*many, 200); // the frame frameForBodies gives them
        QVERIFY(wide.ok());
        const QJsonObject params{{"bodies", 200}, {"width", wide->params.width}, {"height", wide->params.height}};
        QString error;
        const auto read = FrogDocument::fromJson(QJsonObject{{"scene", "many-bodies"}, {"params", params}}, FrogDocument(),
                                                 &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(read->scene.bodies, 200);
    }
};

GRANOTA_TEST_MAIN(TestGuiFrogDocument)
#include "test_gui_frog_document.moc"
