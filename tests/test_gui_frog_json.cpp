// The Frog tab reads a document's recording an event at a time (documentRunFromQJson,
// ui/frog/frog_json.h) instead of turning the whole of it into the core's Json first: the
// same run, or the same refusal word for word, as documentRunFromJson(fromQJson(value)), the
// reader it replaces; and documentRunToQJson writes what documentRunToJson does.
#include "core/softbody/recorded_run.h"
#include "core/softbody/scenes/scene.h"
#include "ui/frog/frog_json.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include "tests/test_main.h"

using namespace granota;
using granota::ui::documentRunFromQJson;
using granota::ui::documentRunToQJson;
using granota::ui::fromQJson;
using granota::ui::toQJson;

class TestGuiFrogJson : public QObject {
    Q_OBJECT
private slots:
    void sameAsTheTree_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::newRow("good") << QByteArray(R"({"steps": 9, "step": 3, "events": [[0, "press", 1, 2], [3, "move", 4, 5],
                                               [9, "release"], [9, "substeps", 4]]})");
        QTest::newRow("no events") << QByteArray(R"({"steps": 9})");
        QTest::newRow("events not a list") << QByteArray(R"({"steps": 9, "events": 3})");
        QTest::newRow("not an object") << QByteArray(R"([1, 2])");
        QTest::newRow("bad steps") << QByteArray(R"({"steps": -1, "events": []})");
        QTest::newRow("step beyond") << QByteArray(R"({"steps": 5, "step": 6, "events": []})");
        QTest::newRow("event beyond") << QByteArray(R"({"steps": 5, "events": [[7, "move", 1, 2]]})");
        QTest::newRow("bad kind") << QByteArray(R"({"steps": 5, "events": [[1, "jump"]]})");
        QTest::newRow("out of order") << QByteArray(R"({"steps": 5, "events": [[3, "release"], [2, "release"]]})");
        QTest::newRow("knob out of range") << QByteArray(R"({"steps": 5, "events": [[1, "edge_damping_ratio", 2.5]]})");
        QTest::newRow("point missing") << QByteArray(R"({"steps": 5, "events": [[1, "move", 1]]})");
    }
    void sameAsTheTree()
    {
        QFETCH(QByteArray, json);
        const QJsonDocument doc = QJsonDocument::fromJson(json);
        const QJsonValue value = doc.isObject() ? QJsonValue(doc.object()) : QJsonValue(doc.array());
        const auto expected = documentRunFromJson(fromQJson(value));
        const auto read = documentRunFromQJson(value);
        QCOMPARE(read.ok(), expected.ok());
        if (!expected.ok()) {
            QCOMPARE(read.error().message, expected.error().message);
            return;
        }
        QCOMPARE(read->steps, expected->steps);
        QCOMPARE(read->step, expected->step);
        QVERIFY(read->events == expected->events);
    }

    // Written an event at a time: the same document part as through the core's Json.
    void writesWhatTheTreeWrites()
    {
        auto spec = loadScene("frog");
        QVERIFY(spec.ok());
        auto run = RecordedRun::start(*spec, SolverKind::Seed);
        QVERIFY(run.ok());
        run->step();
        QVERIFY(run->press(Point(640, 360)));
        run->step();
        run->move(Point(650, 350));
        run->step();
        run->release();
        run->step();
        QCOMPARE(documentRunToQJson(*run), toQJson(documentRunToJson(*run)));
    }
};

GRANOTA_TEST_MAIN(TestGuiFrogJson)
#include "test_gui_frog_json.moc"
