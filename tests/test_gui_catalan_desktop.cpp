// Granota on a Catalan desktop (LANG=LC_ALL=ca_ES.UTF-8, the interface in Catalan): every
// scene loads and draws, documents round-trip, every export is read by a C-locale reader,
// and what the window shows a person uses the decimal comma — in spin boxes, tables,
// readouts and plot axes — while a typed point is still accepted.
#include "catalan_locale.h"
#include "main_window_steps.h"
#include "gui_timeouts.h"

#include "ui/common/decimal_spin_box.h"
#include "ui/shell/document.h"
#include "ui/common/drawable.h"
#include "ui/frog/frog_parameters_panel.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/number_text.h"
#include "ui/common/tab_page.h"

#include "core/softbody/scenes/scene.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"
#include <qcustomplot.h>

#include <algorithm>
#include <charconv>
#include <cmath>

using granota::ui::MainWindow;

namespace {

const QStringList kTabs = {QStringLiteral("decasteljau"), QStringLiteral("bernstein"), QStringLiteral("fit"),
                           QStringLiteral("catmull-rom"), QStringLiteral("frog")};

/// A C-locale number: all of `text`, read by from_chars (which never sees the locale).
bool isCNumber(const QString& text)
{
    const QByteArray b = text.trimmed().toLatin1();
    double v = 0;
    const auto r = std::from_chars(b.constData(), b.constData() + b.size(), v);
    return !b.isEmpty() && r.ec == std::errc() && r.ptr == b.constData() + b.size() && std::isfinite(v);
}

QByteArray readFile(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

int colours(const QImage& image)
{
    QSet<QRgb> seen;
    for (int y = 0; y < image.height(); y += 5)
        for (int x = 0; x < image.width(); x += 5)
            seen.insert(image.pixel(x, y));
    return static_cast<int>(seen.size());
}

} // namespace

class TestGuiCatalanDesktop : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        // QApplication has set LC_NUMERIC from the environment; a Catalan desktop's for sure.
        QVERIFY2(enterCatalanLocale(), kMissingCatalan);
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("GranotaTest"));
        QCoreApplication::setApplicationName(QStringLiteral("GranotaCatalanTest"));
        QVERIFY(granota::ui::setLanguage(QStringLiteral("ca"), false));
    }
    void cleanupTestCase() { granota::ui::setLanguage(QStringLiteral("en"), false); }

    void everySceneLoadsAndDraws()
    {
        MainWindow window;
        window.resize(1024, 768);
        window.show();
        QVERIFY(waitExposed(&window));
        QVERIFY(window.showTab(QStringLiteral("frog")));
        granota::ui::FrogTab* frog = window.frogTab();
        QTemporaryDir dir;
        for (const std::string& n : granota::sceneNames()) {
            const QString name = QString::fromStdString(n);
            QString error;
            QVERIFY2(frog->setScene(name, &error), qPrintable(name + ": " + error));
            QCOMPARE(frog->sceneName(), name);
            // The parameter panel lists the scene's parameters (blank when the scene failed).
            QVERIFY2(!frog->parametersPanel()->findChildren<QDoubleSpinBox*>().isEmpty(), qPrintable(name));
            const QString png = dir.filePath(name + QStringLiteral(".png"));
            QCOMPARE(window.exportCurrent(QStringLiteral("png"), png), QString());
            const QImage image(png);
            QVERIFY2(!image.isNull(), qPrintable(name));
            QVERIFY2(colours(image) > 8, qPrintable(name + QStringLiteral(": a blank canvas")));
        }
    }

    void aFailingSceneShowsTheCoresMessage()
    {
        const QString known = granota::ui::FrogTab::sceneLoadError(
            QStringLiteral("frog"), granota::makeError(granota::ErrorCode::InvalidInput, "JSON: bad number at line 3, column 7"));
        QVERIFY2(known.contains(QStringLiteral("JSON: bad number at line 3, column 7")), qPrintable(known));
        QVERIFY2(known.contains(QStringLiteral("frog")), qPrintable(known));
        const QString unknown = granota::ui::FrogTab::sceneLoadError(
            QStringLiteral("dragons"), granota::makeError(granota::ErrorCode::InvalidInput, "unknown scene"));
        QVERIFY2(unknown.contains(QStringLiteral("dragons")) && unknown.contains(QStringLiteral("frog")), qPrintable(unknown));
        QVERIFY(unknown != known);
    }

    void documentRoundTripsExactly()
    {
        const TemporaryDocument file(QStringLiteral("lliçó.granota"));
        QByteArray saved;
        {
            MainWindow window;
            QVERIFY(loadExamples(window, {"2.3", "2.9", "2.12"}));
            QString error;
            QVERIFY2(window.frogTab()->setScene(QStringLiteral("pendulum-limits"), &error), qPrintable(error));
            QVERIFY2(window.frogTab()->setScene(QStringLiteral("frog"), &error), qPrintable(error));
            QVERIFY2(window.frogTab()->editParameter(QStringLiteral("area_factor"), QJsonValue(0.035), &error),
                     qPrintable(error));
            QVERIFY2(window.saveFile(file.path(), &error), qPrintable(error));
            saved = documentOf(window);
        }
        const QByteArray bytes = readFile(file.path());
        QVERIFY(bytes.contains("0.035"));
        QVERIFY(!bytes.contains("0,035"));
        MainWindow reopened;
        QString error;
        QVERIFY2(reopened.openFile(file.path(), &error), qPrintable(error));
        QCOMPARE(documentOf(reopened), saved);
    }

    void everyExportReadsInTheCLocale()
    {
        MainWindow window;
        window.resize(1024, 768);
        window.show();
        QVERIFY(waitExposed(&window));
        QVERIFY(window.loadExample(QStringLiteral("2.9"))); // decimals in the fit
        QTemporaryDir dir;
        for (const QString& key : kTabs) {
            QVERIFY(window.showTab(key));
            // CSV: every field after the header a C-locale number, all rows as wide as the header.
            const QString csv = dir.filePath(key + QStringLiteral(".csv"));
            QCOMPARE(window.exportCurrent(QStringLiteral("csv"), csv), QString());
            const QStringList lines = QString::fromUtf8(readFile(csv)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            QVERIFY2(lines.size() >= 3, qPrintable(key));
            int width = -1, numeric = 0;
            for (const QString& line : lines) {
                if (line.startsWith(QLatin1Char('#')))
                    continue;
                const QStringList fields = line.split(QLatin1Char(','));
                if (std::none_of(fields.begin(), fields.end(), isCNumber))
                    width = -1; // the header of the next section (the fit writes data, then control points)
                if (width < 0) {
                    width = static_cast<int>(fields.size());
                    continue;
                }
                if (fields.size() != width) {
                    QVERIFY2(false, qPrintable(key + QStringLiteral(": ") + line));
                }
                for (const QString& f : fields)
                    if (isCNumber(f))
                        ++numeric;
                    else
                        QVERIFY2(!QRegularExpression(QStringLiteral("^-?\\d+,\\d")).match(f).hasMatch(), qPrintable(line));
            }
            QVERIFY2(numeric > lines.size(), qPrintable(key));
            // TikZ: every coordinate "(x,y)" is two C numbers (a decimal comma would make three).
            const QString tex = dir.filePath(key + QStringLiteral(".tex"));
            QCOMPARE(window.exportCurrent(QStringLiteral("tikz"), tex), QString());
            const QString tikz = QString::fromUtf8(readFile(tex));
            static const QRegularExpression coord(QStringLiteral("\\((-?[0-9.][^()]*)\\)"));
            int pairs = 0;
            for (auto it = coord.globalMatch(tikz); it.hasNext();) {
                const auto m = it.next();
                const QStringList xy = m.captured(1).split(QLatin1Char(','));
                if (xy.size() == 1)
                    continue; // "(4.16)": a section of the thesis in a comment, not a coordinate
                QVERIFY2(xy.size() == 2 && isCNumber(xy[0]) && isCNumber(xy[1]),
                         qPrintable(key + QStringLiteral(": ") + m.captured(0)));
                ++pairs;
            }
            QVERIFY2(pairs > 2, qPrintable(key));
            // SVG: every coordinate attribute is a C number (QSvgGenerator writes its own).
            const QString svg = dir.filePath(key + QStringLiteral(".svg"));
            QCOMPARE(window.exportCurrent(QStringLiteral("svg"), svg), QString());
            const QString svgText = QString::fromUtf8(readFile(svg));
            static const QRegularExpression attr(QStringLiteral("\\b(?:x|y|width|height|stroke-width)=\"([^\"]*)\""));
            int numbers = 0;
            for (auto it = attr.globalMatch(svgText); it.hasNext();) {
                QString v = it.next().captured(1);
                v.remove(QRegularExpression(QStringLiteral("(px|mm|pt|%)$")));
                QVERIFY2(isCNumber(v), qPrintable(key + QStringLiteral(": ") + v));
                ++numbers;
            }
            QVERIFY2(numbers > 0, qPrintable(key));
            // PDF: a valid file; PNG: the screen's picture.
            const QString pdf = dir.filePath(key + QStringLiteral(".pdf"));
            QCOMPARE(window.exportCurrent(QStringLiteral("pdf"), pdf), QString());
            QVERIFY(readFile(pdf).startsWith("%PDF-"));
            const QString png = dir.filePath(key + QStringLiteral(".png"));
            QCOMPARE(window.exportCurrent(QStringLiteral("png"), png, 150), QString());
            QVERIFY(colours(QImage(png)) > 4);
        }
    }

    void theWindowShowsDecimalCommas()
    {
        MainWindow window;
        window.resize(1024, 768);
        window.show();
        QVERIFY(waitExposed(&window));
        QCOMPARE(granota::ui::displayNumber(0.25), QStringLiteral("0,25"));
        QCOMPARE(granota::ui::displayPoint(1.5, -2), QStringLiteral("(1,5; -2)"));
        QCOMPARE(granota::ui::displayText("(0.5 - 1.25t, 3)"), QStringLiteral("(0,5 - 1,25t; 3)"));
        QCOMPARE(granota::ui::displayText("(1/2 - 3t, 11/2)"), QStringLiteral("(1/2 - 3t, 11/2)")); // as the thesis prints it
        QCOMPARE(granota::ui::displayPoint(2, -3), QStringLiteral("(2, -3)"));
        QCOMPARE(granota::ui::displaySignificant(3.66950989e-08, 2), QStringLiteral("3,7e-08"));
        // Spin boxes: the frog's parameters.
        QVERIFY(window.showTab(QStringLiteral("frog")));
        QVERIFY(window.frogTab()->setScene(QStringLiteral("frog"), nullptr));
        int decimals = 0;
        for (QDoubleSpinBox* spin : window.frogTab()->parametersPanel()->findChildren<QDoubleSpinBox*>()) {
            QVERIFY2(!spin->text().contains(QLatin1Char('.')),
                     qPrintable(spin->objectName() + QStringLiteral(": ") + spin->text()));
            if (spin->text().contains(QLatin1Char(',')))
                ++decimals;
        }
        QVERIFY(decimals > 0);
        // The point table: a typed 0.05688 as "0,05688", 1.25 as "1,25" (a column of short decimals).
        QVERIFY(window.showTab(QStringLiteral("fit")));
        auto* table = window.currentTab()->findChild<QTableWidget*>();
        QVERIFY(table);
        table->item(0, 0)->setText(QStringLiteral("0,05688"));
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("0,05688"));
        table->item(0, 1)->setText(QStringLiteral("1.25")); // a typed point is accepted too
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("1,25"));
        // Plot axes.
        for (QCustomPlot* plot : window.findChildren<QCustomPlot*>())
            QCOMPARE(plot->locale().decimalPoint(), QStringLiteral(","));
        // A live switch to English: points everywhere, plots included.
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
        QCoreApplication::processEvents(); // the LanguageChange events are posted
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("0.05688"));
        for (QCustomPlot* plot : window.findChildren<QCustomPlot*>())
            QCOMPARE(plot->locale().decimalPoint(), QStringLiteral("."));
        for (QDoubleSpinBox* spin : window.frogTab()->parametersPanel()->findChildren<QDoubleSpinBox*>())
            QVERIFY2(!spin->text().contains(QLatin1Char(',')),
                     qPrintable(spin->objectName() + QStringLiteral(": ") + spin->text()));
        QVERIFY(granota::ui::setLanguage(QStringLiteral("ca"), false));
        QCoreApplication::processEvents();
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("0,05688"));
    }

    // Issue 34, item 8: nothing shows a minus on a zero ("-0,0 %" was an area error of
    // −0.0001 % at one decimal); a number that is not zero keeps its sign.
    void noNumberShowsMinusZero()
    {
        QCOMPARE(granota::ui::displayFixed(-0.0001, 1), QStringLiteral("0,0"));
        QCOMPARE(granota::ui::displayFixed(-0.0, 2), QStringLiteral("0,00"));
        QCOMPARE(granota::ui::displayNumber(-0.0), QStringLiteral("0"));
        QCOMPARE(granota::ui::displaySignificant(-0.0, 4), QStringLiteral("0"));
        QCOMPARE(granota::ui::displayFixed(-0.06, 1), QStringLiteral("-0,1"));
        QCOMPARE(granota::ui::displaySignificant(-1e-300, 2), QStringLiteral("-1e-300"));
    }

    void aCatalanSpinBoxReadsACommaOrAPoint()
    {
        granota::ui::DecimalSpinBox spin;
        spin.setLocale(granota::ui::displayLocale(QStringLiteral("ca")));
        spin.setRange(0, 100);
        spin.setDecimals(3);
        QCOMPARE(spin.valueFromText(QStringLiteral("1,5")), 1.5);
        QCOMPARE(spin.valueFromText(QStringLiteral("1.5")), 1.5); // not 15: a point is not a group separator here
        QString typed = QStringLiteral("2.25");
        int pos = 4;
        QCOMPARE(spin.validate(typed, pos), QValidator::Acceptable);
        spin.setValue(0.125);
        QCOMPARE(spin.text(), QStringLiteral("0,125"));
        spin.selectAll();
        QTest::keyClicks(&spin, QStringLiteral("7.5"));
        QTest::keyClick(&spin, Qt::Key_Return);
        QCOMPARE(spin.value(), 7.5);
        spin.setLocale(granota::ui::displayLocale(QStringLiteral("en")));
        QCOMPARE(spin.valueFromText(QStringLiteral("1.5")), 1.5);
    }
};

GRANOTA_TEST_MAIN(TestGuiCatalanDesktop)
#include "test_gui_catalan_desktop.moc"
