// Issue 34, item 10 (the exports a teacher makes for slides and videos): the hodograph's inset
// covers nothing it can keep clear of, on screen and in TikZ; the Catmull-Rom picture has the
// canvas's key and polygon; De Casteljau's vectors are arrows; the frog's TikZ is filled and
// clipped to its frame as the canvas draws it; the frog's frames are one step apart from the
// step shown, at a video size, without live readouts; every file dialog opens in the folder
// used last; Save As answers Ctrl+Shift+S.
#include "core/curves/bezier/de_casteljau.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/shell/main_window.h"
#include "ui/files/tikz_writer.h"

#include "main_window_steps.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QFileDialog>
#include <QImage>
#include <QInputDialog>
#include <QPainter>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include "tests/test_main.h"

#include <functional>
#include <vector>

using granota::Point;
using granota::ui::CatmullRomTab;
using granota::ui::DeCasteljauTab;
using granota::ui::FrogTab;
using granota::ui::MainWindow;
using granota::ui::TikzWriter;

namespace {

/// A cubic from the upper left to the lower right of its box, bulging up: its end P3 is in
/// the lower right corner of the view, the lower left corner is empty.
const std::vector<Point> kEndsLowerRight = {{0, 3}, {2, 3}, {4, 2}, {6, 0}};

/// The QSettings key of the folder used last (ui/files/file_dialogs.h), written out: the
/// test sets it as a user's earlier session would have.
const QString kLastFolder = QStringLiteral("files/lastFolder");

/// Runs `open` (which shows modal dialogs) and answers them as a user would: an input dialog
/// with `answerInput` (or accepted as it is), the first file dialog with `answerFile` (or
/// rejected). Returns the folder the file dialog opened in (empty if none opened).
QString folderOfFileDialog(const std::function<void()>& open, const std::function<void(QFileDialog&)>& answerFile = nullptr,
                           const std::function<void(QInputDialog&)>& answerInput = nullptr)
{
    QString folder;
    QTimer poll;
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* input = qobject_cast<QInputDialog*>(modal)) {
            if (answerInput)
                answerInput(*input);
            input->accept();
        } else if (auto* files = qobject_cast<QFileDialog*>(modal)) {
            folder = files->directory().absolutePath();
            if (answerFile)
                answerFile(*files);
            else
                files->reject();
        } else if (modal) {
            modal->close(); // a message box: not what is tested
        }
    });
    poll.start();
    open();
    poll.stop();
    return folder;
}

/// Every "(x,y)" of `line`, in cm.
std::vector<QPointF> coordinatesOf(const QString& line)
{
    static const QRegularExpression pair(QStringLiteral("\\((-?[0-9.]+),(-?[0-9.]+)\\)"));
    std::vector<QPointF> out;
    for (auto it = pair.globalMatch(line); it.hasNext();) {
        const auto m = it.next();
        out.emplace_back(m.captured(1).toDouble(), m.captured(2).toDouble());
    }
    return out;
}

/// The box of the first `\filldraw … (a) rectangle (b)` after the line containing `after`.
QRectF boxAfter(const QString& tex, const QString& after)
{
    const qsizetype from = tex.indexOf(after);
    if (from < 0)
        return {};
    static const QRegularExpression box(
        QStringLiteral("\\\\filldraw\\[[^\\]]*\\] \\((-?[0-9.]+),(-?[0-9.]+)\\) rectangle \\((-?[0-9.]+),(-?[0-9.]+)\\)"));
    const auto m = box.match(tex, from);
    if (!m.hasMatch())
        return {};
    return QRectF(QPointF(m.captured(1).toDouble(), m.captured(2).toDouble()),
                  QPointF(m.captured(3).toDouble(), m.captured(4).toDouble()))
        .normalized();
}

/// The coordinates of the main picture's lines and dots: every `\draw` and `\fill` before
/// the inset (or the key), in cm.
std::vector<QPointF> mainPictureCoordinates(const QString& tex)
{
    std::vector<QPointF> out;
    for (const QString& line : tex.split(QLatin1Char('\n'))) {
        if (line.contains(QStringLiteral("% inset")) || line.contains(QStringLiteral("% key")))
            break;
        if (line.contains(QStringLiteral("\\draw[")) || line.contains(QStringLiteral("\\fill[")))
            for (const QPointF& q : coordinatesOf(line))
                out.push_back(q);
    }
    return out;
}

