// Issue 35, part 2: a parameter edit is one call into the core. withParameter(scene, key, part,
// index, value) sets one number through the table of scene_parameters.h and checks the scene;
// the reference for every case is the scene file's path (the same value in the file's JSON form,
// through the reader), so each expected scene is computed independently of the code under test.
// A tick writes no scene (sceneWriteCount); the Frog panel's own tick is counted in test_gui_frog.
#include "core/softbody/scenes/scene.h"
#include "core/softbody/scenes/scene_parameters.h"
#include "core/io/json.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

namespace {

Json pair(double a, double b) { return Json(Json::Array{Json(a), Json(b)}); }

} // namespace

class TestSceneParameters : public QObject {
    Q_OBJECT
private slots:
    // One number of each kind of parameter, set by (part, index), against the whole value in the
    // file's form. Values and places picked by hand from resources/scenes/*.json.
    void aTickIsTheFileValue_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("key");
        QTest::addColumn<int>("part");
        QTest::addColumn<int>("index");
        QTest::addColumn<double>("value");
        QTest::newRow("integer") << "frog"
                                 << "sides" << 0 << 0 << 12.0;
        QTest::newRow("number") << "frog"
                                << "spring_length" << 0 << 0 << 7.5;
        QTest::newRow("pair y") << "frog"
                                << "gravity" << 0 << 1 << 0.5;
        QTest::newRow("centre x, no longer the frame's") << "frog"
                                                         << "center" << 0 << 0 << 300.0;
        QTest::newRow("radius, no longer the frame's") << "frog"
                                                       << "radius" << 0 << 0 << 40.0;
        QTest::newRow("grab: above") << "frog"
                                     << "grab" << 0 << 0 << 1.0;
        QTest::newRow("back legs, lower") << "frog"
                                          << "legs" << 1 << 1 << 33.0;
        QTest::newRow("front elbows, max") << "frog"
                                           << "angle_limits" << 4 << 1 << 0.5;
        QTest::newRow("pendulum's elbow, min") << "pendulum-limits"
                                               << "angle_limits" << 1 << 0 << -0.25;
        QTest::newRow("second link") << "pendulum-limits"
                                     << "chain" << 1 << 0 << 55.0;
    }
    void aTickIsTheFileValue()
    {
        QFETCH(QString, scene);
        QFETCH(QString, key);
        QFETCH(int, part);
        QFETCH(int, index);
        QFETCH(double, value);
        const auto spec = loadScene(scene.toStdString());
        QVERIFY(spec.ok());
        const std::string k = key.toStdString();
        const SceneParameter& p = *findSceneParameter(k);
        // The whole value in the file's form, with the one number replaced.
        const Json file = *sceneToJson(*spec).find("params")->find(k);
        Json whole = file;
        switch (p.type) {
        case ParameterType::Integer:
        case ParameterType::Number: whole = Json(value); break;
        case ParameterType::Pair: {
            const Point q(parameterNumber(*spec, p, 0, 0), parameterNumber(*spec, p, 0, 1)); // "frame": the derived numbers
            whole = index == 0 ? pair(value, q.y) : pair(q.x, value);
            break;
        }
        case ParameterType::Choice: whole = Json(std::string(grabChoices()[static_cast<std::size_t>(value)].name)); break;
        case ParameterType::Chain: {
            Json::Array links = *file.asArray();
            links[static_cast<std::size_t>(part)] = Json(value);
            whole = Json(links);
            break;
        }
        case ParameterType::Legs:
        case ParameterType::AngleLimits: {
            const std::string name = p.type == ParameterType::Legs ? legParts()[static_cast<std::size_t>(part)].name
                                                                   : angleLimitOf(*spec, part)->name;
            Json::Array q = *file.find(name)->asArray();
            q[static_cast<std::size_t>(index)] = Json(value);
            whole.set(name, Json(q));
            break;
        }
        default: QFAIL("a parameter the panel does not edit");
        }
        const auto reference = withParameter(*spec, k, whole);
        QVERIFY2(reference.ok(), reference.ok() ? "" : reference.error().message.c_str());
        const auto tick = withParameter(*spec, k, part, index, value);
        QVERIFY2(tick.ok(), tick.ok() ? "" : tick.error().message.c_str());
        QCOMPARE(QString::fromStdString(sceneToJson(*tick).dump()), QString::fromStdString(sceneToJson(*reference).dump()));
        QCOMPARE(parameterNumber(*tick, p, part, index), value);
    }

    // A refused tick says what the file's path says, and leaves nothing half changed.
    void aRefusedTickSaysWhy_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("value");
        QTest::newRow("not whole") << "sides" << 2.5;
        QTest::newRow("too few sides") << "sides" << 2.0;
        QTest::newRow("beyond 1e15") << "spring_length" << 1e16;
    }
    void aRefusedTickSaysWhy()
    {
        QFETCH(QString, key);
        QFETCH(double, value);
        const auto frog = loadScene("frog");
        const auto tick = withParameter(*frog, key.toStdString(), 0, 0, value);
        const auto file = withParameter(*frog, key.toStdString(), Json(value));
        QVERIFY(!tick.ok());
        QVERIFY(!file.ok());
        QCOMPARE(QString::fromStdString(tick.error().message), QString::fromStdString(file.error().message));
    }

    void aPlaceTheParameterLacksIsRefused()
    {
        const auto frog = loadScene("frog");
        QVERIFY(!withParameter(*frog, "gravity", 0, 2, 1.0).ok());     // a pair has x and y
        QVERIFY(!withParameter(*frog, "legs", 2, 0, 1.0).ok());        // front and back only
        QVERIFY(!withParameter(*frog, "grab", 0, 0, 3.0).ok());        // three choices
        const auto unknown = withParameter(*frog, "chain", 0, 0, 1.0); // the frog has no chain
        QVERIFY(!unknown.ok());
        QCOMPARE(unknown.error().id, MessageId::SceneUnknownParameter);
    }

    // What an undo gives back: the parameter as another scene has it, and only that one.
    void withParameterOfCopiesOneParameter()
    {
        const auto frog = loadScene("frog");
        QVERIFY(frog->radiusFromFrame); // the frog's file says "radius": "frame"
        auto edited = withParameter(*frog, "radius", 0, 0, 40.0);
        edited = withParameter(*edited, "gravity", 0, 0, 0.25);
        QVERIFY(edited.ok());
        const auto back = withParameterOf(*edited, *frog, "radius");
        QVERIFY(back.ok());
        QVERIFY(back->radiusFromFrame); // follows the frame again, as before the edit
        QCOMPARE(back->params.radius, frog->params.radius);
        QCOMPARE(back->params.gravity.x, 0.25); // the other edit stays
    }

    // Many ticks, no scene written: the tick path never goes through the writer.
    void aTickWritesNoScene()
    {
        auto spec = loadScene("frog");
        const long before = sceneWriteCount();
        for (int i = 1; i <= 50; ++i) {
            spec = withParameter(*spec, "gravity", 0, 1, 0.01 * i);
            QVERIFY(spec.ok());
        }
        QCOMPARE(sceneWriteCount(), before);
        QCOMPARE(spec->params.gravity.y, 0.01 * 50);
        sceneToJson(*spec); // the counter counts: one write is one
        QCOMPARE(sceneWriteCount(), before + 1);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestSceneParameters)
#include "test_scene_parameters.moc"
