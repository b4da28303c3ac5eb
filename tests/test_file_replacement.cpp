// Writing a user's file keeps the old one until the new one is whole (issue 32, item 1):
// a full disk, a folder that cannot be written, a failed write in the middle of a stream.
// The expected bytes are the ones the test itself wrote before; the reasons are the errno
// the system gives for the situation the test sets up (ENOSPC on a full tmpfs, EACCES…).
#include "core/base/bounded_file.h"
#include "core/base/file_replacement.h"
#include "full_disk.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>
#include "tests/test_main.h"

#include <cerrno>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

using namespace granota;

namespace {

QByteArray contentOf(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}

/// The names in `folder` but the ones given: a hidden file left behind shows here.
QStringList leftovers(const QString& folder, const QStringList& expected)
{
    QStringList out;
    for (const QString& name : QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::System))
        if (!expected.contains(name))
            out << name;
    return out;
}

} // namespace

class TestFileReplacement : public QObject {
    Q_OBJECT
private slots:
    void replacesTheFileWholeAndKeepsItsPermissions()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("a.granota");
        QVERIFY(replaceFile(path.toStdString(), "first"));
        QCOMPARE(contentOf(path), QByteArray("first"));
        QVERIFY(::chmod(QFile::encodeName(path).constData(), 0640) == 0);
        QVERIFY(replaceFile(path.toStdString(), "second, longer"));
        QCOMPARE(contentOf(path), QByteArray("second, longer"));
        struct stat info {};
        QVERIFY(::stat(QFile::encodeName(path).constData(), &info) == 0);
        QCOMPARE(info.st_mode & 07777, 0640u);
        QCOMPARE(leftovers(dir.path(), {"a.granota"}), QStringList());
    }
    void aStreamIsInvisibleUntilCommitted()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("trace.csv");
        QVERIFY(replaceFile(path.toStdString(), "old"));
        {
            auto file = FileReplacement::open(path.toStdString());
            QVERIFY(file);
            // More than the 64 KiB buffer: part of it reaches the hidden file before commit.
            const std::string row(1000, 'r');
            for (int i = 0; i < 200; ++i)
                QVERIFY(file->write(row));
            QCOMPARE(contentOf(path), QByteArray("old"));
        } // dropped without commit: the old file stays, the hidden one goes
        QCOMPARE(contentOf(path), QByteArray("old"));
        QCOMPARE(leftovers(dir.path(), {"trace.csv"}), QStringList());
        auto file = FileReplacement::open(path.toStdString());
        QVERIFY(file);
        QVERIFY(file->write("a,b\n"));
        QVERIFY(file->write("1,2\n"));
        QVERIFY(file->commit());
        QCOMPARE(contentOf(path), QByteArray("a,b\n1,2\n"));
    }
    void aSymbolicLinkKeepsPointingAtTheNewContent()
    {
        QTemporaryDir dir;
        const QString target = dir.filePath("real.csv"), link = dir.filePath("link.csv");
        QVERIFY(replaceFile(target.toStdString(), "old"));
        QVERIFY(QFile::link(target, link));
        QVERIFY(replaceFile(link.toStdString(), "new"));
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(contentOf(target), QByteArray("new"));
    }
    void devicesAreWrittenInPlace()
    {
        QVERIFY(replaceFile("/dev/null", "nothing to keep"));
        const auto full = replaceFile("/dev/full", "x");
        QVERIFY(!full);
        QCOMPARE(full.error().systemError, ENOSPC);
    }
    void aFullDiskKeepsTheOldFileAndSaysWhy()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        const QByteArray old = "{\"small\": \"document\"}"; // under a page, as in the issue
        QVERIFY(disk.put("doc.granota", old));
        QVERIFY(disk.fill());
        const std::string path = disk.filePath("doc.granota").toStdString();
        for (const std::size_t size : {std::size_t(500), std::size_t(100000)}) {
            const auto written = replaceFile(path, std::string(size, 'n'));
            QVERIFY2(!written, "a write onto a full disk reported success");
            QCOMPARE(written.error().systemError, ENOSPC);
            QCOMPARE(written.error().code, ErrorCode::SystemRefused);
            QVERIFY2(QString::fromStdString(written.error().message).contains("No space left on device"),
                     written.error().message.c_str());
            QCOMPARE(disk.read("doc.granota"), old);
        }
        QCOMPARE(leftovers(disk.filePath(""), {"doc.granota", "filler"}), QStringList());
    }
    void aFolderThatCannotBeWrittenKeepsTheOldFile()
    {
        if (::geteuid() == 0)
            QSKIP("root writes into any folder: the read-only case is a read-only mount below");
        QTemporaryDir dir;
        const QString path = dir.filePath("a.granota");
        QVERIFY(replaceFile(path.toStdString(), "old"));
        QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        const auto written = replaceFile(path.toStdString(), "new");
        QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        QVERIFY(!written);
        QCOMPARE(written.error().systemError, EACCES);
        QCOMPARE(contentOf(path), QByteArray("old"));
    }
    void aReadOnlyDiskKeepsTheOldFileAndSaysWhy()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        QVERIFY(disk.put("doc.granota", "old"));
        const QByteArray folder = QFile::encodeName(disk.filePath(""));
        QVERIFY(::mount(nullptr, folder.constData(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) == 0);
        const auto written = replaceFile(disk.filePath("doc.granota").toStdString(), "new");
        QVERIFY(!written);
        QCOMPARE(written.error().systemError, EROFS);
        QCOMPARE(disk.read("doc.granota"), QByteArray("old"));
    }
    void aFolderIsNotReplaced()
    {
        QTemporaryDir dir;
        const auto written = replaceFile(dir.path().toStdString(), "x");
        QVERIFY(!written);
        QCOMPARE(written.error().systemError, EISDIR);
        QVERIFY(QFileInfo(dir.path()).isDir());
    }
    // Issue 32, item 4: a named pipe with no writer is refused at once, not waited on.
    void aPipeIsRefusedWithoutWaiting()
    {
        QTemporaryDir dir;
        const QString fifo = dir.filePath("points.csv");
        QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
        const auto read = readBoundedFile(fifo.toStdString(), 1000); // blocked forever before
        QVERIFY(!read);
        QCOMPARE(read.error().code, ErrorCode::NotAFile);
        QVERIFY2(QString::fromStdString(read.error().message).contains("is a pipe, not a file"), read.error().message.c_str());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestFileReplacement)
#include "test_file_replacement.moc"
