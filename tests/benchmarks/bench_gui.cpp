// Google Benchmark: what a user feels (issue: speed). A drag on a degree-30 curve in the
// De Casteljau tab — the tab's recomputation (curve, levels, table, panel) and a repaint of
// the canvas at 1280×760 — must fit in one frame (16.7 ms at 60 Hz); and a frame of the frog
// canvas with 200 frogs — one step and one paint — too. Both paint as the screen does
// (repaint: paintEvent into the backing store). Both paint as the screen does
// (repaint: paintEvent into the backing store). And a drag on a 1000-point cubic B-spline in the
// B-spline tab, its canvas and basis plot repainted (issue 36).
//   QT_QPA_PLATFORM=offscreen build/bin/granota-bench --benchmark_filter=Gui
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "ui/bsplines/bspline_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_plot_panel.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/point_editor.h"

#include <QApplication>
#include <qcustomplot.h>
#include <QMouseEvent>

#include <benchmark/benchmark.h>

#include <cmath>

using namespace granota;
using namespace granota::ui;

namespace {

/// The widgets need an application; the benchmark runs headless.
void ensureApplication()
{
    static int argc = 1;
    static char name[] = "granota-bench";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance()) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        new QApplication(argc, argv); // lives until the process ends
    }
}

/// A real drag on a degree-30 curve: press on P15's handle, then mouse moves, each followed
/// (when `repaint`) by a repaint into the window's backing store, as on screen. `overlays`
/// switches the tab's options on before the drag starts.
void dragDegree30(benchmark::State& state, bool repaint, void (*overlays)(DeCasteljauTab&))
{
    ensureApplication();
    DeCasteljauTab tab;
    tab.resize(1280, 760);
    tab.show();
    QCoreApplication::processEvents();
    std::vector<Point> points;
    for (int i = 0; i <= 30; ++i)
        points.emplace_back(i, 4 * std::sin(i * 0.7));
    tab.pointEditor()->setPoints(points, QStringLiteral("bench"));
    if (overlays)
        overlays(tab);
    CurveCanvas* canvas = tab.canvas();
    const QPointF start = canvas->view().toScreen(points[15]);
    QMouseEvent press(QEvent::MouseButtonPress, start, canvas->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QCoreApplication::sendEvent(canvas, &press);
    int frame = 0;
    for (auto _ : state) {
        const QPointF at = start + QPointF(0, (frame++ % 2) ? 3 : -3); // the mouse moved
        QMouseEvent move(QEvent::MouseMove, at, canvas->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(canvas, &move);
        if (repaint)
            canvas->repaint();
    }
    QMouseEvent release(QEvent::MouseButtonRelease, start, canvas->mapToGlobal(start), Qt::LeftButton, Qt::NoButton,
                        Qt::NoModifier);
    QCoreApplication::sendEvent(canvas, &release);
    state.counters["frame_budget_ms"] = 1000.0 / 60.0;
}

void BM_GuiDragDegree30(benchmark::State& state) { dragDegree30(state, state.range(0) != 0, nullptr); }

// Issue 15: the same drag with every overlay of the curve's geometry on (normal, osculating
// circle, curvature comb, tight bounding box with its extrema, inflections and cusps, the
// hodograph's inset, tangent, split) — recomputed and repainted within one frame.
void BM_GuiDragDegree30AllOverlays(benchmark::State& state)
{
    dragDegree30(state, true, [](DeCasteljauTab& tab) {
        tab.setTangentVisible(true);
        tab.setSplitVisible(true);
        tab.setNormalVisible(true);
        tab.setOsculatingCircleVisible(true);
        tab.setCombVisible(true);
        tab.setBoundingBoxVisible(true);
        tab.setInflectionsVisible(true);
        tab.setHodographVisible(true);
    });
}

// Issue 36: a real drag of the middle point on a cubic B-spline with `count` control points
// (clamped knots) in the B-spline tab at 1280×760, de Boor's net and the basis plot shown: each
// mouse move recomputes the tab (curve, net, Bézier pieces, ruler, exact panel, basis plot) and
// is followed by a repaint of the canvas and of the basis plot, as on screen.
void dragBSpline(benchmark::State& state, int count)
{
    ensureApplication();
    BSplineTab tab;
    tab.resize(1280, 760);
    tab.show();
    QCoreApplication::processEvents();
    std::vector<Point> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(i * 50.0 / count, 4 * std::sin(i * 70.0 / count));
    tab.pointEditor()->setPoints(points, QStringLiteral("bench"));
    if (tab.pointEditor()->points().size() != points.size() || !tab.setDegree(3) || !tab.setPreset(KnotPreset::Clamped)) {
        state.SkipWithError("the B-spline tab refused the cubic points (BSplineModel::kMaxPoints)");
        return;
    }
    tab.setNetVisible(true);
    QCoreApplication::processEvents();
    CurveCanvas* canvas = tab.canvas();
    QCustomPlot* plot = tab.basisPlot();
    const QPointF start = canvas->view().toScreen(points[static_cast<std::size_t>(count / 2)]);
    QMouseEvent press(QEvent::MouseButtonPress, start, canvas->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QCoreApplication::sendEvent(canvas, &press);
    int frame = 0;
    for (auto _ : state) {
        const QPointF at = start + QPointF(0, (frame++ % 2) ? 3 : -3); // the mouse moved
        QMouseEvent move(QEvent::MouseMove, at, canvas->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(canvas, &move);
        canvas->repaint();
        plot->replot(QCustomPlot::rpImmediateRefresh);
    }
    QMouseEvent release(QEvent::MouseButtonRelease, start, canvas->mapToGlobal(start), Qt::LeftButton, Qt::NoButton,
                        Qt::NoModifier);
    QCoreApplication::sendEvent(canvas, &release);
    state.counters["frame_budget_ms"] = 1000.0 / 60.0;
}

void BM_GuiBSplineDrag1000(benchmark::State& state) { dragBSpline(state, 1000); }
// The same at 200 points, the tab's limit before issue 36's speed work.
void BM_GuiBSplineDrag200(benchmark::State& state) { dragBSpline(state, 200); }

void BM_GuiFrog200(benchmark::State& state)
{
    ensureApplication();
    auto scene = withBodies(*loadScene("many-bodies"), 200);
    FrogCanvas canvas;
    canvas.resize(1280, 760);
    canvas.frogRun()->setSimulation(std::move(Simulation::create(*scene, SolverKind::Stable)).value());
    canvas.frogRun()->setRunning(false);
    canvas.show();
    QCoreApplication::processEvents();
    for (int i = 0; i < 60; ++i)
        canvas.frogRun()->step(); // let them fall and meet
    // Painted as on screen: paintEvent into the window's backing store, where the pond
    // behind the frogs is a pixmap drawn once per size (exports paint it as vectors).
    for (auto _ : state) {
        canvas.frogRun()->step();
        canvas.repaint();
    }
    state.counters["frame_budget_ms"] = 1000.0 / 60.0;
}

// Issue 16: the 200-frog canvas with the plots over time open — the canvas records a
// sample every step and the panel redraws its plot every sixth frame (ten times a second)
// — still a frame in 16.7 ms.
void BM_GuiFrog200Plots(benchmark::State& state)
{
    ensureApplication();
    FrogTab tab;
    tab.resize(1280, 760);
    QString error;
    const SceneSpec spec = *withBodies(*loadScene("many-bodies"), 200); // BM_GuiFrog200's frame
    if (!tab.setScene(QStringLiteral("many-bodies"), &error) ||
        !tab.editParameter(QStringLiteral("width"), spec.params.width, &error) ||
        !tab.editParameter(QStringLiteral("height"), spec.params.height, &error) ||
        !tab.editParameter(QStringLiteral("bodies"), 200, &error)) {
        state.SkipWithError(qPrintable(error));
        return;
    }
    tab.frogRun()->setRunning(false);
    tab.setPlotsShown(true);
    tab.show();
    QCoreApplication::processEvents();
    for (int i = 0; i < 60; ++i)
        tab.frogRun()->step();
    int frame = 0;
    for (auto _ : state) {
        tab.frogRun()->step();
        tab.canvas()->repaint();
        if (++frame % 6 == 0) {
            tab.plotPanel()->refresh(true);
            tab.plotPanel()->plot()->replot(QCustomPlot::rpImmediateRefresh);
        }
    }
    state.counters["frame_budget_ms"] = 1000.0 / 60.0;
    state.counters["samples"] = static_cast<double>(tab.frogRun()->series().samples().size());
}

// Issue 34: a seed body that has blown up (Ex "area" with velmax 1000: its vertices fly
// thousands of scene px away, and on) with the trail on — the trail's 600 points far outside
// the canvas — painted as on screen. It was 7 frames a second in the classroom.
void BM_GuiSeedExplodedTrail(benchmark::State& state)
{
    ensureApplication();
    FrogTab tab;
    tab.resize(1280, 760);
    QString error;
    if (!tab.setScene(QStringLiteral("area"), &error) || !tab.setSolver(SolverKind::Seed, &error) ||
        !tab.editParameter(QStringLiteral("velmax"), 1000, &error)) {
        state.SkipWithError(qPrintable(error));
        return;
    }
    FrogCanvas* canvas = tab.canvas();
    canvas->frogRun()->setRunning(false);
    FrogCanvas::Overlays overlays = canvas->overlays();
    overlays.trail = state.range(0) != 0; // 0: the body alone, to compare
    canvas->setOverlays(overlays);
    tab.show();
    QCoreApplication::processEvents();
    for (int i = 0; i < 600; ++i)
        canvas->frogRun()->step(); // blown up, and the trail full
    for (auto _ : state) {
        canvas->frogRun()->step();
        canvas->repaint();
    }
    state.counters["frame_budget_ms"] = 1000.0 / 60.0;
    state.counters["trail_points"] = static_cast<double>(canvas->frogRun()->trail().size());
    state.counters["trail_segments_drawn"] = static_cast<double>(canvas->trailSegmentsDrawn());
}

} // namespace

BENCHMARK(BM_GuiFrog200Plots)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiDragDegree30)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiDragDegree30AllOverlays)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiFrog200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiBSplineDrag1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiBSplineDrag200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GuiSeedExplodedTrail)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
