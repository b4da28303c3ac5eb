// The Catmull-Rom tab's family selector (issue 37; docs/spline-families.md "The family
// selector"): Catmull-Rom stays the default and old documents load as it, switching family is
// one undo step, and the document keeps the family.
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/catmull_rom/conventions_table.h"
#include "ui/catmull_rom/curve_family.h"
#include "ui/catmull_rom/family_panel.h"
#include "ui/catmull_rom/hermite_handles.h"
#include "ui/catmull_rom/knot_continuity_table.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "gui_timeouts.h"

#include <QCheckBox>
#include <QRegularExpression>
#include <qcustomplot.h>
#include <QComboBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSlider>
#include <QTest>
#include <QUndoStack>
#include "tests/test_main.h"

using namespace granota;
using namespace granota::ui;

namespace {

/// Saved, written as text and read back, as a document would be.
QJsonObject throughText(const QJsonObject& state) { return QJsonDocument::fromJson(QJsonDocument(state).toJson()).object(); }

/// A tab on the closed curve through (0,0), (1,1), (2,0), the example.
QJsonObject closedTriangle(CatmullRomTab& tab)
{
    QJsonObject state = tab.saveState();
    state.insert(QStringLiteral("points"), QJsonArray{QJsonArray{0, 0}, QJsonArray{1, 1}, QJsonArray{2, 0}});
    state.insert(QStringLiteral("mode"), QStringLiteral("closed"));
    return state;
}

bool nearPoint(Point a, Point b, double tol = 1e-12) { return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol; }

} // namespace

class TestGuiCatmullRomFamilies : public QObject {
    Q_OBJECT
private slots:
    void keysRoundTrip()
    {
        // The document keys of the brief, spelled out here (not read from curve_family.cpp).
        const QStringList keys{QStringLiteral("catmull-rom"), QStringLiteral("cardinal"),     QStringLiteral("kochanek-bartels"),
                               QStringLiteral("hermite"),     QStringLiteral("plane-spline"), QStringLiteral("function-data")};
        QCOMPARE(int(kCurveFamilies.size()), keys.size());
        for (std::size_t i = 0; i < kCurveFamilies.size(); ++i) {
            QCOMPARE(curveFamilyKey(kCurveFamilies[i]), keys[int(i)]);
            QCOMPARE(curveFamilyFromKey(keys[int(i)]), std::optional<CurveFamily>(kCurveFamilies[i]));
            QVERIFY(!curveFamilyName(kCurveFamilies[i]).isEmpty());
        }
        QVERIFY(!curveFamilyFromKey(QStringLiteral("bezier")));
    }

    void catmullRomIsTheDefault()
    {
        CatmullRomTab tab;
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
        QCOMPARE(tab.saveState().value(QStringLiteral("family")).toString(), QStringLiteral("catmull-rom"));
        QVERIFY(tab.scene().family.bezier.empty()); // the τ curves are drawn, no family curve
        QCOMPARE(tab.familyPanel()->familyCombo()->currentIndex(), 0);
    }

