// The thesis's figures (issue 33, part 1; docs/thesis-figures.md): each of Fig 2.1–2.10 and
// 4.1–4.13 puts its tab in the state that draws it, whatever the user had on; the gallery
// does it as one undo step; every figure exports in SVG, PDF, PNG, TikZ and CSV in both
// languages; `granota --list-figures` and `--figure N --export F` work with no display at
// all, refuse a bad N or V with status 2, and each figure's CSV has the hash kept in
// tests/data/thesis_figures_csv.sha256 in C.UTF-8 and in ca_ES.UTF-8.
#include "core/io/thesis_figures.h"
#include "core/io/worked_examples.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/scenes/scene.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/shell/thesis_figure_export.h"
#include "ui/shell/thesis_figures_dialog.h"

#include "catalan_locale.h"
#include "main_window_steps.h"

#include <QComboBox>
#include <QCryptographicHash>
#include <QImage>
#include <QListWidget>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QXmlStreamReader>
#include "tests/test_main.h"

#include <cmath>
#include <set>

using granota::FigureVariant;
using granota::ThesisFigure;
using granota::thesisFigures;
using granota::ui::MainWindow;
using granota::ui::TabPage;

namespace {

QString str(const std::string& s) { return QString::fromStdString(s); }

/// The settings a figure names: its own, then its variant's.
QJsonObject namedSettings(const ThesisFigure& f, const FigureVariant& v)
{
    QJsonObject named = QJsonDocument::fromJson(QByteArray::fromStdString(f.state.dump())).object();
    const QJsonObject over = QJsonDocument::fromJson(QByteArray::fromStdString(v.state.dump())).object();
    for (auto it = over.begin(); it != over.end(); ++it)
        named.insert(it.key(), it.value());
    return named;
}

/// What is wrong with an exported file of `format`, or empty.
QString checkFile(const QString& path, const QString& format, QSize size)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("not written");
    const QByteArray bytes = file.readAll();
    if (format == QLatin1String("svg")) {
        QXmlStreamReader xml(bytes);
        bool root = false;
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement && !root)
                root = xml.name() == QLatin1String("svg") ? true : (void(xml.raiseError(QStringLiteral("root"))), false);
        if (xml.hasError() || !root)
            return QStringLiteral("not SVG: ") + xml.errorString();
        if (!bytes.contains("<path") && !bytes.contains("<polyline") && !bytes.contains("<image"))
            return QStringLiteral("an SVG that draws nothing");
    } else if (format == QLatin1String("pdf")) {
        if (!bytes.startsWith("%PDF-") || !bytes.trimmed().endsWith("%%EOF"))
            return QStringLiteral("not PDF");
    } else if (format == QLatin1String("png")) {
        QImage image;
        if (!image.loadFromData(bytes, "PNG"))
            return QStringLiteral("not PNG");
        if (image.size() != size)
            return QStringLiteral("PNG of %1×%2").arg(image.width()).arg(image.height());
        // Not one colour: something is drawn.
        const QRgb first = image.pixel(0, 0);
        bool drawn = false;
        for (int y = 0; y < image.height() && !drawn; y += 7)
            for (int x = 0; x < image.width() && !drawn; x += 7)
                drawn = image.pixel(x, y) != first;
        if (!drawn)
            return QStringLiteral("an empty PNG");
    } else if (format == QLatin1String("tex")) {
        if (!bytes.contains("\\begin{tikzpicture}") || !bytes.contains("\\end{tikzpicture}") || !bytes.contains("\\draw"))
            return QStringLiteral("not a TikZ picture");
    } else if (format == QLatin1String("csv")) {
        const QList<QByteArray> lines = bytes.trimmed().split('\n');
        if (lines.size() < 2 || !lines.last().contains(','))
            return QStringLiteral("a CSV without rows");
        for (const QByteArray& line : lines)
            for (const QByteArray& cell : line.split(','))
                if (QByteArray lower = cell.trimmed().toLower(); lower == "nan" || lower == "inf" || lower == "-inf")
                    return QStringLiteral("a CSV with a NaN or an infinity");
    }
    return {};
}

