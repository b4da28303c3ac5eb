// No number in Granota's own code is converted with a function that follows the C locale,
// and no system error text is taken in the locale's language.
// On a ca_ES.UTF-8 desktop LC_NUMERIC has a decimal comma, and QApplication sets it from
// the environment: strtod("0.5") then reads 0 and printf("%g", 0.5) writes "0,5". The
// core's formatDouble/formatSignificant/formatFixed and std::from_chars, or QLocale::c()
// in ui/, are the ways in and out (ui/common/number_text.h explains which is for what).
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QTest>
#include "tests/test_main.h"

namespace {

/// The C and C++ conversions that read or write a decimal sign through the locale, and the
/// calls that would make the C++ streams follow it.
const QRegularExpression& bannedConversions()
{
    static const QRegularExpression banned(
        QStringLiteral("\\b(?:strto(?:d|f|ld)|ato[fil]|std::sto(?:d|f|ld|i|l|ll|ul|ull)|s?scanf|wcstod)\\s*\\(|"
                       "printf\\s*\\([^;]*%[-+ #0-9.*]*[fgeaFGEA]|"
                       "\\bstd::locale::global\\b|\\bimbue\\s*\\(\\s*std::locale\\s*\\(\\s*\"\"|"
                       // The system's error texts follow LC_MESSAGES: "No resta espai al dispositiu" inside an
                       // English command-line message. systemErrorText() gives them in English.
                       "\\b(?:strerror(?:_r)?|perror)\\s*\\("));
    return banned;
}

} // namespace

class TestLocaleFreeSources : public QObject {
    Q_OBJECT
private slots:
    void noLocaleDependentConversions()
    {
        const QRegularExpression& banned = bannedConversions();
        int files = 0;
        QStringList offenders;
        for (const char* dir : {"core", "app", "ui"}) {
            QDirIterator it(QStringLiteral(GRANOTA_SOURCE_DIR "/") + QLatin1String(dir),
                            {QStringLiteral("*.cpp"), QStringLiteral("*.h"), QStringLiteral("*.inc")}, QDir::Files,
                            QDirIterator::Subdirectories);
            while (it.hasNext()) {
                QFile f(it.next());
                QVERIFY(f.open(QIODevice::ReadOnly));
                ++files;
                int lineNo = 0;
                for (const QByteArray& line : f.readAll().split('\n')) {
                    ++lineNo;
                    const QString text = QString::fromUtf8(line);
                    if (text.trimmed().startsWith(QLatin1String("//")) || text.trimmed().startsWith(QLatin1String("///")))
                        continue;
                    if (banned.match(text).hasMatch())
                        offenders << QStringLiteral("%1:%2: %3").arg(f.fileName()).arg(lineNo).arg(text.trimmed());
                }
            }
        }
        QVERIFY(files > 100);
        QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join(QLatin1Char('\n'))));
    }

    void theCheckCatchesWhatItLooksFor()
    {
        // The pattern, on lines that must trip it and lines that must not.
        const QRegularExpression& banned = bannedConversions();
        for (const char* bad :
             {"double d = std::strtod(s, &end);", "std::snprintf(buf, n, \"%.9g\", v);", "x = std::stod(text);", "atof(p)",
              "std::locale::global(std::locale(\"\"));", "msg + std::strerror(errno)", "perror(\"x\")"})
            QVERIFY2(banned.match(QLatin1String(bad)).hasMatch(), bad);
        for (const char* good : {"std::from_chars(a, b, v);", "std::fprintf(stderr, \"%s\\n\", m);", "formatSignificant(v, 9)",
                                 "std::to_chars(buf, end, v);", "systemErrorText(errno)", "::strerrordesc_np(e)"})
            QVERIFY2(!banned.match(QLatin1String(good)).hasMatch(), good);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestLocaleFreeSources)
#include "test_locale_free_sources.moc"