    void oldDocumentLoadsAsCatmullRom()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::KochanekBartels);
        QJsonObject old = tab.saveState();
        old.remove(QStringLiteral("family")); // a document from before the selector
        QString error;
        QVERIFY2(tab.loadState(old, &error), qPrintable(error));
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
    }

    void unknownFamilyIsRefused()
    {
        CatmullRomTab tab;
        const QJsonObject before = tab.saveState();
        QJsonObject bad = before;
        bad.insert(QStringLiteral("family"), QStringLiteral("nurbs"));
        QString error;
        QVERIFY(!tab.loadState(bad, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(tab.saveState(), before); // nothing the user made is lost
    }

    void switchingFamilyIsOneUndoStep()
    {
        CatmullRomTab tab;
        const int count = tab.undoStack()->count();
        // Through the combo box, as the user does.
        QComboBox* combo = tab.familyPanel()->familyCombo();
        combo->setCurrentIndex(int(CurveFamily::Hermite));
        QVERIFY(tab.settings().family == CurveFamily::Hermite);
        QCOMPARE(tab.undoStack()->count(), count + 1);
        tab.undoStack()->undo();
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
        QCOMPARE(combo->currentIndex(), int(CurveFamily::CatmullRom));
        tab.undoStack()->redo();
        QVERIFY(tab.settings().family == CurveFamily::Hermite);
        QCOMPARE(combo->currentIndex(), int(CurveFamily::Hermite));
    }

    // The example, worked by hand from the 1984 formulas (kochanek_bartels.h) at
    // P₁ = (1,1): Δ₋ = (1,1), Δ₊ = (1,−1), T = B = 0, C = 1/2:
    //   in  = ½[(1 − C)Δ₋ + (1 + C)Δ₊] = ½[(½,½) + (3/2,−3/2)] = (1, −1/2),
    //   out = ½[(1 + C)Δ₋ + (1 − C)Δ₊] = ½[(3/2,3/2) + (½,−½)] = (1, 1/2).
    void kbContinuityHalfSplitsTheTangents()
    {
        CatmullRomTab tab;
        QString error;
        QVERIFY2(tab.loadState(closedTriangle(tab), &error), qPrintable(error));
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.familyPanel()->allKnotsCheck()->setChecked(true);
        // Through the C slider, as the user does: 10 steps of 1/20.
        tab.familyPanel()->tcbSlider(1)->setValue(10);
        QCOMPARE(tab.settings().tcb.size(), std::size_t(3));
        for (const auto& k : tab.settings().tcb)
            QVERIFY(k.continuity == frac(1, 2) && k.tension == 0 && k.bias == 0);
        const FamilyCurve& curve = tab.scene().family;
        QVERIFY2(curve.error.isEmpty(), qPrintable(curve.error));
        QCOMPARE(curve.hermite.size(), std::size_t(3)); // closed: n + 1 segments for q0..q2
        QCOMPARE(curve.tangents.size(), std::size_t(3));
        QVERIFY(nearPoint(curve.tangents[1].in, Point{1, -0.5}));
        QVERIFY(nearPoint(curve.tangents[1].out, Point{1, 0.5}));
        // The curve still passes through the points (segment 0 ends at P₁, segment 1 starts there).
        QVERIFY(nearPoint(curve.hermite[0].p1, Point{1, 1}));
        QVERIFY(nearPoint(curve.hermite[1].p0, Point{1, 1}));
    }

    // The knot table on the same example: at q1 the tangents (1, −1/2) and (1, 1/2) (worked
    // above) differ, so neither C¹ nor G¹ (not parallel: cross product 1·½ − (−½)·1 = 1 ≠ 0),
    // and the jump |out − in| = |(0, 1)| = 1; back at C = 0 the curve is Catmull-Rom with τ = 1/2,
    // C¹ at every knot (Prop 2.3).
    void knotTableShowsC1FailingWhenContinuityIsNotZero()
    {
        CatmullRomTab tab;
        QString error;
        QVERIFY2(tab.loadState(closedTriangle(tab), &error), qPrintable(error));
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.familyPanel()->allKnotsCheck()->setChecked(true);
        KnotContinuityTable* table = tab.knotTable();
        QCOMPARE(table->rowCount(), 3); // closed: every point is a knot
        for (int r = 0; r < 3; ++r)
            QCOMPARE(table->item(r, KnotContinuityTable::C1Column)->text(), QStringLiteral("✓"));
        tab.familyPanel()->tcbSlider(1)->setValue(10); // C = 1/2
        int row = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->knotPoints()[std::size_t(r)] == 1)
                row = r;
        QVERIFY(row >= 0);
        QCOMPARE(table->item(row, KnotContinuityTable::KnotColumn)->text(), QStringLiteral("q1"));
        QCOMPARE(table->item(row, KnotContinuityTable::C0Column)->text(), QStringLiteral("✓"));
        QCOMPARE(table->item(row, KnotContinuityTable::C1Column)->text(), QStringLiteral("✗"));
        QCOMPARE(table->item(row, KnotContinuityTable::G1Column)->text(), QStringLiteral("✗"));
        QVERIFY(!table->knots()[std::size_t(row)].g1);
        QCOMPARE(table->item(row, KnotContinuityTable::JumpColumn)->text(), QStringLiteral("1"));
    }

    // Cardinal c is Catmull-Rom with τ = (1 − c)/2: c = 0 draws the τ = 1/2 curve of Ex 2.11
    // (the default list's selected τ), c = 1 has zero tangents (each segment straight).
    void cardinalIsCatmullRomWithTauFromC()
    {
        CatmullRomTab tab;
        QVERIFY(tab.settings().taus[1] == frac(1, 2));
        const auto catmullRom = tab.scene().curves[1].bezier;
        tab.setFamily(CurveFamily::Cardinal);
        const auto& cardinal = tab.scene().family.bezier;
        QCOMPARE(cardinal.size(), catmullRom.size());
        for (std::size_t i = 0; i < cardinal.size(); ++i)
            for (int k = 0; k < 4; ++k)
                QVERIFY(nearPoint(cardinal[i][std::size_t(k)], catmullRom[i][std::size_t(k)], 1e-12));
        tab.familyPanel()->cardinalSlider()->setValue(CatmullRomSettings::kTcbSteps); // c = 1
        QVERIFY(tab.settings().cardinalTension == 1);
        for (const auto& t : tab.scene().family.tangents)
            QVERIFY(nearPoint(t.in, Point{0, 0}) && nearPoint(t.out, Point{0, 0}));
    }

    // Entering Hermite starts from the Catmull-Rom tangents: on Ex 2.11's points (1,1), (3,4),
    // (2,−1), (5,1) with τ = 1/2, at q1 τ(q2 − q0) = ½(1, −2) = (1/2, −1).
    void hermiteStartsFromTheCatmullRomTangents()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::Hermite);
        QCOMPARE(tab.settings().hermiteTangents.size(), std::size_t(4));
        QVERIFY(nearPoint(tab.settings().hermiteTangents[1], Point{0.5, -1}));
        QVERIFY(nearPoint(tab.scene().family.tangents[1].out, Point{0.5, -1}));
        QVERIFY(tab.hermiteHandles()->active());
    }

    // The handle sits at q + m; dragging it by (dx, dy) pixels moves m by the same move in model
    // units, view.toModel(end) − view.toModel(start) (computed here from the view, not the tab).
    void draggingAHermiteHandleMovesTheTangentByTheDrag()
    {
        CatmullRomTab tab;
        tab.resize(1280, 760);
        tab.show();
        QVERIFY(waitExposed(&tab));
        tab.setFamily(CurveFamily::Hermite);
        const Point before = tab.settings().hermiteTangents[2];
        CurveCanvas* canvas = tab.findChild<CurveCanvas*>();
        QVERIFY(canvas);
        const QPoint start = canvas->view().toScreen(tab.hermiteHandles()->handlePosition(2)).toPoint();
        const QPoint end = start + QPoint(37, -23);
        const Point moved = canvas->view().toModel(QPointF(end)) - canvas->view().toModel(QPointF(start));
        const int count = tab.undoStack()->count();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, start);
        QTest::mouseMove(canvas, start + QPoint(10, -5));
        QTest::mouseMove(canvas, end);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, end);
        const Point after = tab.settings().hermiteTangents[2];
        QVERIFY(nearPoint(after, before + moved, 1e-9));
        QVERIFY(tab.pointEditor()->points()[2] == (Point{2, -1})); // the point stayed
        QCOMPARE(tab.undoStack()->count(), count + 1);             // the whole drag: one step
        tab.undoStack()->undo();
        QVERIFY(tab.settings().hermiteTangents[2] == before);
        tab.undoStack()->redo();
        QVERIFY(nearPoint(tab.settings().hermiteTangents[2], before + moved, 1e-9));
    }

    // Alt + arrows move the selected point's tangent by HermiteHandles::kKeyStep (Shift: ×10).
    void altArrowsMoveTheSelectedTangent()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::Hermite);
        tab.pointEditor()->setSelected(1);
        const Point before = tab.settings().hermiteTangents[1];
        CurveCanvas* canvas = tab.findChild<CurveCanvas*>();
        QTest::keyClick(canvas, Qt::Key_Right, Qt::AltModifier);
        QVERIFY(nearPoint(tab.settings().hermiteTangents[1], before + Point{0.1, 0}, 1e-12));
        QTest::keyClick(canvas, Qt::Key_Down, Qt::AltModifier | Qt::ShiftModifier);
        QVERIFY(nearPoint(tab.settings().hermiteTangents[1], before + Point{0.1, -1}, 1e-12));
        QVERIFY(tab.pointEditor()->points()[1] == (Point{3, 4})); // the point itself did not move
    }

    void tcbAndTangentsSavedAndRead()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::Hermite);
        tab.setHermiteTangent(0, Point{0.25, -3});
        tab.setCardinalTension(frac(-3, 20));
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.pointEditor()->setSelected(2);
        tab.setTcb(0, frac(1, 4));
        tab.setTcb(2, frac(-7, 20));
        QVERIFY(tab.settings().tcb[2].tension == frac(1, 4) && tab.settings().tcb[1].tension == 0);
        const QJsonObject saved = tab.saveState();
        CatmullRomTab other;
        QString error;
        QVERIFY2(other.loadState(throughText(saved), &error), qPrintable(error));
        QVERIFY(other.settings() == tab.settings());
        QVERIFY(other.settings().family == CurveFamily::KochanekBartels);
        QVERIFY(other.settings().tcb[2].bias == frac(-7, 20));
        QVERIFY(other.settings().hermiteTangents[0] == (Point{0.25, -3}));
        QVERIFY(other.settings().cardinalTension == frac(-3, 20));
        QCOMPARE(other.saveState(), saved);
        // A T, C or B outside [−1, 1] is refused, the tab unchanged.
        QJsonObject bad = saved;
        bad.insert(QStringLiteral("tcb"),
                   QJsonArray{QJsonArray{QStringLiteral("0"), QStringLiteral("3/2"), QStringLiteral("0")}});
        QVERIFY(!other.loadState(bad, &error));
        QCOMPARE(other.saveState(), saved);
    }

    void tcbSliderDragIsOneUndoStep()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.familyPanel()->allKnotsCheck()->setChecked(true);
        const int count = tab.undoStack()->count();
        for (int v = 1; v <= 8; ++v)
            tab.familyPanel()->tcbSlider(0)->setValue(v);
        QCOMPARE(tab.undoStack()->count(), count + 1);
        QVERIFY(tab.settings().tcb[0].tension == frac(8, 20));
        tab.undoStack()->undo();
        QVERIFY(tab.settings().tcb.empty() || tab.settings().tcb[0].tension == 0);
    }

    // The conventions, worked by hand from each source's formula (conventions_table.h):
    // τ = 1/2 is curveTightness 0, Primer τₚ = 1, d3 tension 0, KB T = 0; τ = 2 is s = t = T =
    // 1 − 4 = −3 and τₚ = 1/4; τ = 0 has no Primer tension.
    void conventionsConvertTheTension()
    {
        const auto half = tensionConventions(frac(1, 2));
        QCOMPARE(half.size(), std::size_t(5));
        QVERIFY(*half[0].value == frac(1, 2));
        QVERIFY(*half[1].value == 0 && *half[2].value == 1 && *half[3].value == 0 && *half[4].value == 0);
        const auto two = tensionConventions(Rational(2));
        QVERIFY(*two[1].value == -3 && *two[2].value == frac(1, 4) && *two[3].value == -3 && *two[4].value == -3);
        QVERIFY(!tensionConventions(Rational(0))[2].value);
        // In the tab: the cardinal c = 1/2 is τ = 1/4, so the Primer's τₚ = 2.
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::Cardinal);
        tab.familyPanel()->cardinalSlider()->setValue(10);
        QVERIFY(tab.conventionsTable()->tau() == frac(1, 4));
        QCOMPARE(tab.conventionsTable()->item(2, 3)->text(), QStringLiteral("2"));
        QCOMPARE(tab.conventionsTable()->item(1, 3)->text(), QStringLiteral("1/2"));
    }

    // The κ(s) plot shows the family's curve instead of the τ curves; TikZ writes its Hermite
    // segments as Bézier segments (Ex 2.11's four points, open: 3 segments) and its tangents.
    void plotAndTikzFollowTheFamily()
    {
        CatmullRomTab tab;
        tab.setCurvaturePlot(true);
        QCOMPARE(tab.blendingPlot()->graphCount(), 3); // τ = 0, 1/2, 2
        tab.setFamily(CurveFamily::KochanekBartels);
        QCustomPlot* plot = tab.blendingPlot();
        QCOMPARE(plot->graphCount(), 1);
        QCOMPARE(plot->graph(0)->name(), curveFamilyName(CurveFamily::KochanekBartels));
        QVERIFY(plot->graph(0)->dataCount() > 0);
        const QString tikz = tab.tikz();
        QVERIFY2(tikz.contains(QStringLiteral("family kochanek-bartels")), qPrintable(tikz));
        QCOMPARE(int(tikz.count(QStringLiteral(".. controls"))), 3); // the τ curves are not written
        QVERIFY(tikz.contains(QStringLiteral("->")) || tikz.contains(QStringLiteral("stealth")) ||
                tikz.contains(QStringLiteral("latex")));
        // The CSV has the family's samples after the τ curves': the first is q0 = (1, 1) at t = 0.
        const QString csv = tab.csv();
        QVERIFY2(csv.contains(QStringLiteral("\nfamily,segment,t,x,y\nkochanek-bartels,1,0,1,1\n")), qPrintable(csv.left(400)));
    }

    // T, C, B follow their points (issue 37): C = 1/2 at q2 alone on five points; deleting q1
    // leaves it on the old q2, now q1; inserting a point between q0 and q1 moves it to q3 and
    // gives the new point (0, 0, 0); each undo restores the values exactly, with the points.
    void tcbFollowsItsPointThroughDeletionAndInsertion()
    {
        CatmullRomTab tab;
        tab.pointEditor()->setPoints({{0, 0}, {1, 2}, {2, 0}, {3, 2}, {4, 0}}, QStringLiteral("five"));
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.pointEditor()->setSelected(2);
        tab.setTcb(1, frac(1, 2));
        const auto continuities = [&tab] {
            std::vector<Rational> c;
            for (std::size_t i = 0; i < tab.pointEditor()->points().size(); ++i)
                c.push_back(tcbAt(tab.settings(), i).continuity);
            return c;
        };
        const Rational h = frac(1, 2);
        const std::vector<Rational> start{0, 0, h, 0, 0};
        QVERIFY(continuities() == start);
        const int count = tab.undoStack()->count();
        tab.pointEditor()->removePoint(1);
        QVERIFY(continuities() == (std::vector<Rational>{0, h, 0, 0}));
        QCOMPARE(tab.undoStack()->count(), count + 1); // the points and their values: one step
        tab.undoStack()->undo();
        QVERIFY(continuities() == start);
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(5));
        tab.undoStack()->redo();
        QVERIFY(continuities() == (std::vector<Rational>{0, h, 0, 0}));
        tab.undoStack()->undo();
        tab.pointEditor()->insertPoint(1, Point{0.5, 1});
        QVERIFY(continuities() == (std::vector<Rational>{0, 0, 0, h, 0, 0}));
        const TcbKnot<Rational> added = tcbAt(tab.settings(), 1);
        QVERIFY(added.tension == 0 && added.continuity == 0 && added.bias == 0);
        tab.undoStack()->undo();
        QVERIFY(continuities() == start);
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(5));
    }

    // The Hermite tangents follow their points too: the tangent set at q2 stays with that point
    // when q1 is deleted; a point inserted between q0 = (0,0) and q1 = (1,2) at (1/2, 1) gets the
    // Catmull-Rom tangent there, τ(q2 − q0) = ½((1,2) − (0,0)) = (1/2, 1) with the new neighbours
    // (τ = 1/2, uniform); undo restores every tangent exactly.
    void hermiteTangentsFollowTheirPoints()
    {
        CatmullRomTab tab;
        tab.pointEditor()->setPoints({{0, 0}, {1, 2}, {2, 0}, {3, 2}, {4, 0}}, QStringLiteral("five"));
        tab.setFamily(CurveFamily::Hermite);
        tab.setHermiteTangent(2, Point{7, -3});
        const std::vector<Point> before = tab.settings().hermiteTangents;
        QCOMPARE(before.size(), std::size_t(5));
        tab.pointEditor()->removePoint(1);
        QVERIFY(tab.settings().hermiteTangents == (std::vector<Point>{before[0], before[2], before[3], before[4]}));
        QVERIFY(nearPoint(tab.scene().family.tangents[1].out, Point{7, -3}));
        tab.undoStack()->undo();
        QVERIFY(tab.settings().hermiteTangents == before);
        tab.pointEditor()->insertPoint(1, Point{0.5, 1});
        const std::vector<Point>& t = tab.settings().hermiteTangents;
        QCOMPARE(t.size(), std::size_t(6));
        QVERIFY(nearPoint(t[1], Point{0.5, 1}));
        QVERIFY(t[0] == before[0] && t[2] == before[1] && t[3] == before[2] && t[4] == before[3] && t[5] == before[4]);
        tab.undoStack()->undo();
        QVERIFY(tab.settings().hermiteTangents == before);
    }

    // The exact panel describes the family's curve, not the τ curves: on the closed
    // triangle with C = 1/2 it lists at q1 the tangents in (1, −1/2) and out (1, 1/2) (worked by
    // hand above, kbContinuityHalfSplitsTheTangents) as exact fractions, and no Catmull-Rom
    // section (Prop 2.3's "Tangents at the knots"); the Bézier control point b₁ of the segment
    // q1 → q2 is q1 + out/3 = (1, 1) + (1/3, 1/6) = (4/3, 7/6) (hermite_segment.h's rule, by hand).
    void exactPanelDescribesTheFamily()
    {
        CatmullRomTab tab;
        QString error;
        QVERIFY2(tab.loadState(closedTriangle(tab), &error), qPrintable(error));
        ExactPanel* panel = tab.findChild<ExactPanel*>();
        QVERIFY(panel);
        QVERIFY(panel->plainText().contains(QStringLiteral("Prop 2.3")));
        tab.setFamily(CurveFamily::KochanekBartels);
        tab.familyPanel()->allKnotsCheck()->setChecked(true);
        tab.familyPanel()->tcbSlider(1)->setValue(10); // C = 1/2
        const QString text = panel->plainText();
        QVERIFY2(text.contains(curveFamilyName(CurveFamily::KochanekBartels)), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("(1, -1/2)")) && text.contains(QStringLiteral("(1, 1/2)")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("(4/3, 7/6)")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("Prop 2.3")), qPrintable(text));
        // Every other family names itself too, and none shows the Catmull-Rom sections.
        for (CurveFamily f : {CurveFamily::Cardinal, CurveFamily::Hermite, CurveFamily::PlaneSpline, CurveFamily::FunctionData}) {
            tab.setFamily(f);
            QVERIFY2(panel->plainText().contains(curveFamilyName(f)), qPrintable(panel->plainText()));
            QVERIFY2(!panel->plainText().contains(QStringLiteral("Prop 2.3")), qPrintable(panel->plainText()));
        }
    }

    void familySavedAndRead()
    {
        for (CurveFamily f : kCurveFamilies) {
            CatmullRomTab tab;
            tab.setFamily(f);
            const QJsonObject saved = tab.saveState();
            QCOMPARE(saved.value(QStringLiteral("family")).toString(), curveFamilyKey(f));
            CatmullRomTab other;
            QString error;
            QVERIFY2(other.loadState(throughText(saved), &error), qPrintable(error));
            QVERIFY(other.settings() == tab.settings());
            QCOMPARE(other.saveState(), saved);
        }
    }
};

GRANOTA_TEST_MAIN(TestGuiCatmullRomFamilies)
#include "test_gui_catmull_rom_families.moc"
