// The Bernstein tab (docs/tabs.md): Ex 2.4's polynomials, the weights of Def 2.6 applied to
// the De Casteljau tab's points, the shared t in both directions, Ex 2.5/2.6 expanded as
// the thesis prints them, the property checks, and the all-degrees plot.
#include "core/curves/bezier/bernstein.h"
#include "core/io/worked_examples.h"
#include "ui/decasteljau/decasteljau_parameter_control.h"
#include "ui/bernstein/bernstein_tab.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "gui_timeouts.h"

#include <QCheckBox>
#include <QImage>
#include <QPainter>
#include <QJsonObject>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include "tests/test_main.h"
#include <QUndoStack>
#include <qcustomplot.h>

#include <cmath>

using granota::ui::BernsteinTab;
using granota::ui::DeCasteljauTab;

namespace {

/// The two tabs, as the main window builds them.
struct Tabs {
    DeCasteljauTab deCasteljau;
    BernsteinTab bernstein{deCasteljau.curveModel()};
};

const granota::WorkedExample& example(const char* id)
{
    const granota::WorkedExample* ex = granota::findWorkedExample(id);
    Q_ASSERT(ex);
    return *ex;
}

} // namespace

class TestGuiBernstein : public QObject {
    Q_OBJECT

private slots:
    // Ex 2.4: every polynomial the thesis prints for n ≤ 5.
    void example24()
    {
        Tabs tabs;
        QVERIFY(tabs.bernstein.loadExample(example("2.4")));
        QCOMPARE(tabs.bernstein.degree(), 5);
        QVERIFY(tabs.bernstein.allDegrees());
        const QString text = tabs.bernstein.exactPanel()->plainText();
        const QStringList printed = {"B0^0(t) = 1",
                                     "B0^1(t) = 1 - t",
                                     "B1^1(t) = t",
                                     "B0^2(t) = 1 - 2t + t^2",
                                     "B1^2(t) = 2t - 2t^2",
                                     "B2^2(t) = t^2",
                                     "B0^3(t) = 1 - 3t + 3t^2 - t^3",
                                     "B1^3(t) = 3t - 6t^2 + 3t^3",
                                     "B2^3(t) = 3t^2 - 3t^3",
                                     "B3^3(t) = t^3",
                                     "B0^4(t) = 1 - 4t + 6t^2 - 4t^3 + t^4",
                                     "B1^4(t) = 4t - 12t^2 + 12t^3 - 4t^4",
                                     "B2^4(t) = 6t^2 - 12t^3 + 6t^4",
                                     "B3^4(t) = 4t^3 - 4t^4",
                                     "B4^4(t) = t^4",
                                     "B0^5(t) = 1 - 5t + 10t^2 - 10t^3 + 5t^4 - t^5",
                                     "B1^5(t) = 5t - 20t^2 + 30t^3 - 20t^4 + 5t^5",
                                     "B2^5(t) = 10t^2 - 30t^3 + 30t^4 - 10t^5",
                                     "B3^5(t) = 10t^3 - 20t^4 + 10t^5",
                                     "B4^5(t) = 5t^4 - 5t^5",
                                     "B5^5(t) = t^5"};
        for (const QString& line : printed)
            QVERIFY2(text.contains(line + QLatin1Char('\n')), qPrintable(line));
        QVERIFY(!text.contains(QStringLiteral("B0^6(t)")));
        // All degrees 0…5 plotted: 1 + 2 + … + 6 graphs.
        QCOMPARE(tabs.bernstein.basisPlot()->graphCount(), 21);
        // The graphs are the polynomials: B_2^5 at t = 0.3 (graph index 15 + 2).
        const QCPGraph* g = tabs.bernstein.basisPlot()->graph(17);
        const double t = g->data()->at(60)->key, value = g->data()->at(60)->value;
        QVERIFY(std::fabs(t - 0.3) < 1e-12);
        QVERIFY(std::fabs(value - 10 * 0.09 * std::pow(0.7, 3)) < 1e-12);
    }

