#pragma once
/// \file user_file.h
/// Reading a file the user chose (a document, an autosave, data to fit) with the bound of
/// core/base/input_limits.h on the bytes read, and writing one (a document, an autosave, an
/// export) so that the old file is kept until the new one is whole
/// (core/base/file_replacement.h), each with a translated message naming what is wrong.

#include <QByteArray>
#include <QString>

#include <optional>

namespace granota::ui {

/// The file's bytes, or nothing with `error` set: it is missing or unreadable, it is a
/// folder, or it holds more than kMaxFileBytes (devices and pipes included: the bound is
/// on what is read, not on the size the file reports).
std::optional<QByteArray> readUserFile(const QString& path, QString* error);

/// Replaces the file at `path` with `bytes`, all or nothing: on failure the old file is as
/// it was, and `reason` says why in the user's language (“there is no space left on the
/// disk”, “the disk is read-only”…), as the end of a sentence without its full stop.
bool writeUserFile(const QString& path, const QByteArray& bytes, QString* reason);

/// Why the system refused a read or a write, translated: from an errno (ENOSPC, EROFS,
/// EACCES…); a reason without its own text gives its number.
QString systemReason(int errnoValue);

} // namespace granota::ui
