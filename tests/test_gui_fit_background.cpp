// Long fits of the Fitting tab run on a worker thread (ui/fit/background_fit.h). The issue's
// document, 2 000 points at degree 100 with 1 000 parameter corrections, took 87 s to open
// on the GUI thread: now it opens at once with the tab saying it is fitting, Cancel stops it
// with the best fit so far, the finished fit equals the core's fitBezier of the same data
// (computed here on this thread), an export waits for the finished fit, and a newer edit
// supersedes a fit still running (its result is never shown). Nothing here is timed: the
// waits are QTRY_* bounded by kEventWaitMs (gui_timeouts.h).
#include "core/curves/fitting/least_squares_fit.h"
#include "ui/common/point_editor.h"
#include "ui/fit/fit_tab.h"
#include "gui_timeouts.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QThreadPool>
#include <QUndoStack>
#include "tests/test_main.h"

#include <cmath>

using granota::ui::FitSettings;
using granota::ui::FitTab;
using namespace granota;

namespace {

/// `count` samples of a wavy curve with a little deterministic noise: at degree 100 the
/// parameter correction goes on lowering the error for hundreds of corrections.
std::vector<Point> wavySamples(int count)
{
    std::vector<Point> q;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / (count - 1);
        q.emplace_back(std::cos(5 * s) + s + 0.01 * std::sin(13.0 * i), std::sin(4 * s) - s * s + 0.01 * std::cos(37.0 * i));
    }
    return q;
}

/// The Fitting tab's part of a .granota document (docs/file-formats.md).
QJsonObject documentPart(const std::vector<Point>& q, int degree, int iterations)
{
    QJsonArray points;
    for (const Point& p : q)
        points.append(QJsonArray{p.x, p.y});
    return {{QStringLiteral("points"), points},
            {QStringLiteral("degree"), degree},
            {QStringLiteral("correctParameters"), true},
            {QStringLiteral("iterations"), iterations}};
}

FitOptions correcting(int degree, int iterations)
{
    FitOptions o;
    o.degree = degree;
    o.correctParameters = true;
    o.maxCorrections = iterations;
    return o;
}

constexpr int kPoints = 2000, kDegree = 100;

} // namespace

class TestGuiFitBackground : public QObject {
    Q_OBJECT
private slots:
    void theIssuesDocumentIsLong()
    {
        // The premise: this document is far beyond what the tab fits on the GUI thread.
        QVERIFY(fitWork(kPoints, kDegree, true, 1000) > 100 * FitTab::kBackgroundFitWork);
        // and a small one is not (it is fitted at once, as before).
        QVERIFY(fitWork(200, 3, true, 10) < FitTab::kBackgroundFitWork);
    }

