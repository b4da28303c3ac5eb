// Issue 35, part 3: values keep their exact form. A point typed as 1/3 or 0.1, nudged with the
// arrow keys and molded with Alt+arrows shows its exact value in the point table, the exact
// panel and the CSV export — never the binary noise of its double (0.15000000000000002,
// 1.0132244897959184) — and a document keeps it.
//
// The expected values are computed by hand below (Def 2.6 and molding.h's formula), and their
// decimal texts with Python's fractions.Fraction and decimal modules (16 significant digits,
// half up, for the table; 15 for the CSV), not by Granota's code.

#include "gui_timeouts.h"

#include "core/exact/rational.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "ui/decasteljau/decasteljau_tab.h"

#include <QRegularExpression>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

#include "tests/test_main.h"

using granota::ui::DeCasteljauTab;
using granota::ui::displayText;

namespace {

QStringList column(QTableWidget* table, int c)
{
    QStringList texts;
    for (int r = 0; r < table->rowCount(); ++r)
        texts << table->item(r, c)->text();
    return texts;
}

/// The texts as the table shows them in the interface language ("0,11" in Catalan).
QStringList shown(const QStringList& cTexts)
{
    QStringList out;
    for (const QString& s : cTexts)
        out << displayText(s.toStdString());
    return out;
}

/// Binary noise: a run of six 0s or 9s after the decimal sign, or a number of 17 significant
/// digits. A number is digits with at most one decimal sign (a CSV's commas: replace them first).
QString noiseIn(const QString& text)
{
    static const QRegularExpression run(QStringLiteral("[.,][0-9]*?(000000|999999)"));
    static const QRegularExpression number(QStringLiteral("[0-9]+(?:[.,][0-9]+)?"));
    if (const auto m = run.match(text); m.hasMatch())
        return m.captured(0);
    for (auto it = number.globalMatch(text); it.hasNext();) {
        const QString n = it.next().captured(0);
        QString digits = n;
        digits.remove(QLatin1Char('.')).remove(QLatin1Char(','));
        while (digits.startsWith(QLatin1Char('0')))
            digits.remove(0, 1);
        if (digits.size() >= 17)
            return n;
    }
    return QString();
}

} // namespace

