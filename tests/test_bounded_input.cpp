// Reading untrusted files with a bound on the bytes read, and quoting untrusted text in
// messages (issue 12, items 8 and 13).
#include "core/base/bounded_file.h"
#include "core/base/display_text.h"
#include "core/base/input_limits.h"
#include "catalan_locale.h"

#include <QTemporaryDir>
#include <QtTest>
#include "tests/test_main.h"

#include <cerrno>
#include <clocale>
#include <cstring>
#include <fstream>

using namespace granota;

class TestBoundedInput : public QObject {
    Q_OBJECT
private slots:
    void devicesStopAtTheBound()
    {
        // /dev/zero reports size 0 and never ends: the read stops just past the bound.
        for (const char* device : {"/dev/zero", "/dev/urandom"}) {
            const auto bytes = readBoundedFile(device, 4096);
            QVERIFY2(!bytes, device);
            QCOMPARE(bytes.error().code, ErrorCode::OutOfRange);
            QVERIFY(QString::fromStdString(bytes.error().message).contains("larger than 4096 bytes"));
        }
        const auto big = readBoundedFile("/dev/zero", kMaxFileBytes);
        QVERIFY(!big);
        QVERIFY(QString::fromStdString(big.error().message).contains("64 MB"));
    }
    void fileAtTheBoundIsRead()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("exact.csv").toStdString();
        std::ofstream(path, std::ios::binary) << std::string(1000, 'x');
        const auto exact = readBoundedFile(path, 1000);
        QVERIFY(exact);
        QCOMPARE(exact->size(), std::size_t(1000));
        QVERIFY(!readBoundedFile(path, 999));
        std::ofstream(path, std::ios::binary | std::ios::trunc);
        const auto empty = readBoundedFile(path, 10);
        QVERIFY(empty);
        QVERIFY(empty->empty());
    }
    void foldersAndMissingFilesAreNamed()
    {
        QTemporaryDir dir;
        const auto folder = readBoundedFile(dir.path().toStdString(), 100);
        QVERIFY(!folder);
        QVERIFY2(QString::fromStdString(folder.error().message).contains("is a folder"), folder.error().message.c_str());
        const auto missing = readBoundedFile(dir.filePath("nope.csv").toStdString(), 100);
        QVERIFY(!missing);
        QVERIFY(QString::fromStdString(missing.error().message).contains("No such file"));
    }
    // The reason in a command-line message is English on a Catalan desktop, as the message is.
    void systemErrorsAreEnglishInEveryLocale()
    {
        QVERIFY2(enterCatalanLocale(), kMissingCatalan);
        const std::string localized = std::strerror(ENOSPC); // what the old messages used
        QCOMPARE(QString::fromStdString(systemErrorText(ENOSPC)), QString("No space left on device"));
        QCOMPARE(QString::fromStdString(systemErrorText(ENOENT)), QString("No such file or directory"));
        const auto missing = readBoundedFile("/nonexistent/x.csv", 10);
        QVERIFY(!missing);
        QVERIFY2(QString::fromStdString(missing.error().message).contains("No such file"), missing.error().message.c_str());
        std::setlocale(LC_ALL, "C");
        QVERIFY2(localized != "No space left on device", "the Catalan locale has no Catalan messages");
    }
    void controlCharactersAreEscaped_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QByteArray>("shown");
        QTest::newRow("plain") << QByteArray("1.5x") << QByteArray("'1.5x'");
        QTest::newRow("terminal escape") << QByteArray("\033[2J\033]0;pwned\007x") << QByteArray("'\\x1b[2J\\x1b]0;pwned\\x07x'");
        QTest::newRow("newline and tab") << QByteArray("a\nb\tc\r") << QByteArray("'a\\nb\\tc\\r'");
        QTest::newRow("DEL") << QByteArray("a\x7f") << QByteArray("'a\\x7f'");
        QTest::newRow("C1 CSI") << QByteArray("a\xc2\x9b"
                                              "2J")
                                << QByteArray("'a\\xc2\\x9b2J'");
        QTest::newRow("accents kept") << QByteArray("Animació·é") << QByteArray("'Animació·é'");
        QTest::newRow("invalid UTF-8") << QByteArray("\xff\xc3") << QByteArray("'\\xff\\xc3'");
        QTest::newRow("overlong") << QByteArray("\xc0\xaf") << QByteArray("'\\xc0\\xaf'");
        QTest::newRow("NUL") << QByteArray("a\0b", 3) << QByteArray("'a\\x00b'");
    }
    void controlCharactersAreEscaped()
    {
        QFETCH(QByteArray, text);
        QFETCH(QByteArray, shown);
        QCOMPARE(QByteArray::fromStdString(quotedForDisplay(std::string_view(text.constData(), text.size()))), shown);
    }
    void longTextIsCutOnACharacter()
    {
        const std::string accents(200, 'x');
        const std::string shown = quotedForDisplay(accents, 10);
        QCOMPARE(QString::fromStdString(shown), QString("'xxxxxxxxxx…'"));
        std::string e;
        for (int i = 0; i < 20; ++i)
            e += "é";
        QCOMPARE(QString::fromStdString(quotedForDisplay(e, 3)), QString::fromUtf8("'ééé…'"));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBoundedInput)
#include "test_bounded_input.moc"
