// The B-spline tab's weights and continuity (issue 36): the plot under the canvas switches to
// κ(s) (one undo step, saved), and κ jumps at a double knot of a cubic (C¹) by the amount the
// two Bézier pieces give by hand while it is continuous at simple knots (C²); a point's weight
// changes by Shift+wheel and the + and − keys, two significant digits exactly, consecutive
// changes one undo step, never ≤ 0; the homogeneous curve (wx, wy, w) divided by w is the
// rational curve, (3/4, 1, 5/4) at u = 1/2 on the quarter circle by hand; the point table's w
// column edits one weight at a time, as typed, one undo step each, never ≤ 0.
#include "core/curves/bsplines/de_boor.h"
#include "ui/bsplines/bspline_curvature_plot.h"
#include "ui/bsplines/bspline_examples.h"
#include "ui/bsplines/bspline_tab.h"
#include "ui/bsplines/weight_gesture.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "gui_timeouts.h"

#include <QCheckBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>
#include <qcustomplot.h>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;
using namespace granota::ui;

namespace {

void showWeightsTab(BSplineTab& tab)
{
    tab.resize(1280, 760);
    tab.show();
    QVERIFY(waitExposed(&tab));
}

std::vector<Rational> weightList(std::initializer_list<std::pair<long, long>> list)
{
    std::vector<Rational> out;
    for (const auto& [p, q] : list)
        out.push_back(frac(p, q));
    return out;
}

/// Six points of a clamped cubic whose Bézier pieces are easy by hand (see kappaJumpsAtADoubleKnot).
const std::vector<Point> kJumpPoints = {{0, 0}, {1, 2}, {2, 2}, {5, 2}, {6, 0}, {8, 1}};

} // namespace