/// The environment of a run with no display at all: no DISPLAY, no Wayland, no platform asked.
QProcessEnvironment headless(const QTemporaryDir& dir, const QStringList& locale)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM", "LANGUAGE", "LC_ALL", "LANG"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
    for (const QString& assignment : locale)
        env.insert(assignment.section(QLatin1Char('='), 0, 0), assignment.section(QLatin1Char('='), 1));
    return env;
}

struct Run {
    int status = -1;
    QString out, err;
};

Run runGranota(const QStringList& arguments, const QProcessEnvironment& env)
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(GRANOTA_GUI_PATH), arguments);
    Run run;
    if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit)
        return run;
    run.status = p.exitCode();
    run.out = QString::fromUtf8(p.readAllStandardOutput());
    run.err = QString::fromUtf8(p.readAllStandardError());
    return run;
}

/// Bernstein basis B_i^n(t), computed here from its definition (Def 2.6).
double bernstein(int i, int n, double t)
{
    double c = 1;
    for (int k = 1; k <= i; ++k)
        c = c * (n - i + k) / k;
    return c * std::pow(t, i) * std::pow(1 - t, n - i);
}

} // namespace

class TestGuiThesisFigures : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { useTestSettings(); }

    // The catalogue is the thesis's list: Fig 2.1–2.10 and 4.1–4.13 in order, each with a
    // caption in both languages, a tab that exists, its worked example or scene, and
    // variants of distinct names; Figs 2.1, 2.7 and 2.8 have `definition` and `thesis`.
    void catalogueIsTheThesis()
    {
        QStringList expected;
        for (int i = 1; i <= 10; ++i)
            expected << QStringLiteral("2.%1").arg(i);
        for (int i = 1; i <= 13; ++i)
            expected << QStringLiteral("4.%1").arg(i);
        QStringList numbers;
        MainWindow window;
        for (const ThesisFigure& f : thesisFigures()) {
            numbers << str(f.number);
            QVERIFY2(!f.caption.ca.empty() && !f.caption.en.empty() && f.caption.ca != f.caption.en, f.number.c_str());
            QVERIFY2(window.tab(str(f.tab)), f.number.c_str());
            QVERIFY2(f.example.empty() || granota::findWorkedExample(f.example), f.number.c_str());
            QVERIFY2(f.scene.empty() || granota::loadScene(f.scene).ok(), f.number.c_str());
            QVERIFY2(!f.variants.empty(), f.number.c_str());
            std::set<std::string> names;
            for (const FigureVariant& v : f.variants)
                QVERIFY2(names.insert(v.name).second, f.number.c_str());
            if (f.number == "2.1" || f.number == "2.7" || f.number == "2.8") {
                QCOMPARE(f.variants.front().name, std::string("definition"));
                QVERIFY(names.count("thesis"));
            }
        }
        QCOMPARE(numbers, expected);
    }

    // Each figure and variant, shown, leaves its tab with every setting it names as it names
    // it — so a setting a tab ignored would fail here — and names every on/off setting the
    // tab saves, so that nothing the user had on shows in a figure. A frog figure is paused
    // at its step with no overlay, on the seed solver.
    void everyFigureShowsItsState()
    {
        MainWindow window;
        window.resize(1280, 800);
        for (const ThesisFigure& f : thesisFigures())
            for (const FigureVariant& v : f.variants) {
                const QString what = QStringLiteral("Fig %1 %2").arg(str(f.number), str(v.name));
                QString error;
                QVERIFY2(granota::ui::showThesisFigure(window, f, v, false, &error), qPrintable(what + error));
                if (!f.art.empty())
                    continue;
                TabPage* page = window.tab(str(f.tab));
                QCOMPARE(window.currentTab(), page);
                const QJsonObject state = page->saveState();
                if (!f.scene.empty()) {
                    QCOMPARE(state.value(QStringLiteral("scene")).toString(), str(f.scene));
                    QCOMPARE(state.value(QStringLiteral("solver")).toString(), QStringLiteral("seed"));
                    const QJsonObject overlays = state.value(QStringLiteral("overlays")).toObject();
                    for (auto it = overlays.begin(); it != overlays.end(); ++it)
                        QVERIFY2(!it.value().toBool(), qPrintable(what + QStringLiteral(": overlay ") + it.key()));
                    const granota::RecordedRun* run = window.frogTab()->canvas()->frogRun()->recorded();
                    QVERIFY(run);
                    QCOMPARE(run->stepCount(), f.steps);
                    QVERIFY(!window.frogTab()->frogRun()->running());
                    continue;
                }
                const QJsonObject named = namedSettings(f, v);
                for (auto it = named.begin(); it != named.end(); ++it)
                    QVERIFY2(state.value(it.key()) == it.value(),
                             qPrintable(what + QStringLiteral(": ") + it.key() + QStringLiteral(" is ") +
                                        QString::fromUtf8(QJsonDocument(QJsonObject{{it.key(), state.value(it.key())}})
                                                              .toJson(QJsonDocument::Compact))));
                for (auto it = state.begin(); it != state.end(); ++it)
                    if (it.value().isBool())
                        QVERIFY2(named.contains(it.key()), qPrintable(what + QStringLiteral(" does not name ") + it.key()));
            }
    }

    // Fig 2.7's `thesis` variant is Ex 2.9 fitted with Annex III's t: computed here as
    // BezParamProp does (t_j = Σ_{m<j} |Q_m| / Σ_{m≤k−2} |Q_m|, Annex III ll. 6–19) and the
    // normal equations MᵀM P = MᵀQ solved by Gaussian elimination; the tab's CSV has those
    // control points, and the `definition` variant's differ from them.
    void fig27ThesisIsAnnexIII()
    {
        const ThesisFigure* f = granota::findThesisFigure("2.7");
        QVERIFY(f);
        const granota::WorkedExample* ex = granota::findWorkedExample("2.9");
        QVERIFY(ex);
        std::vector<std::array<double, 2>> q;
        for (const auto& p : ex->points)
            q.push_back({granota::toDouble(p.x), granota::toDouble(p.y)});
        const int k = static_cast<int>(q.size()), n = ex->degree;
        std::vector<double> t(static_cast<std::size_t>(k), 0.0);
        double total = 0;
        for (int m = 0; m <= k - 2; ++m)
            total += std::hypot(q[std::size_t(m)][0], q[std::size_t(m)][1]);
        double sum = 0;
        for (int j = 1; j < k; ++j) {
            sum += std::hypot(q[std::size_t(j - 1)][0], q[std::size_t(j - 1)][1]);
            t[std::size_t(j)] = sum / total;
        }
        QVERIFY(std::abs(t[2] - 0.19913) < 5e-6); // as the issue reads it off Annex III
        // A = MᵀM | MᵀQ, then elimination with partial pivoting.
        const int cols = n + 1;
        std::vector<std::vector<double>> a(std::size_t(cols), std::vector<double>(std::size_t(cols + 2), 0.0));
        for (int i = 0; i < k; ++i)
            for (int r = 0; r < cols; ++r) {
                const double br = bernstein(r, n, t[std::size_t(i)]);
                for (int c = 0; c < cols; ++c)
                    a[std::size_t(r)][std::size_t(c)] += br * bernstein(c, n, t[std::size_t(i)]);
                a[std::size_t(r)][std::size_t(cols)] += br * q[std::size_t(i)][0];
                a[std::size_t(r)][std::size_t(cols + 1)] += br * q[std::size_t(i)][1];
            }
        for (int c = 0; c < cols; ++c) {
            int pivot = c;
            for (int r = c + 1; r < cols; ++r)
                if (std::abs(a[std::size_t(r)][std::size_t(c)]) > std::abs(a[std::size_t(pivot)][std::size_t(c)]))
                    pivot = r;
            std::swap(a[std::size_t(c)], a[std::size_t(pivot)]);
            for (int r = 0; r < cols; ++r)
                if (r != c) {
                    const double factor = a[std::size_t(r)][std::size_t(c)] / a[std::size_t(c)][std::size_t(c)];
                    for (int j = c; j < cols + 2; ++j)
                        a[std::size_t(r)][std::size_t(j)] -= factor * a[std::size_t(c)][std::size_t(j)];
                }
        }
        MainWindow window;
        window.resize(1280, 800);
        QTemporaryDir dir;
        const auto controlPoints = [&](const char* variant) {
            QString error;
            std::vector<std::array<double, 2>> points;
            if (!granota::ui::showThesisFigure(window, *f, *granota::findFigureVariant(*f, variant), false, &error))
                return points;
            const QString file = dir.filePath(QStringLiteral("fig.csv"));
            if (!granota::ui::exportThesisFigure(window, *f, QStringLiteral("csv"), file, QSize(), 96).isEmpty())
                return points;
            QFile in(file);
            in.open(QIODevice::ReadOnly);
            const QString text = QString::fromUtf8(in.readAll());
            const QString table = text.section(QStringLiteral("j,P_x,P_y\n"), 1);
            for (const QString& line : table.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
                const QStringList cells = line.split(QLatin1Char(','));
                if (cells.size() == 3)
                    points.push_back({cells[1].toDouble(), cells[2].toDouble()});
            }
            return points;
        };
        const auto thesis = controlPoints("thesis");
        QCOMPARE(int(thesis.size()), cols);
        for (int c = 0; c < cols; ++c)
            for (int d = 0; d < 2; ++d) {
                const double expected = a[std::size_t(c)][std::size_t(cols + d)] / a[std::size_t(c)][std::size_t(c)];
                QVERIFY2(
                    std::abs(thesis[std::size_t(c)][std::size_t(d)] - expected) < 1e-9,
                    qPrintable(
                        QStringLiteral("P%1: %2 against %3").arg(c).arg(thesis[std::size_t(c)][std::size_t(d)]).arg(expected)));
            }
        const auto definition = controlPoints("definition");
        QCOMPARE(int(definition.size()), cols);
        QVERIFY(std::abs(definition[0][0] - thesis[0][0]) > 0.1);
    }

    // What the user had on (the tangent, the comb, the hodograph) does not show in Fig 2.2.
    void figureHidesWhatTheUserHadOn()
    {
        MainWindow window;
        window.resize(1280, 800);
        QVERIFY(window.loadExample(QStringLiteral("2.3")));
        TabPage* page = window.tab(QStringLiteral("decasteljau"));
        QJsonObject state = page->saveState();
        for (const char* key : {"tangent", "curvatureComb", "hodograph", "normal", "construction"})
            state.insert(QString::fromLatin1(key), true);
        QString error;
        QVERIFY2(page->loadState(state, &error), qPrintable(error));
        const ThesisFigure* f = granota::findThesisFigure("2.2");
        QVERIFY(granota::ui::showThesisFigure(window, *f, f->variants.front(), false, &error));
        const QJsonObject shown = page->saveState();
        for (const char* key : {"tangent", "curvatureComb", "hodograph", "normal", "construction"})
            QVERIFY2(!shown.value(QString::fromLatin1(key)).toBool(), key);
    }

    // Help ▸ Thesis figures: choosing Fig 2.7, variant `thesis`, and Show loads Ex 2.9 with
    // Annex III's parameters as one undo step named for the figure; Undo gives back the tab
    // as it was (points and parametrisation).
    void galleryShowIsOneUndoStep()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("fit")));
        TabPage* fit = window.tab(QStringLiteral("fit"));
        const QJsonObject before = fit->saveState();
        window.showThesisFigures();
        auto* dialog = window.findChild<granota::ui::ThesisFiguresDialog*>();
        QVERIFY(dialog);
        const auto& figures = thesisFigures();
        const int row = int(
            std::find_if(figures.begin(), figures.end(), [](const ThesisFigure& f) { return f.number == "2.7"; }) -
            figures.begin());
        dialog->list()->setCurrentRow(row);
        dialog->variants()->setCurrentIndex(dialog->variants()->findData(QStringLiteral("thesis")));
        QCOMPARE(dialog->variants()->currentText(), QStringLiteral("as the thesis computed it"));
        QVERIFY(dialog->note()->text().contains(QStringLiteral("BezParamProp")));
        const int steps = fit->undoStack()->count();
        QVERIFY(dialog->showChosen());
        QCOMPARE(window.currentTab(), fit);
        QCOMPARE(fit->saveState().value(QStringLiteral("parametrization")).toString(), QStringLiteral("annex-iii"));
        QCOMPARE(fit->undoStack()->count(), steps + 1);
        QVERIFY(fit->undoStack()->undoText().contains(QStringLiteral("2.7")));
        fit->undoStack()->undo();
        QCOMPARE(fit->saveState(), before);
        fit->undoStack()->redo();
        QCOMPARE(fit->saveState().value(QStringLiteral("parametrization")).toString(), QStringLiteral("annex-iii"));
        // In Catalan, the list shows the thesis's own captions.
        granota::ui::setLanguage(QStringLiteral("ca"), false);
        QCoreApplication::processEvents(); // the LanguageChange is posted
        QVERIFY2(dialog->list()->item(row)->text().contains(QStringLiteral("proporcionals a les distàncies")),
                 qPrintable(dialog->list()->item(row)->text()));
        QCOMPARE(dialog->variants()->currentText(), QStringLiteral("com la va calcular la tesi")); // kept, translated
        granota::ui::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::processEvents();
        QVERIFY(dialog->list()->item(row)->text().contains(QStringLiteral("proportional to the distances")));
    }

    // Every figure, in every format, in both languages, through the code `--export` runs:
    // a valid SVG, PDF, PNG of the size asked, TikZ picture and CSV; each other variant as a
    // PNG and a CSV.
    void everyFigureExportsInEveryFormat()
    {
        MainWindow window;
        window.resize(1280, 800);
        QTemporaryDir dir;
        const QSize size(640, 480);
        for (const QString& language : {QStringLiteral("en"), QStringLiteral("ca")}) {
            granota::ui::setLanguage(language, false);
            for (const ThesisFigure& f : thesisFigures())
                for (const FigureVariant& v : f.variants) {
                    const bool first = &v == &f.variants.front();
                    if (!first && language == QLatin1String("ca"))
                        continue;
                    QString error;
                    QVERIFY2(granota::ui::showThesisFigure(window, f, v, false, &error), qPrintable(error));
                    for (const QString& format : granota::ui::thesisFigureFormats()) {
                        if (!first && format != QLatin1String("png") && format != QLatin1String("csv"))
                            continue;
                        const QString file = dir.filePath(QStringLiteral("fig.") + format);
                        QFile::remove(file);
                        const QString what =
                            QStringLiteral("Fig %1 %2 %3 (%4)").arg(str(f.number), str(v.name), format, language);
                        const QString exported = granota::ui::exportThesisFigure(window, f, format, file, size, 96);
                        QVERIFY2(exported.isEmpty(), qPrintable(what + QStringLiteral(": ") + exported));
                        const QString problem = checkFile(file, format, size);
                        QVERIFY2(problem.isEmpty(), qPrintable(what + QStringLiteral(": ") + problem));
                    }
                }
        }
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    // Issue 34, item 10: Fig 2.10's key was fixed in the top-left corner, over q0's label. The
    // Catmull-Rom key goes where it covers least, as the De Casteljau tab's: clear of every
    // point and label, over no more of the curves than the top-left corner would be.
    void fig210KeyCoversNoLabel_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("ca") << QStringLiteral("ca"); // the longer key: "discontínua: extrems de tipus …"
    }
    void fig210KeyCoversNoLabel()
    {
        QFETCH(QString, language);
        granota::ui::setLanguage(language, false);
        const auto english = qScopeGuard([] { granota::ui::setLanguage(QStringLiteral("en"), false); });
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        QVERIFY(waitExposed(&window));
        const ThesisFigure* figure = granota::findThesisFigure("2.10");
        QVERIFY(figure);
        QString error;
        QVERIFY2(granota::ui::showThesisFigure(window, *figure, figure->variants.front(), false, &error), qPrintable(error));
        auto* tab = qobject_cast<granota::ui::CatmullRomTab*>(window.tab(QStringLiteral("catmull-rom")));
        QVERIFY(tab);
        // As `granota --figure 2.10 --export f.png` draws it: the canvas laid out at 800×600.
        QTemporaryDir dir;
        const QSize size(800, 600);
        QCOMPARE(granota::ui::exportThesisFigure(window, *figure, QStringLiteral("png"), dir.filePath(QStringLiteral("f.png")),
                                                 size, 96),
                 QString());
        // (800 × 578 here: what the window's smallest size leaves; the export scales that view.)
        QVERIFY(std::abs(tab->canvas()->width() - size.width()) < 40 && std::abs(tab->canvas()->height() - size.height()) < 40);
        const auto& view = tab->canvas()->view();
        const auto& style = tab->canvas()->style();
        const QRectF key = tab->legendRect(view, style);
        QVERIFY(!key.isEmpty());
        QVERIFY(view.viewport().contains(key));
        // Each point's handle and label "q<i>", as the point editor draws them (point_editor.cpp:
        // the text from (r + 3, −r) off the centre, on its baseline).
        const QFontMetricsF fm(style.labelFont());
        const double r = style.handleRadius();
        const auto& q = tab->pointEditor()->points();
        QVERIFY(!q.empty());
        for (std::size_t i = 0; i < q.size(); ++i) {
            const QPointF s = view.toScreen(q[i]);
            const QRectF handle(s - QPointF(r, r), QSizeF(2 * r, 2 * r));
            const QRectF label(s.x() + r + 3 * style.scale, s.y() - r - fm.ascent(),
                               fm.horizontalAdvance(QStringLiteral("q%1").arg(i)), fm.height());
            QVERIFY2(!key.intersects(handle) && !key.intersects(label), qPrintable(QStringLiteral("q%1 under the key").arg(i)));
        }
        // Over the curves, no more than the corner a fixed key took.
        const auto samplesIn = [&](const QRectF& box) {
            int k = 0;
            for (const auto& curve : tab->scene().curves)
                for (const granota::Point& p : curve.samples)
                    k += box.contains(view.toScreen(p));
            return k;
        };
        const QRectF topLeft(view.viewport().topLeft() + QPointF(8, 8) * style.scale, key.size());
        QVERIFY2(samplesIn(key) <= samplesIn(topLeft),
                 qPrintable(QStringLiteral("%1 > %2").arg(samplesIn(key)).arg(samplesIn(topLeft))));
    }

    // With no display at all: --list-figures prints the 23 figures (number, variants, the
    // caption in the language asked), --figure writes each format, and a bad figure,
    // variant or format is status 2 with "error: ".
    void headlessRuns()
    {
        QTemporaryDir dir;
        const QProcessEnvironment env = headless(dir, {});
        const Run list = runGranota({QStringLiteral("--list-figures"), QStringLiteral("--lang"), QStringLiteral("ca")}, env);
        QCOMPARE(list.status, 0);
        const QStringList lines = list.out.trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), int(thesisFigures().size()));
        QCOMPARE(lines[6], QStringLiteral("2.7\tdefinition, thesis\t") + str(thesisFigures()[6].caption.ca));
        const Run english = runGranota({QStringLiteral("--list-figures"), QStringLiteral("--lang"), QStringLiteral("en")}, env);
        QVERIFY(english.out.contains(str(thesisFigures()[0].caption.en)));
        for (const QString& format : granota::ui::thesisFigureFormats()) {
            const QString file = dir.filePath(QStringLiteral("f.") + format);
            const Run run = runGranota({QStringLiteral("--figure"), QStringLiteral("2.8"), QStringLiteral("--variant"),
                                        QStringLiteral("thesis"), QStringLiteral("--size"), QStringLiteral("500x400"),
                                        QStringLiteral("--export"), file},
                                       env);
            QVERIFY2(run.status == 0, qPrintable(format + QStringLiteral(": ") + run.err));
            QVERIFY2(run.err.isEmpty(), qPrintable(run.err)); // no notices from Qt either
            const QString problem = checkFile(file, format, QSize(500, 400));
            QVERIFY2(problem.isEmpty(), qPrintable(format + QStringLiteral(": ") + problem));
        }
        const Run dpi = runGranota({QStringLiteral("--figure"), QStringLiteral("4.11"), QStringLiteral("--size"),
                                    QStringLiteral("200x100"), QStringLiteral("--dpi"), QStringLiteral("192"),
                                    QStringLiteral("--export"), dir.filePath(QStringLiteral("head.png"))},
                                   env);
        QCOMPARE(dpi.status, 0);
        QCOMPARE(QImage(dir.filePath(QStringLiteral("head.png"))).size(), QSize(400, 200));
        const QList<QStringList> bad = {
            {QStringLiteral("--figure"), QStringLiteral("2.11"), QStringLiteral("--export"),
             dir.filePath(QStringLiteral("x.svg"))},
            {QStringLiteral("--figure"), QStringLiteral("2.7"), QStringLiteral("--variant"), QStringLiteral("matlab"),
             QStringLiteral("--export"), dir.filePath(QStringLiteral("x.svg"))},
            {QStringLiteral("--figure"), QStringLiteral("2.7"), QStringLiteral("--export"),
             dir.filePath(QStringLiteral("x.jpg"))},
            {QStringLiteral("--figure"), QStringLiteral("2.7")},
            {QStringLiteral("--figure"), QStringLiteral("2.7"), QStringLiteral("--dpi"), QStringLiteral("5000"),
             QStringLiteral("--export"), dir.filePath(QStringLiteral("x.png"))},
        };
        for (const QStringList& arguments : bad) {
            const Run run = runGranota(arguments, env);
            QVERIFY2(run.status == 2 && run.err.startsWith(QStringLiteral("error: ")),
                     qPrintable(arguments.join(QLatin1Char(' ')) + QStringLiteral(" → ") + run.err));
            QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.svg"))));
        }
    }

    // Each figure's CSV, written headless, has the SHA-256 kept in
    // tests/data/thesis_figures_csv.sha256 (made by this export and checked by eye against
    // the thesis's figures; the numbers in it are checked by the tabs' own tests), the same
    // under C.UTF-8 and under a Catalan desktop's ca_ES.UTF-8.
    void csvGoldenInBothLocales()
    {
        QFile golden(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/data/thesis_figures_csv.sha256"));
        QVERIFY(golden.open(QIODevice::ReadOnly | QIODevice::Text));
        QHash<QString, QString> hashes;
        for (const QByteArray& line : golden.readAll().split('\n')) {
            const QList<QByteArray> cells = line.simplified().split(' ');
            if (cells.size() == 2)
                hashes.insert(QString::fromLatin1(cells[0]), QString::fromLatin1(cells[1]));
        }
        QVERIFY(std::setlocale(LC_ALL, kCatalanLocale)); // the locale exists on this machine
        std::setlocale(LC_ALL, "C");
        QTemporaryDir dir;
        for (const QStringList& locale :
             {QStringList{QStringLiteral("LANG=C.UTF-8"), QStringLiteral("LC_ALL=C.UTF-8")}, catalanEnvironment()}) {
            const QProcessEnvironment env = headless(dir, locale);
            for (const ThesisFigure& f : thesisFigures()) {
                const QString file = dir.filePath(QStringLiteral("fig.csv"));
                QFile::remove(file);
                const Run run = runGranota({QStringLiteral("--figure"), str(f.number), QStringLiteral("--export"), file}, env);
                QVERIFY2(run.status == 0, qPrintable(str(f.number) + run.err));
                QFile csv(file);
                QVERIFY(csv.open(QIODevice::ReadOnly));
                const QString hash = QString::fromLatin1(
                    QCryptographicHash::hash(csv.readAll(), QCryptographicHash::Sha256).toHex());
                QVERIFY2(hashes.contains(str(f.number)), qPrintable(QStringLiteral("no golden hash for Fig ") + str(f.number)));
                QVERIFY2(hashes.value(str(f.number)) == hash,
                         qPrintable(QStringLiteral("Fig %1 under %2: %3").arg(str(f.number), locale.first(), hash)));
            }
        }
    }
};

GRANOTA_TEST_MAIN(TestGuiThesisFigures)
#include "test_gui_thesis_figures.moc"
