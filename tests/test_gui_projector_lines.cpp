// Issue 34, item 11: what a projector lost is drawn thick and dark enough. On a 1024×768
// screen (a window of 1024×738):
// - the bare polygon of §4.1–4.7 is at least 2 px wide on screen: measured in the pixels,
//   across its most upright edge, as the sum of each pixel's share of the ink's darkness
//   (antialiasing spreads a line over pixels; the sum is its width);
// - the broad phase's boxes and links, and De Casteljau's extrema ◆, are drawn with pens at least
//   2 device px wide whose colour stands out from the white canvas by a contrast ratio of at
//   least 3:1 (WCAG's, computed here from the colours), recorded as paths (path_recorder.h).
// Each was thinner or paler before: the polygon 1.5 px, the boxes 1.2 px, the ◆ a white 1 px edge.
#include "canvas_pixels.h"
#include "main_window_steps.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/path_recorder.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "gui_timeouts.h"

#include "core/softbody/simulation.h"

#include <QCheckBox>
#include <QPushButton>
#include <QTest>
#include "tests/test_main.h"

#include <algorithm>
#include <cmath>
#include <vector>

using granota::Point;
using granota::ui::FrogCanvas;
using granota::ui::MainWindow;
using granota::ui::PathRecorder;

namespace {


/// WCAG's relative luminance of an opaque colour.
double luminance(const QColor& c)
{
    const auto channel = [](double v) {
        v /= 255;
        return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * channel(c.red()) + 0.7152 * channel(c.green()) + 0.0722 * channel(c.blue());
}

/// WCAG's contrast ratio of `c` on white.
double contrastOnWhite(const QColor& c) { return (1.0 + 0.05) / (luminance(c) + 0.05); }

/// What a drawable paints, as paths with their pens (device pixels).
template <class View> std::vector<PathRecorder::Shape> recorded(View* view, QSize size)
{
    PathRecorder recorder(size);
    {
        QPainter painter(&recorder);
        view->render(painter, QRectF(QPointF(0, 0), QSizeF(size)));
    }
    return recorder.shapes();
}

} // namespace

class TestGuiProjectorLines : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        useTestSettings();
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    void bareBodyOutlineIsTwoPixelsWide()
    {
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("frog")));
        granota::ui::FrogTab* tab = window.frogTab();
        QString error;
        QVERIFY2(tab->setScene(QStringLiteral("polygon"), &error), qPrintable(error)); // §4.1, a bare polygon
        tab->findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        FrogCanvas* canvas = tab->canvas();
        canvas->setOverlays(FrogCanvas::Overlays()); // nothing over the outline
        settle();
        std::vector<Point> vertices;
        canvas->frogRun()->simulation()->bodyVertices(0, vertices);
        QVERIFY(vertices.size() >= 3);
        // The most upright edge of the polygon on screen, and its midpoint.
        QPointF a, b;
        double best = -1;
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const QPointF p = canvas->toWidget(vertices[i]), q = canvas->toWidget(vertices[(i + 1) % vertices.size()]);
            const double upright = std::abs(q.y() - p.y()) / std::max(1e-9, std::hypot(q.x() - p.x(), q.y() - p.y()));
            if (std::hypot(q.x() - p.x(), q.y() - p.y()) > 20 && upright > best) {
                best = upright;
                a = p;
                b = q;
            }
        }
        QVERIFY2(best > 0.9, "an edge within 25° of upright, 20 px long");
        const QPointF mid = (a + b) / 2;
        // The edge's normal against the row: a row crosses a line of width w over w / |n.x| px.
        const double nx = std::abs(b.y() - a.y()) / std::hypot(b.x() - a.x(), b.y() - a.y());
        const QImage image = renderedPixels(canvas);
        const int y = int(std::lround(mid.y())), x0 = int(std::lround(mid.x()));
        const int reach = 8;
        QVERIFY(x0 - reach >= 0 && x0 + reach < image.width() && y >= 0 && y < image.height());
        // The background on each side, a few pixels away from the line, and the ink's darkness.
        const double left = qGray(image.pixel(x0 - reach, y)), right = qGray(image.pixel(x0 + reach, y));
        const double ink = qGray(tab->canvas()->art().inkPen().color().rgb());
        const double background = std::min(left, right);
        QVERIFY2(background - ink > 100, qPrintable(QStringLiteral("background %1, ink %2").arg(background).arg(ink)));
        double coverage = 0;
        for (int x = x0 - reach + 1; x < x0 + reach; ++x)
            coverage += std::clamp((background - qGray(image.pixel(x, y))) / (background - ink), 0.0, 1.0);
        const double width = coverage * nx;
        qInfo("the outline is %.2f px wide on a canvas of %d×%d", width, canvas->width(), canvas->height());
        QVERIFY2(width >= 2.0, qPrintable(QStringLiteral("the outline is %1 px wide").arg(width)));
    }

    void broadPhaseBoxesAreThickAndDark()
    {
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("frog")));
        granota::ui::FrogTab* tab = window.frogTab();
        QString error;
        QVERIFY2(tab->setScene(QStringLiteral("many-bodies"), &error), qPrintable(error)); // the stable solver's collisions
        tab->findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        FrogCanvas* canvas = tab->canvas();
        FrogCanvas::Overlays pairs;
        pairs.pairs = true;
        canvas->setOverlays(pairs);
        std::vector<std::pair<int, int>> candidates;
        for (int i = 0; i < 600 && candidates.empty(); ++i) {
            canvas->frogRun()->step();
            canvas->frogRun()->simulation()->broadPhasePairs(candidates);
        }
        QVERIFY2(!candidates.empty(), "the bodies never came near each other");
        settle();
        // kPairColour (frog_overlay_painter.cpp), the colour the boxes and links are drawn in.
        const QColor pairColour(0xc2, 0x18, 0x5b);
        int drawn = 0;
        for (const PathRecorder::Shape& shape : recorded(canvas, canvas->size()))
            if (shape.stroke.isValid() && shape.stroke.rgb() == pairColour.rgb()) {
                ++drawn;
                QVERIFY2(shape.strokeWidth >= 2.0, qPrintable(QStringLiteral("a %1 px pen").arg(shape.strokeWidth)));
                QVERIFY(shape.stroke.alpha() == 255);
            }
        QVERIFY(drawn >= 3 * int(candidates.size())); // two boxes and a link a pair
        QVERIFY2(contrastOnWhite(pairColour) >= 3.0, qPrintable(QString::number(contrastOnWhite(pairColour))));
    }

    void extremaDiamondsAreThickAndDark()
    {
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("decasteljau")));
        auto* tab = qobject_cast<granota::ui::DeCasteljauTab*>(window.currentTab());
        QVERIFY(tab);
        QVERIFY(window.loadExample(QStringLiteral("2.3"))); // a curve with extrema of x and y inside it
        tab->setBoundingBoxVisible(true);
        settle();
        granota::ui::CurveCanvas* canvas = tab->canvas();
        // kBoxColour (decasteljau_tab.cpp): the ◆'s fill; a ◆ is a closed path of four corners.
        const QColor boxColour(0x5e, 0x6a, 0x78);
        int diamonds = 0;
        for (const PathRecorder::Shape& shape : recorded(canvas, canvas->size())) {
            if (!shape.fill.isValid() || shape.fill.rgb() != boxColour.rgb())
                continue;
            const QList<QPolygonF> polygons = shape.path.toSubpathPolygons();
            if (polygons.size() != 1 || polygons.front().size() < 4 || polygons.front().size() > 5)
                continue;
            ++diamonds;
            QVERIFY2(shape.stroke.isValid() && shape.strokeWidth >= 2.0,
                     qPrintable(QStringLiteral("a %1 px edge").arg(shape.strokeWidth)));
            QVERIFY2(contrastOnWhite(shape.stroke) >= 3.0, qPrintable(shape.stroke.name()));
            const QRectF extent = shape.path.boundingRect();
            QVERIFY2(extent.width() >= 10 && extent.height() >= 10,
                     qPrintable(QStringLiteral("%1×%2 px").arg(extent.width()).arg(extent.height())));
        }
        QVERIFY2(diamonds >= 2, qPrintable(QString::number(diamonds)));
    }
};

GRANOTA_TEST_MAIN(TestGuiProjectorLines)
#include "test_gui_projector_lines.moc"
