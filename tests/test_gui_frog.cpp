// The frog lab tab (docs/scenes.md): stepping, grabbing and spawning through the canvas's own
// mouse and key events, the scene's own parameters applied live and undoably, every scene on
// both solvers, the frame export and the document round trip.
#include "core/base/math_constants.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_trace.h"
#include "ui/frog/frog_art.h"
#include "ui/common/number_text.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_parameters_panel.h"
#include "ui/frog/frog_plot_panel.h"
#include "ui/frog/frog_tab.h"
#include "cli_runner.h"
#include "gui_timeouts.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QImage>
#include <QJsonArray>
#include <QLabel>
#include <QPainter>
#include <QPicture>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QGroupBox>
#include <QSet>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include "tests/test_main.h"
#include <qcustomplot.h>

#include <QJsonDocument>

using namespace granota;
using namespace granota::ui;

Q_DECLARE_METATYPE(granota::SolverKind)

namespace {

Point centroid(const Simulation& sim, int body = 0)
{
    std::vector<Point> v;
    sim.bodyVertices(body, v);
    Point c(0, 0);
    for (const Point& p : v)
        c += p;
    return Point(c.x / v.size(), c.y / v.size());
}

void steps(FrogTab& tab, int n)
{
    for (int i = 0; i < n; ++i)
        tab.frogRun()->step();
}

/// How many different colours a coarse grid of the image has: a drawn scene has many.
int colours(const QImage& image)
{
    QSet<QRgb> seen;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7)
            seen.insert(image.pixel(x, y));
    return seen.size();
}

} // namespace

class TestGuiFrog : public QObject {
    Q_OBJECT

    std::unique_ptr<FrogTab> m_tab;

    FrogTab& tab() { return *m_tab; }

private slots:
    void init()
    {
        m_tab = std::make_unique<FrogTab>();
        m_tab->resize(1280, 760);
        m_tab->show();
        QVERIFY(waitExposed(m_tab.get()));
    }
    void cleanup() { m_tab.reset(); }

