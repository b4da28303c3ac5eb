#include "ui/fit/background_fit.h"

#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace granota::ui {

namespace {

/// How often progress() is emitted while a fit runs.
constexpr int kProgressMs = 100;

} // namespace

/// What the worker shares with the GUI thread: two atomics; the future is the GUI thread's.
struct BackgroundFit::Job {
    std::atomic<bool> cancel{false};
    std::atomic<int> done{0};
    int allowed = 0;
    bool userCancelled = false;
    QFuture<Expected<FitResult>> future;
    QFutureWatcher<Expected<FitResult>>* watcher = nullptr;
};

BackgroundFit::BackgroundFit(QObject* parent) : QObject(parent), m_progressTimer(new QTimer(this))
{
    m_progressTimer->setInterval(kProgressMs);
    connect(m_progressTimer, &QTimer::timeout, this, [this] {
        if (m_job)
            emit progress(m_job->done.load(), m_job->allowed);
    });
}

BackgroundFit::~BackgroundFit() { supersede(); }

void BackgroundFit::start(std::vector<Point> q, FitOptions options)
{
    supersede();
    auto job = std::make_shared<Job>();
    job->allowed = options.correctParameters ? options.maxCorrections : 0;
    // The worker keeps the job alive by its own pointer: a superseded fit runs on to its next
    // check with nothing of this object.
    options.keepGoing = [job](int done) {
        job->done.store(done);
        return !job->cancel.load();
    };
    job->future = QtConcurrent::run([q = std::move(q), options = std::move(options)] { return fitBezier(q, options); });
    job->watcher = new QFutureWatcher<Expected<FitResult>>(this);
    connect(job->watcher, &QFutureWatcherBase::finished, this, [this, raw = job.get()] {
        if (m_job.get() == raw)
            deliver();
    });
    job->watcher->setFuture(job->future);
    m_job = std::move(job);
    m_progressTimer->start();
}

void BackgroundFit::supersede()
{
    if (!m_job)
        return;
    m_job->cancel.store(true);
    // The watcher goes once its fit has stopped; its result is dropped.
    QFutureWatcher<Expected<FitResult>>* watcher = m_job->watcher;
    watcher->disconnect(this);
    if (watcher->isFinished())
        watcher->deleteLater();
    else
        connect(watcher, &QFutureWatcherBase::finished, watcher, &QObject::deleteLater);
    m_job.reset();
    m_progressTimer->stop();
}

void BackgroundFit::cancel()
{
    if (!m_job)
        return;
    m_job->userCancelled = true;
    m_job->cancel.store(true);
}

bool BackgroundFit::cancelling() const { return m_job && m_job->userCancelled; }

int BackgroundFit::correctionsDone() const { return m_job ? m_job->done.load() : 0; }

int BackgroundFit::correctionsAllowed() const { return m_job ? m_job->allowed : 0; }

void BackgroundFit::finish()
{
    if (!m_job)
        return;
    m_job->future.waitForFinished();
    deliver();
}

void BackgroundFit::deliver()
{
    std::shared_ptr<Job> job = std::move(m_job);
    m_progressTimer->stop();
    job->watcher->disconnect(this);
    job->watcher->deleteLater();
    m_result.emplace(job->future.takeResult());
    emit finished();
}

Expected<FitResult> BackgroundFit::takeResult()
{
    Expected<FitResult> r = m_result ? std::move(*m_result) : makeError(ErrorCode::InvalidInput, "no fit");
    m_result.reset();
    return r;
}

} // namespace granota::ui
