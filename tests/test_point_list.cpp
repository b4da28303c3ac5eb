// Reading points: inline lists, CSV and JSON files; every coordinate exact; every kind of
// bad input a clear error naming where it is.
#include "core/base/input_limits.h"
#include "core/io/point_list.h"
#include "core/exact/polynomial_text.h"

#include "catalan_locale.h"

#include <QtTest>
#include "tests/test_main.h"

#include <algorithm>
#include <clocale>
#include <string>

using namespace granota;

namespace {

/// `count` points "i,i" as CSV lines, or as a JSON list.
std::string generatedPoints(std::size_t count, bool asJson)
{
    std::string text = asJson ? "[" : "";
    for (std::size_t i = 0; i < count; ++i) {
        const std::string n = std::to_string(i);
        text += asJson ? (i ? ",[" : "[") + n + "," + n + "]" : n + "," + n + "\n";
    }
    return asJson ? text + "]" : text;
}

} // namespace

class TestPointList : public QObject {
    Q_OBJECT
private slots:
    void inlineList()
    {
        auto p = parsePointList(" 2,3; -1/2, 8 ;0.25,-1e-3; ");
        QVERIFY(p.ok());
        QCOMPARE(int(p->size()), 3);
        QCOMPARE((*p)[1].x, frac(-1, 2));
        QCOMPARE((*p)[2].x, frac(1, 4));
        QCOMPARE((*p)[2].y, frac(-1, 1000)); // the decimal, exactly, not the nearest double
    }

    void csv()
    {
        auto p = parsePointCsv("x,y\n# a comment\n0,0\n\n1,3\r\n4, 2\n");
        QVERIFY(p.ok());
        QCOMPARE(int(p->size()), 3);
        QCOMPARE((*p)[2].x, Rational(4));
        auto bad = parsePointCsv("0,0\n1,3\n4,two\n");
        QVERIFY(!bad.ok());
        QVERIFY(bad.error().message.find("line 3") != std::string::npos);
        QVERIFY(bad.error().message.find("'two'") != std::string::npos);
    }