template <class Tab> void show(Tab& tab)
{
    tab.resize(1100, 700);
    tab.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tab));
    QCoreApplication::processEvents();
}

} // namespace

class TestGuiExports : public QObject {
    Q_OBJECT

private:
    /// The De Casteljau tab of `window` on screen with its hodograph shown, on `example` (or,
    /// for none, a curve ending in the lower right corner); nullptr if that cannot be done.
    static DeCasteljauTab* showHodographOf(MainWindow& window, const QString& example)
    {
        auto* tab = window.findChild<DeCasteljauTab*>();
        if (!showOnTab(window, QStringLiteral("decasteljau")) || !tab)
            return nullptr;
        if (example.isEmpty())
            tab->loadCurve(kEndsLowerRight, QStringLiteral("curve"));
        else if (!window.loadExample(example))
            return nullptr;
        tab->setHodographVisible(true);
        return tab;
    }

private slots:
    void initTestCase() { useTestSettings(); }

    // A curve that ends in the lower right corner of its view (P3), where the inset used to
    // be drawn over its end, and Ex 2.3 (the example): on screen the inset covers no
    // handle and no sample of the curve, and the key keeps clear of it.
    void theHodographInsetCoversNothingOnScreen_data()
    {
        QTest::addColumn<QString>("example");
        QTest::newRow("end in the lower right") << QString();
        QTest::newRow("Ex 2.3") << QStringLiteral("2.3");
    }
    // Issue 34, item 11: the labels now write their indices as Unicode sub- and superscripts;
    // TikZ turns each run of them into one LaTeX group (expected strings written by hand from
    // LaTeX's syntax: "Pᵢ₊₁" is P with the subscript i+1).
    void texTextGroupsIndices_data()
    {
        QTest::addColumn<QString>("label");
        QTest::addColumn<QString>("tex");
        QTest::newRow("P_{i+1}") << QStringLiteral("Pᵢ₊₁") << QStringLiteral("P$_{i+1}$");
        QTest::newRow("B_i^n") << QStringLiteral("Bᵢⁿ(t)") << QStringLiteral("B$_{i}^{n}$(t)");
        QTest::newRow("10^16") << QStringLiteral("10¹⁶") << QStringLiteral("10$^{16}$");
        QTest::newRow("w_j") << QStringLiteral("wⱼ(t, τ)") << QStringLiteral("w$_{j}$(t, $\\tau$)");
        QTest::newRow("P_{10}") << QStringLiteral("P₁₀") << QStringLiteral("P$_{10}$");
        QTest::newRow("M^T") << QStringLiteral("MᵀM") << QStringLiteral("M$^{T}$M");
    }
    void texTextGroupsIndices()
    {
        QFETCH(QString, label);
        QFETCH(QString, tex);
        QCOMPARE(TikzWriter::texText(label), tex);
    }

    void theHodographInsetCoversNothingOnScreen()
    {
        QFETCH(QString, example);
        MainWindow window;
        DeCasteljauTab* tab = showHodographOf(window, example);
        QVERIFY(tab);
        QCoreApplication::processEvents();
        const auto& view = tab->canvas()->view();
        const auto& style = tab->canvas()->style();
        const QRectF inset = tab->hodographInset(view, style);
        QVERIFY(!inset.isEmpty());
        const double r = style.handleRadius();
        const auto& P = tab->pointEditor()->points();
        for (std::size_t i = 0; i < P.size(); ++i) {
            const QPointF s = view.toScreen(P[i]);
            QVERIFY2(!inset.intersects(QRectF(s - QPointF(r, r), QSizeF(2 * r, 2 * r))),
                     qPrintable(QStringLiteral("P%1 under the inset").arg(i)));
        }
        for (const Point& q : tab->curve())
            QVERIFY2(!inset.contains(view.toScreen(q)), "the curve under the inset");
        QVERIFY(!tab->legendRect(view, style).intersects(inset));
    }

    // The same in TikZ: no coordinate of the main picture (the curve's polyline, the polygon,
    // the points) lies inside the inset's frame.
    void theHodographInsetCoversNothingInTikz_data() { theHodographInsetCoversNothingOnScreen_data(); }
    void theHodographInsetCoversNothingInTikz()
    {
        QFETCH(QString, example);
        MainWindow window;
        DeCasteljauTab* tab = showHodographOf(window, example);
        QVERIFY(tab);
        const QString tex = tab->tikz();
        const QRectF inset = boxAfter(tex, QStringLiteral("% inset"));
        QVERIFY2(!inset.isEmpty(), qPrintable(tex));
        const std::vector<QPointF> drawn = mainPictureCoordinates(tex);
        QVERIFY(drawn.size() > 50); // the curve's samples at least
        for (const QPointF& q : drawn)
            QVERIFY2(!inset.contains(q), qPrintable(QStringLiteral("(%1,%2) under the inset").arg(q.x()).arg(q.y())));
    }

