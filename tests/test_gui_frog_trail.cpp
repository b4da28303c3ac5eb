// Issue 34, item 11: the trail of a blown-up seed body is drawn at a bounded cost. Its 600
// points swept the frame back and forth every step; stroked as one path with round joins and
// caps it took 4.7 s a frame (tests/benchmarks/bench_gui.cpp, BM_GuiSeedExplodedTrail; never
// timed here). The canvas now draws only the segments in the frame, each cut to it, the newest
// first up to 20 times the frame's width plus height of line (frog_overlay_painter.cpp, kTrailInkBudget).
// Here: the cut (ui/common/segment_clip.h) on cases worked by hand, the number of segments a
// blown-up trail draws against a count made here from the trail itself, and an ordinary trail
// drawn whole.
#include "canvas_pixels.h"
#include "core/softbody/simulation.h"
#include "ui/common/segment_clip.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "gui_timeouts.h"

#include <QPushButton>
#include <QTest>
#include "tests/test_main.h"

#include <cmath>
#include <memory>

using granota::Point;
using granota::SolverKind;
using granota::ui::clipSegment;
using granota::ui::FrogCanvas;
using granota::ui::FrogTab;

class TestGuiFrogTrail : public QObject {
    Q_OBJECT

    std::unique_ptr<FrogTab> m_tab;

    /// The trail on, the tab paused, `steps` steps, then one paint: what the canvas drew.
    void runWithTrail(int steps)
    {
        m_tab->findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        FrogCanvas* canvas = m_tab->canvas();
        FrogCanvas::Overlays overlays = canvas->overlays();
        overlays.trail = true;
        canvas->setOverlays(overlays);
        for (int i = 0; i < steps; ++i)
            canvas->frogRun()->step();
        renderedPixels(canvas); // one paint
    }

private slots:
    void init()
    {
        m_tab = std::make_unique<FrogTab>();
        m_tab->resize(1280, 760);
        m_tab->show();
        QVERIFY(waitExposed(m_tab.get()));
    }
    void cleanup() { m_tab.reset(); }

    void segmentsAreCutToTheBox()
    {
        const QRectF box(0, 0, 10, 4);
        // Across the box: its entry and exit on the left and right sides.
        auto part = clipSegment(Point(-5, 2), Point(15, 2), box);
        QVERIFY(part);
        QCOMPARE(part->first, Point(0, 2));
        QCOMPARE(part->second, Point(10, 2));
        // Inside: unchanged.
        part = clipSegment(Point(1, 1), Point(9, 3), box);
        QVERIFY(part);
        QCOMPARE(part->first, Point(1, 1));
        QCOMPARE(part->second, Point(9, 3));
        // From far away (1e12 px) into the box along y = 2: it enters at x = 10.
        part = clipSegment(Point(1e12, 2), Point(5, 2), box);
        QVERIFY(part);
        QCOMPARE(part->first, Point(10, 2));
        QCOMPARE(part->second, Point(5, 2));
        // A diagonal from (−2, −2) to (6, 6) enters at (0, 0) and leaves through the top (y = 4) at (4, 4).
        part = clipSegment(Point(-2, -2), Point(6, 6), box);
        QVERIFY(part);
        QCOMPARE(part->first, Point(0, 0));
        QCOMPARE(part->second, Point(4, 4));
        // Missing it, parallel to a side outside it, or not finite: nothing.
        QVERIFY(!clipSegment(Point(-5, 5), Point(15, 5), box));
        QVERIFY(!clipSegment(Point(11, -1), Point(20, 3), box));
        QVERIFY(!clipSegment(Point(std::nan(""), 1), Point(5, 1), box));
        QVERIFY(!clipSegment(Point(1, 1), Point(INFINITY, 1), box));
    }

    // Ex "area" on the seed with velmax 1000 blows up (test_gui_frog, seedExplosionSaysPressReset).
    void aBlownUpTrailDrawsABoundedPart()
    {
        QVERIFY(m_tab->setScene(QStringLiteral("area"), nullptr));
        QVERIFY(m_tab->setSolver(SolverKind::Seed, nullptr));
        QVERIFY(m_tab->editParameter(QStringLiteral("velmax"), QJsonValue(1000), nullptr));
        runWithTrail(600);
        FrogCanvas* canvas = m_tab->canvas();
        QVERIFY(std::abs(canvas->frogRun()->simulation()->readouts().areaErrorPercent) > 100); // blown up
        const auto& trail = canvas->frogRun()->trail();
        QVERIFY(trail.size() >= 500);
        // Counted here: the newest segments in the frame (with its 5 % margin), up to 20 × (W + H)
        // of line between them.
        const double W = m_tab->scene().params.width, H = m_tab->scene().params.height;
        const double margin = 0.05 * std::max(W, H);
        const QRectF frame(-margin, -margin, W + 2 * margin, H + 2 * margin);
        double ink = 0;
        int expected = 0, inFrame = 0;
        for (std::size_t i = trail.size() - 1; i >= 1; --i)
            if (const auto part = clipSegment(trail[i - 1], trail[i], frame)) {
                ++inFrame;
                if (ink < 20 * (W + H)) {
                    ++expected;
                    ink += std::hypot(part->second.x - part->first.x, part->second.y - part->first.y);
                }
            }
        QCOMPARE(canvas->trailSegmentsDrawn(), expected);
        QVERIFY2(expected < inFrame / 4, qPrintable(QStringLiteral("%1 of %2").arg(expected).arg(inFrame))); // a small part
    }

    // The frog jumping with its trail: every segment is drawn.
    void anOrdinaryTrailIsDrawnWhole()
    {
        runWithTrail(300);
        FrogCanvas* canvas = m_tab->canvas();
        QVERIFY(canvas->frogRun()->trail().size() >= 300);
        QCOMPARE(canvas->trailSegmentsDrawn(), int(canvas->frogRun()->trail().size()) - 1);
    }
};

GRANOTA_TEST_MAIN(TestGuiFrogTrail)
#include "test_gui_frog_trail.moc"