    // Issue 34, item 9: what a spreadsheet saves. LibreOffice or Excel in Catalan writes
    // "x;y" with decimal commas; a tab between the columns comes with either decimal sign.
    // Expected values are the fractions the decimals denote, written by hand.
    void spreadsheetColumns_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("semicolons, decimal commas") << "x;y\r\n0,5;-1,25\r\n2;3,75\r\n";
        QTest::newRow("tabs, decimal points") << "x\ty\n0.5\t-1.25\n2\t3.75\n";
        QTest::newRow("tabs, decimal commas") << "0,5\t-1,25\n2\t3,75\n";
        QTest::newRow("commas, decimal points") << "x,y\n0.5,-1.25\n2,3.75\n";
        QTest::newRow("semicolons, spaces") << " 0,5 ; -1,25\n2 ; 3,75\n";
    }
    void spreadsheetColumns()
    {
        QFETCH(QString, text);
        auto p = parsePointCsv(text.toStdString());
        QVERIFY2(p.ok(), p.ok() ? "" : p.error().message.c_str());
        QCOMPARE(int(p->size()), 2);
        QCOMPARE((*p)[0].x, frac(1, 2));
        QCOMPARE((*p)[0].y, frac(-5, 4));
        QCOMPARE((*p)[1].x, Rational(2));
        QCOMPARE((*p)[1].y, frac(15, 4));
        QVERIFY(parsePointFile(text.toStdString()).ok()); // what Fitting ▸ Import CSV reads
    }

    // Issue 34, item 5: an error names its sentence and values for the GUI's translation
    // (message_id.h) and keeps the English the CLI prints, as before.
    void errorsNameTheirSentence()
    {
        auto notANumber = parsePointCsv("0,0\n1,3\n4,two\n");
        QVERIFY(!notANumber.ok());
        const Error& e = notANumber.error();
        QCOMPARE(e.message, std::string("line 3: point 2: y = 'two' is not a finite number (write integers, decimals or "
                                        "fractions p/q)"));
        QCOMPARE(int(e.id), int(MessageId::CoordinateNotANumber));
        QCOMPARE(e.line, 3L);
        QCOMPARE(int(e.args.size()), 3);
        QCOMPARE(*e.args[0].number, 2.0);
        QCOMPARE(e.args[1].text, std::string("y"));
        QCOMPARE(e.args[2].text, std::string("'two'"));
        // Still three numbers on a line of a spreadsheet's file: no pair, said as such.
        auto three = parsePointCsv("1;2;3\n");
        QVERIFY(!three.ok());
        QCOMPARE(int(three.error().id), int(MessageId::PointNotAPair));
        QCOMPARE(three.error().line, 1L);
        QCOMPARE(three.error().message, std::string("line 1: point 0: expected \"x,y\", got '1;2;3'"));
        auto none = parsePointCsv("# nothing\n");
        QCOMPARE(int(none.error().id), int(MessageId::FileHoldsNoPoints));
    }

    void json()
    {
        auto p = parsePointJson(" [[0, 0], [\"7/2\", -2.5], [1e2,5]] ");
        QVERIFY(p.ok());
        QCOMPARE(int(p->size()), 3);
        QCOMPARE((*p)[1].x, frac(7, 2));
        QCOMPARE((*p)[1].y, frac(-5, 2));
        QCOMPARE((*p)[2].x, Rational(100));
        QVERIFY(parsePointFile("[[1,2]]").ok());
        QVERIFY(parsePointFile("1,2\n").ok());
    }
    void jsonDecimalsExact()
    {
        // The decimals as written, not the doubles nearest to them.
        auto p = parsePointJson("[[0.1, 3], [-0.30, 1e-3], [\"1/3\", 12345678901234567890.5]]");
        QVERIFY2(p.ok(), p.ok() ? "" : p.error().message.c_str());
        QCOMPARE((*p)[0].x, frac(1, 10));
        QCOMPARE((*p)[1].x, frac(-3, 10));
        QCOMPARE((*p)[1].y, frac(1, 1000));
        QCOMPARE((*p)[2].x, frac(1, 3));
        QCOMPARE((*p)[2].y, Rational(mpz_class("24691357802469135781"), mpz_class(2)));
        CatalanNumbers catalan; // where the decimal separator is a comma, too
        QVERIFY2(catalan.active(), kMissingCatalan);
        auto q = parsePointJson("[[0.1, 2.5]]");
        QVERIFY2(q.ok(), q.ok() ? "" : q.error().message.c_str());
        QCOMPARE((*q)[0].x, frac(1, 10));
        QCOMPARE((*q)[0].y, frac(5, 2));
    }
    void jsonErrorsSayWhere_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("syntax") << "[[1,2],\n [3 4]]"
                                << "at line 2, column 5";
        QTest::newRow("triple") << "[[1,2],[1,2,3]]"
                                << "point 1 is '[1,2,3]', not a pair [x,y]";
        QTest::newRow("not a list") << "{\"x\":1}"
                                    << "not a list";
        QTest::newRow("bad string") << "[[1,2],[\"two\",3]]"
                                    << "point 1: x = 'two' is not a finite number";
        QTest::newRow("null") << "[[1,null]]"
                              << "point 0: y = 'null' is not a finite number";
    }
    void jsonErrorsSayWhere()
    {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        auto p = parsePointJson(text.toStdString());
        QVERIFY(!p.ok());
        QVERIFY2(p.error().message.find(expected.toStdString()) != std::string::npos, p.error().message.c_str());
    }

    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("asJson");
        QTest::newRow("empty") << "" << false;
        QTest::newRow("NaN") << "0,0;nan,1" << false;
        QTest::newRow("inf") << "0,0;1,-inf" << false;
        QTest::newRow("three coordinates") << "0,0,0" << false;
        QTest::newRow("one coordinate") << "0,0;5" << false;
        QTest::newRow("empty item") << "0,0;;1,1" << false;
        QTest::newRow("letters") << "a,b" << false;
        QTest::newRow("json not a list") << "{\"x\":1}" << true;
        QTest::newRow("json triple") << "[[1,2,3]]" << true;
        QTest::newRow("json NaN") << "[[1,NaN]]" << true;
        QTest::newRow("json unterminated") << "[[1,2]" << true;
        QTest::newRow("json trailing text") << "[[1,2]] x" << true;
        QTest::newRow("json empty") << "[]" << true;
        QTest::newRow("json plus sign") << "[[+1,2]]" << true;      // not a JSON number: write "+1"
        QTest::newRow("json bare fraction") << "[[7/2,2]]" << true; // fractions go in strings: "7/2"
        QTest::newRow("json leading dot") << "[[.5,2]]" << true;    // nor is .5
        QTest::newRow("binary garbage") << QString::fromLatin1("\x01\x02\xff,\x03") << false;
    }
    void rejects()
    {
        QFETCH(QString, text);
        QFETCH(bool, asJson);
        const std::string s = text.toStdString();
        auto p = asJson ? parsePointJson(s) : parsePointList(s);
        QVERIFY(!p.ok());
        QVERIFY(!p.error().message.empty());
    }

    // A file saved by a spreadsheet or Notepad starts with a UTF-8 byte-order mark.
    void byteOrderMarkIsSkipped()
    {
        const std::string bom = "\xEF\xBB\xBF";
        for (const std::string& text :
             {bom + "x,y\n0,0\n1,3\n", bom + "0,0\n1,3\n", bom + "[[0,0],[1,3]]", bom + " [[0,0],[1,3]]"}) {
            for (auto reader : {parsePointFile, text.find('[') != std::string::npos ? parsePointJson : parsePointCsv}) {
                const auto p = reader(text);
                QVERIFY2(p.ok(), p.ok() ? "" : p.error().message.c_str());
                QCOMPARE(int(p->size()), 2);
                QCOMPARE((*p)[1].y, Rational(3));
            }
        }
        // Only at the start: a mark inside the text is still not a number.
        QVERIFY(!parsePointCsv("0,0\n" + bom + "1,3\n").ok());
    }

    // A cell with terminal escapes is shown escaped: a message cannot clear the screen.
    void errorsEscapeControlCharacters()
    {
        for (auto reader : {parsePointCsv, parsePointList}) {
            const auto p = reader("\033[2J\033]0;pwned\007x,1\n");
            QVERIFY(!p.ok());
            const std::string& m = p.error().message;
            for (char c : m)
                QVERIFY2(static_cast<unsigned char>(c) >= 0x20, m.c_str());
            QVERIFY2(m.find("\\x1b[2J") != std::string::npos, m.c_str());
        }
        const auto j = parsePointJson("[[\"\\u001b[2J\",1]]");
        QVERIFY(!j.ok());
        QVERIFY2(j.error().message.find("\\x1b") != std::string::npos, j.error().message.c_str());
    }

    // One limit for every reader, shared by the CLI and the GUI (core/base/input_limits.h).
    void atMostMaxDataPoints_data()
    {
        QTest::addColumn<bool>("asJson");
        QTest::newRow("CSV") << false;
        QTest::newRow("JSON") << true;
    }
    void atMostMaxDataPoints()
    {
        QFETCH(bool, asJson);
        const auto most = parsePointFile(generatedPoints(kMaxDataPoints, asJson));
        QVERIFY2(most.ok(), most.ok() ? "" : most.error().message.c_str());
        QCOMPARE(most->size(), kMaxDataPoints);
        const auto tooMany = parsePointFile(generatedPoints(kMaxDataPoints + 1, asJson));
        QVERIFY(!tooMany.ok());
        QVERIFY2(tooMany.error().message.find("more than " + std::to_string(kMaxDataPoints) + " points") != std::string::npos,
                 tooMany.error().message.c_str());
        std::string inlineList = generatedPoints(kMaxDataPoints + 1, false);
        std::replace(inlineList.begin(), inlineList.end(), '\n', ';');
        QVERIFY(!parsePointList(inlineList).ok());
    }

    void polynomialTextRoundTrips()
    {
        for (const char* s : {"2 - 6t - t^2", "-1/2 t + t^2 - 1/2 t^3", "t^4", "3", "-7t"}) {
            auto p = parsePolynomial(s);
            QVERIFY2(p.has_value(), s);
            QCOMPARE(QString::fromStdString(toText(*p)), QString(s));
        }
        QCOMPARE(*parsePolynomial("t + t"), (Polynomial<Rational>{Rational(0), Rational(2)}));
        for (const char* bad : {"", "2 +", "t^", "2x", "t t", "1/0 t"})
            QVERIFY2(!parsePolynomial(bad).has_value(), bad);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestPointList)
#include "test_point_list.moc"