    // TikzWriter places its inset where it covers least: a line through the lower right
    // corner sends it to the lower left, one along the bottom to the top.
    void theTikzInsetGoesWhereItCoversLeast()
    {
        const auto insetOf = [](const std::vector<Point>& line) {
            TikzWriter w;
            w.polyline({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, Qt::gray, 0.4, false, true); // the frame
            w.polyline(line, Qt::blue);
            w.beginInset(QStringLiteral("inset"));
            w.polyline({{0, 0}, {1, 1}}, Qt::red);
            w.endInset();
            return boxAfter(w.str(), QStringLiteral("% inset"));
        };
        // Width 10 cm (TikzOptions' default), 1 unit = 1 cm less the margins: the inset is
        // 3 units wide, at most 2.25 tall (its proportions, tikz_writer.h).
        const QRectF lowerRight = insetOf({{6, 0.2}, {9.8, 1.5}});
        QVERIFY(!lowerRight.isEmpty());
        QVERIFY2(lowerRight.left() < 1, "the lower right is taken: the inset goes left");
        QVERIFY(lowerRight.top() < 0.1);
        const QRectF bottom = insetOf({{0.2, 0.5}, {9.8, 0.5}});
        QVERIFY2(bottom.top() > 2, "the bottom is taken: the inset goes up");
    }

    // The Catmull-Rom TikZ has what the canvas shows: the dashed polygon of the points q_i
    // (their coordinates, in order) and the key with a line per τ, its colour and the text
    // of the canvas's key in TeX.
    void catmullRomTikzHasTheKeyAndThePolygon()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("catmull-rom")));
        QVERIFY(loadExamples(window, {"2.13"}));
        auto* tab = window.findChild<CatmullRomTab*>();
        QVERIFY(tab);
        const QString tex = tab->tikz();
        const auto& points = tab->pointEditor()->points();
        // The polygon: a dashed line through as many coordinates as there are points.
        bool polygon = false;
        for (const QString& line : tex.split(QLatin1Char('\n')))
            if (line.contains(QStringLiteral("dashed")) && line.startsWith(QStringLiteral("  \\draw[")) &&
                coordinatesOf(line).size() == points.size() && !line.contains(QStringLiteral("cycle")))
                polygon = true;
        QVERIFY2(polygon, qPrintable(tex));
        // The key: one line per entry of the canvas's key, τ written as TeX.
        QVERIFY2(tex.contains(QStringLiteral("% key")), qPrintable(tex));
        const auto legend = tab->legend();
        QVERIFY(!legend.entries.empty());
        for (const auto& entry : legend.entries)
            QVERIFY2(tex.contains(TikzWriter::texText(entry.text)), qPrintable(entry.text));
        QVERIFY(tex.contains(QStringLiteral("$\\tau$ = 1/2")));
    }

    // De Casteljau's tangent and normal are arrows in TikZ, as on the canvas: each `\draw`
    // from c(t) has an arrowhead (-stealth).
    void deCasteljauVectorsAreArrows()
    {
        DeCasteljauTab tab;
        show(tab);
        tab.setTangentVisible(true);
        tab.setNormalVisible(true);
        const QString tex = tab.tikz();
        const QStringList arrows = tex.split(QLatin1Char('\n')).filter(QStringLiteral("-stealth"));
        QVERIFY2(arrows.size() >= 2, qPrintable(tex));
    }

    // The frog's TikZ is drawn as the canvas draws it: bodies filled with the skin's colour,
    // legs filled, feet drawn, everything clipped to the frame (the feet of the frog on the
    // floor reach below it; the canvas clips them).
    void frogTikzIsFilledAndInsideTheFrame()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* tab = window.findChild<FrogTab*>();
        QVERIFY(tab);
        const QString tex = tab->tikz();
        QVERIFY2(tex.contains(QStringLiteral("fill=g30A130")), qPrintable(tex)); // the seed's fill(48, 161, 48)
        const int clip = static_cast<int>(tex.indexOf(QStringLiteral("\\clip")));
        QVERIFY2(clip > 0, qPrintable(tex));
        // The frame is the first \draw; the clip is its rectangle.
        const QStringList lines = tex.split(QLatin1Char('\n'));
        std::vector<QPointF> frame;
        for (const QString& line : lines)
            if (line.contains(QStringLiteral("\\draw[")) && frame.empty())
                frame = coordinatesOf(line);
        QCOMPARE(frame.size(), std::size_t(4));
        const QRectF box = QRectF(frame[0], frame[2]).normalized();
        const QString clipLine = tex.mid(clip, tex.indexOf(QLatin1Char('\n'), clip) - clip);
        const std::vector<QPointF> corners = coordinatesOf(clipLine);
        QCOMPARE(corners.size(), std::size_t(2));
        QCOMPARE(QRectF(corners[0], corners[1]).normalized(), box);
        // Every body and leg is drawn after the clip, inside its scope.
        QVERIFY(tex.indexOf(QStringLiteral("fill=g30A130")) > clip);
    }

    // Issue 34, item 10: the frog's head is in its TikZ, over the body, as the canvas paints
    // it: after a "% the head" comment, its paths, the eye whites filled with their colour. At least the parts FrogArt draws for it are there: the outline, two
    // cheeks, two eye whites, two nostrils, the mouth and two pupils (frog_art.cpp,
    // paintHeadStill and paintPupils), 10 paths. The export compiles with the rest in
    // test_gui_tikz_latex (its frog figure is this scene).
    void frogTikzHasTheHead()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* tab = window.findChild<FrogTab*>();
        QVERIFY(tab);
        const QString tex = tab->tikz();
        const int head = static_cast<int>(tex.indexOf(QStringLiteral("% the head")));
        QVERIFY2(head > 0, qPrintable(tex));
        const QString after = tex.mid(head);
        const QStringList paths =
            after.split(QLatin1Char('\n')).filter(QRegularExpression(QStringLiteral("^\\s*\\\\(draw|fill|filldraw)\\b")));
        QVERIFY2(paths.size() >= 10, qPrintable(after));
        QVERIFY2(after.contains(QStringLiteral("fill=gFDFDF4")), qPrintable(after)); // the eye whites, frog_art.cpp
    }

    // File ▸ Export ▸ Frog animation as PNG frames, through its dialogs while the run goes on:
    // 3 frames of the size chosen (the default, 1280 × 720, even sides), frame k the picture
    // of the run at the step shown when the menu was chosen plus k (rendered here after
    // going back to that step), without the text panel although the frame time and the
    // readouts are on (the canvas's own rendering with them differs).
    void frogFramesAreOneStepApartAtVideoSize()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* tab = window.findChild<FrogTab*>();
        auto* canvas = window.findChild<granota::ui::FrogCanvas*>();
        QVERIFY(tab && canvas);
        QTRY_VERIFY(canvas->frogRun()->simulation() && canvas->frogRun()->simulation()->stepCount() > 5); // running
        granota::ui::FrogCanvas::Overlays live;
        live.frameTime = true;
        live.readouts = true;
        canvas->setOverlays(live);
        QTemporaryDir dir;
        QAction* frames = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->text() == MainWindow::tr("Frog animation as PNG frames…"))
                frames = a;
        QVERIFY(frames);
        long shown = -1;
        folderOfFileDialog(
            [&] {
                shown = canvas->frogRun()->simulation()->stepCount();
                frames->trigger();
            },
            [&](QFileDialog& d) {
                d.setDirectory(dir.path());
                QMetaObject::invokeMethod(&d, "accept"); // a protected slot
            },
            [](QInputDialog& d) {
                if (d.inputMode() == QInputDialog::IntInput)
                    d.setIntValue(3);
            });
        QDir out(dir.path());
        QCOMPARE(out.entryList({QStringLiteral("frame_*.png")}, QDir::Files).size(), 3);
        const auto picture = [canvas](QSize size, bool textPanel) {
            QImage image(size, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::white);
            QPainter p(&image);
            if (textPanel)
                canvas->render(p, QRectF(QPointF(0, 0), QSizeF(size)));
            else
                canvas->renderFrame(p, QRectF(QPointF(0, 0), QSizeF(size)));
            p.end();
            return image.convertToFormat(QImage::Format_ARGB32);
        };
        for (int k = 0; k < 3; ++k) {
            const QImage frame(out.filePath(QStringLiteral("frame_%1.png").arg(k, 4, 10, QLatin1Char('0'))));
            QCOMPARE(frame.size(), QSize(1280, 720));
            QVERIFY(canvas->frogRun()->seek(shown + k));
            const QImage expected = picture(frame.size(), false);
            QVERIFY2(frame.convertToFormat(QImage::Format_ARGB32) == expected,
                     qPrintable(QStringLiteral("frame %1 is not step %2").arg(k).arg(shown + k)));
            QVERIFY(picture(frame.size(), true) != expected); // the readouts were on
        }
    }

    // Every file dialog opens in the folder used last (a setting kept across sessions), not
    // in $HOME or the working folder; a file saved elsewhere makes its folder the one used last.
    void fileDialogsOpenInTheFolderUsedLast()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("fit")));
        QTemporaryDir first, second;
        QSettings().setValue(kLastFolder, first.path());
        const QString expected = QDir(first.path()).absolutePath();
        const auto action = [&window](const QString& text) -> QAction* {
            for (QAction* a : window.findChildren<QAction*>())
                if (a->text() == text)
                    return a;
            return nullptr;
        };
        for (const char* text : {"&Open…", "Save &As…", "SVG drawing…"}) {
            QAction* a = action(MainWindow::tr(text));
            QVERIFY2(a, text);
            QCOMPARE(folderOfFileDialog([a] { a->trigger(); }), expected);
        }
        QAbstractButton* import = nullptr;
        for (QAbstractButton* b : window.findChildren<QAbstractButton*>())
            if (b->text() == QCoreApplication::translate("granota::ui::FitTab", "&Import CSV…"))
                import = b;
        QVERIFY(import);
        QCOMPARE(folderOfFileDialog([import] { import->click(); }), expected);
        QVERIFY(window.showTab(QStringLiteral("frog")));
        QAction* frames = action(MainWindow::tr("Frog animation as PNG frames…"));
        QVERIFY(frames);
        QCOMPARE(folderOfFileDialog([frames] { frames->trigger(); }), expected);
        // A drawing saved in the second folder: the next dialog opens there.
        QVERIFY(window.showTab(QStringLiteral("fit")));
        const QString svg = QDir(second.path()).filePath(QStringLiteral("fit.svg"));
        folderOfFileDialog([&] { action(MainWindow::tr("SVG drawing…"))->trigger(); },
                           [&svg](QFileDialog& d) {
                               d.selectFile(svg);
                               QMetaObject::invokeMethod(&d, "accept"); // a protected slot
                           });
        QVERIFY(QFileInfo::exists(svg));
        QCOMPARE(folderOfFileDialog([&] { action(MainWindow::tr("&Open…"))->trigger(); }), QDir(second.path()).absolutePath());
    }

    // No dialog of the application calls QFileDialog's static functions itself: they all go
    // through ui/shell/file_dialogs (which remembers the folder).
    void everyFileDialogGoesThroughTheHelper()
    {
        QDirIterator it(QStringLiteral(GRANOTA_SOURCE_DIR "/ui"), {QStringLiteral("*.cpp")}, QDir::Files,
                        QDirIterator::Subdirectories);
        int files = 0;
        while (it.hasNext()) {
            const QString path = it.next();
            ++files;
            if (path.endsWith(QStringLiteral("files/file_dialogs.cpp")))
                continue;
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(f.readAll());
            QVERIFY2(!text.contains(QStringLiteral("QFileDialog::get")), qPrintable(path));
        }
        QVERIFY(files > 20);
    }

    // File ▸ Save As answers Ctrl+Shift+S (docs/classroom.md) whatever the platform's key
    // theme says QKeySequence::SaveAs is (nothing under a plain X11 or offscreen).
    void saveAsAnswersCtrlShiftS()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        qInfo() << "QKeySequence::SaveAs here:" << QKeySequence::keyBindings(QKeySequence::SaveAs);
        QAction* saveAs = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->text() == MainWindow::tr("Save &As…"))
                saveAs = a;
        QVERIFY(saveAs);
        QVERIFY(saveAs->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
        // Typed: the save dialog opens.
        bool opened = false;
        QTimer poll;
        poll.setInterval(10);
        QObject::connect(&poll, &QTimer::timeout, [&opened] {
            if (auto* d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
                opened = d->objectName() == QStringLiteral("saveDocumentDialog");
                d->reject();
            }
        });
        poll.start();
        QTest::keyClick(&window, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
        poll.stop();
        QVERIFY(opened);
    }
};

GRANOTA_TEST_MAIN(TestGuiExports)
#include "test_gui_exports.moc"
