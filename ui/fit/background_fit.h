#pragma once
/// \file background_fit.h
/// A least-squares fit (fitBezier, core/curves/fitting/least_squares_fit.h) on a worker
/// thread, for the fits too long to make the window wait: thousands of points at a high
/// degree with hundreds of parameter corrections take minutes. One fit is current at a time:
/// starting another supersedes it (its result is never delivered, and it stops at its next
/// FitOptions::keepGoing check), cancel() stops it at that check and delivers the best fit so
/// far (FitResult::cancelled), and finish() waits for it, for exports and screenshots that
/// must show the finished fit. The worker has its own copy of the points and the options;
/// nothing of the tab is touched off the GUI thread.

#include "core/base/expected.h"
#include "core/curves/fitting/least_squares_fit.h"

#include <QObject>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

class QTimer;

namespace granota::ui {

class BackgroundFit : public QObject {
    Q_OBJECT
public:
    explicit BackgroundFit(QObject* parent = nullptr);
    /// Supersedes the current fit, if any (it is cancelled and its result dropped).
    ~BackgroundFit() override;

    /// Fits q with options on a worker thread; a fit still running is superseded.
    void start(std::vector<Point> q, FitOptions options);
    /// Drops the current fit without delivering it (a quick fit made on the GUI thread replaces it).
    void supersede();
    /// Stops the current fit at its next check; finished() then brings the best fit so far.
    void cancel();
    /// Waits for the current fit and delivers it now (finished() is emitted before this returns).
    void finish();

    bool running() const { return m_job != nullptr; }
    bool cancelling() const;
    /// The corrections made so far by the current fit, and the most it may make.
    int correctionsDone() const;
    int correctionsAllowed() const;
    /// The result finished() announced (once).
    Expected<FitResult> takeResult();

signals:
    /// The current fit is done (or stopped by cancel()): take its result with takeResult().
    void finished();
    /// While it runs, a few times a second: corrections made so far.
    void progress(int done, int allowed);

private:
    struct Job;
    void deliver();
    std::shared_ptr<Job> m_job; ///< the current fit, or nullptr
    std::optional<Expected<FitResult>> m_result;
    QTimer* m_progressTimer = nullptr;
};

} // namespace granota::ui
