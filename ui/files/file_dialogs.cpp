#include "ui/files/file_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>

namespace granota::ui {

QString lastFileFolder()
{
    const QString folder = QSettings().value(QLatin1String(kLastFolderKey)).toString();
    return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QDir::homePath();
}

void rememberFileFolder(const QString& path)
{
    if (path.isEmpty())
        return;
    const QFileInfo info(path);
    QSettings().setValue(QLatin1String(kLastFolderKey), info.isDir() ? info.absoluteFilePath() : info.absolutePath());
}

QString openFileName(QWidget* parent, const QString& caption, const QString& filter)
{
    const QString file = QFileDialog::getOpenFileName(parent, caption, lastFileFolder(), filter);
    rememberFileFolder(file);
    return file;
}

QString saveFileName(QWidget* parent, const QString& caption, const QString& suggestedName, const QString& filter)
{
    const QString file = QFileDialog::getSaveFileName(parent, caption, QDir(lastFileFolder()).filePath(suggestedName), filter);
    rememberFileFolder(file);
    return file;
}

QString existingFolder(QWidget* parent, const QString& caption)
{
    const QString folder = QFileDialog::getExistingDirectory(parent, caption, lastFileFolder());
    rememberFileFolder(folder);
    return folder;
}

} // namespace granota::ui
