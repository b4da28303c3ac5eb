#include "ui/shell/user_file.h"

#include "core/base/bounded_file.h"
#include "core/base/input_limits.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace granota::ui {

std::optional<QByteArray> readUserFile(const QString& path, QString* error)
{
    const QString name = QFileInfo(path).fileName().isEmpty() ? path : QFileInfo(path).fileName();
    const Expected<std::string> read = readBoundedFile(QFile::encodeName(path).toStdString(), kMaxFileBytes);
    if (read)
        return QByteArray::fromStdString(*read);
    if (read.error().code == ErrorCode::OutOfRange)
        *error = QCoreApplication::translate("granota::ui::UserFile",
                                             "“%1” is larger than %2 MB, the most Granota reads from one file.")
                     .arg(name)
                     .arg(kMaxFileBytes / (1024 * 1024));
    else if (QFileInfo(path).isDir())
        *error = QCoreApplication::translate("granota::ui::UserFile", "“%1” is a folder, not a file.").arg(name);
    else {
        QFile file(path);
        *error = QCoreApplication::translate("granota::ui::UserFile", "Cannot open “%1”: %2")
                     .arg(name, file.open(QIODevice::ReadOnly)
                                    ? QCoreApplication::translate("granota::ui::UserFile", "it cannot be read.")
                                    : file.errorString());
    }
    return std::nullopt;
}

} // namespace granota::ui
