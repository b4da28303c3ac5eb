// The JSON reader/writer behind scenes, examples and the CLI's output.
#include "core/io/json.h"

#include "catalan_locale.h"

#include <QtTest>

#include <algorithm>
#include "tests/test_main.h"

#include <clocale>
#include <cmath>
#include <limits>
#include <string>

using namespace granota;

namespace {


std::string bytes(const QByteArray& a) { return std::string(a.constData(), static_cast<std::size_t>(a.size())); }

/// Whether `s` ends with `tail`.
bool endsWith(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

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
        QVERIFY2(catalan.active(), kMissingCatalan);
        Json a = Json::array();
        a.push(0.5).push(1500.25).push(-2.5e-7).push(12);
        QCOMPARE(a.dump(), std::string("[0.5,1500.25,-2.5e-07,12]"));
    }
    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        for (const char* bad :
             {"", "{", "[1,2", "{\"a\" 1}", "{a:1}", "[1,]", "nul", "[NaN]", "[1e999]", "\"abc", "[1] 2", "{\"a\":1,}"})
            QTest::newRow(bad) << QString(bad);
        QTest::newRow("deep") << QString(1000, '[');
    }
    void rejects()
    {
        QFETCH(QString, text);
        auto v = Json::parse(text.toStdString());
        QVERIFY(!v.ok());
        // Where it goes wrong, by line; an empty text has no place to name.
        QVERIFY2(v.error().message.find("line") != std::string::npos || v.error().message == "JSON: the file is empty",
                 v.error().message.c_str());
    }

    // A document cut short (a full disk, a copy stopped half-way) is said in plain words with
    // the byte where it stops — not the parser's "unexpected end of input" or "invalid
    // literal". Every cut of a document that touches each kind of value: N is the length
    // of the cut, and the line is one more than the newlines kept.
    void cutOffDocuments()
    {
        const std::string doc = "{\"format\": \"granota\",\n \"a\": [1.5, -2e3, true, \"x\\u00e9y\", null],\n"
                                " \"b\": {\"c\": false, \"d\": \"é\"}}";
        QVERIFY(Json::parse(doc).ok());
        for (std::size_t n = 1; n < doc.size(); ++n) {
            const std::string cut = doc.substr(0, n);
            const auto v = Json::parse(cut);
            QVERIFY2(!v.ok(), cut.c_str());
            const long line = 1 + std::count(cut.begin(), cut.end(), '\n');
            const std::string expected = "JSON: the file is cut off at byte " + std::to_string(n) + " (line " +
                                         std::to_string(line) + ")";
            QVERIFY2(v.error().message == expected, (cut + " → " + v.error().message).c_str());
        }
        QCOMPARE(Json::parse("").error().message, std::string("JSON: the file is empty"));
        QCOMPARE(Json::parse(" \n\t").error().message, std::string("JSON: the file holds only blanks"));
        // Text that goes wrong before its end is still placed by line and column.
        QVERIFY(endsWith(Json::parse("[tx]").error().message, "at line 1, column 3"));
    }

    // Numbers exactly as RFC 8259 writes them; the error names where the number goes wrong.
    void strictNumbers_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("where");
        QTest::newRow("plus sign") << QByteArray("+1") << QByteArray("at line 1, column 1");
        QTest::newRow("leading zero") << QByteArray("[0, 01]") << QByteArray("at line 1, column 6");
        QTest::newRow("negative leading zero") << QByteArray("-01") << QByteArray("at line 1, column 3");
        QTest::newRow("no integer part") << QByteArray("[.5]") << QByteArray("at line 1, column 2");
        QTest::newRow("no fraction digits") << QByteArray("[1.]") << QByteArray("at line 1, column 4");
        QTest::newRow("no fraction before exponent") << QByteArray("1.e5") << QByteArray("at line 1, column 3");
        QTest::newRow("no exponent digits") << QByteArray("[1e]") << QByteArray("at line 1, column 4");
        QTest::newRow("no exponent digits, at the end") << QByteArray("1e") << QByteArray("cut off at byte 2 (line 1)");
        QTest::newRow("exponent sign alone") << QByteArray("[1e+]") << QByteArray("at line 1, column 5");
        QTest::newRow("minus alone") << QByteArray("[-]") << QByteArray("at line 1, column 3");
        QTest::newRow("minus alone, at the end") << QByteArray("-") << QByteArray("cut off at byte 1 (line 1)");
        QTest::newRow("hexadecimal") << QByteArray("0x10") << QByteArray("at line 1, column 2");
    }
    void strictNumbers()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, where);
        auto v = Json::parse(bytes(text));
        QVERIFY2(!v.ok(), text.constData());
        QVERIFY2(v.error().message.rfind("JSON: ", 0) == 0, v.error().message.c_str());
        QVERIFY2(endsWith(v.error().message, bytes(where)), v.error().message.c_str());
    }
    void acceptsNumbers_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<double>("value");
        QTest::newRow("zero") << QByteArray("0") << 0.0;
        QTest::newRow("fraction") << QByteArray("-0.5") << -0.5;
        QTest::newRow("exponent") << QByteArray("1E+2") << 100.0;
        QTest::newRow("negative exponent") << QByteArray("-1.5e-3") << -1.5e-3;
        QTest::newRow("beyond 64 bits") << QByteArray("123456789012345678901234567890") << 1.2345678901234568e29;
        QTest::newRow("largest double") << QByteArray("1.7976931348623157e308") << std::numeric_limits<double>::max();
        QTest::newRow("smallest double") << QByteArray("4.9e-324") << std::numeric_limits<double>::denorm_min();
        QTest::newRow("below the smallest double") << QByteArray("1e-400") << 0.0;
    }
    void acceptsNumbers()
    {
        QFETCH(QByteArray, text);
        QFETCH(double, value);
        auto v = Json::parse(bytes(text));
        QVERIFY2(v.ok(), v.ok() ? "" : v.error().message.c_str());
        QCOMPARE(*v->asNumber(), value);
    }
    void tooLargeNumbers_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("number");
        QTest::addColumn<QByteArray>("where");
        const QByteArray many = "1" + QByteArray(400, '0');
        QTest::newRow("1e400") << QByteArray("1e400") << QByteArray("1e400") << QByteArray("at line 1, column 1");
        QTest::newRow("negative") << QByteArray("[0, -1e400]") << QByteArray("-1e400") << QByteArray("at line 1, column 5");
        QTest::newRow("in an object") << QByteArray("{\"g\":\n  2e308}") << QByteArray("2e308")
                                      << QByteArray("at line 2, column 3");
        QTest::newRow("many digits") << many << many << QByteArray("at line 1, column 1");
    }
    void tooLargeNumbers()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, number);
        QFETCH(QByteArray, where);
        auto v = Json::parse(bytes(text));
        QVERIFY(!v.ok());
        const std::string& m = v.error().message;
        QVERIFY2(m.find("the number " + bytes(number) + " is too large for a double") != std::string::npos, m.c_str());
        QVERIFY2(endsWith(m, bytes(where)), m.c_str());
    }
    void rejectsNanAndInfinity_data()
    {
        QTest::addColumn<QByteArray>("text");
        for (const char* bad : {"NaN", "[NaN]", "nan", "-nan", "Infinity", "[-Infinity]", "inf", "[1, -inf]", "{\"g\": NaN}"})
            QTest::newRow(bad) << QByteArray(bad);
    }
    void rejectsNanAndInfinity()
    {
        QFETCH(QByteArray, text);
        auto v = Json::parse(bytes(text));
        QVERIFY(!v.ok());
        QVERIFY2(v.error().message.find(" at line 1, column ") != std::string::npos, v.error().message.c_str());
    }

    // A number read keeps its text, for readers that want it exactly.
    void numberTextAsWritten()
    {
        auto v = Json::parse("[0.10, -0, 1E+2, 123456789012345678901234567890, 7, {\"x\": 2.50}]");
        QVERIFY(v.ok());
        const Json::Array& a = *v->asArray();
        QCOMPARE(std::string(*a[0].numberText()), std::string("0.10"));
        QCOMPARE(std::string(*a[1].numberText()), std::string("-0"));
        QVERIFY(std::signbit(*a[1].asNumber()));
        QCOMPARE(std::string(*a[2].numberText()), std::string("1E+2"));
        QCOMPARE(std::string(*a[3].numberText()), std::string("123456789012345678901234567890"));
        QCOMPARE(std::string(*a[4].numberText()), std::string("7"));
        const Json copy = a[5];
        QCOMPARE(std::string(*copy.find("x")->numberText()), std::string("2.50"));
        // Output is unchanged by it: the shortest form of the double.
        QCOMPARE(v->dump(), std::string("[0.1,0,100,1.2345678901234568e+29,7,{\"x\":2.5}]"));
        // Only parsed numbers have a text.
        QVERIFY(!Json(0.5).numberText());
        QVERIFY(!Json(3).numberText());
        QVERIFY(!Json("0.5").numberText());
        QVERIFY(!Json().numberText());
        QVERIFY(!v->numberText());
    }
    void readsNumbersWhateverTheLocale()
    {
        CatalanNumbers catalan;
        QVERIFY2(catalan.active(), kMissingCatalan);
        auto v = Json::parse("[0.5, -1.25e3, 2]");
        QVERIFY2(v.ok(), v.ok() ? "" : v.error().message.c_str());
        const Json::Array& a = *v->asArray();
        QCOMPARE(*a[0].asNumber(), 0.5);
        QCOMPARE(*a[1].asNumber(), -1250.0);
        QCOMPARE(std::string(*a[0].numberText()), std::string("0.5"));
        QCOMPARE(std::string(*a[1].numberText()), std::string("-1.25e3"));
        QCOMPARE(int(Json::parse("[0,5]")->asArray()->size()), 2); // two numbers, not 0.5
    }

    void unicodeEscapes()
    {
        auto frog = Json::parse("\"\\ud83d\\udc38\"");
        QVERIFY2(frog.ok(), frog.ok() ? "" : frog.error().message.c_str());
        QCOMPARE(*frog->asString(), std::string("\xf0\x9f\x90\xb8")); // U+1F438 in UTF-8
        QCOMPARE(*Json::parse("\"\\u0041\\u00e9\\u20AC\"")->asString(), std::string("A\xc3\xa9\xe2\x82\xac"));
        QCOMPARE(*Json::parse("\"\\u0000\"")->asString(), std::string(1, '\0')); // escaped NUL is fine
    }
    void rejectsBadEscapes_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("where");
        QTest::newRow("not hexadecimal") << QByteArray("\"\\u00zz\"") << QByteArray("at line 1, column 6");
        QTest::newRow("signed") << QByteArray("\"\\u-123\"") << QByteArray("at line 1, column 4");
        QTest::newRow("too short") << QByteArray("\"\\u12\"") << QByteArray("at line 1, column 6");
        QTest::newRow("lone high surrogate") << QByteArray("\"\\ud83d\"") << QByteArray("at line 1, column 8");
        QTest::newRow("high then not low") << QByteArray("\"\\ud83d\\u0041\"") << QByteArray("at line 1, column 13");
        QTest::newRow("lone low surrogate") << QByteArray("[\"\\udc38\"]") << QByteArray("at line 1, column 8");
        QTest::newRow("unknown escape") << QByteArray("[\"\\x\"]") << QByteArray("at line 1, column 4");
    }
    void rejectsBadEscapes()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, where);
        auto v = Json::parse(bytes(text));
        QVERIFY2(!v.ok(), text.constData());
        QVERIFY2(endsWith(v.error().message, bytes(where)), v.error().message.c_str());
    }
    void rejectsIllFormedUtf8_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("stray byte") << QByteArray("\"\xff\"");
        QTest::newRow("cut short") << QByteArray("\"\xc3\"");
        QTest::newRow("encoded surrogate") << QByteArray("\"\xed\xa0\xbd\"");
    }
    void rejectsIllFormedUtf8()
    {
        QFETCH(QByteArray, text);
        QVERIFY(!Json::parse(bytes(text)).ok());
        QVERIFY(Json::parse("\"\xc3\xa9\xf0\x9f\x90\xb8\"").ok()); // é and the frog, well formed
    }

    void nestingLimit()
    {
        constexpr int kLimit = 256;
        QVERIFY(Json::parse(std::string(kLimit, '[') + std::string(kLimit, ']')).ok());
        std::string objects;
        for (int i = 0; i < kLimit; ++i)
            objects += "{\"a\":";
        objects += "1" + std::string(kLimit, '}');
        QVERIFY(Json::parse(objects).ok());
        auto deep = Json::parse("[\n" + std::string(kLimit, '[') + std::string(kLimit + 1, ']'));
        QVERIFY(!deep.ok());
        QCOMPARE(deep.error().message,
                 std::string("JSON: arrays and objects nested deeper than 256 levels at line 2, column 256"));
        QVERIFY(!Json::parse(std::string(1000000, '[')).ok()); // an error, not a stack overflow
    }

    // The line and column are those of the first byte that cannot continue the JSON text.
    void errorPositions_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("where");
        QTest::newRow("bad value") << QByteArray("{\n  \"a\": 1,\n  \"b\": x\n}") << QByteArray("at line 3, column 8");
        QTest::newRow("CRLF lines") << QByteArray("{\r\n  \"a\": 1,\r\n  \"b\": ]}") << QByteArray("at line 3, column 8");
        QTest::newRow("trailing comma") << QByteArray("[1,\n\n  2,]") << QByteArray("at line 3, column 5");
        QTest::newRow("end of text") << QByteArray("[1,\n2") << QByteArray("cut off at byte 5 (line 2)");
        QTest::newRow("newline in a string") << QByteArray("[\"a\nb\"]") << QByteArray("at line 1, column 4");
        QTest::newRow("tab in a string") << QByteArray("{\"a\":\n\"x\ty\"}") << QByteArray("at line 2, column 3");
        QTest::newRow("bad escape") << QByteArray("[\"\\q\"]") << QByteArray("at line 1, column 4");
    }
    void errorPositions()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, where);
        auto v = Json::parse(bytes(text));
        QVERIFY(!v.ok());
        QVERIFY2(v.error().message.rfind("JSON: ", 0) == 0, v.error().message.c_str());
        QVERIFY2(endsWith(v.error().message, bytes(where)), v.error().message.c_str());
    }

    void rejectsTrailingText_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("where");
        QTest::newRow("second value") << QByteArray("[1] 2") << QByteArray("at line 1, column 5");
        QTest::newRow("word") << QByteArray("{}\nx") << QByteArray("at line 2, column 1");
        QTest::newRow("glued literal") << QByteArray("truex") << QByteArray("at line 1, column 5");
        QTest::newRow("two strings") << QByteArray("\"a\"\"b\"") << QByteArray("at line 1, column 4");
        QTest::newRow("two numbers") << QByteArray("[12 345]") << QByteArray("at line 1, column 5");
        QTest::newRow("two literals") << QByteArray("{\"a\": true\nfalse}") << QByteArray("at line 2, column 1");
        QTest::newRow("extra bracket") << QByteArray("[1]]") << QByteArray("at line 1, column 4");
        QTest::newRow("NUL then text") << QByteArray("[1]\0x", 5) << QByteArray("at line 1, column 4");
        QTest::newRow("NUL at the end") << QByteArray("[1]\0", 4) << QByteArray("at line 1, column 4");
    }
    void rejectsTrailingText()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, where);
        auto v = Json::parse(bytes(text));
        QVERIFY(!v.ok());
        QVERIFY2(endsWith(v.error().message, bytes(where)), v.error().message.c_str());
    }

    void repeatedKeyKeepsItsPlace()
    {
        auto v = Json::parse("{\"b\":1,\"a\":2,\"b\":3}");
        QVERIFY(v.ok());
        QCOMPARE(v->dump(), std::string("{\"b\":3,\"a\":2}"));
    }
    void writesControlCharactersEscaped()
    {
        QCOMPARE(Json(std::string("a\x01\x1f\b\f\n\t\r\"\\")).dump(),
                 std::string("\"a\\u0001\\u001f\\u0008\\u000c\\n\\t\\r\\\"\\\\\""));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestJson)
#include "test_json.moc"
