// The JSON reader/writer behind scenes, examples and the CLI's output.
#include "core/json.h"

#include <QtTest>

#include <clocale>
#include <string>

using namespace granota;

namespace {

/// Switches LC_NUMERIC to Catalan (decimal comma) for one scope, and back.
class CatalanNumbers {
public:
    CatalanNumbers() : m_saved(std::setlocale(LC_NUMERIC, nullptr)) { m_active = std::setlocale(LC_NUMERIC, "ca_ES.UTF-8"); }
    ~CatalanNumbers() { std::setlocale(LC_NUMERIC, m_saved.c_str()); }
    bool active() const { return m_active; }

private:
    std::string m_saved;
    bool m_active = false;
};

} // namespace

class TestJson : public QObject {
    Q_OBJECT
private slots:
    void roundTrip()
    {
        const std::string text = "{\"name\":\"frog\",\"sides\":10,\"gravity\":[0,0.75],\"on\":true,\"none\":null,"
                                 "\"s\":\"a\\\"b\\\\c\\u00e9\"}";
        auto v = Json::parse(text);
        QVERIFY(v.ok());
        QCOMPARE(*v->find("name")->asString(), std::string("frog"));
        QCOMPARE(*v->find("sides")->asNumber(), 10.0);
        QCOMPARE(*v->find("gravity")->asArray()->at(1).asNumber(), 0.75);
        QVERIFY(v->find("none")->isNull());
        QCOMPARE(*v->find("s")->asString(), std::string("a\"b\\c\xc3\xa9"));
        QVERIFY(v->find("missing") == nullptr);
        // Writing and reading again gives the same text: key order is kept.
        auto again = Json::parse(v->dump());
        QVERIFY(again.ok());
        QCOMPARE(again->dump(), v->dump());
        QVERIFY2(v->dump().find("\"name\":\"frog\",\"sides\":10") != std::string::npos, v->dump().c_str());
        QVERIFY(Json::parse(v->dump(2)).ok()); // pretty form parses too
    }
    void shortestNumbers()
    {
        Json a = Json::array();
        a.push(0.1).push(1e-9).push(-3).push(123456789.0).push(10).push(100).push(1500.5).push(1e21);
        QCOMPARE(a.dump(), std::string("[0.1,1e-09,-3,123456789,10,100,1500.5,1e+21]"));
    }
    void writesNumbersWhateverTheLocale()
    {
        CatalanNumbers catalan;
        if (!catalan.active())
            QSKIP("the ca_ES.UTF-8 locale is not installed");
        Json a = Json::array();
        a.push(0.5).push(1500.25).push(-2.5e-7).push(12);
        QCOMPARE(a.dump(), std::string("[0.5,1500.25,-2.5e-07,12]"));
    }
    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        for (const char* bad : {"", "{", "[1,2", "{\"a\" 1}", "{a:1}", "[1,]", "nul", "[NaN]", "[1e999]", "\"abc", "[1] 2", "{\"a\":1,}"})
            QTest::newRow(bad) << QString(bad);
        QTest::newRow("deep") << QString(1000, '[');
    }
    void rejects()
    {
        QFETCH(QString, text);
        auto v = Json::parse(text.toStdString());
        QVERIFY(!v.ok());
        QVERIFY(v.error().message.find("line") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TestJson)
#include "test_json.moc"