class TestGuiExactValues : public QObject {
    Q_OBJECT
private slots:
    void typedNudgedAndMoldedValuesStayExact()
    {
        DeCasteljauTab tab; // P0 (0, 0), P1 (1, 2), P2 (3, 2), P3 (4, 0), t = 1/2
        tab.resize(1280, 760);
        tab.show();
        QVERIFY(waitExposed(&tab));
        granota::ui::PointEditor* editor = tab.pointEditor();
        QTableWidget* table = tab.pointTable();
        // Snapping to a grid of 0.01: one arrow key moves a coordinate by 1/100, whatever the zoom.
        editor->setGridStep(0.01);
        editor->setSnapEnabled(true);

        // Typed: P1.y = 1/3, P2.x = 0.1.
        table->item(1, 1)->setText(QStringLiteral("1/3"));
        table->item(2, 0)->setText(QStringLiteral("0.1"));
        QCOMPARE(column(table, 0), shown({"0", "1", "0.1", "4"}));
        QCOMPARE(column(table, 1), shown({"0", "1/3", "2", "0"})); // a repeating value: fractions

        // Nudged five times: P2.x from 1/10 to 15/100 by steps of 1/100 (in doubles,
        // 0.1 + 0.01 + … + 0.01 is 0.15000000000000002).
        const double sum = 0.1 + 0.01 + 0.01 + 0.01 + 0.01 + 0.01;
        QVERIFY(sum != 0.15);
        editor->setSelected(2);
        for (int i = 0; i < 5; ++i)
            QTest::keyClick(tab.canvas(), Qt::Key_Right);
        QCOMPARE(column(table, 0), shown({"0", "1", "0.15", "4"}));
        QCOMPARE(column(table, 1), shown({"0", "1/3", "2", "0"}));
        // The exact panel at t = 1/2: c(1/2) = (P0 + 3 P1 + 3 P2 + P3)/8 (Def 2.6)
        // = ((3 + 45/100 + 4)/8, (1 + 6)/8) = (149/160, 7/8).
        const QString panel = tab.exactPanel()->plainText();
        QVERIFY2(panel.contains(QStringLiteral("(149/160, 7/8)")), qPrintable(panel));
        QVERIFY2(tab.csv().startsWith(QStringLiteral("i,x,y\n0,0,0\n1,1,0.333333333333333\n2,0.15,2\n3,4,0\n")),
                 qPrintable(tab.csv()));

        // Molded at t = 1/3 by one step right and one up (Alt+arrows): c(1/3) moves by
        // (1/100, 1/100) and P_i by B_i(1/3)/Σ_j B_j(1/3)² times that (molding.h). With
        // B(1/3) = (8, 12, 6, 1)/27 and Σ B_j² = 245/729, the factors are (216, 324, 162, 27)/245:
        //   P0 = (54/6125, 54/6125)            P1 = (6206/6125, 6368/18375)
        //   P2 = (3837/24500, 24581/12250)     P3 = (98027/24500, 27/24500)
        tab.setT(1.0 / 3);
        QTest::keyClick(tab.canvas(), Qt::Key_Right, Qt::AltModifier);
        QTest::keyClick(tab.canvas(), Qt::Key_Up, Qt::AltModifier);
        // Denominators beyond 1000: decimals, each to 16 significant digits (Python:
        // Decimal(54)/Decimal(6125) rounded is 0.008816326530612245; the double's own digits end in …244).
        const QStringList xs = {"0.008816326530612245", "1.013224489795918", "0.1566122448979592", "4.001102040816327"};
        const QStringList ys = {"0.008816326530612245", "0.3465578231292517", "2.006612244897959", "0.001102040816326531"};
        QCOMPARE(column(table, 0), shown(xs));
        QCOMPARE(column(table, 1), shown(ys));
        for (int c = 0; c < 2; ++c)
            for (const QString& cell : column(table, c))
                QVERIFY2(noiseIn(cell).isEmpty(), qPrintable(cell));
        // c(1/3) was ((12 + 6·15/100 + 4)/27, (12/3 + 12)/27) = (169/270, 16/27); now plus 1/100 each:
        // (1717/2700, 1627/2700) = (0.6359259…, 0.6025925…), six digits in the panel.
        const QString molded = tab.exactPanel()->plainText();
        QVERIFY2(molded.contains(displayText("(0.635926, 0.602593)")), qPrintable(molded));
        QVERIFY2(molded.contains(QStringLiteral("54/6125")), qPrintable(molded)); // the exact polynomials
        QVERIFY2(noiseIn(molded).isEmpty(), qPrintable(noiseIn(molded)));
        // The CSV: 15 significant digits of each exact value (Python: '%.15g' of the fraction).
        const QString csv = tab.csv();
        QVERIFY2(csv.startsWith(QStringLiteral("i,x,y\n"
                                               "0,0.00881632653061224,0.00881632653061224\n"
                                               "1,1.01322448979592,0.346557823129252\n"
                                               "2,0.156612244897959,2.00661224489796\n"
                                               "3,4.00110204081633,0.00110204081632653\n")),
                 qPrintable(csv));
        QVERIFY2(noiseIn(QString(csv).replace(QLatin1Char(','), QLatin1Char(' '))).isEmpty(), qPrintable(csv));

        // A document keeps the exact values: reopened, the table reads the same.
        DeCasteljauTab other;
        QString error;
        QVERIFY2(other.loadState(tab.saveState(), &error), qPrintable(error));
        QCOMPARE(column(other.pointTable(), 0), shown(xs));
        QCOMPARE(column(other.pointTable(), 1), shown(ys));
        // Undone, the nudged and typed values are back as they were typed.
        tab.undoStack()->undo(); // the molds (one step)
        QCOMPARE(column(table, 0), shown({"0", "1", "0.15", "4"}));
        QCOMPARE(column(table, 1), shown({"0", "1/3", "2", "0"}));
    }
};

GRANOTA_TEST_MAIN(TestGuiExactValues)
#include "test_gui_exact_values.moc"