class TestGuiBSplineWeights : public QObject {
    Q_OBJECT
private slots:
    void curvaturePlotIsOneUndoStepAndSaved()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        const int undo = tab.undoStack()->count();
        auto* check = tab.findChild<QCheckBox*>(QStringLiteral("bsplineCurvaturePlot"));
        QVERIFY(check);
        QVERIFY(!check->isChecked());
        check->click();
        QVERIFY(tab.model().curvaturePlot);
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QVERIFY(tab.saveState().value(QStringLiteral("curvature_plot")).toBool());
        // κ(s) drawn: one graph, the curve's, over s ∈ [0, L].
        QCOMPARE(tab.basisPlot()->graphCount(), 1);
        QVERIFY(!tab.scene().curvature.samples.empty());
        QCOMPARE(tab.basisPlot()->xAxis->range().upper, tab.scene().curvature.length());
        BSplineTab other;
        QString error;
        QVERIFY2(other.loadState(tab.saveState(), &error), qPrintable(error));
        QVERIFY(other.model().curvaturePlot);
        tab.undoStack()->undo();
        QVERIFY(!tab.model().curvaturePlot);
        QVERIFY(!check->isChecked());
        QVERIFY(tab.scene().curvature.samples.empty());
        // The basis functions again: N₀…N₅ and Σ.
        QCOMPARE(tab.basisPlot()->graphCount(), 7);
    }

    // A clamped cubic on P0…P5 = (0,0), (1,2), (2,2), (5,2), (6,0), (8,1) with the knots
    // 0,0,0,0, 1/3, 1/3, 1,1,1,1: the double knot 1/3 (C¹). By hand, Boehm's insertion of 1/3
    // once more (span k = 5, α = (1/3 − u₃)/(u₆ − u₃) = 1/3) adds Q = (2/3)P₂ + (1/3)P₃ = (3, 2),
    // and the pieces are [P₀, P₁, P₂, Q] and [Q, P₃, P₄, P₅]. κ at the end of a cubic piece is
    // (2/3)(b₂ − b₁)×(b₃ − b₂)/|b₃ − b₂|³ and at its start (2/3)(b₁ − b₀)×(b₂ − b₁)/|b₁ − b₀|³:
    // left (1,0)×(1,0) = 0, so κ = 0; right (2,0)×(1,−2) = −4 over 2³, so κ = −1/3. With the
    // simple knots 1/3, 2/3 of the clamped preset the curve is C² and κ continuous.
    void kappaJumpsAtADoubleKnot()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        tab.pointEditor()->setPoints(kJumpPoints, QStringLiteral("points"));
        tab.setCurvaturePlot(true);
        const auto continuousAtEachKnot = [&tab] {
            const CurvatureProfile& k = tab.scene().curvature;
            for (std::size_t i = 1; i < k.samples.size(); ++i) {
                const double left = *k.samples[i - 1].back().kappa, right = *k.samples[i].front().kappa;
                if (std::fabs(left - right) > 1e-9 * std::max(1.0, std::fabs(left)))
                    return false;
            }
            return true;
        };
        QCOMPARE(tab.scene().curvature.samples.size(), std::size_t(3));
        QVERIFY(continuousAtEachKnot());
        QCOMPARE(tab.scene().curvatureKnots.size(), std::size_t(2));
        for (const auto& k : tab.scene().curvatureKnots)
            QCOMPARE(k.multiplicity, 1);
        QCOMPARE(continuityLabel(3, 1), QStringLiteral("C²"));

        QVERIFY(tab.moveKnot(5, frac(1, 3))); // u₅ = 2/3 onto its neighbour u₄ = 1/3
        QCOMPARE(tab.knots()[5], frac(1, 3));
        const CurvatureProfile& k = tab.scene().curvature;
        QCOMPARE(k.samples.size(), std::size_t(2));
        QVERIFY(std::fabs(*k.samples[0].back().kappa - 0.0) < 1e-12);
        QVERIFY(std::fabs(*k.samples[1].front().kappa - (-1.0 / 3)) < 1e-12);
        QVERIFY(!continuousAtEachKnot());
        QCOMPARE(tab.scene().curvatureKnots.size(), std::size_t(1));
        QCOMPARE(tab.scene().curvatureKnots[0].multiplicity, 2);
        QCOMPARE(tab.scene().curvatureKnots[0].s, k.knots[1]);
        QCOMPARE(continuityLabel(3, 2), QStringLiteral("C¹"));
        QCOMPARE(continuityLabel(3, 3), QStringLiteral("C⁰"));
        // The plot labels its knot C¹.
        bool labelled = false;
        for (int i = 0; i < tab.basisPlot()->itemCount(); ++i)
            if (auto* text = qobject_cast<QCPItemText*>(tab.basisPlot()->item(i)))
                labelled = labelled || text->text() == QStringLiteral("C¹");
        QVERIFY(labelled);
    }

    void steppedWeightsAreTwoSignificantDigits()
    {
        // 2^(±1/4) = 1.1892…, 0.8409…: 1.2 and 0.84; four notches double or halve exactly.
        QCOMPARE(steppedWeight(Rational(1), 1), frac(6, 5));
        QCOMPARE(steppedWeight(Rational(1), -1), frac(21, 25));
        QCOMPARE(steppedWeight(Rational(1), 4), Rational(2));
        QCOMPARE(steppedWeight(Rational(1), -4), frac(1, 2));
        QCOMPARE(steppedWeight(frac(6, 5), 1), frac(7, 5)); // 1.2 × 1.1892 = 1.427
        QCOMPARE(steppedWeight(Rational(99), 1), Rational(120));
        QCOMPARE(steppedWeight(frac(1, 1000), -1), frac(1, 1000)); // the smallest: stays, never ≤ 0
    }

    // The quarter circle's middle weight (the example's 1, 1, 2) by Shift+wheel over P₁ and by
    // the keys: only that weight changes, the points do not, consecutive changes are one undo
    // step and that undo restores 1 exactly; the weights field shows the same values.
    void weightByWheelAndKeys()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        tab.loadBSplineExample(BSplineExampleId::QuarterCircle);
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
        const std::vector<Point> points = tab.pointEditor()->points();
        const int undo = tab.undoStack()->count();
        CurveCanvas* canvas = tab.canvas();
        const QPointF at = canvas->view().toScreen(points[1]);
        QWheelEvent wheel(at, canvas->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::ShiftModifier,
                          Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(canvas, &wheel);
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {6, 5}, {2, 1}}));
        QCOMPARE(tab.pointEditor()->selected(), 1);
        QCOMPARE(tab.pointEditor()->points(), points);
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        auto* field = tab.findChild<QLineEdit*>(QStringLiteral("bsplineWeights"));
        QVERIFY(field);
        QCOMPARE(field->text(), QStringLiteral("1, 6/5, 2"));
        // The + key on the selected point: one more notch, the same undo step.
        canvas->setFocus();
        QTest::keyClick(canvas, Qt::Key_Plus);
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {7, 5}, {2, 1}}));
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QCOMPARE(field->text(), QStringLiteral("1, 7/5, 2"));
        // A wheel without Shift zooms, as before.
        const double zoom = canvas->view().scale();
        QWheelEvent plain(at, canvas->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                          false);
        QCoreApplication::sendEvent(canvas, &plain);
        QVERIFY(canvas->view().scale() > zoom);
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {7, 5}, {2, 1}}));
        tab.undoStack()->undo();
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
        QCOMPARE(tab.pointEditor()->points(), points);
        // The − key many times: down to the smallest weight, then a refusal; never ≤ 0.
        for (int i = 0; i < 60; ++i)
            QTest::keyClick(canvas, Qt::Key_Minus);
        QCOMPARE(tab.model().weights[1], kMinWeight);
        QVERIFY(!tab.stepWeight(1, -1));
        QVERIFY(!tab.lastMessage().isEmpty());
    }

    // With the control points hidden, Shift+wheel over where P₁ is changes no weight, as the
    // + and − keys do not: a hidden point cannot be picked.
    void noWeightByWheelWhenPointsAreHidden()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        tab.loadBSplineExample(BSplineExampleId::QuarterCircle);
        CurveCanvas* canvas = tab.canvas();
        const QPointF at = canvas->view().toScreen(tab.pointEditor()->points()[1]);
        tab.pointEditor()->setSelected(1);
        tab.pointEditor()->setHandlesVisible(false);
        const int undo = tab.undoStack()->count();
        QWheelEvent wheel(at, canvas->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::ShiftModifier,
                          Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(canvas, &wheel);
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
        QCOMPARE(tab.undoStack()->count(), undo);
    }

    // The quarter circle's weights (1, 1, 2) in the table's w column (column 2). Typing 3/2 in
    // P₁'s row changes that weight alone, exactly: (1, 3/2, 2), what the weights field, the
    // scene (the rings) and the column then show; one undo step, whose undo gives (1, 1, 2)
    // back everywhere. 0, −1, text and a radical are refused with a message, nothing changes
    // and the cell shows the weight again.
    void weightTypedInTheTable()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        tab.loadBSplineExample(BSplineExampleId::QuarterCircle);
        PointTable* table = tab.pointTable();
        auto* field = tab.findChild<QLineEdit*>(QStringLiteral("bsplineWeights"));
        QVERIFY(field);
        QCOMPARE(table->columnCount(), 3);
        QCOMPARE(table->horizontalHeaderItem(2)->text(), QStringLiteral("w"));
        QVERIFY(!table->horizontalHeaderItem(2)->toolTip().isEmpty());
        const auto column = [table] {
            QStringList texts;
            for (int i = 0; i < table->rowCount(); ++i)
                texts << table->item(i, 2)->text();
            return texts.join(QStringLiteral(", "));
        };
        QCOMPARE(column(), QStringLiteral("1, 1, 2"));
        const std::vector<Point> points = tab.pointEditor()->points();
        const int undo = tab.undoStack()->count();

        table->item(1, 2)->setText(QStringLiteral("3/2"));
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {3, 2}, {2, 1}}));
        QCOMPARE(tab.scene().exact.weights, tab.model().weights);
        QCOMPARE(field->text(), QStringLiteral("1, 3/2, 2"));
        QCOMPARE(column(), QStringLiteral("1, 3/2, 2"));
        QCOMPARE(tab.pointEditor()->points(), points);
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        tab.undoStack()->undo();
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
        QCOMPARE(tab.scene().exact.weights, tab.model().weights);
        QCOMPARE(field->text(), QStringLiteral("1, 1, 2"));
        QCOMPARE(column(), QStringLiteral("1, 1, 2"));

        // A decimal is read exactly: 0.7 is 7/10.
        table->item(0, 2)->setText(QStringLiteral("0.7"));
        QCOMPARE(tab.model().weights, weightList({{7, 10}, {1, 1}, {2, 1}}));
        QCOMPARE(column(), QStringLiteral("7/10, 1, 2"));
        tab.undoStack()->undo();

        QSignalSpy messages(&tab, &BSplineTab::statusMessage);
        const int commands = tab.undoStack()->count(), at = tab.undoStack()->index(); // 0.7 is there to redo
        const QStringList refused = {QStringLiteral("0"), QStringLiteral("-1"), QStringLiteral("abc"), QStringLiteral("√2/2"),
                                     QString()};
        for (const QString& text : refused) {
            table->item(1, 2)->setText(text);
            QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
            QCOMPARE(tab.undoStack()->count(), commands);
            QCOMPARE(tab.undoStack()->index(), at);
            QCOMPARE(table->item(1, 2)->text(), QStringLiteral("1"));
            QCOMPARE(field->text(), QStringLiteral("1, 1, 2"));
        }
        QCOMPARE(messages.count(), static_cast<int>(refused.size()));
        // The x and y columns still edit the points.
        table->item(2, 0)->setText(QStringLiteral("1/2"));
        QCOMPARE(tab.pointEditor()->points()[2], (Point{0.5, 1}));
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {2, 1}}));
    }

    // A polynomial curve shows 1 in every row; typing 2 in P₀'s row makes it rational with 1 at
    // every other point (as stepWeight does), one undo step; typing 1 changes nothing.
    void weightTypedInThePolynomialCurvesTable()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        QVERIFY(tab.model().weights.empty());
        PointTable* table = tab.pointTable();
        QCOMPARE(table->rowCount(), 6);
        for (int i = 0; i < table->rowCount(); ++i)
            QCOMPARE(table->item(i, 2)->text(), QStringLiteral("1"));
        const int undo = tab.undoStack()->count();
        table->item(0, 2)->setText(QStringLiteral("1"));
        QVERIFY(tab.model().weights.empty());
        QCOMPARE(tab.undoStack()->count(), undo);
        table->item(0, 2)->setText(QStringLiteral("2"));
        QCOMPARE(tab.model().weights, weightList({{2, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}));
        QVERIFY(tab.scene().curve.rational());
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("2"));
        tab.undoStack()->undo();
        QVERIFY(tab.model().weights.empty());
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("1"));
    }

    void weightOfAPolynomialCurve()
    {
        // No weights yet: the stepped point gets 6/5, every other point 1.
        BSplineTab tab;
        showWeightsTab(tab);
        QVERIFY(tab.model().weights.empty());
        QVERIFY(tab.stepWeight(2, 1));
        QCOMPARE(tab.model().weights, weightList({{1, 1}, {1, 1}, {6, 5}, {1, 1}, {1, 1}, {1, 1}}));
        QVERIFY(tab.scene().curve.rational());
        tab.undoStack()->undo();
        QVERIFY(tab.model().weights.empty());
    }

    // The quarter circle (1, 0), (1, 1), (0, 1) with weights 1, 1, 2 on the knots 0,0,0,1,1,1 is
    // the rational quadratic Bézier curve: with B₀ = (1 − u)², B₁ = 2u(1 − u), B₂ = u², the
    // homogeneous curve is H(u) = (B₀ + B₁, B₁ + 2B₂, B₀ + B₁ + 2B₂); at u = 1/2 that is
    // (1/4 + 1/2, 1/2 + 1/2, 1/4 + 1/2 + 1/2) = (3/4, 1, 5/4), and H/w = (3/5, 4/5).
    void homogeneousCurveProjectsOntoTheRationalCurve()
    {
        BSplineTab tab;
        showWeightsTab(tab);
        tab.loadBSplineExample(BSplineExampleId::QuarterCircle);
        const int undo = tab.undoStack()->count();
        QVERIFY(tab.homogeneousInset().isEmpty());
        tab.setHomogeneousCurveVisible(true);
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QVERIFY(!tab.homogeneousInset().isEmpty());
        const HomogeneousView& h = tab.scene().homogeneous;
        QCOMPARE(h.controlPoints.size(), std::size_t(3));
        QCOMPARE(h.controlPoints[2].x, 0.0);
        QCOMPARE(h.controlPoints[2].y, 2.0);
        QCOMPARE(h.controlPoints[2].w, 2.0);
        QCOMPARE(h.u.size(), std::size_t(BSplineScene::kHomogeneousSamples));
        const std::size_t middle = h.u.size() / 2;
        QCOMPARE(h.u[middle], 0.5);
        QVERIFY(std::fabs(h.curve[middle].x - 0.75) < 1e-15);
        QVERIFY(std::fabs(h.curve[middle].y - 1.0) < 1e-15);
        QVERIFY(std::fabs(h.curve[middle].w - 1.25) < 1e-15);
        for (std::size_t j = 0; j < h.u.size(); ++j) {
            const double u = h.u[j], b0 = (1 - u) * (1 - u), b1 = 2 * u * (1 - u), b2 = u * u;
            const double w = b0 + b1 + 2 * b2;
            QVERIFY(std::fabs(h.curve[j].w - w) < 1e-14);
            QVERIFY(std::fabs(h.curve[j].x / h.curve[j].w - (b0 + b1) / w) < 1e-14);
            QVERIFY(std::fabs(h.curve[j].y / h.curve[j].w - (b1 + 2 * b2) / w) < 1e-14);
            QVERIFY(std::fabs(h.planeCurve[j].x - (b0 + b1) / w) < 1e-14);
        }
        // Saved, and drawn on the canvas (the inset's panel is not the paper's colour).
        QVERIFY(tab.saveState().value(QStringLiteral("homogeneous_curve")).toBool());
        const QImage image = tab.canvas()->grab().toImage();
        const QRect inset = tab.homogeneousInset().toRect();
        int purple = 0;
        for (int y = inset.top(); y <= inset.bottom(); y += 2)
            for (int x = inset.left(); x <= inset.right(); x += 2) {
                const QColor c = image.pixelColor(x, y);
                purple += c.red() > 100 && c.blue() > 130 && c.green() < 110;
            }
        QVERIFY2(purple > 20, qPrintable(QString::number(purple)));
        tab.undoStack()->undo();
        QVERIFY(tab.homogeneousInset().isEmpty());
        QVERIFY(tab.scene().homogeneous.empty());
    }
};

GRANOTA_TEST_MAIN(TestGuiBSplineWeights)
#include "test_gui_bspline_weights.moc"
