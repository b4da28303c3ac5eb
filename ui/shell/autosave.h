#pragma once
/// \file autosave.h
/// Where a window's unsaved work is kept between saves, and what earlier sessions left.
///
/// Each window writes its own file, `<folder>/<session>.granota`, and holds a lock beside
/// it (`….granota.lock`, QLockFile) while it lives. A clean close or a save removes the
/// file; a crash leaves it with its lock free. An autosave whose lock is free is an
/// orphan: the work of a session that ended without saving. Orphans are offered for
/// recovery and are never deleted or overwritten unless the user says so: what could
/// not be recovered is moved aside to `<folder>/kept/`.

#include <QDateTime>
#include <QLockFile>
#include <QString>
#include <QVector>

#include <memory>

namespace granota::ui {

struct Orphan {
    QString path;
    QString documentFile; ///< the document it belongs to; empty for Untitled (or unreadable)
    QDateTime written;
};

class Autosave {
public:
    /// This session's autosave in `folder` (created if needed).
    explicit Autosave(const QString& folder = defaultFolder());
    ~Autosave(); ///< frees the lock and leaves the file, as a crash would

    static QString defaultFolder(); ///< under the application's data directory
    QString folder() const { return m_folder; }
    QString path() const { return m_path; }

    /// Writes `bytes` atomically; false with a (translated) reason.
    bool write(const QByteArray& bytes, QString* error);
    /// Removes this session's file (after a save, or a close the user agreed to).
    void remove();

    /// The orphans in the folder, newest first.
    QVector<Orphan> orphans() const;
    /// Takes an orphan's lock while it is offered: no other window lists it meanwhile. Null
    /// when another window has it, or the orphan is gone.
    static std::unique_ptr<QLockFile> holdOrphan(const QString& orphanPath);
    /// Deletes an orphan (the user chose to discard it, or it was recovered whole).
    static bool discard(const QString& orphanPath);
    /// Moves an orphan to `<folder>/kept/` under a name no autosave takes; the new path,
    /// or empty if it could not be moved (then it stays where it was).
    QString keepAside(const QString& orphanPath) const;

private:
    QString m_folder;
    QString m_path;
    std::unique_ptr<QLockFile> m_lock;
};

} // namespace granota::ui
