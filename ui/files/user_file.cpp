#include "ui/files/user_file.h"

#include "core/base/bounded_file.h"
#include "core/base/file_replacement.h"
#include "core/base/input_limits.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <cerrno>

namespace granota::ui {

QString systemReason(int errnoValue)
{
    switch (errnoValue) {
    case ENOSPC: return QCoreApplication::translate("granota::ui::UserFile", "there is no space left on the disk");
    case EDQUOT: return QCoreApplication::translate("granota::ui::UserFile", "your disk quota is full");
    case EROFS: return QCoreApplication::translate("granota::ui::UserFile", "the disk is read-only");
    case EACCES:
    case EPERM: return QCoreApplication::translate("granota::ui::UserFile", "you do not have permission");
    case ENOENT: return QCoreApplication::translate("granota::ui::UserFile", "it does not exist");
    case ENOTDIR: return QCoreApplication::translate("granota::ui::UserFile", "a folder on its path does not exist");
    case EISDIR: return QCoreApplication::translate("granota::ui::UserFile", "it is a folder");
    case ENAMETOOLONG: return QCoreApplication::translate("granota::ui::UserFile", "the name is too long");
    case EFBIG: return QCoreApplication::translate("granota::ui::UserFile", "the file would be too large for the disk");
    case EIO: return QCoreApplication::translate("granota::ui::UserFile", "the disk reported an error");
    case EMFILE:
    case ENFILE: return QCoreApplication::translate("granota::ui::UserFile", "too many files are open");
    case ETXTBSY:
    case EBUSY: return QCoreApplication::translate("granota::ui::UserFile", "the file is in use");
    default: return QCoreApplication::translate("granota::ui::UserFile", "the system refused it (error %1)").arg(errnoValue);
    }
}

std::optional<QByteArray> readUserFile(const QString& path, QString* error)
{
    const QString name = QFileInfo(path).fileName().isEmpty() ? path : QFileInfo(path).fileName();
    const Expected<std::string> read = readBoundedFile(QFile::encodeName(path).toStdString(), kMaxFileBytes);
    if (read)
        return QByteArray::fromStdString(*read);
    switch (read.error().code) {
    case ErrorCode::OutOfRange:
        *error = QCoreApplication::translate("granota::ui::UserFile",
                                             "“%1” is larger than %2 MB, the most Granota reads from one file.")
                     .arg(name)
                     .arg(kMaxFileBytes / (1024 * 1024));
        break;
    case ErrorCode::NotAFile:
        *error = QFileInfo(path).isDir()
                     ? QCoreApplication::translate("granota::ui::UserFile", "“%1” is a folder, not a file.").arg(name)
                     : QCoreApplication::translate("granota::ui::UserFile", "“%1” is a pipe or a device, not a file.").arg(name);
        break;
    default:
        *error = QCoreApplication::translate("granota::ui::UserFile", "Cannot open “%1”: %2.")
                     .arg(name, systemReason(read.error().systemError));
    }
    return std::nullopt;
}

bool writeUserFile(const QString& path, const QByteArray& bytes, QString* reason)
{
    const Expected<void> written = replaceFile(QFile::encodeName(path).toStdString(),
                                               std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (!written)
        *reason = systemReason(written.error().systemError);
    return written.ok();
}

} // namespace granota::ui
