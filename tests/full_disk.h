#pragma once
// A real full disk for the tests of issue 32: a tmpfs of a few pages mounted on a temporary
// folder, then filled until the system says ENOSPC. Mounting needs CAP_SYS_ADMIN — CI runs
// as root in its own machine; elsewhere the tests that need it say so and skip.
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <cerrno>
#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>

class FullDisk {
public:
    FullDisk()
    {
        if (!m_dir.isValid())
            return;
        m_mounted = ::mount("tmpfs", QFile::encodeName(m_dir.path()).constData(), "tmpfs", MS_NOSUID | MS_NODEV,
                            "size=64k,mode=0777") == 0;
    }
    ~FullDisk()
    {
        if (m_mounted)
            ::umount2(QFile::encodeName(m_dir.path()).constData(), MNT_DETACH);
    }
    FullDisk(const FullDisk&) = delete;
    FullDisk& operator=(const FullDisk&) = delete;

    bool mounted() const { return m_mounted; }
    static const char* whyNot() { return "mounting a tmpfs needs root (CAP_SYS_ADMIN), as CI has"; }
    QString filePath(const QString& name) const { return QDir(m_dir.path()).filePath(name); }

    /// Puts `bytes` in `name` while there is room, before fill().
    bool put(const QString& name, const QByteArray& bytes) const
    {
        QFile f(filePath(name));
        return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size() && f.flush();
    }
    /// Fills what is left with one file until write(2) says ENOSPC; true when it did.
    bool fill() const
    {
        const int fd = ::open(QFile::encodeName(filePath(QStringLiteral("filler"))).constData(),
                              O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
        if (fd < 0)
            return false;
        const QByteArray block(4096, 'f');
        bool full = false;
        for (int i = 0; i < 1000 && !full; ++i) {
            if (::write(fd, block.constData(), static_cast<size_t>(block.size())) < 0)
                full = errno == ENOSPC;
        }
        // A last byte in a partly written page: the disk is now full to the byte.
        while (!full && ::write(fd, "f", 1) == 1) {
        }
        ::close(fd);
        return full || errno == ENOSPC;
    }
    /// The bytes of `name` now (empty when it is missing).
    QByteArray read(const QString& name) const
    {
        QFile f(filePath(name));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

private:
    QTemporaryDir m_dir;
    bool m_mounted = false;
};