    void smallHeadsFromTheCachedImageLookLikeThePaths()
    {
        // A crowd of small heads is drawn from an image made once per size; a vector device
        // (QPicture, as SVG and PDF) gets the paths. Both renderings of a 40-px head agree
        // to a few levels per channel on average, and the image is actually drawn.
        const FrogArt art;
        const double scale = 0.3; // 132 × 0.3 ≈ 40 px wide: below kHeadImageBelowPx
        QVERIFY(132 * scale < FrogArt::kHeadImageBelowPx);
        const auto paint = [&](QPaintDevice* device) {
            QPainter p(device);
            p.setRenderHint(QPainter::Antialiasing, true);
            p.setRenderHint(QPainter::SmoothPixmapTransform, true);
            art.paintHead(p, QPointF(32, 32), 0.4, scale, QPointF(60, 10));
        };
        QImage fromImage(64, 64, QImage::Format_ARGB32_Premultiplied);
        fromImage.fill(Qt::white);
        paint(&fromImage);
        QPicture picture;
        paint(&picture);
        QImage fromPaths(64, 64, QImage::Format_ARGB32_Premultiplied);
        fromPaths.fill(Qt::white);
        {
            QPainter p(&fromPaths);
            p.setRenderHint(QPainter::Antialiasing, true);
            p.drawPicture(0, 0, picture);
        }
        double difference = 0;
        int inked = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const QColor a = fromImage.pixelColor(x, y), b = fromPaths.pixelColor(x, y);
                difference += std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
                inked += b != QColor(Qt::white) ? 1 : 0;
            }
        difference /= 3.0 * 64 * 64;
        QVERIFY2(inked > 600, qPrintable(QString::number(inked))); // the head covers ~1000 px
        QVERIFY2(difference < 6, qPrintable(QString::number(difference)));
        QImage again(64, 64, QImage::Format_ARGB32_Premultiplied);
        again.fill(Qt::white);
        paint(&again);
        QCOMPARE(again, fromImage); // the cached image, drawn again
    }

    // Issue 33, part 7: on the seed solver the head is drawn as Annex II draws it (l. 543:
    // image(cap, vert[0] − (1109/16, 747/16), 1109/8 × 747/8), upright, its box's centre at
    // vertex 0 + (0, ½) by Java's int division), however the body has turned; on the stable
    // solver Granota's head turns with it, along v₉ → v₁. A frog pushed sideways by gravity
    // with an x part has turned after 150 steps.
    void seedHeadIsAnnexIIsStableHeadTurns()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().applyParameter(QStringLiteral("gravity"), QJsonArray{0.6, 0.75}, nullptr));
        for (SolverKind solver : {SolverKind::Seed, SolverKind::Stable}) {
            QVERIFY(tab().setSolver(solver, nullptr));
            steps(tab(), 150);
            std::vector<Point> v;
            tab().frogRun()->simulation()->bodyVertices(0, v);
            const Point along = v[1] - v[v.size() - 1];
            const double turned = std::atan2(along.y, along.x); // computed here, not by head_pose
            QVERIFY2(std::fabs(turned) > 0.05, qPrintable(QString::number(turned)));
            const HeadPose pose = tab().canvas()->headPose(0);
            if (solver == SolverKind::Seed) {
                QCOMPARE(pose.angle, 0.0);
                QCOMPARE(pose.centre, Point(v[0].x - 69 + 138 / 2.0, v[0].y - 46 + 93 / 2.0));
            } else {
                QCOMPARE(pose.angle, turned);
                QCOMPARE(pose.centre, v[0]);
            }
        }
    }

    void startsOnTheFrogWithTheSeed()
    {
        QCOMPARE(tab().sceneName(), QStringLiteral("frog"));
        QCOMPARE(tab().solver(), SolverKind::Seed);
        QVERIFY(tab().parametersPanel()->keys().contains("legs"));
        auto* combo = tab().findChild<QComboBox*>("frogScene");
        QVERIFY(combo);
        QCOMPARE(combo->count(), 18);
        QCOMPARE(combo->itemText(0), QStringLiteral("4.1 Polygon and mouse"));
        QCOMPARE(combo->itemText(14), QStringLiteral("4.16 The frog"));
        QCOMPARE(combo->itemText(17), QStringLiteral("5.2.3 Other shapes"));
        QCOMPARE(combo->currentData().toString(), QStringLiteral("frog"));
    }

    // With several bodies the readouts say whose figure each is: the area line is the first
    // body's, the solver's area error the mean of all; with one body they say neither.
    void manyBodiesReadoutsSayWhoseFigureItIs()
    {
        FrogCanvas* canvas = tab().canvas();
        FrogCanvas::Overlays overlays;
        overlays.area = true;
        overlays.readouts = true;
        canvas->setOverlays(overlays);
        QVERIFY(tab().setScene("many-bodies", nullptr));
        const int bodies = canvas->frogRun()->simulation()->bodyCount();
        QVERIFY(bodies > 1);
        const QString first = QStringLiteral("Body 1 of %1: area").arg(bodies);
        const QString mean = QStringLiteral("Area error, mean of the %1 bodies,").arg(bodies);
        QTRY_VERIFY2_WITH_TIMEOUT(canvas->textLines().join('\n').contains(first), qPrintable(canvas->textLines().join('\n')),
                                  kEventWaitMs);
        const QString lines = canvas->textLines().join('\n');
        QVERIFY2(lines.contains(mean), qPrintable(lines));
        QVERIFY2(!lines.contains(QStringLiteral("Area error ")), qPrintable(lines));

        QVERIFY(tab().setScene("frog", nullptr));
        QCOMPARE(canvas->frogRun()->simulation()->bodyCount(), 1);
        QTRY_VERIFY2_WITH_TIMEOUT(canvas->textLines().join('\n').contains(QStringLiteral("Area error ")),
                                  qPrintable(canvas->textLines().join('\n')), kEventWaitMs);
        QVERIFY(!canvas->textLines().join('\n').contains(QStringLiteral("Body 1 of")));
    }

    void stepButtonAdvancesExactlyOneStep()
    {
        QVERIFY(tab().setScene("gravity", nullptr));
        auto* pause = tab().findChild<QPushButton*>("frogPause");
        auto* step = tab().findChild<QPushButton*>("frogStep");
        QVERIFY(pause && step);
        pause->click();
        QVERIFY(!tab().frogRun()->running());
        QVERIFY(!tab().frogRun()->animating());
        const Simulation* sim = tab().frogRun()->simulation();
        const long before = sim->stepCount();
        const Point start = centroid(*sim);
        step->click();
        QCOMPARE(sim->stepCount(), before + 1);
        QTest::qWait(100); // paused: the timer adds nothing
        QCOMPARE(sim->stepCount(), before + 1);
        for (int i = 0; i < 40; ++i)
            step->click();
        QCOMPARE(sim->stepCount(), before + 41);
        QVERIFY2(centroid(*sim).y > start.y + 50, "the polygon falls under gravity (§4.2)");

        // Running again: the 60 Hz timer drives the steps.
        pause->click();
        QVERIFY(tab().frogRun()->running());
        QVERIFY(tab().frogRun()->animating());
        QTRY_VERIFY_WITH_TIMEOUT(sim->stepCount() > before + 41 + 5, kEventWaitMs);
    }

    void aHeavyStepRunsSlowerThanRealTime()
    {
        // Issue 12: the stable solver with 10000 sides costs 30–50 ms a step; stepped every
        // frame it held the event loop frame after frame. Now a frame steps at most
        // FrogRun::kFrameWork of counted work (points × substeps), and says it is slower.
        FrogCanvas* canvas = tab().canvas();
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        QCOMPARE(canvas->frogRun()->framesPerStep(), 1); // the thesis's frog: one step per frame, real time
        QString error;
        QVERIFY2(tab().editParameter("sides", 10000, &error), qPrintable(error));
        const Simulation* sim = canvas->frogRun()->simulation();
        const long work = sim->workPerStep();
        QVERIFY(work >= 10000L * 8); // 10000 vertices, 8 substeps
        const int every = canvas->frogRun()->framesPerStep();
        QCOMPARE(every, static_cast<int>((work + FrogRun::kFrameWork - 1) / FrogRun::kFrameWork));
        QVERIFY(every > 1);
        QVERIFY2(canvas->textLines().join('\n').contains("slower than real time"), qPrintable(canvas->textLines().join('\n')));
        QVERIFY(canvas->frogRun()->running() && canvas->frogRun()->animating());
        const long stepsBefore = sim->stepCount(), framesBefore = canvas->frogRun()->frameCount();
        QTRY_VERIFY_WITH_TIMEOUT(canvas->frogRun()->frameCount() >= framesBefore + 3 * every, 60000);
        const long frames = canvas->frogRun()->frameCount() - framesBefore, steps = sim->stepCount() - stepsBefore;
        QVERIFY(steps >= 1); // it runs, slowly
        // Counted work per frame within the budget: one step every `every` frames at most.
        QVERIFY2(steps * work <= (frames + every) * FrogRun::kFrameWork,
                 qPrintable(QStringLiteral("%1 steps in %2 frames").arg(steps).arg(frames)));
        // Back to the thesis's 10 sides: real time again, the note gone.
        QVERIFY(tab().editParameter("sides", 10, &error));
        QCOMPARE(canvas->frogRun()->framesPerStep(), 1);
        QVERIFY(!canvas->textLines().join('\n').contains("slower than real time"));
        const long realBefore = canvas->frogRun()->simulation()->stepCount(), realFrames = canvas->frogRun()->frameCount();
        QTRY_VERIFY_WITH_TIMEOUT(canvas->frogRun()->frameCount() >= realFrames + 10, kEventWaitMs);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount() - realBefore, canvas->frogRun()->frameCount() - realFrames);
    }

    // Issue 16: slow motion steps once every few frames, never with a smaller step, so at ⅛
    // the seed's frog still goes through the rows of SeedFrog.java's trace, bit for bit.
    void slowMotionKeepsTheSeedTrace()
    {
        QFile reference(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/data/seed_frog_trace.csv"));
        QVERIFY(reference.open(QIODevice::ReadOnly));
        const QList<QByteArray> rows = reference.readAll().split('\n');
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true); // the timer off: the test runs the frames
        auto* speed = tab().findChild<QComboBox*>("frogSpeed");
        QVERIFY(speed);
        QCOMPARE(speed->count(), 6);
        QCOMPARE(speed->itemText(0), QStringLiteral("⅛×"));
        speed->setCurrentIndex(0);
        emit speed->activated(0);
        FrogCanvas* canvas = tab().canvas();
        QCOMPARE(canvas->frogRun()->speed(), 0.125);
        QCOMPARE(canvas->frogRun()->framesPerStep(), 8);
        QVERIFY(canvas->textLines().join('\n').contains("Slow motion"));
        const Simulation* sim = canvas->frogRun()->simulation();
        QCOMPARE(QByteArray::fromStdString(simulationTraceRow(*sim)), rows[1]);
        for (int frame = 1; frame <= 1600; ++frame) {
            const long before = sim->stepCount();
            canvas->frogRun()->runFrame();
            QCOMPARE(sim->stepCount() - before, frame % 8 == 0 ? 1L : 0L);
            if (frame % 8 == 0)
                QCOMPARE(QByteArray::fromStdString(simulationTraceRow(*sim)), rows[1 + frame / 8]);
        }
        // Fast: ] twice from 1× is 4×, four steps a frame, the same rows.
        QVERIFY(tab().setScene("frog", nullptr));
        sim = canvas->frogRun()->simulation();
        tab().setSpeed(1);
        // ] is a shortcut of the tab's window: it answers only once the window manager has
        // made that window active (a bounded wait, which names the window if it fails).
        QVERIFY(waitActive(&tab()));
        QTest::keyClick(canvas, Qt::Key_BracketRight);
        QTest::keyClick(canvas, Qt::Key_BracketRight);
        QCOMPARE(canvas->frogRun()->speed(), 4.0);
        QCOMPARE(speed->currentText(), QStringLiteral("4×"));
        QCOMPARE(canvas->frogRun()->stepsPerFrame(), 4);
        for (int frame = 1; frame <= 50; ++frame) {
            canvas->frogRun()->runFrame();
            QCOMPARE(sim->stepCount(), 4L * frame);
            QCOMPARE(QByteArray::fromStdString(simulationTraceRow(*sim)), rows[1 + 4 * frame]);
        }
        QVERIFY(canvas->textLines().join('\n').contains("4 steps a frame"));
        // The speed is kept with the document; a speed not offered is refused.
        const QJsonObject saved = tab().saveState();
        QCOMPARE(saved["speed"].toDouble(), 4.0);
        tab().setSpeed(0.25);
        QVERIFY(tab().loadState(saved, nullptr));
        QCOMPARE(canvas->frogRun()->speed(), 4.0);
        QJsonObject bad = saved;
        bad["speed"] = 3;
        QString error;
        QVERIFY(!tab().loadState(bad, &error));
        QVERIFY(error.contains("speed"));
        QCOMPARE(canvas->frogRun()->speed(), 4.0);
    }

    // Issue 16: the plots over time under the canvas. They record only while shown, draw the
    // last seconds, stand still while paused, and export exactly what simulate --series writes.
    void plotsOverTime_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<SolverKind>("solver");
        QTest::newRow("frog, seed") << "frog" << SolverKind::Seed;
        QTest::newRow("frog, stable") << "frog" << SolverKind::Stable;
        QTest::newRow("pendulum-limits, stable") << "pendulum-limits" << SolverKind::Stable;
    }
    void plotsOverTime()
    {
        QFETCH(QString, scene);
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene(scene, nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        FrogPlotPanel* panel = tab().plotPanel();
        QVERIFY(!panel->isVisible());
        steps(tab(), 10);
        QVERIFY(canvas->frogRun()->series().samples().empty()); // hidden: nothing recorded
        tab().reset();
        auto* box = tab().findChild<QCheckBox*>("frogShowPlots");
        QVERIFY(box && !box->isChecked());
        box->click();
        QVERIFY(panel->isVisible() && canvas->frogRun()->recordingSeries());
        QTRY_VERIFY_WITH_TIMEOUT(panel->height() >= 150, kEventWaitMs);
        QVERIFY(canvas->height() > panel->height()); // the canvas keeps most of the column
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(1));
        steps(tab(), 240);
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(241));
        panel->refresh(true);
        QCustomPlot* plot = panel->plot();
        QCOMPARE(panel->view(), FrogPlotPanel::View::Energy);
        QCPGraph* total = plot->graph(3);
        QCOMPARE(total->dataCount(), 241);
        QCOMPARE(total->data()->at(240)->key, 4.0); // 240 steps at 60 a second
        QCOMPARE(total->data()->at(240)->value, canvas->frogRun()->series().samples().back().total);
        QCOMPARE(plot->graph(2)->visible(), solver == SolverKind::Stable); // elastic: the stable solver's only
        QCOMPARE(plot->xAxis->range().lower, 0.0);
        QCOMPARE(plot->xAxis->range().upper, 10.0);
        // Paused, the timer steps nothing: the plot stands still.
        QTest::qWait(350);
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(241));
        QCOMPARE(total->dataCount(), 241);
        // A window of 2 s scrolls: the last 2 s only.
        panel->setWindowSeconds(2);
        QCOMPARE(plot->xAxis->range().lower, 2.0);
        QCOMPARE(total->data()->at(0)->key, 2.0);
        // The other views.
        const bool pendulum = scene.startsWith("pendulum");
        panel->setView(FrogPlotPanel::View::Phase);
        QCOMPARE(panel->view(), pendulum ? FrogPlotPanel::View::Phase : FrogPlotPanel::View::Energy);
        if (pendulum) {
            QCOMPARE(plot->plottableCount(), 6 + 2); // the energy graphs, hidden, and one orbit per link
            QVERIFY(plot->itemCount() >= 2);         // the shoulder's two limits
        }
        panel->setView(FrogPlotPanel::View::AreaError);
        QCOMPARE(plot->graph(0)->dataCount(), 121);
        QCOMPARE(plot->graph(0)->data()->at(120)->value, canvas->frogRun()->series().samples().back().areaErrorPercent);
        QVERIFY(!plot->graph(3)->visible());

        // The CSV is granota-cli simulate --series, byte for byte.
        QTemporaryDir dir;
        const QString mine = dir.filePath("gui.csv"), theirs = dir.filePath("cli.csv");
        QString error;
        QVERIFY2(panel->exportCsv(mine, &error), qPrintable(error));
        const CliRun run = runCli({"simulate", "--scene", scene, "--solver", QString::fromStdString(solverName(solver)),
                                   "--steps", "240", "--series", theirs});
        QCOMPARE(run.exitCode, 0);
        QFile a(mine), b(theirs);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray gui = a.readAll(), cli = b.readAll();
        QCOMPARE(gui.count('\n'), 242);
        QVERIFY(gui == cli);
        QVERIFY(!panel->exportCsv(dir.filePath("no/such/folder/x.csv"), &error));
        QVERIFY(!error.isEmpty());

        // Hidden again: recording stops; a new run starts a new series.
        box->click();
        QVERIFY(!panel->isVisible() && !canvas->frogRun()->recordingSeries());
        box->click();
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(1));
        tab().reset();
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(1));
        QCOMPARE(canvas->frogRun()->series().samples().front().step, 0L);
    }

    // Plots per body: with several bodies the panel lists them; one chosen, the plots and the
    // CSV are its own (simulate --series-body), and the canvas marks it with its number.
    void plotsPerBody()
    {
        QVERIFY(tab().setScene("many-bodies", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        QString error;
        QVERIFY2(tab().editParameter("bodies", 3, &error), qPrintable(error));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        FrogPlotPanel* panel = tab().plotPanel();
        tab().setPlotsShown(true);
        steps(tab(), 120);
        panel->refresh(true);
        auto* list = panel->findChild<QComboBox*>("frogPlotBody");
        QVERIFY(list && list->isVisible());
        QCOMPARE(list->count(), 4);
        QCOMPARE(list->itemText(0), QStringLiteral("All bodies"));
        QCOMPARE(list->itemText(3), QStringLiteral("Body 3"));
        QCOMPARE(panel->body(), -1);
        QCOMPARE(canvas->markedBody(), -1);
        const QImage plain = canvas->grab().toImage();
        const auto marked = [](const QImage& image) {
            int n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    n += image.pixelColor(x, y) == QColor(0xd8, 0x1b, 0x60);
            return n;
        };
        QCOMPARE(marked(plain), 0);

        list->setCurrentIndex(2);
        emit list->activated(2); // as a click on "Body 2" does
        QCOMPARE(panel->body(), 1);
        QCOMPARE(canvas->markedBody(), 1);
        QVERIFY(marked(canvas->grab().toImage()) > 100); // its outline and its number
        const SeriesSample& last = canvas->frogRun()->series().samples().back();
        QCOMPARE(last.bodies.size(), std::size_t(3));
        QCPGraph* total = panel->plot()->graph(3);
        QCOMPARE(total->dataCount(), 121);
        QCOMPARE(total->data()->at(120)->value, last.bodies[1].total);
        QVERIFY(last.bodies[1].total != last.total);
        panel->setView(FrogPlotPanel::View::Contacts);
        QCOMPARE(panel->plot()->graph(0)->data()->at(120)->value, double(last.bodies[1].contacts));
        panel->setView(FrogPlotPanel::View::Energy);

        // The CSV of body 2 is simulate --series-body 2's, byte for byte.
        QTemporaryDir dir;
        const QString mine = dir.filePath("gui.csv"), theirs = dir.filePath("cli.csv");
        QVERIFY2(panel->exportCsv(mine, &error), qPrintable(error));
        const CliRun run = runCli({"simulate", "--scene", "many-bodies", "--solver", "stable", "--set", "bodies=3", "--steps",
                                   "120", "--series", theirs, "--series-body", "2"});
        QCOMPARE(run.exitCode, 0);
        QFile a(mine), b(theirs);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray gui = a.readAll();
        QCOMPARE(gui.count('\n'), 122);
        QVERIFY(gui == b.readAll());

        // A reset keeps the choice; plots hidden, nothing is marked; shown again, it is.
        tab().reset();
        steps(tab(), 2);
        panel->refresh(true);
        QCOMPARE(panel->body(), 1);
        tab().setPlotsShown(false);
        QCOMPARE(canvas->markedBody(), -1);
        tab().setPlotsShown(true);
        QCOMPARE(canvas->markedBody(), 1);
        // Many bodies: their values are kept once one is chosen, and the note says from when.
        list->setCurrentIndex(0);
        emit list->activated(0); // all bodies: a new run of many keeps none
        QVERIFY(!canvas->frogRun()->series().bodiesAsked());
        QVERIFY2(tab().editParameter("bodies", SeriesRecorder::kBodiesKeptUnasked + 6, &error), qPrintable(error));
        steps(tab(), 3);
        panel->refresh(true);
        QVERIFY(!canvas->frogRun()->series().keepsBodies());
        list->setCurrentIndex(5);
        emit list->activated(5);
        QCOMPARE(canvas->markedBody(), 4);
        QVERIFY(canvas->frogRun()->series().bodiesAsked());
        auto* note = panel->findChild<QLabel*>();
        steps(tab(), 3);
        panel->refresh(true);
        QVERIFY(canvas->frogRun()->series().keepsBodies());
        QCOMPARE(canvas->frogRun()->series().bodiesKeptFrom(), 4L);
        QCOMPARE(panel->plot()->graph(3)->dataCount(), 3); // steps 4, 5, 6
        QVERIFY2(note && note->text().startsWith(QStringLiteral("Body 5 alone: its values are kept from 0.1 s on.")),
                 qPrintable(note ? note->text() : QString()));
        // One body: no list, the scene's values, nothing marked.
        QVERIFY(tab().setScene("frog", nullptr));
        steps(tab(), 2);
        panel->refresh(true);
        QVERIFY(!list->isVisible());
        QCOMPARE(panel->body(), -1);
        QCOMPARE(canvas->markedBody(), -1);
        tab().setPlotsShown(false);
    }

    // A heavy step at 4×: only the steps a frame holds run in it.
    void fastRunsOnlyWhatAFrameHolds()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        QString error;
        QVERIFY2(tab().editParameter("sides", 1000, &error), qPrintable(error)); // 8000 work: 3 steps a frame
        tab().setSpeed(4);
        FrogCanvas* canvas = tab().canvas();
        const long work = canvas->frogRun()->simulation()->workPerStep();
        QCOMPARE(canvas->frogRun()->stepsPerFrame(), int(FrogRun::kFrameWork / work));
        QVERIFY(canvas->frogRun()->stepsPerFrame() < 4);
        QVERIFY(canvas->frogRun()->effectiveSpeed() < 4);
    }

    void hiddenTabStopsTheTimer()
    {
        QVERIFY(tab().frogRun()->animating());
        tab().hide();
        QVERIFY(!tab().frogRun()->animating());
        tab().show();
        QVERIFY(tab().frogRun()->animating());
    }

    // Issue 16, both solvers at once: the ghost is the other solver's run of the same scene,
    // fed the same mouse — its states are exactly a replay of the run's recording on that
    // solver — and it follows the timeline back and forth. The overlay is one undo step.
    void ghostFollowsTheSameMouse()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        QCOMPARE(canvas->frogRun()->ghost(), nullptr);
        steps(tab(), 30);
        auto* ghostBox = tab().findChild<QCheckBox*>("frogOverlay6");
        QVERIFY(ghostBox);
        const int undoSteps = tab().undoStack()->count();
        ghostBox->click(); // on late: the ghost catches up with the run
        QCOMPARE(tab().undoStack()->count(), undoSteps + 1);
        QVERIFY(canvas->frogRun()->ghost());
        QCOMPARE(canvas->frogRun()->ghost()->solver(), SolverKind::Seed);
        QCOMPARE(canvas->frogRun()->ghost()->stepCount(), 30L);
        const QPoint at = canvas->toWidget(centroid(*canvas->frogRun()->simulation())).toPoint();
        QTest::mouseMove(canvas, at);
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, at);
        for (int i = 1; i <= 15; ++i) {
            QTest::mouseMove(canvas, at + QPoint(10 * i, -6 * i));
            steps(tab(), 2);
        }
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, at + QPoint(150, -90));
        steps(tab(), 90);
        QCOMPARE(canvas->frogRun()->ghost()->stepCount(), 150L);
        // The seed's replay of the run's recording goes through the ghost's states.
        Recording asSeed = canvas->frogRun()->recorded()->recording();
        asSeed.solver = SolverKind::Seed;
        auto replay = RecordedRun::load(asSeed);
        QVERIFY(replay.ok());
        std::vector<std::string> rows{simulationTraceRow(replay->simulation())};
        while (replay->stepCount() < 150) {
            replay->step();
            rows.push_back(simulationTraceRow(replay->simulation()));
        }
        QCOMPARE(simulationTraceRow(*canvas->frogRun()->ghost()), rows[150]);
        QVERIFY(simulationTraceRow(*canvas->frogRun()->ghost()) != simulationTraceRow(*canvas->frogRun()->simulation()));
        QVERIFY(canvas->textLines().join('\n').contains("Dashed ghost: the seed solver fed the same mouse"));
        // The timeline takes it along.
        for (int t : {70, 0, 149, 31}) {
            tab().timeline()->setValue(t);
            QCOMPARE(canvas->frogRun()->ghost()->stepCount(), long(t));
            QCOMPARE(simulationTraceRow(*canvas->frogRun()->ghost()), rows[std::size_t(t)]);
        }
        // Kept in the document; off again with Ctrl+Z.
        QVERIFY(tab().saveState()["overlays"].toObject()["ghost"].toBool());
        tab().undoStack()->undo();
        QVERIFY(!ghostBox->isChecked());
        QCOMPARE(canvas->frogRun()->ghost(), nullptr);
        // Pendulums too: the ghost of the stable solver over the seed's.
        QVERIFY(tab().setScene("pendulum-limits", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        ghostBox->click();
        QCOMPARE(canvas->frogRun()->ghost()->solver(), SolverKind::Stable);
        QCOMPARE(canvas->frogRun()->ghost()->chainCount(), canvas->frogRun()->simulation()->chainCount());
    }

    // Issue 16: the trail of a chosen point. By default the pendulum's tip; Shift+click picks
    // another without grabbing; it keeps the last 10 s, and a seek starts it again.
    void trailFollowsTheChosenPoint()
    {
        QVERIFY(tab().setScene("pendulum-limits", nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        auto* trailBox = tab().findChild<QCheckBox*>("frogOverlay7");
        QVERIFY(trailBox);
        trailBox->click();
        QVERIFY(canvas->overlays().trail);
        std::vector<Point> joints;
        canvas->frogRun()->simulation()->chainJoints(0, joints);
        QVERIFY(canvas->frogRun()->trailPoint().joint);
        QCOMPARE(canvas->frogRun()->trailPoint().index, int(joints.size()) - 1);
        steps(tab(), 100);
        QCOMPARE(canvas->frogRun()->trail().size(), std::size_t(101));
        canvas->frogRun()->simulation()->chainJoints(0, joints);
        QCOMPARE(canvas->frogRun()->trail().back(), joints.back());
        // Shift+click on the frog's body picks its vertex and grabs nothing.
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(!canvas->frogRun()->trailPoint().joint); // the frog's default: vertex 0 of body 0
        steps(tab(), 40);
        std::vector<Point> body;
        canvas->frogRun()->simulation()->bodyVertices(0, body);
        QTest::mouseClick(canvas, Qt::LeftButton, Qt::ShiftModifier, canvas->toWidget(body[3]).toPoint());
        QVERIFY(!canvas->frogRun()->simulation()->grabbing());
        QCOMPARE(canvas->frogRun()->trailPoint().index, 3);
        QCOMPARE(canvas->frogRun()->trail().size(), std::size_t(1));
        QVERIFY(canvas->frogRun()->recorded()->recording().events.empty()); // nothing recorded
        steps(tab(), 700);
        QCOMPARE(canvas->frogRun()->trail().size(), std::size_t(FrogRun::kTrailSteps));
        canvas->frogRun()->simulation()->bodyVertices(0, body);
        QCOMPARE(canvas->frogRun()->trail().back(), body[3]);
        QVERIFY(canvas->textLines().join('\n').contains("Trail of vertex 3 of body 1"));
        tab().timeline()->setValue(300);
        QCOMPARE(canvas->frogRun()->trail().size(), std::size_t(1));
        trailBox->click();
        QVERIFY(!canvas->overlays().trail);
    }

    // Issue 16: the broad phase's pairs and the contacts, on the stable solver; the seed has
    // none to show and says why.
    void broadPhaseOverlay()
    {
        QVERIFY(tab().setScene("many-bodies", nullptr));
        QCOMPARE(tab().solver(), SolverKind::Stable); // collisions start on the stable solver
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        auto* box = tab().findChild<QCheckBox*>("frogOverlay8");
        QVERIFY(box);
        box->click();
        std::vector<std::pair<int, int>> pairs;
        int most = 0;
        for (int i = 0; i < 300; ++i) {
            canvas->frogRun()->step();
            canvas->frogRun()->simulation()->broadPhasePairs(pairs);
            most = std::max(most, int(pairs.size()));
            for (const auto& [a, b] : pairs)
                QVERIFY(a < b && a >= 0 && b < canvas->frogRun()->simulation()->bodyCount());
        }
        QVERIFY2(most > 0, "the bodies never came near each other");
        const QString lines = canvas->textLines().join('\n');
        QVERIFY2(lines.contains(QStringLiteral("Broad phase: %1 candidate pairs, %2 contacts")
                                    .arg(pairs.size())
                                    .arg(canvas->frogRun()->simulation()->readouts().contacts)),
                 qPrintable(lines));
        QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
        QPainter painter(&image);
        canvas->render(painter, QRectF(image.rect())); // draws the boxes and links without fault
        painter.end();
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        canvas->frogRun()->step();
        canvas->frogRun()->simulation()->broadPhasePairs(pairs);
        QVERIFY(pairs.empty());
        QVERIFY(canvas->textLines().join('\n').contains("the seed has no collisions"));
    }

    // Issue 16, measuring: the protractor draws each limited joint's angle over its range
    // and counts the joints held at a limit; the ruler, dragged with the right button or
    // Ctrl and the left, or placed with L and the arrows, measures in scene px, grabs
    // nothing and records no press; a click or Esc clears it.
    void protractorAndRuler()
    {
        QVERIFY(tab().setScene("pendulum-limits", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        QCoreApplication::processEvents();
        FrogCanvas* canvas = tab().canvas();
        auto* box = tab().findChild<QCheckBox*>("frogOverlay9");
        QVERIFY(box);
        QCOMPARE(box->text(), QStringLiteral("Protractor"));
        const auto redPixels = [canvas] {
            QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
            QPainter painter(&image);
            canvas->render(painter, QRectF(image.rect()));
            painter.end();
            int n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    n += std::abs(c.red() - 0xc6) + std::abs(c.green() - 0x28) + std::abs(c.blue() - 0x28) < 40;
                }
            return n;
        };
        const int redBefore = redPixels();
        box->click();
        QVERIFY(canvas->overlays().protractor);
        const auto held = [canvas] {
            int n = 0;
            for (const LinkAngleReading& a : canvas->linkAngles(0))
                n += a.atLimit;
            return n;
        };
        // Hanging straight down, the shoulder sits on its limit of 0 (§4.15: [0, π]).
        QCOMPARE(canvas->linkAngles(0).size(), std::size_t(2));
        QVERIFY(canvas->linkAngles(0)[0].atLimit);
        QVERIFY(
            canvas->textLines().join('\n').contains(QStringLiteral("Protractor: %1 of 2 joints held at a limit").arg(held())));
        QVERIFY2(redPixels() > redBefore + 10, "the joint held at its limit is not drawn red");
        // Swung off the limit, the count follows.
        for (int i = 0; i < 40; ++i) {
            QTest::mouseMove(canvas, canvas->toWidget(Point(640 - 8 * i, 200)).toPoint());
            canvas->frogRun()->step();
        }
        QVERIFY(
            canvas->textLines().join('\n').contains(QStringLiteral("Protractor: %1 of 2 joints held at a limit").arg(held())));
        QVERIFY(tab().setScene("pendulum-chain", nullptr));
        QVERIFY(canvas->textLines().join('\n').contains("Protractor: no joint of this scene has angle limits"));

        // The ruler, with the right button, on the frog.
        QVERIFY(tab().setScene("frog", nullptr));
        QCoreApplication::processEvents();
        const auto presses = [canvas] {
            const auto& events = canvas->frogRun()->recorded()->recording().events;
            return std::count_if(events.begin(), events.end(), [](const InputEvent& e) { return e.kind == InputKind::Press; });
        };
        const QPoint a = canvas->toWidget(centroid(*canvas->frogRun()->simulation())).toPoint(), b = a + QPoint(60, -80);
        QTest::mousePress(canvas, Qt::RightButton, Qt::NoModifier, a);
        QTest::mouseMove(canvas, b);
        QTest::mouseRelease(canvas, Qt::RightButton, Qt::NoModifier, b);
        QVERIFY(canvas->ruler());
        const Point from = canvas->toScene(a), to = canvas->toScene(b);
        QCOMPARE(canvas->ruler()->first, from);
        QCOMPARE(canvas->ruler()->second, to);
        QVERIFY2(canvas->rulerText().startsWith(displayFixed(std::hypot(to.x - from.x, to.y - from.y), 1) + " px"),
                 qPrintable(canvas->rulerText()));
        QVERIFY(!canvas->frogRun()->simulation()->grabbing()); // inside the body, and nothing grabbed
        QCOMPARE(presses(), 0);
        QTest::mouseClick(canvas, Qt::RightButton, Qt::NoModifier, b); // a click clears it
        QVERIFY(!canvas->ruler());
        QTest::mousePress(canvas, Qt::LeftButton, Qt::ControlModifier, a);
        QTest::mouseMove(canvas, b);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::ControlModifier, b);
        QVERIFY(canvas->ruler());
        QVERIFY(!canvas->frogRun()->simulation()->grabbing());
        QCOMPARE(presses(), 0);
        // From the keyboard: L at the cursor, three steps right, L; Esc clears it.
        canvas->setFocus();
        QTest::keyClick(canvas, Qt::Key_Escape);
        QVERIFY(!canvas->ruler());
        QTest::keyClick(canvas, Qt::Key_L);
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(canvas, Qt::Key_Right);
        QTest::keyClick(canvas, Qt::Key_L);
        QVERIFY(canvas->ruler());
        QCOMPARE(canvas->ruler()->second.x - canvas->ruler()->first.x, 3 * FrogCanvas::kKeyboardStep);
        QCOMPARE(canvas->rulerText(), QStringLiteral("%1 px (Δx %1, Δy %2)").arg(displayFixed(30, 1), displayFixed(0, 1)));
        QTest::keyClick(canvas, Qt::Key_Right); // fixed: the cursor moves alone
        QCOMPARE(canvas->ruler()->second.x - canvas->ruler()->first.x, 3 * FrogCanvas::kKeyboardStep);
        // A document keeps the measure shown; a bad one is refused and changes nothing.
        const auto kept = *canvas->ruler();
        const QJsonObject saved = tab().saveState();
        QCOMPARE(saved["ruler"].toArray().size(), 4);
        QTest::keyClick(canvas, Qt::Key_Escape);
        QVERIFY(!canvas->ruler());
        QVERIFY(tab().loadState(saved, nullptr));
        QVERIFY(canvas->ruler() && *canvas->ruler() == kept);
        QJsonObject bad = saved;
        bad["ruler"] = QJsonArray{1, 2, 3};
        QString error;
        QVERIFY(!tab().loadState(bad, &error));
        QVERIFY2(error.contains("ruler"), qPrintable(error));
        QVERIFY(canvas->ruler() && *canvas->ruler() == kept);
        canvas->setFocus();
        QTest::keyClick(canvas, Qt::Key_Escape);
        QVERIFY(!canvas->ruler());
    }

    // Issue 16: the stable solver's knobs, shown while it runs, turn live: the run goes on
    // from its step with them, one undo step a knob, and the recording keeps each turn, so
    // the document gives it back and the timeline shows the knobs in force at each step;
    // the seed's box is hidden, and the knobs stay when the stage changes.
    void stableKnobs()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        auto* box = tab().findChild<QGroupBox*>("frogStableBox");
        auto* substeps = tab().findChild<QSpinBox*>("frogSubsteps");
        auto* compliance = tab().findChild<QDoubleSpinBox*>("frogEdgeCompliance");
        QVERIFY(box && substeps && compliance);
        QVERIFY(!box->isVisibleTo(&tab()));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        QVERIFY(box->isVisibleTo(&tab()));
        QCOMPARE(substeps->value(), 8);
        FrogCanvas* canvas = tab().canvas();
        QCOMPARE(canvas->frogRun()->simulation()->substeps(), 8);
        for (int i = 0; i < 5; ++i)
            canvas->frogRun()->step();
        QUndoStack* undo = tab().undoStack();
        const int before = undo->count();
        substeps->setValue(16);
        substeps->setValue(24); // a run of edits of one knob: one step
        QCOMPARE(canvas->frogRun()->simulation()->substeps(), 24);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 5L); // live: the run goes on
        QCOMPARE(undo->count(), before + 1);
        for (int i = 0; i < 3; ++i)
            canvas->frogRun()->step();
        compliance->setValue(0.01);
        QCOMPARE(canvas->frogRun()->simulation()->stableSettings().edgeCompliance, 0.01);
        QCOMPARE(tab().scene().stable.edgeCompliance, 2e-3); // the run started with it
        QCOMPARE(undo->count(), before + 2);
        const auto* note = tab().findChild<QLabel*>("frogStableNote");
        QVERIFY2(note->text().contains("rings with a period of"), qPrintable(note->text()));
        const QJsonObject saved = tab().saveState();
        QCOMPARE(saved["stable"].toObject()["substeps"].toInt(), 8); // the start; the turns are events
        const QJsonArray events = saved["recording"].toObject()["events"].toArray();
        QCOMPARE(events.size(), 2);
        QCOMPARE(events[0].toArray(), (QJsonArray{5, "substeps", 24}));
        QCOMPARE(events[1].toArray(), (QJsonArray{8, "edge_compliance", 0.01}));
        undo->undo();
        QCOMPARE(canvas->frogRun()->simulation()->stableSettings().edgeCompliance, 2e-3);
        QCOMPARE(compliance->value(), 0.002);
        undo->undo();
        QCOMPARE(canvas->frogRun()->simulation()->substeps(), 8);
        QCOMPARE(substeps->value(), 8);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 8L);
        QVERIFY(tab().loadState(saved, nullptr));
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 8L);
        QCOMPARE(canvas->frogRun()->simulation()->substeps(), 24);
        QCOMPARE(substeps->value(), 24);
        QCOMPARE(compliance->value(), 0.01);
        // The timeline shows the knobs each step had.
        tab().timeline()->setValue(3);
        QCOMPARE(substeps->value(), 8);
        QCOMPARE(compliance->value(), 0.002);
        tab().timeline()->setValue(6);
        QCOMPARE(substeps->value(), 24);
        QCOMPARE(compliance->value(), 0.002);
        // A stage of its own keeps the knobs in force; a bad document value is refused.
        QVERIFY(tab().setScene("many-bodies", nullptr));
        QCOMPARE(canvas->frogRun()->simulation()->substeps(), 24);
        QCOMPARE(tab().scene().stable.substeps, 24);
        QJsonObject bad = saved;
        bad["stable"] = QJsonObject{{"substeps", 40}};
        QString error;
        QVERIFY(!tab().loadState(bad, &error));
        QVERIFY2(error.contains("substeps"), qPrintable(error));
        QCOMPARE(tab().sceneName(), QStringLiteral("many-bodies"));
    }

    // Stiffness as Box2D states it: the edge frequency box is the compliance for the scene's
    // edge (either sets the other), and the damping ratio is a live knob recorded as the
    // others are; the document keeps it and gives it back.
    void edgeFrequencyAndDampingRatio()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        auto* compliance = tab().findChild<QDoubleSpinBox*>("frogEdgeCompliance");
        auto* hertz = tab().findChild<QDoubleSpinBox*>("frogEdgeHertz");
        auto* damping = tab().findChild<QDoubleSpinBox*>("frogEdgeDamping");
        QVERIFY(compliance && hertz && damping);
        FrogCanvas* canvas = tab().canvas();
        const auto spring = canvas->frogRun()->simulation()->edgeSpring(0);
        QVERIFY(spring && spring->restLength > 1 && spring->vertexMass > 0);
        // α = 0.002 on the frog's edge: T = 2π √(α L m) steps, f = 60 / T.
        const double period = 2 * kPi * std::sqrt(0.002 * spring->restLength * spring->vertexMass);
        QCOMPARE(hertz->value(), std::round(6000 / period) / 100);
        QVERIFY(hertz->isEnabled());
        hertz->setValue(10);
        const double alpha = canvas->frogRun()->simulation()->stableSettings().edgeCompliance;
        QVERIFY(std::abs(alpha - std::pow(3 / kPi, 2) / (spring->restLength * spring->vertexMass)) <= 1e-12);
        QCOMPARE(compliance->value(), std::round(alpha * 1e4) / 1e4);
        QCOMPARE(hertz->value(), 10.0);
        compliance->setValue(0); // rigid: no frequency to state
        QVERIFY(!hertz->isEnabled());
        compliance->setValue(0.002);
        QVERIFY(hertz->isEnabled());

        for (int i = 0; i < 4; ++i)
            canvas->frogRun()->step();
        QCOMPARE(damping->value(), 0.0);
        damping->setValue(0.3);
        QCOMPARE(canvas->frogRun()->simulation()->stableSettings().edgeDampingRatio, 0.3);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 4L); // live
        QCOMPARE(tab().scene().stable.edgeDampingRatio, 0.0);
        const QJsonObject saved = tab().saveState();
        const QJsonArray events = saved["recording"].toObject()["events"].toArray();
        QCOMPARE(events.last().toArray(), (QJsonArray{4, "edge_damping_ratio", 0.3}));
        QVERIFY(!saved["stable"].toObject().contains("edge_damping_ratio")); // the run started without
        tab().undoStack()->undo();
        QCOMPARE(canvas->frogRun()->simulation()->stableSettings().edgeDampingRatio, 0.0);
        QCOMPARE(damping->value(), 0.0);
        QVERIFY(tab().loadState(saved, nullptr));
        QCOMPARE(damping->value(), 0.3);
        QCOMPARE(canvas->frogRun()->simulation()->stableSettings().edgeDampingRatio, 0.3);
        tab().reset(); // a new run starts with the knobs in force, kept in the document's "stable"
        QCOMPARE(tab().scene().stable.edgeDampingRatio, 0.3);
        QCOMPARE(tab().saveState()["stable"].toObject()["edge_damping_ratio"].toDouble(), 0.3);
        QJsonObject bad = saved;
        bad["stable"] = QJsonObject{{"substeps", 8}, {"edge_compliance", 0.002}, {"edge_damping_ratio", 2.5}};
        QString error;
        QVERIFY(!tab().loadState(bad, &error));
        QVERIFY2(error.contains("a damping ratio from 0 to 2"), qPrintable(error));
        damping->setValue(0);
        tab().reset();
        QVERIFY(tab().setScene("pendulum-limits", nullptr)); // no springs: nothing to set
        QVERIFY(!damping->isEnabled() && !hertz->isEnabled());
        QCOMPARE(hertz->text(), QStringLiteral("—"));
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(damping->isEnabled() && hertz->isEnabled());
        QVERIFY(hertz->text() != QStringLiteral("—"));
    }

    // Issue 16, rewind: the canvas records the mouse's grab and throw; the timeline goes
    // back to any step and gives the state the run went through there, "," and "." step
    // back and on, running on replays the recorded rows, hovering and clicks that grab
    // nothing leave the recording whole, a press on the body branches, and the document
    // keeps the run and gives it back at the step it was saved.
    void timelineScrubsTheRun_data()
    {
        QTest::addColumn<SolverKind>("solver");
        QTest::newRow("seed") << SolverKind::Seed;
        QTest::newRow("stable") << SolverKind::Stable;
    }
    void timelineScrubsTheRun()
    {
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        tab().findChild<QPushButton*>("frogPause")->setChecked(true);
        tab().setPlotsShown(true);
        QCoreApplication::processEvents(); // the canvas takes its new, smaller size before the mouse aims at it
        FrogCanvas* canvas = tab().canvas();
        QSlider* timeline = tab().timeline();
        QVERIFY(timeline);
        const auto row = [canvas] { return simulationTraceRow(*canvas->frogRun()->simulation()); };
        std::vector<std::string> rows{row()};
        const auto stepAndKeep = [&](int n) {
            for (int i = 0; i < n; ++i) {
                canvas->frogRun()->step();
                rows.push_back(row());
            }
        };
        stepAndKeep(60);
        const QPoint at = canvas->toWidget(centroid(*canvas->frogRun()->simulation())).toPoint();
        QTest::mouseMove(canvas, at);
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, at);
        QVERIFY(canvas->frogRun()->simulation()->grabbing());
        for (int i = 1; i <= 20; ++i) {
            QTest::mouseMove(canvas, at + QPoint(8 * i, -9 * i));
            stepAndKeep(2);
        }
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, at + QPoint(160, -180));
        stepAndKeep(100);
        QCOMPARE(canvas->frogRun()->recordedSteps(), 200L);
        QCOMPARE(timeline->maximum(), 200);
        QCOMPARE(timeline->value(), 200);
        const auto* label = tab().findChild<QLabel*>("frogTimelineLabel");
        QCOMPARE(label->text(), QStringLiteral("Step 200 of 200 · 3.33 s"));
        QVERIFY(canvas->frogRun()->recorded()->recording().events.size() >= 22);

        // The slider goes back; the plots keep their samples up to the step.
        tab().findChild<QPushButton*>("frogPause")->setChecked(false);
        timeline->setValue(75);
        QVERIFY(tab().findChild<QPushButton*>("frogPause")->isChecked()); // scrubbing pauses
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 75L);
        QCOMPARE(row(), rows[75]);
        QCOMPARE(canvas->frogRun()->series().samples().back().step, 75L);
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(76));
        for (int t : {0, 199, 61, 62, 100, 1, 140}) {
            timeline->setValue(t);
            QCOMPARE(row(), rows[std::size_t(t)]);
        }
        // , and . (shortcuts of the tab's window: they answer once it is active).
        QVERIFY(waitActive(&tab()));
        QTest::keyClick(canvas, Qt::Key_Comma);
        QCOMPARE(row(), rows[139]);
        QCOMPARE(timeline->value(), 139);
        QTest::keyClick(canvas, Qt::Key_Period);
        QCOMPARE(row(), rows[140]);
        QVERIFY(canvas->frogRun()->playingBack());
        QVERIFY(canvas->textLines().join('\n').contains("Replaying the recorded run, step 140 of 200"));

        // Hovering, and a click on empty ground, change nothing recorded.
        QTest::mouseMove(canvas, canvas->toWidget(Point(100, 100)).toPoint());
        QTest::mouseClick(canvas, Qt::LeftButton, Qt::NoModifier, canvas->toWidget(Point(100, 100)).toPoint());
        QCOMPARE(canvas->frogRun()->recordedSteps(), 200L);
        // Running on replays the recorded rows, and the plots follow.
        while (canvas->frogRun()->simulation()->stepCount() < 200) {
            canvas->frogRun()->runFrame();
            QCOMPARE(row(), rows[std::size_t(canvas->frogRun()->simulation()->stepCount())]);
        }
        QVERIFY(!canvas->frogRun()->playingBack());
        QCOMPARE(canvas->frogRun()->series().samples().size(), std::size_t(201));

        // The document keeps the run, and gives it back at the step it was saved.
        timeline->setValue(120);
        const QJsonObject saved = tab().saveState();
        const QJsonObject recording = saved["recording"].toObject();
        QCOMPARE(recording["steps"].toInt(), 200);
        QCOMPARE(recording["step"].toInt(), 120);
        QCOMPARE(recording["events"].toArray().size(), int(canvas->frogRun()->recorded()->recording().events.size()));
        tab().reset();
        QCOMPARE(canvas->frogRun()->recordedSteps(), 0L);
        QString error;
        QVERIFY2(tab().loadState(saved, &error), qPrintable(error));
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 120L);
        QCOMPARE(row(), rows[120]);
        QCOMPARE(timeline->maximum(), 200);
        QCOMPARE(tab().saveState(), saved);
        timeline->setValue(200);
        QCOMPARE(row(), rows[200]);

        // The stopwatch: M marks the step shown, and the label counts from it both ways.
        timeline->setValue(60);
        QTest::keyClick(canvas, Qt::Key_M);
        QCOMPARE(tab().markedStep(), 60L);
        QVERIFY(tab().findChild<QPushButton*>("frogStopwatch")->isChecked());
        timeline->setValue(150);
        QVERIFY2(label->text().contains("1.50 s (90 steps) since step 60"), qPrintable(label->text()));
        timeline->setValue(30);
        QVERIFY2(label->text().contains("0.50 s (30 steps) before step 60"), qPrintable(label->text()));
        QTest::keyClick(canvas, Qt::Key_M);
        QCOMPARE(tab().markedStep(), -1L);
        QVERIFY(!label->text().contains("since"));
        QTest::keyClick(canvas, Qt::Key_M); // marked at 30, then a Reset clears it
        QCOMPARE(tab().markedStep(), 30L);
        const QJsonObject marked = tab().saveState();
        QVERIFY(!marked.contains("mark")); // a measuring tool, not part of the document
        tab().reset();
        QCOMPARE(tab().markedStep(), -1L);
        QVERIFY(tab().loadState(saved, nullptr));

        // A press on the body branches: the future after it is gone.
        timeline->setValue(150);
        const QPoint body = canvas->toWidget(centroid(*canvas->frogRun()->simulation())).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, body);
        QVERIFY(canvas->frogRun()->simulation()->grabbing());
        QCOMPARE(canvas->frogRun()->recordedSteps(), 150L);
        QCOMPARE(timeline->maximum(), 150);
        QVERIFY(!canvas->frogRun()->playingBack());
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, body);

        // Bad recordings are refused with a message, the tab unchanged.
        const QJsonObject before = tab().saveState();
        const auto refused = [&](const QJsonObject& r, const char* words) {
            QJsonObject bad = saved;
            bad["recording"] = r;
            QString message;
            QVERIFY(!tab().loadState(bad, &message));
            QVERIFY2(message.contains(QLatin1String(words)), qPrintable(message));
            QCOMPARE(tab().saveState(), before);
        };
        QJsonObject r = recording;
        r["step"] = 201;
        refused(r, "step");
        r = recording;
        r["steps"] = -4;
        refused(r, "steps");
        r = recording;
        r["events"] = QJsonArray{QJsonArray{5, "release"}, QJsonArray{4, "release"}};
        refused(r, "event 2");
        r = recording;
        // One event, appended: QJsonArray{QJsonArray{…}} is a copy of the inner array for
        // clang (a list of one element of the same type) and a list of one array for GCC.
        QJsonArray pressWithoutPlace;
        pressWithoutPlace.append(QJsonArray{5, "press"});
        r["events"] = pressWithoutPlace;
        refused(r, "x and y");
        refused(QJsonObject{{"steps", 10}}, "events");
    }

    void mouseGrabMovesTheBody_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<SolverKind>("solver");
        QTest::newRow("frog seed") << "frog" << SolverKind::Seed;
        QTest::newRow("frog stable") << "frog" << SolverKind::Stable;
        QTest::newRow("verlet seed") << "verlet" << SolverKind::Seed;
    }
    void mouseGrabMovesTheBody()
    {
        QFETCH(QString, scene);
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene(scene, nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        tab().findChild<QPushButton*>("frogPause")->click();
        steps(tab(), 200); // on the floor
        FrogCanvas* canvas = tab().canvas();
        const Simulation* sim = canvas->frogRun()->simulation();
        const Point start = centroid(*sim);
        const QPoint at = canvas->toWidget(start).toPoint();
        QTest::mouseMove(canvas, at);
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, at);
        QVERIFY(sim->grabbing());
        for (int i = 1; i <= 30; ++i) {
            const Point mouse(start.x + 150.0 * i / 30, start.y - 250.0 * i / 30);
            QTest::mouseMove(canvas, canvas->toWidget(mouse).toPoint());
            steps(tab(), 3);
        }
        steps(tab(), 60);
        const Point held = centroid(*sim);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier,
                            canvas->toWidget(Point(start.x + 150, start.y - 250)).toPoint());
        QVERIFY(!sim->grabbing());
        QVERIFY2(held.x > start.x + 100, qPrintable(QString("centroid x %1 → %2").arg(start.x).arg(held.x)));
        QVERIFY2(held.y < start.y - 80, qPrintable(QString("centroid y %1 → %2").arg(start.y).arg(held.y)));
        QVERIFY(sim->finite());
    }

    void grabbingOutsideTheWindowIsSafe()
    {
        tab().findChild<QPushButton*>("frogPause")->click();
        steps(tab(), 150);
        FrogCanvas* canvas = tab().canvas();
        const Simulation* sim = canvas->frogRun()->simulation();
        const QPoint at = canvas->toWidget(centroid(*sim)).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, at);
        QVERIFY(sim->grabbing());
        for (const QPoint p : {QPoint(-3000, -2000), QPoint(50000, 40), QPoint(10, 90000)}) {
            QTest::mouseMove(canvas, p);
            steps(tab(), 20);
        }
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, QPoint(10, 90000));
        steps(tab(), 100);
        QVERIFY(sim->finite());
        QVERIFY(sim->inBounds(1.0));
    }

    void spaceSpawnsAFrogHeldAtTheMouse()
    {
        tab().findChild<QPushButton*>("frogPause")->click();
        steps(tab(), 100);
        FrogCanvas* canvas = tab().canvas();
        const Simulation* sim = canvas->frogRun()->simulation();
        QVERIFY(centroid(*sim).y > 450); // fallen
        QTest::mouseMove(canvas, canvas->toWidget(Point(300, 200)).toPoint());
        QTest::keyPress(canvas, Qt::Key_Space);
        QVERIFY(sim->grabbing());
        steps(tab(), 60);
        const Point held = centroid(*sim);
        QVERIFY2(std::abs(held.x - 300) < 80 && held.y < 330, qPrintable(QString("%1, %2").arg(held.x).arg(held.y)));
        QTest::keyRelease(canvas, Qt::Key_Space);
        QVERIFY(!sim->grabbing());
        steps(tab(), 300);
        QVERIFY(centroid(*sim).y > 450); // let go, it falls again
    }

    void panelShowsOnlyTheScenesParameters()
    {
        QVERIFY(tab().setScene("gravity", nullptr));
        QStringList keys = tab().parametersPanel()->keys();
        QVERIFY(keys.contains("gravity"));
        QVERIFY(!keys.contains("spring_length"));
        QVERIFY(!keys.contains("legs"));
        QVERIFY(tab().parametersPanel()->spinBox("gravity", 1));
        QVERIFY(!tab().parametersPanel()->spinBox("spring_length"));
        QCOMPARE(tab().findChild<QComboBox*>("frogScene")->currentData().toString(), QStringLiteral("gravity"));

        QVERIFY(tab().setScene("frog", nullptr));
        keys = tab().parametersPanel()->keys();
        QVERIFY(keys.contains("legs"));
        QVERIFY(keys.contains("angle_limits"));
        QVERIFY(tab().parametersPanel()->spinBox("legs", 3)); // front upper, lower, back upper, lower
        QVERIFY(!keys.contains("bodies"));
        // Angle limits are shown in degrees: Annex II's π/12 at the front elbows is 15°.
        QDoubleSpinBox* elbowFront = tab().parametersPanel()->spinBox("angle_limits", 9);
        QVERIFY(elbowFront);
        QCOMPARE(elbowFront->value(), 15.0);

        QVERIFY(tab().setScene("pendulum-chain", nullptr));
        QCOMPARE(tab().parametersPanel()->keys(), (QStringList{"center", "width", "height", "chain"}));

        QString error;
        QVERIFY(!tab().setScene("dragon", &error));
        QVERIFY(error.contains("dragon"));
        QCOMPARE(tab().sceneName(), QStringLiteral("pendulum-chain"));
    }

    void parameterAppliesLiveAndUndoes()
    {
        QVERIFY(tab().setScene("verlet", nullptr));
        tab().findChild<QPushButton*>("frogPause")->click();
        QDoubleSpinBox* gy = tab().parametersPanel()->spinBox("gravity", 1);
        QVERIFY(gy);
        gy->setValue(0); // as the user does: the panel applies it to the running scene
        QCOMPARE(tab().scene().params.gravity.y, 0.0);
        const Simulation* sim = tab().frogRun()->simulation();
        steps(tab(), 150);
        const double floating = centroid(*sim).y;
        QVERIFY2(floating < 370, qPrintable(QString::number(floating))); // no gravity: it does not fall

        QCOMPARE(tab().undoStack()->count(), 1);
        tab().undoStack()->undo();
        QCOMPARE(tab().scene().params.gravity.y, 0.75);
        QCOMPARE(tab().parametersPanel()->spinBox("gravity", 1)->value(), 0.75);
        sim = tab().frogRun()->simulation();
        steps(tab(), 150);
        QVERIFY(centroid(*sim).y > 500); // gravity again: on the floor

        // A refused value: a message, nothing changed, no undo step.
        QString error;
        QVERIFY(!tab().editParameter("sides", 2, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(tab().scene().params.sides, 10);
        QVERIFY(!tab().editParameter("legs", QJsonArray{1, 2}, &error)); // verlet has no legs
        QCOMPARE(tab().undoStack()->count(), 1);
    }

    // Issue 35: a tick of the panel is one call into the core (FrogTab::editParameterNumber →
    // withParameter(scene, key, part, index, value)); the scene is never written to JSON on the
    // way, which the scene writer's counter shows over many ticks of three kinds of field.
    void aParameterTickWritesNoScene()
    {
        QVERIFY(tab().setScene("frog", nullptr));
        tab().findChild<QPushButton*>("frogPause")->click();
        QDoubleSpinBox* gy = tab().parametersPanel()->spinBox("gravity", 1);
        QDoubleSpinBox* backLower = tab().parametersPanel()->spinBox("legs", 3);
        QDoubleSpinBox* sides = tab().parametersPanel()->spinBox("sides");
        QVERIFY(gy && backLower && sides);
        const double gravity = tab().scene().params.gravity.y, lower = tab().scene().params.legs[2].lower;
        const int sideCount = tab().scene().params.sides;
        const long writes = sceneWriteCount();
        const int ticks = 10;
        for (int i = 0; i < ticks; ++i) {
            gy->stepBy(1);
            backLower->stepBy(-1);
            sides->stepBy(1);
        }
        QCOMPARE(sceneWriteCount(), writes);
        // Each tick moved its number by the table's step (scene_parameters.cpp: 0.05, 5, 1).
        QCOMPARE(tab().scene().params.gravity.y, gravity + ticks * 0.05);
        QCOMPARE(tab().scene().params.legs[2].lower, lower - ticks * 5);
        QCOMPARE(tab().scene().params.sides, sideCount + ticks);
        // The ticks of one field merge into one step; undone, each number is as it was.
        QUndoStack* undo = tab().undoStack();
        while (undo->canUndo())
            undo->undo();
        QCOMPARE(tab().scene().params.gravity.y, gravity);
        QCOMPARE(tab().scene().params.legs[2].lower, lower);
        QCOMPARE(tab().scene().params.sides, sideCount);
    }

    void radiusFollowsTheFrameUntilSet()
    {
        // Annex II's r = |height/6|: the panel shows the derived value, a new height moves it,
        // a number typed in holds, and undo gives the rule back.
        QVERIFY(tab().setScene("frog", nullptr));
        tab().findChild<QPushButton*>("frogPause")->click();
        QDoubleSpinBox* radius = tab().parametersPanel()->spinBox("radius");
        QDoubleSpinBox* height = tab().parametersPanel()->spinBox("height");
        QDoubleSpinBox* cy = tab().parametersPanel()->spinBox("center", 1);
        QVERIFY(radius && height && cy);
        QCOMPARE(radius->value(), 120.0);
        const int before = tab().undoStack()->count();
        height->setValue(600);
        QCOMPARE(tab().scene().params.radius, 100.0);
        QCOMPARE(radius->value(), 100.0);
        QCOMPARE(cy->value(), 300.0);
        radius->setValue(90);
        QVERIFY(!tab().scene().radiusFromFrame);
        height->setValue(720);
        QCOMPARE(tab().scene().params.radius, 90.0);
        QCOMPARE(cy->value(), 360.0);
        while (tab().undoStack()->count() > before && tab().undoStack()->canUndo())
            tab().undoStack()->undo();
        QVERIFY(tab().scene().radiusFromFrame);
        QCOMPARE(tab().scene().params.radius, 120.0);
        QCOMPARE(radius->value(), 120.0);
    }

    void extremeValuesStayFinite_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<SolverKind>("solver");
        const std::pair<const char*, QJsonValue> cases[] = {
            {"sides", 3},         {"sides", 200},       {"target_area", 0},
            {"target_area", 1e9}, {"area_factor", 1e5}, {"gravity", QJsonArray{0, 1e5}},
            {"velmax", 1e9},      {"spring_length", 0},
        };
        for (SolverKind k : {SolverKind::Seed, SolverKind::Stable})
            for (const auto& [key, value] : cases)
                QTest::newRow(qPrintable(QString("%1=%2 %3")
                                             .arg(key, value.isArray() ? QString("0,1e5") : QString::number(value.toDouble()),
                                                  QString::fromStdString(solverName(k)))))
                    << QString(key) << value << k;
    }
    void extremeValuesStayFinite()
    {
        QFETCH(QString, key);
        QFETCH(QJsonValue, value);
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene("tuned", nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        tab().findChild<QPushButton*>("frogPause")->click();
        QString error;
        QVERIFY2(tab().editParameter(key, value, &error), qPrintable(error));
        steps(tab(), 200);
        QVERIFY(tab().frogRun()->simulation()->finite());
        QImage image(320, 180, QImage::Format_ARGB32_Premultiplied);
        QPainter p(&image);
        tab().canvas()->render(p, QRectF(0, 0, 320, 180));
    }

    void everySceneOnBothSolvers_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<SolverKind>("solver");
        for (const std::string& name : sceneNames())
            for (SolverKind k : {SolverKind::Seed, SolverKind::Stable})
                QTest::newRow(qPrintable(QString::fromStdString(name + " " + solverName(k))))
                    << QString::fromStdString(name) << k;
    }
    void everySceneOnBothSolvers()
    {
        QFETCH(QString, scene);
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene(scene, nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        QCOMPARE(tab().solver(), solver);
        tab().findChild<QPushButton*>("frogPause")->click();
        for (int i = 0; i < 6; ++i) // every overlay drawn too
            tab().findChild<QCheckBox*>(QString("frogOverlay%1").arg(i))->setChecked(true);
        FrogCanvas* canvas = tab().canvas();
        QTest::mouseMove(canvas, canvas->toWidget(Point(500, 300)).toPoint()); // the pendulums follow it
        steps(tab(), 300);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 300L);
        QVERIFY(canvas->frogRun()->simulation()->finite());
        QImage image(640, 360, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::black);
        {
            QPainter p(&image);
            canvas->render(p, QRectF(0, 0, 640, 360));
        }
        QVERIFY(colours(image) > 20);
        QVERIFY(!tab().csv().isEmpty());
        QVERIFY(tab().tikz().contains("tikzpicture"));
    }

    void bezierScenesSwitchToThePerFrameFit()
    {
        QVERIFY(tab().setScene("bezier", nullptr));
        FrogCanvas* canvas = tab().canvas();
        const std::size_t precomputed = canvas->bodyOutline(0).size();
        QCOMPARE(precomputed, std::size_t(tab().scene().bezierSamples)); // the body is the samples
        auto* fit = tab().findChild<QRadioButton*>("frogBezierFit");
        QVERIFY(fit && fit->isVisibleTo(&tab()));
        fit->setChecked(true);
        QCOMPARE(canvas->bezierOutline(), FrogCanvas::BezierOutline::Fit);
        const std::size_t fitted = canvas->bodyOutline(0).size();
        QVERIFY(fitted > precomputed); // the fitted curve, sampled finely
        QVERIFY(tab().saveState().value("bezier_outline").toString() == "fit");
        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(!tab().findChild<QRadioButton*>("frogBezierFit")->isVisibleTo(&tab()));
    }

    void exportFramesWritesPngs()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const long before = tab().frogRun()->simulation()->stepCount();
        tab().findChild<QPushButton*>("frogPause")->click();
        QCOMPARE(tab().exportFrames(dir.path() + "/frames", 4), QString());
        for (int i = 0; i < 4; ++i) {
            QImage image(dir.path() + QString("/frames/frame_%1.png").arg(i, 4, 10, QChar('0')));
            QVERIFY(!image.isNull());
            QCOMPARE(image.size(), FrogTab::kFrameSize); // a video size, not the canvas's
        }
        QVERIFY(!QFile::exists(dir.path() + "/frames/frame_0004.png"));
        QCOMPARE(tab().frogRun()->simulation()->stepCount(), before + 3); // exactly one step between frames
        QVERIFY(!tab().exportFrames(dir.path(), 0).isEmpty());
    }

    void saveLoadRoundTrip()
    {
        QVERIFY(tab().setScene("pendulum-limits", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr));
        QVERIFY(tab().editParameter("chain", QJsonArray{70, 95}, nullptr));
        tab().findChild<QCheckBox*>("frogOverlay2")->setChecked(true);
        const QJsonObject saved = tab().saveState();

        QVERIFY(tab().setScene("frog", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        tab().findChild<QCheckBox*>("frogOverlay2")->setChecked(false);
        QString error;
        QVERIFY2(tab().loadState(saved, &error), qPrintable(error));
        QCOMPARE(tab().sceneName(), QStringLiteral("pendulum-limits"));
        QCOMPARE(tab().solver(), SolverKind::Stable);
        QCOMPARE(tab().scene().chain, (std::vector<double>{70, 95}));
        QVERIFY(tab().canvas()->overlays().area);
        QVERIFY(tab().findChild<QCheckBox*>("frogOverlay2")->isChecked());
        QCOMPARE(tab().parametersPanel()->spinBox("chain", 1)->value(), 95.0);
        QCOMPARE(tab().saveState(), saved);

        // Bad states: refused with a message, the tab unchanged.
        QJsonObject bad = saved;
        bad["scene"] = "dragon";
        QVERIFY(!tab().loadState(bad, &error));
        QVERIFY(error.contains("dragon"));
        bad = saved;
        bad["solver"] = "magic";
        QVERIFY(!tab().loadState(bad, &error));
        bad = saved;
        bad["params"] = QJsonObject{{"sides", 10}}; // the pendulum has no sides
        QVERIFY(!tab().loadState(bad, &error));
        bad = saved;
        bad["params"] = QJsonObject{{"width", 0}};
        QVERIFY(!tab().loadState(bad, &error));
        bad = saved;
        bad["overlays"] = QJsonObject{{"area", "yes"}};
        QVERIFY(!tab().loadState(bad, &error));
        QCOMPARE(tab().saveState(), saved);
    }

    void aDocumentAskingForTooManyVerticesIsRefused()
    {
        // Issue 12: a 110-byte document froze the GUI (5000 bodies of 10000 sides, each
        // within its own range).
        const QByteArray text = R"({"frog":{"scene":"many-bodies","params":{"bodies":5000,"sides":10000}}})";
        QVERIFY(text.size() <= 110);
        const QJsonObject frog = QJsonDocument::fromJson(text).object()["frog"].toObject();
        const QJsonObject before = tab().saveState();
        QString error;
        QVERIFY(!tab().loadState(frog, &error));
        QVERIFY2(error.contains("100000 vertices"), qPrintable(error));
        QCOMPARE(tab().saveState(), before);
        // 5000 bodies of 10 sides are 50 000 vertices, but they do not fit the scene's frame.
        QJsonObject fewerSides = frog;
        fewerSides["params"] = QJsonObject{{"bodies", 5000}};
        QVERIFY(!tab().loadState(fewerSides, &error));
        QVERIFY2(error.contains("or widen the frame"), qPrintable(error));
        QCOMPARE(tab().saveState(), before);
    }

    // Issue 32, item 6: §4.9's body is sampled once from a Bézier curve of degree `sides`
    // at `bezier_samples` points, sides² × samples of work: this document (10¹¹
    // interpolations) froze the window 48 s, and typing 10000 into Sides on the scene with
    // 2000 points 45 s. Both are refused now, before any of the work, with a message naming
    // what to lower (core/base/input_limits.h, kMaxBezierOutlineWork = 5·10⁸).
    void aBezierBodyTooCostlyToBuildIsRefused()
    {
        const QByteArray text = R"({"frog":{"scene":"bezier","params":{"sides":10000,"bezier_samples":2000}}})";
        const QJsonObject frog = QJsonDocument::fromJson(text).object()["frog"].toObject();
        const QJsonObject before = tab().saveState();
        QString error;
        QVERIFY(!tab().loadState(frog, &error));
        QVERIFY2(error.contains("lower the sides or the Bézier samples"), qPrintable(error));
        QCOMPARE(tab().saveState(), before);

        // The spin box: 2000 points are accepted at 10 sides (10·11/2·2000 = 110 000), then
        // 10000 typed into Sides and Enter is refused: the field shows 10 again, a message says why.
        QVERIFY(tab().setScene("bezier", nullptr));
        QDoubleSpinBox* samples = tab().parametersPanel()->spinBox("bezier_samples");
        QDoubleSpinBox* sides = tab().parametersPanel()->spinBox("sides");
        QVERIFY(samples && sides);
        samples->setValue(2000);
        QCOMPARE(tab().scene().bezierSamples, 2000);
        QSignalSpy said(&tab(), &FrogTab::statusMessage);
        sides->setFocus();
        sides->selectAll();
        QTest::keyClicks(sides, "10000");
        QTest::keyClick(sides, Qt::Key_Return);
        QCOMPARE(tab().scene().params.sides, 10);
        QCOMPARE(tab().parametersPanel()->spinBox("sides")->value(), 10.0);
        QVERIFY(!said.isEmpty());
        QVERIFY2(said.last().at(0).toString().contains("lower the sides or the Bézier samples"),
                 qPrintable(said.last().at(0).toString()));
        QCOMPARE(tab().frogRun()->simulation()->scene().params.sides, 10); // the running body too
        // At these 2000 points the budget holds 706 sides (706·707/2·2000 = 499 142 000 ≤ 5·10⁸;
        // 707 would be 500 500 000): accepted.
        sides->selectAll();
        QTest::keyClicks(sides, "706");
        QTest::keyClick(sides, Qt::Key_Return);
        QCOMPARE(tab().scene().params.sides, 706);
    }

    // Issue 14, item 17: the seed solver says when it cannot keep the scene's shapes.
    void seedSaysItRoundsOtherShapes()
    {
        auto* note = tab().findChild<QLabel*>("frogSolverNote");
        QVERIFY(note);
        QVERIFY(tab().setScene("shapes", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        QVERIFY(note->isVisible());
        QVERIFY2(note->text().contains("angle constraints") && note->text().contains("Stable"), qPrintable(note->text()));
        QVERIFY(tab().setSolver(SolverKind::Stable, nullptr)); // the stable solver keeps the shapes
        QVERIFY(!note->isVisible());
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        QVERIFY(tab().setScene("frog", nullptr)); // a regular polygon: nothing to say
        QVERIFY(!note->isVisible());
    }

    // A seed that blows up (area error past ±100 %) says to press Reset or switch solver,
    // with or without the readouts overlay; the stable solver on the same values does not.
    void seedExplosionSaysPressReset()
    {
        QVERIFY(tab().setScene("area", nullptr));
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        QVERIFY(tab().editParameter("velmax", QJsonValue(1000), nullptr));
        FrogCanvas* canvas = tab().canvas();
        tab().findChild<QPushButton*>("frogPause")->click();
        steps(tab(), 300);
        QVERIFY(std::abs(canvas->frogRun()->simulation()->readouts().areaErrorPercent) > 100);
        QString lines = canvas->textLines().join('\n');
        QVERIFY2(lines.contains("Reset (R)") && lines.contains("Stable solver"), qPrintable(lines));
        // The warning under the canvas offers both ways out: Reset starts the scene again…
        auto* warning = tab().findChild<QWidget*>("frogExplosion");
        auto* reset = tab().findChild<QPushButton*>("frogExplosionReset");
        auto* stable = tab().findChild<QPushButton*>("frogExplosionStable");
        QVERIFY(warning->isVisibleTo(&tab()) && stable->isVisibleTo(&tab()));
        reset->click();
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 0L);
        QVERIFY(!warning->isVisibleTo(&tab()));
        steps(tab(), 300);
        QVERIFY(warning->isVisibleTo(&tab()));
        // …and the stable solver takes the same values, as one undo step.
        const int undoSteps = tab().undoStack()->count();
        stable->click();
        QCOMPARE(tab().solver(), SolverKind::Stable);
        QCOMPARE(tab().scene().params.velmax, 1000.0);
        QCOMPARE(tab().undoStack()->count(), undoSteps + 1);
        QVERIFY(!warning->isVisibleTo(&tab()));
        steps(tab(), 300);
        QVERIFY(!warning->isVisibleTo(&tab()));
        lines = canvas->textLines().join('\n');
        QVERIFY2(!lines.contains("Reset (R)"), qPrintable(lines));
        tab().reset(); // and once started again, the seed's hint is gone too
        QVERIFY(tab().setSolver(SolverKind::Seed, nullptr));
        QVERIFY2(!canvas->textLines().join('\n').contains("Reset (R)"), qPrintable(canvas->textLines().join('\n')));
    }

    // §4.1: the mouse sets the polygon's radius, and the panel's radius field shows it.
    void polygonRadiusFieldFollowsTheMouse_data()
    {
        QTest::addColumn<SolverKind>("solver");
        QTest::newRow("seed") << SolverKind::Seed;
        QTest::newRow("stable") << SolverKind::Stable;
    }
    void polygonRadiusFieldFollowsTheMouse()
    {
        QFETCH(SolverKind, solver);
        QVERIFY(tab().setScene("polygon", nullptr));
        QVERIFY(tab().setSolver(solver, nullptr));
        FrogCanvas* canvas = tab().canvas();
        QDoubleSpinBox* radius = tab().parametersPanel()->spinBox("radius");
        QVERIFY(radius);
        QCOMPARE(radius->value(), 120.0);
        const double h = tab().scene().params.height;
        double set = 0; // the radius the mouse set last
        for (double y : {h / 2 + 200, h / 2 - 50}) {
            const QPoint at = canvas->toWidget(Point(640, y)).toPoint();
            QTest::mouseMove(canvas, at);
            const double expected = std::abs(canvas->toScene(QPointF(at)).y - h / 2); // r = |mouseY − h/2|
            set = expected;
            QVERIFY2(std::abs(radius->value() - expected) < 0.051,
                     qPrintable(QString("field %1, mouse radius %2").arg(radius->value()).arg(expected)));
            std::vector<Point> v;
            canvas->frogRun()->simulation()->bodyVertices(0, v);
            QVERIFY(std::abs(distance(v[0], Point(640, h / 2)) - expected) < 0.01); // the polygon is that size
        }
        QVERIFY(!tab().undoStack()->canUndo()); // the mouse is not an edit

        // The tab keeps no scene of its own (issue 35): the radius the mouse set lives in the
        // run, which the panel and an edit start from.
        QCOMPARE(&tab().scene(), &tab().frogRun()->scene());
        QCOMPARE(tab().frogRun()->sceneAsEdited().params.radius, set);
        QVERIFY(tab().frogRun()->sceneAsEdited().radiusFromFrame); // still the frame's until typed (§4.1)
    }

    // The thin line across the sky is the frame's top edge: a caption says so, in the sky
    // bar above it when the canvas is taller than the scene, else just under it.
    void frameTopLineIsCaptioned()
    {
        FrogCanvas* canvas = tab().canvas();
        QVERIFY(canvas->height() * 16 > canvas->width() * 9 + 160); // a sky bar above the frame
        const int top = int(std::floor(canvas->toWidget(Point(0, 0)).y())) - 2;
        QVERIFY(top > 10);
        QImage image(canvas->size(), QImage::Format_ARGB32);
        image.fill(Qt::white);
        {
            QPainter p(&image);
            canvas->render(p, QRectF(QPointF(0, 0), QSizeF(canvas->size())));
        }
        const QRgb sky = image.pixel(2, 2); // the bar's plain colour
        int ink = 0;
        for (int y = 0; y < top; ++y)
            for (int x = 0; x < image.width(); ++x)
                if (qGray(image.pixel(x, y)) < qGray(sky) - 60)
                    ++ink;
        QVERIFY2(ink > 50, qPrintable(QString("%1 dark pixels above the frame").arg(ink)));
        QVERIFY(canvas->frameCaption().contains("frame"));
        // A wide canvas has no bar: the caption sits inside the frame, under its top edge.
        const QRectF wide(0, 0, 1600, 400);
        const QRectF caption = canvas->frameCaptionRect(wide);
        QVERIFY(caption.top() >= 0 && caption.bottom() < wide.height() / 4);
    }

    void tinyWindowIsSafe()
    {
        tab().resize(30, 20);
        QTest::qWait(50);
        FrogCanvas* canvas = tab().canvas();
        canvas->resize(3, 2);
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
        QTest::mouseMove(canvas, QPoint(2, 1));
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, QPoint(2, 1));
        canvas->repaint();
        QVERIFY(canvas->frogRun()->simulation()->finite());
    }
};

GRANOTA_TEST_MAIN(TestGuiFrog)
#include "test_gui_frog.moc"