    // Opening returns while the fit runs; Cancel stops the correction and shows the best fit
    // found so far, saying so; the user's points and settings are kept.
    void openingReturnsAndCancelStops()
    {
        const std::vector<Point> q = wavySamples(kPoints);
        FitTab tab;
        QString error;
        QVERIFY2(tab.loadState(documentPart(q, kDegree, 1000), &error), qPrintable(error));
        QVERIFY(tab.isFitting());
        QVERIFY(!tab.currentFit());
        QVERIFY2(tab.readoutText().contains(QStringLiteral("Fitting in the background")), qPrintable(tab.readoutText()));
        QVERIFY(tab.cancelButton()->isVisibleTo(&tab));
        QVERIFY(tab.cancelButton()->isEnabled());
        QCOMPARE(tab.pointEditor()->points(), q);
        // At least one correction made (the progress bar follows them), then Cancel.
        QTRY_VERIFY_WITH_TIMEOUT(tab.fitProgress()->value() >= 1, kEventWaitMs);
        tab.cancelButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!tab.isFitting(), kEventWaitMs);
        const FitResult* fit = tab.currentFit();
        QVERIFY(fit);
        QVERIFY(fit->cancelled);
        QVERIFY(fit->corrections >= 1 && fit->corrections < 1000);
        QVERIFY2(tab.warningText().contains(QStringLiteral("Cancelled after")), qPrintable(tab.warningText()));
        QVERIFY(!tab.cancelButton()->isVisibleTo(&tab));
        QCOMPARE(tab.pointEditor()->points(), q);
        QCOMPARE(tab.settings().iterations, 1000);
        QCOMPARE(tab.settings().degree, kDegree);
    }

    // The fit made in the background is the core's, bit for bit; CSV (an export) asked while
    // it runs waits for it.
    void finishedFitEqualsTheCore()
    {
        const std::vector<Point> q = wavySamples(kPoints);
        const auto expected = fitBezier(q, correcting(kDegree, 2));
        QVERIFY(expected.ok());
        QVERIFY(fitWork(q.size(), kDegree, true, 2) > FitTab::kBackgroundFitWork);
        FitTab tab;
        QString error;
        QVERIFY2(tab.loadState(documentPart(q, kDegree, 2), &error), qPrintable(error));
        QVERIFY(tab.isFitting());
        QSignalSpy shown(&tab, &FitTab::backgroundFitShown);
        const QString csv = tab.csv();
        QVERIFY(!tab.isFitting());
        QCOMPARE(shown.count(), 1);
        QVERIFY(csv.contains(QStringLiteral("\nj,P_x,P_y\n")));
        QCOMPARE(csv.count(QLatin1Char('\n')), kPoints + 1 + 2 + kDegree + 1);
        const FitResult* fit = tab.currentFit();
        QVERIFY(fit);
        QVERIFY(!fit->cancelled);
        QCOMPARE(fit->corrections, expected->corrections);
        QCOMPARE(fit->controlPoints, expected->controlPoints);
        QCOMPARE(fit->params, expected->params);
        QCOMPARE(fit->sse, expected->sse);
        QVERIFY(tab.readoutText().contains(QStringLiteral("Squared error")));
    }

    // Edits while a fit runs: each supersedes the one before, and only the last is shown
    // (the superseded ones stop at their next check and are dropped).
    void aNewerEditSupersedes()
    {
        std::vector<Point> q = wavySamples(kPoints);
        FitTab tab;
        QString error;
        QVERIFY2(tab.loadState(documentPart(q, kDegree, 1000), &error), qPrintable(error));
        QVERIFY(tab.isFitting());
        QSignalSpy shown(&tab, &FitTab::backgroundFitShown);
        FitSettings s = tab.settings();
        s.iterations = 2;
        tab.changeSettings(s, QStringLiteral("two corrections"));
        QVERIFY(tab.isFitting());
        QVERIFY(!tab.currentFit());
        const Point moved(0.5, 0.25);
        tab.pointEditor()->movePoint(7, moved); // a drag's step
        q[7] = moved;
        QVERIFY(tab.isFitting());
        QTRY_VERIFY_WITH_TIMEOUT(!tab.isFitting(), kEventWaitMs);
        // Every superseded fit has stopped; whatever they finished with is not shown.
        QThreadPool::globalInstance()->waitForDone();
        QCoreApplication::processEvents();
        QCOMPARE(shown.count(), 1);
        const auto expected = fitBezier(q, correcting(kDegree, 2));
        QVERIFY(expected.ok());
        QVERIFY(tab.currentFit());
        QVERIFY(!tab.currentFit()->cancelled);
        QCOMPARE(tab.currentFit()->controlPoints, expected->controlPoints);
        QCOMPARE(tab.currentFit()->sse, expected->sse);
        // A quick fit supersedes a long one too: 10 points (degree 9), fitted at once.
        tab.changeSettings(
            [&] {
                FitSettings t = tab.settings();
                t.iterations = 1000;
                return t;
            }(),
            QStringLiteral("long again"));
        QVERIFY(tab.isFitting());
        tab.pointEditor()->setPoints(std::vector<Point>(q.begin(), q.begin() + 10), QStringLiteral("fewer"));
        QVERIFY(!tab.isFitting());
        QVERIFY(tab.currentFit());
        QCOMPARE(tab.currentFit()->controlPoints.size(), std::size_t(10)); // degree lowered to k = 9
        QThreadPool::globalInstance()->waitForDone();
        QCoreApplication::processEvents();
        QCOMPARE(shown.count(), 1);
        QCOMPARE(tab.currentFit()->controlPoints.size(), std::size_t(10));
    }
};

GRANOTA_TEST_MAIN(TestGuiFitBackground)
#include "test_gui_fit_background.moc"
