// The main window as a whole (issue: the application): every tab present, every worked
// example loads into its tab, documents round-trip, exports are valid files, a live
// language switch retranslates every visible text, autosave and presentation mode, and the
// command-line options of docs/classroom.md on the real binary.
#include "ui/common/curve_canvas.h"
#include "ui/common/drawable.h"
#include "ui/files/exporter.h"
#include "ui/shell/document.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/shell/tikz_options_dialog.h"
#include "ui/common/work_precision_panel.h"
#include "ui/common/work_precision_plot.h"
#include "ui/frog/frog_tab.h"
#include "gui_timeouts.h"

#include "main_window_steps.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QTimer>
#include <QSettings>
#include <QDoubleSpinBox>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QGroupBox>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTabWidget>
#include <QTableWidget>
#include <QHeaderView>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"
#include <QXmlStreamReader>
#include <qcustomplot.h>

#include <algorithm>
#include <map>

using granota::ui::MainWindow;
using granota::ui::TabPage;

namespace {

const QStringList kTabs = {QStringLiteral("decasteljau"), QStringLiteral("bernstein"), QStringLiteral("fit"),
                           QStringLiteral("catmull-rom"), QStringLiteral("frog"),      QStringLiteral("bspline")};

/// Every user-visible text of the window, keyed by where it is: widget texts, titles,
/// tooltips, placeholders, combo items, table headers, tab titles, menu and action texts.
std::map<QString, QString> visibleTexts(MainWindow& window)
{
    std::map<QString, QString> texts;
    auto add = [&texts](const QString& where, const QString& text) {
        QString t = text;
        t.remove(QLatin1Char('&'));
        if (!t.trimmed().isEmpty())
            texts[where] = t;
    };
    int counter = 0;
    for (QWidget* w : window.findChildren<QWidget*>()) {
        const QString id = QStringLiteral("%1#%2").arg(QString::fromLatin1(w->metaObject()->className())).arg(counter++);
        add(id + QStringLiteral(".toolTip"), w->toolTip());
        if (auto* l = qobject_cast<QLabel*>(w))
            add(id + QStringLiteral(".text"), l->text());
        if (auto* b = qobject_cast<QAbstractButton*>(w))
            add(id + QStringLiteral(".text"), b->text());
        if (auto* g = qobject_cast<QGroupBox*>(w))
            add(id + QStringLiteral(".title"), g->title());
        if (auto* c = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < c->count(); ++i)
                add(id + QStringLiteral(".item%1").arg(i), c->itemText(i));
        if (auto* t = qobject_cast<QTableWidget*>(w))
            for (int i = 0; i < t->columnCount(); ++i)
                if (auto* h = t->horizontalHeaderItem(i))
                    add(id + QStringLiteral(".header%1").arg(i), h->text());
        if (auto* tabs = qobject_cast<QTabWidget*>(w))
            for (int i = 0; i < tabs->count(); ++i)
                add(id + QStringLiteral(".tab%1").arg(i), tabs->tabText(i));
        if (auto* m = qobject_cast<QMenu*>(w))
            add(id + QStringLiteral(".title"), m->title());
    }
    int a = 0;
    for (QAction* action : window.findChildren<QAction*>()) {
        if (action->isSeparator())
            continue;
        add(QStringLiteral("action#%1.text").arg(a), action->text());
        add(QStringLiteral("action#%1.toolTip").arg(a++),
            action->toolTip() == action->text().remove(QLatin1Char('&')) ? QString() : action->toolTip());
    }
    return texts;
}

/// Texts that are the same in Catalan and English: names, symbols and numbers.
bool languageNeutral(const QString& text)
{
    static const QStringList names = {QStringLiteral("De Casteljau"), QStringLiteral("Bernstein"), QStringLiteral("Catmull-Rom"),
                                      QStringLiteral("Granota"), QStringLiteral("Català"), QStringLiteral("English"),
                                      QStringLiteral("TikZ"), QStringLiteral("QR"), QStringLiteral("SVD"), QStringLiteral("PNG"),
                                      QStringLiteral("SVG"), QStringLiteral("PDF"), QStringLiteral("CSV"),
                                      QStringLiteral("Verlet"), QStringLiteral("XPBD"),
                                      // Words that are spelt the same in Catalan.
                                      QStringLiteral("Tangent"), QStringLiteral("5.2.1 Obstacles"),
                                      QStringLiteral("Centre (x, y)"), QStringLiteral("B-spline"), QStringLiteral("B-splines"),
                                      // The knot table's headers: orders of continuity and the tangent jump.
                                      QStringLiteral("C⁰"), QStringLiteral("C¹"), QStringLiteral("C²"), QStringLiteral("G¹"),
                                      QStringLiteral("G²"), QStringLiteral("|p′₊ − p′₋|"),
                                      // Names of methods and sources (the Catmull-Rom tab's families).
                                      QStringLiteral("Fritsch–Carlson"), QStringLiteral("Steffen"),
                                      QStringLiteral("Catmull-Rom τ = 1/2"), QStringLiteral("Interval"),
                                      QStringLiteral("Processing"), QStringLiteral("d3-shape"),
                                      QStringLiteral("Primer on Bézier curves"), QStringLiteral("Kochanek–Bartels (C = B = 0)")};
    if (names.contains(text.trimmed()))
        return true;
    if (text.endsWith(QLatin1String(".granota"))) // File ▸ Open Recent lists file names
        return true;
    // Numbers, symbols, variable names, point labels, file names.
    static const QRegularExpression symbols(
        QStringLiteral("^[\\s0-9.,:;/+\\-−=×·²³⁴⅛¼½<>()\\[\\]{}|%…ταtnuxyijkPQqBcwsW_′'^√∞≤≥✓✗µ]*$"));
    return symbols.match(text).hasMatch();
}

} // namespace

