#pragma once
/// \file user_file.h
/// Reading a file the user chose (a document, an autosave, data to fit) with the bound of
/// core/base/input_limits.h on the bytes read, and a translated message naming what is wrong.

#include <QByteArray>
#include <QString>

#include <optional>

namespace granota::ui {

/// The file's bytes, or nothing with `error` set: it is missing or unreadable, it is a
/// folder, or it holds more than kMaxFileBytes (devices and pipes included: the bound is
/// on what is read, not on the size the file reports).
std::optional<QByteArray> readUserFile(const QString& path, QString* error);

} // namespace granota::ui
