#pragma once
/// \file file_dialogs.h
/// Every file dialog of the application (open, save, export, import, the frames' folder):
/// each opens in the folder used last by any of them, remembered across sessions
/// (QSettings key kLastFolderKey), not in $HOME each time (issue 34, item 10). A file chosen
/// or a folder chosen becomes the folder used last.

#include <QString>

class QWidget;

namespace granota::ui {

inline constexpr const char* kLastFolderKey = "files/lastFolder";

/// The folder used last by a file dialog if it still exists, else the home folder.
QString lastFileFolder();
/// Remembers the folder of `path` (a file: its folder; an existing folder: itself).
void rememberFileFolder(const QString& path);

/// QFileDialog::getOpenFileName in the folder used last; remembers the folder of the file chosen.
QString openFileName(QWidget* parent, const QString& caption, const QString& filter);
/// QFileDialog::getSaveFileName in the folder used last, proposing `suggestedName` (a bare
/// file name) there; remembers the folder of the file chosen.
QString saveFileName(QWidget* parent, const QString& caption, const QString& suggestedName, const QString& filter);
/// QFileDialog::getExistingDirectory starting in the folder used last; remembers the folder chosen.
QString existingFolder(QWidget* parent, const QString& caption);

} // namespace granota::ui