/// Starts a full (not quick) measurement and cancels it at once: true when the panel then
/// finishes, within a minute, and says it did not complete.
/// The work-precision panel of `tab`, shown, after measuring `report` (quick settings);
/// nullptr when it could not be measured.
granota::ui::WorkPrecisionPanel* measuredPanel(MainWindow& window, const QString& tab, const std::string& report)
{
    if (!showOnTab(window, tab))
        return nullptr;
    window.setWorkPrecisionVisible(true);
    auto* panel = window.workPrecisionPanel(tab);
    if (!panel)
        return nullptr;
    panel->setQuick(true);
    panel->selectReport(report);
    QSignalSpy done(panel, &granota::ui::WorkPrecisionPanel::finished);
    panel->measure();
    return done.wait(60000) && panel->report() ? panel : nullptr;
}

bool measureAndCancel(granota::ui::WorkPrecisionPanel* panel)
{
    panel->setQuick(false);
    QSignalSpy cancelled(panel, &granota::ui::WorkPrecisionPanel::finished);
    panel->measure();
    panel->cancel();
    return cancelled.wait(60000) && cancelled.size() == 1 && !cancelled.first().first().toBool();
}

class TestGuiMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("GranotaTest"));
        QCoreApplication::setApplicationName(QStringLiteral("GranotaTest"));
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    void everyTabInOrder()
    {
        MainWindow window;
        QCOMPARE(window.tabs().size(), kTabs.size());
        for (int i = 0; i < kTabs.size(); ++i) {
            QCOMPARE(window.tabs()[i]->key(), kTabs[i]);
            QVERIFY(window.showTab(kTabs[i]));
            QCOMPARE(window.currentTab()->key(), kTabs[i]);
        }
        QVERIFY(!window.showTab(QStringLiteral("nope")));
    }

    // Redo from the keyboard: Ctrl+Shift+Z and Ctrl+Y each redo what Ctrl+Z undid, as real key
    // events through the window's shortcuts.
    void redoFromTheKeyboard_data()
    {
        QTest::addColumn<int>("key");
        QTest::addColumn<int>("modifiers");
        QTest::newRow("Ctrl+Shift+Z") << int(Qt::Key_Z) << int(Qt::ControlModifier | Qt::ShiftModifier);
        QTest::newRow("Ctrl+Y") << int(Qt::Key_Y) << int(Qt::ControlModifier);
    }

    void redoFromTheKeyboard()
    {
        QFETCH(int, key);
        QFETCH(int, modifiers);
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        window.activateWindow();
        QVERIFY(waitActive(&window));
        QVERIFY(loadExamples(window, {"2.3"}));
        QUndoStack* stack = window.currentTab()->undoStack();
        QVERIFY(stack->canUndo());
        const int done = stack->index();
        QWidget* target = window.currentTab()->findChild<granota::ui::CurveCanvas*>();
        QVERIFY(target);
        target->setFocus(Qt::OtherFocusReason);
        QTest::keyClick(target, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(stack->index(), done - 1);
        QTest::keyClick(target, Qt::Key(key), Qt::KeyboardModifiers(modifiers));
        QCOMPARE(stack->index(), done);
    }

    // No key is given twice, to one action or to two actions of the window: Qt then calls the
    // shortcut ambiguous and runs neither.
    void noTwoActionsShareAKey()
    {
        MainWindow window;
        QHash<QString, QString> owner;
        for (const QAction* action : window.findChildren<QAction*>()) {
            if (action->shortcutContext() == Qt::WidgetShortcut)
                continue;
            const QString name = action->text().isEmpty() ? action->objectName() : action->text();
            QSet<QString> own;
            for (const QKeySequence& key : action->shortcuts()) {
                const QString k = key.toString(QKeySequence::PortableText);
                QVERIFY2(!own.contains(k), qPrintable(name + QStringLiteral(" has ") + k + QStringLiteral(" twice")));
                own.insert(k);
                QVERIFY2(!owner.contains(k) || owner[k] == name,
                         qPrintable(k + QStringLiteral(": ") + owner.value(k) + QStringLiteral(" and ") + name));
                owner.insert(k, name);
            }
        }
        QVERIFY(owner.contains(QStringLiteral("Ctrl+Shift+Z")));
        QVERIFY(owner.contains(QStringLiteral("Ctrl+Y")));
    }

    void everyExampleLoads_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<QString>("tab");
        const char* const ids[][2] = {{"2.1", "catmull-rom"}, {"2.2", "decasteljau"},  {"2.3", "decasteljau"},
                                      {"2.4", "bernstein"},   {"2.5", "bernstein"},    {"2.6", "bernstein"},
                                      {"2.7", "fit"},         {"2.8", "fit"},          {"2.9", "fit"},
                                      {"2.10", "fit"},        {"2.11", "catmull-rom"}, {"2.12", "catmull-rom"},
                                      {"2.13", "catmull-rom"}};
        for (const auto& row : ids)
            QTest::newRow(row[0]) << QString::fromLatin1(row[0]) << QString::fromLatin1(row[1]);
    }
    void everyExampleLoads()
    {
        QFETCH(QString, id);
        QFETCH(QString, tab);
        MainWindow window;
        window.showTab(QStringLiteral("frog"));
        QVERIFY2(window.loadExample(id), qPrintable(id));
        QCOMPARE(window.currentTab()->key(), tab);
        QVERIFY(!window.loadExample(QStringLiteral("9.9")));
    }

    void documentRoundTrip()
    {
        const TemporaryDocument file(QStringLiteral("lesson.granota"));
        QByteArray saved;
        {
            MainWindow window;
            QVERIFY(loadExamples(window, {"2.3", "2.8", "2.13"}));
            QVERIFY(window.isModified());
            QString error;
            QVERIFY2(window.saveFile(file.path(), &error), qPrintable(error));
            QVERIFY(!window.isModified());
            saved = documentOf(window);
        }
        const QJsonDocument json = QJsonDocument::fromJson([&] {
            QFile f(file.path());
            f.open(QIODevice::ReadOnly);
            return f.readAll();
        }());
        QCOMPARE(json.object().value(QStringLiteral("format")).toString(), QStringLiteral("granota"));
        for (const QString& key : kTabs)
            QVERIFY2(json.object().value(QStringLiteral("tabs")).toObject().contains(key), qPrintable(key));

        MainWindow reopened;
        const QByteArray fresh = granota::ui::serializeDocument(reopened.tabs(), QStringLiteral("catmull-rom"));
        QVERIFY(fresh != saved); // the examples changed the document
        QString error;
        QVERIFY2(reopened.openFile(file.path(), &error), qPrintable(error));
        QCOMPARE(reopened.currentTab()->key(), QStringLiteral("catmull-rom"));
        QCOMPARE(documentOf(reopened), saved);
        QCOMPARE(reopened.currentFile(), file.path());
    }

    void badDocumentsAreRefusedAndLoseNothing_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("garbage") << QByteArray("\x01\x02 not json");
        QTest::newRow("other json") << QByteArray("{\"hello\": 1}");
        QTest::newRow("future version") << QByteArray("{\"format\": \"granota\", \"version\": 99, \"tabs\": {}}");
        QTest::newRow("nan point") << QByteArray(
            "{\"format\": \"granota\", \"version\": 1, \"tabs\": {\"decasteljau\": {\"points\": [[\"nan\", 1], [2, 3]]}}}");
        QTest::newRow("tab not an object") << QByteArray(
            "{\"format\": \"granota\", \"version\": 1, \"tabs\": {\"fit\": {\"degree\": -5, \"points\": 7}}}");
    }
    void badDocumentsAreRefusedAndLoseNothing()
    {
        QFETCH(QByteArray, bytes);
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("bad.granota"));
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        MainWindow window;
        QVERIFY(window.loadExample(QStringLiteral("2.2")));
        const QByteArray before = granota::ui::serializeDocument(window.tabs(), QString());
        QString error;
        QVERIFY(!window.openFile(file, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(granota::ui::serializeDocument(window.tabs(), QString()), before);
        QVERIFY(!window.openFile(dir.filePath(QStringLiteral("missing.granota")), &error));
    }

    // A PNG for print is the screen's picture, only sharper: the 300 DPI image, brought down
    // to 96 DPI, matches the 96 DPI image (text drawn three times too large would not).
    void pngForPrintIsTheScreensPicture_data()
    {
        QTest::addColumn<QString>("tab");
        for (const QString& key : kTabs)
            if (key != QLatin1String("frog")) // it moves between two exports
                QTest::newRow(qPrintable(key)) << key;
    }
    void pngForPrintIsTheScreensPicture()
    {
        QFETCH(QString, tab);
        MainWindow window;
        QVERIFY(showOnTab(window, tab));
        QVERIFY(loadExamples(window, {"2.2"}));
        QVERIFY(window.showTab(tab));
        QTemporaryDir dir;
        const QString screen = dir.filePath(QStringLiteral("96.png")), print = dir.filePath(QStringLiteral("300.png"));
        QCOMPARE(window.exportCurrent(QStringLiteral("png"), screen, 96), QString());
        QCOMPARE(window.exportCurrent(QStringLiteral("png"), print, 300), QString());
        const QImage a = QImage(screen).convertToFormat(QImage::Format_Grayscale8);
        const QImage b = QImage(print)
                             .scaled(a.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation)
                             .convertToFormat(QImage::Format_Grayscale8);
        QVERIFY(!a.isNull() && !b.isNull());
        // Ink (dark pixels) in each, and how much of it the two share.
        long inkA = 0, inkB = 0, both = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) {
                const bool da = qGray(a.pixel(x, y)) < 110, db = qGray(b.pixel(x, y)) < 110;
                inkA += da;
                inkB += db;
                both += da && db;
            }
        QVERIFY(inkA > 100);
        const double ratio = double(inkB) / double(inkA), shared = double(both) / double(std::max(inkA, inkB));
        QVERIFY2(ratio > 0.7 && ratio < 1.4 && shared > 0.5,
                 qPrintable(QStringLiteral("ink 96 DPI %1, 300 DPI %2, shared %3").arg(inkA).arg(inkB).arg(shared)));
    }

    // File ▸ Export ▸ TikZ asks for the width, the greatest height, axes and grid (issue 14,
    // item 15), starting from the last choice, which OK keeps and Cancel does not; the
    // dialog speaks Catalan in Catalan.
    void tikzOptionsDialogKeepsTheLastChoice()
    {
        using granota::ui::TikzOptions;
        using granota::ui::TikzOptionsDialog;
        QSettings().remove(QStringLiteral("tikz"));
        QCOMPARE(TikzOptions::load().widthCm, TikzOptions::kDefaultWidthCm);
        QCOMPARE(TikzOptions::load().axes, false);
        // The teacher sets 7.5 cm, 5 cm and axes, and presses OK.
        const auto answer = [](double width, double height, bool axes, bool accept) {
            QTimer::singleShot(0, [=] {
                auto* dialog = qobject_cast<TikzOptionsDialog*>(QApplication::activeModalWidget());
                QVERIFY(dialog);
                dialog->findChild<QDoubleSpinBox*>(QStringLiteral("tikzWidth"))->setValue(width);
                dialog->findChild<QDoubleSpinBox*>(QStringLiteral("tikzHeight"))->setValue(height);
                dialog->findChild<QCheckBox*>(QStringLiteral("tikzAxes"))->setChecked(axes);
                accept ? dialog->accept() : dialog->reject();
            });
        };
        TikzOptions chosen;
        answer(7.5, 5, true, true);
        QVERIFY(TikzOptionsDialog::ask(nullptr, &chosen));
        QCOMPARE(chosen.widthCm, 7.5);
        QCOMPARE(chosen.maxHeightCm, 5.0);
        QVERIFY(chosen.axes && !chosen.grid);
        QCOMPARE(TikzOptions::load().widthCm, 7.5);
        QVERIFY(TikzOptions::load().axes);
        // Cancel keeps the last choice.
        answer(20, 20, false, false);
        QVERIFY(!TikzOptionsDialog::ask(nullptr, &chosen));
        QCOMPARE(TikzOptions::load().widthCm, 7.5);
        // A setting out of range (edited by hand) comes back inside it.
        QSettings().setValue(QStringLiteral("tikz/widthCm"), 1000);
        QCOMPARE(TikzOptions::load().widthCm, TikzOptions::kMaxCm);
        // In Catalan, every text of the dialog is Catalan.
        granota::ui::setLanguage(QStringLiteral("ca"), false);
        {
            TikzOptionsDialog dialog(TikzOptions{});
            QCOMPARE(dialog.windowTitle(), QStringLiteral("Figura TikZ"));
            QCOMPARE(dialog.findChild<QCheckBox*>(QStringLiteral("tikzGrid"))->text(), QStringLiteral("Quadrícula"));
            QVERIFY(
                dialog.findChild<QDoubleSpinBox*>(QStringLiteral("tikzHeight"))->toolTip().contains(QStringLiteral("6,5 cm")));
        }
        granota::ui::setLanguage(QStringLiteral("en"), false);
        QSettings().remove(QStringLiteral("tikz"));
    }

    void exportsAreValidFiles_data()
    {
        QTest::addColumn<QString>("tab");
        for (const QString& key : kTabs)
            QTest::newRow(qPrintable(key)) << key;
    }
    void exportsAreValidFiles()
    {
        QFETCH(QString, tab);
        MainWindow window;
        QVERIFY(showOnTab(window, tab));
        QTemporaryDir dir;
        // PNG at 300 DPI: the view's size scaled by 300/96, and the DPI recorded in the file.
        const QString png = dir.filePath(QStringLiteral("view.png"));
        QCOMPARE(window.exportCurrent(QStringLiteral("png"), png, 300), QString());
        QImage image(png);
        QVERIFY(!image.isNull());
        const QSize expected = granota::ui::pngPixelSize(window.currentTab()->exportView()->exportSize(), 300);
        QCOMPARE(image.size(), expected);
        QVERIFY(image.width() > 600);
        QVERIFY(qAbs(image.dotsPerMeterX() - 11811) <= 1);
        // The picture is not blank: more than a handful of colours.
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 7)
            for (int x = 0; x < image.width(); x += 7)
                colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 4, qPrintable(QString::number(colours.size())));
        // SVG: well-formed XML that Qt's renderer accepts.
        const QString svg = dir.filePath(QStringLiteral("view.svg"));
        QCOMPARE(window.exportCurrent(QStringLiteral("svg"), svg), QString());
        {
            QFile f(svg);
            QVERIFY(f.open(QIODevice::ReadOnly));
            QXmlStreamReader xml(&f);
            int elements = 0;
            while (!xml.atEnd())
                if (xml.readNext() == QXmlStreamReader::StartElement)
                    ++elements;
            QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
            QVERIFY(elements > 10);
        }
        QVERIFY(QSvgRenderer(svg).isValid());
        // PDF: header and trailer.
        const QString pdf = dir.filePath(QStringLiteral("view.pdf"));
        QCOMPARE(window.exportCurrent(QStringLiteral("pdf"), pdf), QString());
        {
            QFile f(pdf);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray bytes = f.readAll();
            QVERIFY(bytes.startsWith("%PDF-"));
            QVERIFY(bytes.trimmed().endsWith("%%EOF"));
        }
        // CSV: a header and rows of numbers with the same number of fields.
        const QString csv = dir.filePath(QStringLiteral("data.csv"));
        QCOMPARE(window.exportCurrent(QStringLiteral("csv"), csv), QString());
        {
            QFile f(csv);
            QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
            const QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            QVERIFY(lines.size() >= 3);
            QVERIFY(lines[0].contains(QLatin1Char(',')));
        }
        // TikZ: one picture.
        const QString tex = dir.filePath(QStringLiteral("view.tex"));
        QCOMPARE(window.exportCurrent(QStringLiteral("tikz"), tex), QString());
        {
            QFile f(tex);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(f.readAll());
            QCOMPARE(text.count(QStringLiteral("\\begin{tikzpicture}")), 1);
            QVERIFY(text.contains(QStringLiteral("\\draw")));
            QVERIFY(!text.contains(QStringLiteral("nan")) && !text.contains(QStringLiteral("inf")));
        }
        // A file that cannot be written gives a message, not a crash.
        QVERIFY(!window.exportCurrent(QStringLiteral("png"), QStringLiteral("/nonexistent/dir/x.png")).isEmpty());
        QVERIFY(!window.exportCurrent(QStringLiteral("png"), png, 5).isEmpty());
    }

    // Edit ▸ Undo and Redo speak the interface's language whatever the history holds: empty,
    // with a step, and after a live switch from English to Catalan and back.
    void undoAndRedoSpeakTheLanguage()
    {
        granota::ui::setLanguage(QStringLiteral("en"), false);
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        QAction* undo = nullptr;
        QAction* redo = nullptr;
        for (QAction* a : window.findChildren<QAction*>()) {
            if (a->shortcuts().contains(QKeySequence(QKeySequence::Undo)))
                undo = a;
            if (a->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)))
                redo = a;
        }
        QVERIFY(undo && redo);
        QCOMPARE(undo->text(), QStringLiteral("&Undo"));
        QVERIFY(granota::ui::setLanguage(QStringLiteral("ca"), false));
        QCoreApplication::processEvents();
        for (const QString& key : kTabs) { // every tab's history is empty: the plain words
            QVERIFY(window.showTab(key));
            QCOMPARE(undo->text(), QStringLiteral("&Desfés"));
            QCOMPARE(redo->text(), QStringLiteral("&Refés"));
        }
        QVERIFY(window.showTab(QStringLiteral("decasteljau")));
        QVERIFY(loadExamples(window, {"2.2"}));
        QVERIFY2(undo->text().startsWith(QStringLiteral("&Desfés ")), qPrintable(undo->text()));
        window.currentTab()->undoStack()->undo();
        QVERIFY2(redo->text().startsWith(QStringLiteral("&Refés ")), qPrintable(redo->text()));
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
        QCoreApplication::processEvents();
        QVERIFY2(redo->text().startsWith(QStringLiteral("&Redo ")), qPrintable(redo->text()));
        QCOMPARE(undo->text(), QStringLiteral("&Undo"));
    }

    void languageSwitchRetranslatesEveryText()
    {
        granota::ui::setLanguage(QStringLiteral("en"), false);
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        QVERIFY(waitExposed(&window));
        for (const QString& id : {QStringLiteral("2.2"), QStringLiteral("2.4"), QStringLiteral("2.8"), QStringLiteral("2.13")})
            QVERIFY(window.loadExample(id));
        const auto english = visibleTexts(window);
        QVERIFY(english.size() > 50);
        QVERIFY(granota::ui::setLanguage(QStringLiteral("ca"), false));
        QCoreApplication::processEvents();
        const auto catalan = visibleTexts(window);
        QStringList untranslated;
        for (const auto& [where, text] : english) {
            auto it = catalan.find(where);
            if (it != catalan.end() && it->second == text && !languageNeutral(text))
                untranslated << QStringLiteral("%1: “%2”").arg(where, text);
        }
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join(QLatin1Char('\n'))));
        QCOMPARE(window.tabs()[2]->title(), QStringLiteral("Ajust"));
        // And back: the English texts return exactly.
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
        QCoreApplication::processEvents();
        const auto again = visibleTexts(window);
        int same = 0;
        for (const auto& [where, text] : english) {
            auto it = again.find(where);
            same += it != again.end() && it->second == text;
        }
        QVERIFY2(same >= static_cast<int>(english.size() * 0.95), qPrintable(QString::number(same)));
    }

    void autosaveRecoversTheDocument()
    {
        QByteArray state;
        QString autosave;
        {
            MainWindow window;
            QVERIFY(window.loadExample(QStringLiteral("2.9")));
            autosave = window.autosaveFile();
            QVERIFY(window.autosave());
            QVERIFY(QFile::exists(autosave));
            state = granota::ui::serializeDocument(window.tabs(), window.currentTab()->key());
        } // destroyed without a clean close: the autosave stays, as after a crash
        QVERIFY(QFile::exists(autosave));
        MainWindow next;
        QString error;
        QVERIFY2(next.openFile(autosave, &error), qPrintable(error));
        QCOMPARE(granota::ui::serializeDocument(next.tabs(), next.currentTab()->key()), state);
        QFile::remove(autosave);
    }

    void workPrecisionBelowEachTab_data()
    {
        QTest::addColumn<QString>("tab");
        QTest::addColumn<int>("methods");
        QTest::newRow("decasteljau") << QStringLiteral("decasteljau") << 2; // curve sampling: uniform, adaptive
        QTest::newRow("bernstein") << QStringLiteral("bernstein") << 3;     // De Casteljau, Bernstein, Horner
        QTest::newRow("fit") << QStringLiteral("fit") << 3;                 // normal equations, QR, SVD
        QTest::newRow("catmull-rom") << QStringLiteral("catmull-rom") << 2;
        QTest::newRow("frog") << QStringLiteral("frog") << 5; // Euler, semi-implicit, Verlet (two starts), RK4
    }
    void workPrecisionBelowEachTab()
    {
        QFETCH(QString, tab);
        QFETCH(int, methods);
        MainWindow window;
        QVERIFY(showOnTab(window, tab));
        QVERIFY(!window.workPrecisionVisible());
        window.setWorkPrecisionVisible(true);
        QVERIFY(window.workPrecisionVisible());
        auto* panel = window.workPrecisionPanel(tab);
        QVERIFY(panel && panel->isVisible());
        panel->setQuick(true);
        QSignalSpy done(panel, &granota::ui::WorkPrecisionPanel::finished);
        panel->measure();
        QVERIFY(panel->running());
        QVERIFY(done.wait(60000));
        QCOMPARE(done.first().first().toBool(), true);
        QVERIFY(panel->report().has_value());
        QCOMPARE(panel->plot()->graphCount(), methods);
        QVERIFY(panel->plot()->xAxis->scaleType() == QCPAxis::stLogarithmic);
        QVERIFY(panel->plot()->yAxis->scaleType() == QCPAxis::stLogarithmic);
        // Cancelling stops a measurement and keeps the window responsive.
        QVERIFY(measureAndCancel(panel));
        window.setWorkPrecisionVisible(false);
        QVERIFY(!window.workPrecisionVisible());
    }

    // Issue 16: the Frog tab's stable solver box opens the soft-body report below the tab.
    void frogOpensTheSoftBodyReport()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* frog = qobject_cast<granota::ui::FrogTab*>(window.currentTab());
        QVERIFY(frog->setSolver(granota::SolverKind::Stable, nullptr));
        auto* panel = window.workPrecisionPanel(QStringLiteral("frog"));
        panel->selectReport("integrators");
        QVERIFY(!window.workPrecisionVisible());
        auto* button = frog->findChild<QPushButton*>(QStringLiteral("frogSoftBodyReport"));
        QVERIFY(button && button->isVisibleTo(&window));
        button->click();
        QVERIFY(window.workPrecisionVisible());
        QCOMPARE(panel->selectedReport(), std::string("soft-body"));
        QVERIFY(frog->setSolver(granota::SolverKind::Seed, nullptr));
        QVERIFY(!button->isVisibleTo(&window)); // the seed has no substeps
    }

    // Another report chosen, then a measurement cancelled: the plot is empty, with no axis
    // title and no legend left from the report before.
    void aCancelledReportLeavesNothingOfTheLastOne()
    {
        MainWindow window;
        auto* panel = measuredPanel(window, QStringLiteral("decasteljau"), "curve-sampling");
        QVERIFY(panel);
        QVERIFY(!panel->plot()->yAxis->label().isEmpty());
        QVERIFY(panel->plot()->legend->visible());
        const auto isEmpty = [panel] {
            return panel->plot()->graphCount() == 0 && panel->plot()->xAxis->label().isEmpty() &&
                   panel->plot()->yAxis->label().isEmpty() && !panel->plot()->legend->visible();
        };
        panel->selectReport("bezier-evaluation");
        QVERIFY(!panel->report().has_value());
        QVERIFY(isEmpty());
        QVERIFY(measureAndCancel(panel));
        QVERIFY(isEmpty());
    }

    // Curve sampling's lesson is "fewer points for the same error": it is plotted against the
    // points, where adaptive's markers lie left of uniform's at each error; the choice box
    // switches to run time and back.
    void curveSamplingIsPlottedAgainstPoints()
    {
        MainWindow window;
        auto* panel = measuredPanel(window, QStringLiteral("decasteljau"), "curve-sampling");
        QVERIFY(panel);
        QVERIFY(panel->report().has_value());
        QVERIFY(panel->axis() == granota::WorkPrecisionAxis::Knob);
        QCustomPlot* plot = panel->plot();
        QCOMPARE(plot->xAxis->label(), granota::ui::reportAxisTitle(*panel->report(), granota::WorkPrecisionAxis::Knob));
        QVERIFY(plot->xAxis->label().contains(QStringLiteral("points")));
        QCOMPARE(plot->graphCount(), 2);
        QCPGraph* uniform = plot->graph(0);
        QCPGraph* adaptive = plot->graph(1);
        QCOMPARE(uniform->name(), granota::ui::reportMethod("uniform"));
        QCOMPARE(adaptive->name(), granota::ui::reportMethod("adaptive"));
        // The plotted keys are the points of the report, and adaptive needs fewer at each error.
        const auto& samples = panel->report()->find("uniform")->samples;
        QCOMPARE(uniform->dataCount(), static_cast<int>(samples.size()));
        for (int i = 0; i < uniform->dataCount(); ++i)
            QCOMPARE(uniform->data()->at(i)->key, samples[static_cast<std::size_t>(i)].knob);
        int compared = 0;
        for (int i = 0; i < adaptive->dataCount(); ++i) {
            const double error = adaptive->data()->at(i)->value;
            for (int j = 0; j + 1 < uniform->dataCount(); ++j)
                if (uniform->data()->at(j)->value >= error && error > uniform->data()->at(j + 1)->value) {
                    QVERIFY2(adaptive->data()->at(i)->key < uniform->data()->at(j + 1)->key, qPrintable(QString::number(error)));
                    ++compared;
                }
        }
        QVERIFY(compared >= 3);
        panel->setAxis(granota::WorkPrecisionAxis::Seconds);
        QCOMPARE(plot->xAxis->label(), granota::ui::reportAxisTitle(*panel->report(), granota::WorkPrecisionAxis::Seconds));
        QCOMPARE(plot->graph(0)->data()->at(0)->key, samples.front().seconds);
    }

    // Issue 33, part 5: the Frog tab's reports include energy-drift, drawn against the step
    // number on log axes, |E/E0 − 1| with its five methods; nothing is timed, so the x axis
    // cannot be switched to run time.
    void frogHasTheEnergyDriftReport()
    {
        MainWindow window;
        auto* panel = measuredPanel(window, QStringLiteral("frog"), "energy-drift");
        QVERIFY(panel);
        QCOMPARE(QString::fromStdString(panel->report()->name), QStringLiteral("energy-drift"));
        auto* plot = panel->plot();
        QCOMPARE(plot->graphCount(), 5);
        QCOMPARE(plot->graph(3)->name(), granota::ui::reportMethod("Verlet (Annex II start)"));
        QVERIFY(plot->xAxis->scaleType() == QCPAxis::stLogarithmic && plot->yAxis->scaleType() == QCPAxis::stLogarithmic);
        QCOMPARE(plot->xAxis->label(), granota::ui::reportAxisTitle(*panel->report(), granota::WorkPrecisionAxis::Knob));
        QVERIFY(plot->xAxis->range().contains(1) && plot->xAxis->range().contains(100000));
        // RK4's last point: |g^(10⁵) − 1| = 1.386e-3 (closed form in tests/energy_drift_closed_forms.h).
        const auto rk4 = plot->graph(4)->data();
        QVERIFY(std::fabs((rk4->end() - 1)->value - 1.38619e-3) < 1e-8);
        // Explicit Euler's 10³⁰⁵ leaves the frame at the report's ceiling.
        QCOMPARE(plot->yAxis->range().upper, 1e3);
        panel->setAxis(granota::WorkPrecisionAxis::Seconds);
        QCOMPARE(plot->xAxis->label(), granota::ui::reportAxisTitle(*panel->report(), granota::WorkPrecisionAxis::Knob));
        auto* axisBox = panel->findChildren<QComboBox*>().at(1);
        QVERIFY(!axisBox->isEnabled());
    }

    // The Catmull-Rom tab measures a Catmull-Rom curve, not the De Casteljau tab's Bézier curve.
    void catmullRomTabHasItsOwnReport()
    {
        MainWindow window;
        auto* panel = measuredPanel(window, QStringLiteral("catmull-rom"), "catmull-rom-sampling");
        QVERIFY(panel);
        const auto& names = panel->reportNames();
        QVERIFY(std::find(names.begin(), names.end(), "catmull-rom-sampling") != names.end());
        QVERIFY(std::find(names.begin(), names.end(), "curve-sampling") == names.end());
        QVERIFY(std::find(names.begin(), names.end(), "bezier-evaluation") == names.end());
        QCOMPARE(QString::fromStdString(panel->report()->name), QStringLiteral("catmull-rom-sampling"));
        QCOMPARE(panel->plot()->graph(0)->name(), granota::ui::reportMethod("uniform t per segment"));
    }

    void presentationModeEnlargesText()
    {
        MainWindow window;
        const double normal = QApplication::font().pointSizeF();
        window.setPresentation(true);
        QVERIFY(window.presentation());
        QVERIFY(QApplication::font().pointSizeF() > normal * 1.3);
        window.setPresentation(false);
        QCOMPARE(QApplication::font().pointSizeF(), normal);
    }

    void commandLineOptions_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("tab and language") << QStringList{"--tab", "fit", "--lang", "ca"} << 0;
        QTest::newRow("example") << QStringList{"--example", "2.13"} << 0;
        QTest::newRow("scene") << QStringList{"--scene", "pendulum-limits"} << 0;
        QTest::newRow("presentation") << QStringList{"--tab", "bernstein", "--presentation"} << 0;
        QTest::newRow("bad tab") << QStringList{"--tab", "nope"} << 2;
        QTest::newRow("bad language") << QStringList{"--lang", "fr"} << 2;
        QTest::newRow("bad example") << QStringList{"--example", "3.1"} << 2;
        QTest::newRow("bad scene") << QStringList{"--scene", "dragon"} << 2;
        QTest::newRow("plot of body 3") << QStringList{"--scene", "many-bodies", "--plots",     "energy",
                                                       "--steps", "5",           "--plot-body", "3"}
                                        << 0;
        QTest::newRow("plot of body 13 of 12") << QStringList{"--scene", "many-bodies", "--plot-body", "13"} << 2;
        QTest::newRow("plot of body zero") << QStringList{"--scene", "many-bodies", "--plot-body", "0"} << 2;
        QTest::newRow("plot of a body, one body") << QStringList{"--scene", "frog", "--plot-body", "1"} << 2;
    }
    void commandLineOptions()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, exitCode);
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("shot.png"));
        QProcess process;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
        env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
        QDir(dir.path()).mkdir(QStringLiteral("runtime"));
        QFile::setPermissions(dir.filePath(QStringLiteral("runtime")),
                              QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        env.insert(QStringLiteral("XDG_RUNTIME_DIR"), dir.filePath(QStringLiteral("runtime")));
        process.setProcessEnvironment(env);
        process.start(QStringLiteral(GRANOTA_GUI_PATH), arguments + QStringList{QStringLiteral("--screenshot"), png});
        QVERIFY(process.waitForFinished(120000));
        QCOMPARE(process.exitCode(), exitCode);
        if (exitCode == 0) {
            const QImage image(png);
            QCOMPARE(image.size(), QSize(1280, 800));
        } else {
            const QStringList lines = QString::fromUtf8(process.readAllStandardError()).split(QLatin1Char('\n'));
            QVERIFY2(std::any_of(lines.begin(), lines.end(),
                                 [](const QString& l) { return l.startsWith(QStringLiteral("error: ")); }),
                     qPrintable(lines.join(QLatin1Char('|'))));
            QVERIFY(!QFile::exists(png));
        }
    }

    // Over SSH or in CI there is no display at all: --help and --screenshot still work (the
    // application picks the offscreen platform itself); before, Qt aborted on "could not
    // connect to display".
    void helpAndScreenshotWithoutADisplay()
    {
        QTemporaryDir dir;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"})
            env.remove(QString::fromLatin1(name));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
        env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
        QProcess help;
        help.setProcessEnvironment(env);
        help.start(QStringLiteral(GRANOTA_GUI_PATH), {QStringLiteral("--help")});
        QVERIFY(help.waitForFinished(120000));
        QCOMPARE(help.exitStatus(), QProcess::NormalExit);
        QCOMPARE(help.exitCode(), 0);
        QVERIFY(QString::fromUtf8(help.readAllStandardOutput()).contains(QStringLiteral("--screenshot")));
        const QString png = dir.filePath(QStringLiteral("shot.png"));
        QProcess shot;
        shot.setProcessEnvironment(env);
        shot.start(QStringLiteral(GRANOTA_GUI_PATH),
                   {QStringLiteral("--lang"), QStringLiteral("ca"), QStringLiteral("--screenshot"), png});
        QVERIFY(shot.waitForFinished(120000));
        QCOMPARE(shot.exitStatus(), QProcess::NormalExit);
        QVERIFY2(shot.exitCode() == 0, shot.readAllStandardError().constData());
        QCOMPARE(QImage(png).size(), QSize(1280, 800));
    }

    // A screenshot is a one-off render: it opens a document in another language and leaves
    // the user's saved language, recent files and data folder exactly as they were.
    void aScreenshotRunWritesNoSettings()
    {
        QTemporaryDir dir;
        const QString config = dir.filePath(QStringLiteral("config"));
        const QString data = dir.filePath(QStringLiteral("data"));
        QVERIFY(QDir().mkpath(config + QStringLiteral("/Granota")));
        const QString settingsFile = config + QStringLiteral("/Granota/Granota.conf");
        const QByteArray saved = "[General]\nlanguage=en\n";
        {
            QFile f(settingsFile);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(saved);
        }
        MainWindow source;
        QVERIFY(loadExamples(source, {"2.2"}));
        const QString document = dir.filePath(QStringLiteral("lesson.granota"));
        {
            QFile f(document);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(documentOf(source));
        }
        QProcess process;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), config);
        env.insert(QStringLiteral("XDG_DATA_HOME"), data);
        process.setProcessEnvironment(env);
        const QString png = dir.filePath(QStringLiteral("shot.png"));
        process.start(QStringLiteral(GRANOTA_GUI_PATH),
                      {QStringLiteral("--lang"), QStringLiteral("ca"), QStringLiteral("--presentation"),
                       QStringLiteral("--screenshot"), png, document});
        QVERIFY(process.waitForFinished(120000));
        QCOMPARE(process.exitCode(), 0);
        QVERIFY(QFile::exists(png));
        QFile after(settingsFile);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), saved);
        QCOMPARE(QDir(config + QStringLiteral("/Granota")).entryList(QDir::Files), QStringList{QStringLiteral("Granota.conf")});
        QVERIFY2(!QFileInfo::exists(data + QStringLiteral("/Granota")), "the screenshot run wrote into the data folder");
    }
};

GRANOTA_TEST_MAIN(TestGuiMainWindow)
#include "test_gui_main_window.moc"