    void allDegreesGraphCount_data()
    {
        QTest::addColumn<int>("n");
        for (int n : {0, 1, 4, 12, 30})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void allDegreesGraphCount()
    {
        QFETCH(int, n);
        Tabs tabs;
        tabs.bernstein.setDegree(n);
        tabs.bernstein.setAllDegrees(false);
        QCOMPARE(tabs.bernstein.basisPlot()->graphCount(), n + 1);
        tabs.bernstein.setAllDegrees(true);
        QCOMPARE(tabs.bernstein.basisPlot()->graphCount(), (n + 1) * (n + 2) / 2);
        // The spin box follows and bounds the degree.
        QCOMPARE(tabs.bernstein.findChild<QSpinBox*>()->value(), n);
        tabs.bernstein.setDegree(99);
        QCOMPARE(tabs.bernstein.degree(), BernsteinTab::kMaxDegree);
    }

    // The bars are B_i^n(t) for the De Casteljau tab's n + 1 points, and they sum to 1.
    void weightsSumToOne()
    {
        Tabs tabs;
        QVERIFY(tabs.deCasteljau.loadExample(example("2.2")));
        for (double t : {0.0, 0.1, 1.0 / 3.0, 0.5, 0.77, 1.0}) {
            tabs.deCasteljau.setT(t);
            const auto data = tabs.bernstein.weightBars()->data();
            QCOMPARE(data->size(), 5);
            double sum = 0.0;
            for (int i = 0; i < data->size(); ++i) {
                QCOMPARE(data->at(i)->key, double(i));
                QVERIFY(std::fabs(data->at(i)->value - granota::bernstein(i, 4, t)) < 1e-15);
                sum += data->at(i)->value;
            }
            QVERIFY2(std::fabs(sum - 1.0) < 1e-12, qPrintable(QString::number(sum, 'g', 17)));
        }
        // c(t) from Def 2.6 and from De Casteljau, side by side: at t = 1 both are P4 = (-7, -2).
        QVERIFY(tabs.bernstein.curvePointText().contains(QStringLiteral("(-7, -2)")));
        // A new point changes the number of bars.
        tabs.deCasteljau.pointEditor()->insertPoint(5, {1, 1});
        QCOMPARE(tabs.bernstein.weightBars()->data()->size(), 6);
    }

    // One t for both tabs: each moves the other.
    void sharedParameter()
    {
        Tabs tabs;
        tabs.deCasteljau.setT(0.2);
        QCOMPARE(tabs.bernstein.t(), 0.2);
        QCOMPARE(tabs.bernstein.markerT(), 0.2);
        QCOMPARE(tabs.bernstein.parameterControl()->slider()->value(), 200);

        // The Bernstein tab's own slider drives the De Casteljau tab.
        tabs.bernstein.parameterControl()->slider()->setValue(730);
        QCOMPARE(tabs.deCasteljau.t(), 0.73);
        QCOMPARE(tabs.deCasteljau.parameterControl()->slider()->value(), 730);
        QCOMPARE(tabs.bernstein.markerT(), 0.73);

        // And so does a click on the basis plot.
        tabs.bernstein.resize(1280, 760);
        tabs.bernstein.show();
        QVERIFY(waitExposed(&tabs.bernstein));
        QCustomPlot* plot = tabs.bernstein.basisPlot();
        const int x = static_cast<int>(plot->xAxis->coordToPixel(0.25));
        const int y = static_cast<int>(plot->yAxis->coordToPixel(0.5));
        QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
        QVERIFY(std::fabs(tabs.deCasteljau.t() - 0.25) < 0.01);
        QCOMPARE(tabs.bernstein.markerT(), tabs.deCasteljau.t());
    }

    // The hover readout shows B_i^n at the t under the mouse.
    void hoverReadout()
    {
        Tabs tabs;
        tabs.bernstein.setAllDegrees(false);
        tabs.bernstein.setDegree(2);
        const QString r = tabs.bernstein.readout(0.5);
        QVERIFY(r.contains(QStringLiteral("t = 0.500")));
        QVERIFY(r.contains(QStringLiteral("B₀² = 0.2500")));
        QVERIFY(r.contains(QStringLiteral("B₁² = 0.5000")));
        QVERIFY(!r.contains(QStringLiteral("B₃")));
    }

    // Issue 34, item 11: at n = 30 (all degrees on) the readout named B₀…B₁₁, all 0.0000 at
    // t = 1/2. It lists the polynomials that matter: consecutive i around the peak i ≈ n t, each
    // of them at least as large as any left out, in order of i, with "…" for those left out.
    void hoverReadoutListsThePolynomialsThatMatter_data()
    {
        QTest::addColumn<double>("t");
        QTest::newRow("t = 1/2") << 0.5;
        QTest::newRow("t = 0.1") << 0.1;
        QTest::newRow("t = 0.9") << 0.9;
        QTest::newRow("t = 0") << 0.0;
    }
    void hoverReadoutListsThePolynomialsThatMatter()
    {
        QFETCH(double, t);
        constexpr int n = 30;
        Tabs tabs;
        tabs.bernstein.setDegree(n);
        tabs.bernstein.setAllDegrees(true);
        const QStringList lines = tabs.bernstein.readout(t).split(QLatin1Char('\n'));
        // Which B_i³⁰ are listed: the subscript digits after "B".
        const QString subscripts = QStringLiteral("₀₁₂₃₄₅₆₇₈₉");
        QList<int> listed;
        for (const QString& line : lines) {
            if (!line.startsWith(QLatin1Char('B')))
                continue;
            int i = 0;
            for (int k = 1; k < line.size() && subscripts.contains(line[k]); ++k)
                i = 10 * i + static_cast<int>(subscripts.indexOf(line[k]));
            listed << i;
        }
        QVERIFY2(listed.size() >= 10, qPrintable(lines.join(QLatin1Char('|'))));
        for (int k = 1; k < listed.size(); ++k)
            QCOMPARE(listed[k], listed[k - 1] + 1); // consecutive, in order
        // Independently: B_i^n(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ (Def 2.5) by the closed form.
        const auto value = [t](int i) {
            return std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0)) * std::pow(t, i) *
                   std::pow(1 - t, n - i);
        };
        const int peak = static_cast<int>(std::lround(n * t));
        QVERIFY2(listed.contains(peak), qPrintable(lines.join(QLatin1Char('|'))));
        double smallestListed = 1, largestLeftOut = 0;
        for (int i = 0; i <= n; ++i) {
            if (listed.contains(i))
                smallestListed = std::min(smallestListed, value(i));
            else
                largestLeftOut = std::max(largestLeftOut, value(i));
        }
        QVERIFY(smallestListed >= largestLeftOut * (1 - 1e-12));
        QCOMPARE(lines.first(), QStringLiteral("t = %1").arg(QString::number(t, 'f', 3)));
        QVERIFY(lines.contains(QStringLiteral("…"))); // some are left out, and it says so
    }

    // The readout's values are those of the t it names (t to three decimals), and it leaves
    // the plot when t changes.
    void hoverReadoutMatchesItsT()
    {
        Tabs tabs;
        tabs.bernstein.setAllDegrees(false);
        tabs.bernstein.setDegree(4);
        const QString r = tabs.bernstein.readout(0.29963);
        QVERIFY2(r.contains(QStringLiteral("t = 0.300")), qPrintable(r));
        QVERIFY2(r.contains(QStringLiteral("B₀⁴ = 0.2401")), qPrintable(r)); // 0.7⁴
        QVERIFY2(r.contains(QStringLiteral("B₄⁴ = 0.0081")), qPrintable(r)); // 0.3⁴

        tabs.bernstein.resize(900, 700);
        tabs.bernstein.show();
        QVERIFY(waitExposed(&tabs.bernstein));
        QCustomPlot* plot = tabs.bernstein.basisPlot();
        const QPoint at(static_cast<int>(plot->xAxis->coordToPixel(0.6)), static_cast<int>(plot->yAxis->coordToPixel(0.5)));
        QTest::mouseMove(plot, at);
        QTRY_VERIFY_WITH_TIMEOUT(tabs.bernstein.readoutShown(), kEventWaitMs);
        tabs.bernstein.setT(0.1);
        QVERIFY(!tabs.bernstein.readoutShown());
    }

    // Ex 2.5 and Ex 2.6: the points go to the De Casteljau tab (undoable there) and the
    // curve comes out in powers of t exactly as printed.
    void examples25and26_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<QStringList>("printed");
        QTest::newRow("Ex 2.5") << QStringLiteral("2.5")
                                << QStringList{"(2 - 8t + 12t^2 - 8t^3 + 2t^4, 3 - 12t + 18t^2 - 12t^3 + 3t^4)",
                                               "(-4t + 12t^2 - 12t^3 + 4t^4, 32t - 96t^2 + 96t^3 - 32t^4)",
                                               "(-30t^2 + 60t^3 - 30t^4, -18t^2 + 36t^3 - 18t^4)",
                                               "(12t^3 - 12t^4, 0)",
                                               "(-7t^4, -2t^4)",
                                               "α(t) = (2 - 12t - 6t^2 + 52t^3 - 43t^4, 3 + 20t - 96t^2 + 120t^3 - 49t^4)"};
        QTest::newRow("Ex 2.6") << QStringLiteral("2.6")
                                << QStringList{"(1 - 4t + 6t^2 - 4t^3 + t^4, 7 - 28t + 42t^2 - 28t^3 + 7t^4)",
                                               "(0, -12t + 36t^2 - 36t^3 + 12t^4)",
                                               "(-24t^2 + 48t^3 - 24t^4, -12t^2 + 24t^3 - 12t^4)",
                                               "(32t^3 - 32t^4, 0)",
                                               "(t^4, 7t^4)",
                                               "α(t) = (1 - 4t - 18t^2 + 76t^3 - 54t^4, 7 - 40t + 66t^2 - 40t^3 + 14t^4)"};
    }
    void examples25and26()
    {
        QFETCH(QString, id);
        QFETCH(QStringList, printed);
        Tabs tabs;
        tabs.bernstein.setAllDegrees(true);
        const int before = tabs.deCasteljau.undoStack()->count();
        QVERIFY(tabs.bernstein.loadExample(example(qPrintable(id))));
        QCOMPARE(tabs.deCasteljau.pointEditor()->points().size(), std::size_t(5));
        // One step on the history the two tabs share (the points, t, the degree, docs/tabs.md).
        QCOMPARE(tabs.bernstein.undoStack(), tabs.deCasteljau.undoStack());
        QCOMPARE(tabs.deCasteljau.undoStack()->count(), before + 1);
        QCOMPARE(tabs.bernstein.degree(), 4);
        QVERIFY(!tabs.bernstein.allDegrees());
        const QString text = tabs.bernstein.exactPanel()->plainText();
        for (const QString& p : printed)
            QVERIFY2(text.contains(p), qPrintable(p + QStringLiteral("\n---\n") + text));
        // The same curve the De Casteljau tab shows.
        QVERIFY(tabs.deCasteljau.exactPanel()->plainText().contains(printed.last().mid(7)));
        tabs.deCasteljau.undoStack()->undo();
        QVERIFY(!tabs.bernstein.exactPanel()->plainText().contains(printed.last()));
        QVERIFY(tabs.bernstein.allDegrees()); // the degree and the view came back with the points
    }

    // Partition of unity, symmetry and Lemma 2.1 at the current n and t: ✓, tiny residuals.
    void propertyChecks_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("t");
        QTest::newRow("n=5 t=0.5") << 5 << 0.5;
        QTest::newRow("n=1 t=0") << 1 << 0.0;
        QTest::newRow("n=17 t=0.31") << 17 << 0.31;
        QTest::newRow("n=30 t=0.999") << 30 << 0.999;
    }
    void propertyChecks()
    {
        QFETCH(int, n);
        QFETCH(double, t);
        Tabs tabs;
        tabs.bernstein.setDegree(n);
        tabs.deCasteljau.setT(t);
        const auto& c = tabs.bernstein.checks();
        QVERIFY(c.partitionOfUnity.residual < 1e-12);
        QVERIFY(c.symmetry.residual < 1e-12);
        QVERIFY(c.recursion.residual < 1e-12);
        QVERIFY(c.partitionOfUnity.exact && c.symmetry.exact && c.recursion.exact);
        const QStringList lines = tabs.bernstein.checkTexts();
        QCOMPARE(lines.size(), 3);
        for (const QString& line : lines) {
            QVERIFY2(line.contains(QStringLiteral("✓")), qPrintable(line));
            QVERIFY(!line.contains(QStringLiteral("✗")));
        }
        QVERIFY(lines[0].contains(QStringLiteral("Partition of unity")));
        QVERIFY(lines[2].contains(QStringLiteral("Lemma 2.1")));
        QVERIFY(lines[0].contains(QStringLiteral("<sup>%1</sup>").arg(n))); // the degree shown
    }

    void recursionNeedsDegreeOne()
    {
        Tabs tabs;
        tabs.bernstein.setDegree(0);
        QVERIFY(!tabs.bernstein.checks().recursion.applies);
        QVERIFY(tabs.bernstein.checkTexts()[2].contains(QStringLiteral("n ≥ 1")));
    }

    void saveLoadAndRefuse()
    {
        Tabs tabs;
        tabs.bernstein.setDegree(7);
        tabs.bernstein.setAllDegrees(true);
        tabs.deCasteljau.setT(0.125);
        const QJsonObject saved = tabs.bernstein.saveState();
        QCOMPARE(saved.value("degree").toInt(), 7);
        QCOMPARE(saved.value("mode").toString(), QStringLiteral("all"));
        QCOMPARE(saved.value("t").toDouble(), 0.125);

        Tabs other;
        QString error;
        QVERIFY(other.bernstein.loadState(saved, &error));
        QCOMPARE(other.bernstein.saveState(), saved);
        QCOMPARE(other.deCasteljau.t(), 0.125);
        QCOMPARE(other.bernstein.basisPlot()->graphCount(), 36);

        for (const QJsonObject& bad : {QJsonObject{{"degree", 31}}, QJsonObject{{"degree", 2.5}}, QJsonObject{{"mode", "some"}},
                                       QJsonObject{{"t", -0.1}}, QJsonObject{{"degree", "3"}}}) {
            QVERIFY(!other.bernstein.loadState(bad, &error));
            QVERIFY(!error.isEmpty());
            QCOMPARE(other.bernstein.saveState(), saved);
        }
    }

    // Fig 2.4 one plot at a time: "mode": "single" with each degree Ex 2.4 prints (0 … 5) draws
    // that degree's n + 1 polynomials and nothing else — with "t_marker": false not even the line
    // at t — on the plot (what File ▸ Export draws), in the TikZ and in the CSV. The values are
    // C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ computed here (Def 2.5).
    void oneDegreeAloneForFigure24()
    {
        Tabs tabs;
        for (int n = 0; n <= 5; ++n) {
            QString error;
            QVERIFY2(tabs.bernstein.loadState(QJsonObject{{"degree", n}, {"mode", "single"}, {"t_marker", false}}, &error),
                     qPrintable(error));
            QCustomPlot* plot = tabs.bernstein.basisPlot();
            QCOMPARE(plot->graphCount(), n + 1);
            for (int i = 0; i <= n; ++i) {
                const auto data = plot->graph(i)->data();
                double binomial = 1;
                for (int j = 1; j <= i; ++j)
                    binomial = binomial * (n - i + j) / j;
                for (int k = 0; k < data->size(); k += 20) {
                    const double t = data->at(k)->key;
                    QVERIFY(std::fabs(data->at(k)->value - binomial * std::pow(t, i) * std::pow(1 - t, n - i)) < 1e-12);
                }
            }
            // Nothing but the graphs: no marker, no readout among the plot's items.
            for (int k = 0; k < plot->itemCount(); ++k)
                QVERIFY(!plot->item(k)->visible());
            const QString tex = tabs.bernstein.tikz();
            QCOMPARE(tex.count(QStringLiteral("\\draw")), 2 + n + 1); // the axes and the n + 1 polynomials
            QVERIFY(!tex.contains(QStringLiteral("dashed")));
            QCOMPARE(tabs.bernstein.csv().section(QLatin1Char('\n'), 0, 0).count(QLatin1Char(',')), n + 1);
        }
        // The marker back: one line more, in the document and undoable through its check box.
        QCheckBox* marker = nullptr;
        for (QCheckBox* box : tabs.bernstein.findChildren<QCheckBox*>())
            if (box->text() == QStringLiteral("Mark t"))
                marker = box;
        QVERIFY(marker && !marker->isChecked());
        marker->click();
        QVERIFY(tabs.bernstein.tMarkerVisible());
        QCOMPARE(tabs.bernstein.saveState().value(QStringLiteral("t_marker")).toBool(false), true);
        QCOMPARE(tabs.bernstein.tikz().count(QStringLiteral("dashed")), 1);
        tabs.bernstein.undoStack()->undo();
        QVERIFY(!tabs.bernstein.tMarkerVisible() && !marker->isChecked());
        QString error;
        QVERIFY(tabs.bernstein.loadState(QJsonObject{{"degree", 2}}, &error)); // older documents: the marker shown
        QVERIFY(tabs.bernstein.tMarkerVisible());
        QVERIFY(!tabs.bernstein.loadState(QJsonObject{{"t_marker", 1}}, &error));
    }

    // The readout that follows the mouse is no part of the picture: an export made while it is
    // shown is the export made without it, and the readout is still there afterwards.
    void exportLeavesTheHoverReadoutOut()
    {
        Tabs tabs;
        tabs.bernstein.resize(900, 700);
        tabs.bernstein.show();
        QVERIFY(waitExposed(&tabs.bernstein));
        const auto render = [&tabs] {
            granota::ui::Drawable* view = tabs.bernstein.exportView();
            QImage image(view->exportSize().toSize(), QImage::Format_ARGB32);
            QPainter painter(&image);
            view->render(painter, QRectF(image.rect()));
            return image;
        };
        const QImage without = render();
        QCustomPlot* plot = tabs.bernstein.basisPlot();
        QTest::mouseMove(plot, QPoint(static_cast<int>(plot->xAxis->coordToPixel(0.3)),
                                      static_cast<int>(plot->yAxis->coordToPixel(0.5))));
        QTRY_VERIFY_WITH_TIMEOUT(tabs.bernstein.readoutShown(), kEventWaitMs);
        QCOMPARE(render(), without);
        QVERIFY(tabs.bernstein.readoutShown());
    }

    void csvAndTikz()
    {
        Tabs tabs;
        tabs.bernstein.setDegree(2);
        const QStringList lines = tabs.bernstein.csv().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines[0], QStringLiteral("t,B_0^2,B_1^2,B_2^2"));
        QCOMPARE(lines.size(), 102);
        QCOMPARE(lines[51], QStringLiteral("0.5,0.25,0.5,0.25"));
        const QString tex = tabs.bernstein.tikz();
        QCOMPARE(tex.count(QStringLiteral("\\draw")), 2 + 3 + 1); // axes, three curves, the t line
        QVERIFY(tabs.bernstein.exportView()->exportSize().width() > 0);
    }
};

GRANOTA_TEST_MAIN(TestGuiBernstein)
#include "test_gui_bernstein.moc"
