#include "ui/shell/autosave.h"

#include "ui/shell/document.h"
#include "ui/files/user_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>

namespace granota::ui {

namespace {

const QString kSuffix = QStringLiteral(".granota");
const QString kLockSuffix = QStringLiteral(".lock");
const QString kKept = QStringLiteral("kept");

} // namespace

QString Autosave::defaultFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

Autosave::Autosave(const QString& folder) : m_folder(folder)
{
    QDir().mkpath(m_folder);
    // Granota 0.x kept one autosave for every window beside the folder: it becomes an
    // orphan like any other, offered at the next start.
    const QString single = QFileInfo(m_folder).absolutePath() + QStringLiteral("/autosave") + kSuffix;
    if (folder == defaultFolder() && QFile::exists(single))
        QFile::rename(single, QDir(m_folder).filePath(QStringLiteral("single-autosave") + kSuffix));
    const QString session = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_path = QDir(m_folder).filePath(session + kSuffix);
    m_lock = std::make_unique<QLockFile>(m_path + kLockSuffix);
    m_lock->setStaleLockTime(0); // a live session's lock never goes stale with age
    m_lock->tryLock(0);          // if the folder is not writable, write() says so
}

Autosave::~Autosave() = default;

bool Autosave::write(const QByteArray& bytes, QString* error)
{
    QDir().mkpath(m_folder);
    if (!m_lock->isLocked())
        m_lock->tryLock(0);
    // Replaced whole (ui/files/user_file.h): on a full disk the last good autosave stays.
    QString reason;
    if (!writeUserFile(m_path, bytes, &reason)) {
        *error = QCoreApplication::translate("granota::ui::Autosave", "Cannot write the autosave “%1”: %2.")
                     .arg(QDir::toNativeSeparators(m_path), reason);
        return false;
    }
    return true;
}

void Autosave::remove() { QFile::remove(m_path); }

QVector<Orphan> Autosave::orphans() const
{
    QVector<Orphan> out;
    const QFileInfoList files = QDir(m_folder).entryInfoList({QStringLiteral("*") + kSuffix}, QDir::Files);
    for (const QFileInfo& file : files) {
        const QString path = file.absoluteFilePath();
        if (path == QFileInfo(m_path).absoluteFilePath())
            continue;
        QLockFile lock(path + kLockSuffix);
        lock.setStaleLockTime(0); // stale only if its process has gone
        if (!lock.tryLock(0))
            continue; // a running session's
        QString ignored;
        const std::optional<QByteArray> bytes = readUserFile(path, &ignored);
        const std::optional<QString> document = bytes ? autosaveDocumentFile(*bytes) : std::nullopt;
        out.push_back({path, document.value_or(QString()), file.lastModified()});
    }
    std::sort(out.begin(), out.end(), [](const Orphan& a, const Orphan& b) { return a.written > b.written; });
    return out;
}

std::unique_ptr<QLockFile> Autosave::holdOrphan(const QString& orphanPath)
{
    auto lock = std::make_unique<QLockFile>(orphanPath + kLockSuffix);
    lock->setStaleLockTime(0); // stale only if its process has gone
    if (!lock->tryLock(0) || !QFileInfo::exists(orphanPath))
        return nullptr;
    return lock;
}

bool Autosave::discard(const QString& orphanPath)
{
    const bool removed = QFile::remove(orphanPath);
    QFile::remove(orphanPath + kLockSuffix);
    return removed;
}

QString Autosave::keepAside(const QString& orphanPath) const
{
    const QDir kept(QDir(m_folder).filePath(kKept));
    QDir().mkpath(kept.path());
    const QString stamp = QFileInfo(orphanPath).lastModified().toString(QStringLiteral("yyyy-MM-dd-HHmmss"));
    QString target = kept.filePath(QStringLiteral("autosave-%1%2").arg(stamp, kSuffix));
    for (int i = 2; QFile::exists(target); ++i)
        target = kept.filePath(QStringLiteral("autosave-%1-%2%3").arg(stamp).arg(i).arg(kSuffix));
    if (!QFile::rename(orphanPath, target))
        return QString();
    QFile::remove(orphanPath + kLockSuffix);
    return target;
}

} // namespace granota::ui
