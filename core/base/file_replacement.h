#pragma once
/// \file file_replacement.h
/// Writing a user's file so that the old one is kept until the new one is whole. What is
/// written goes to a hidden file beside the target (".NAME.XXXXXX"); only commit() puts it
/// in the target's place, after every byte has been written without a buffer the system may
/// drop, synced to the disk and its size checked, and then by rename(2), which replaces the
/// file in one step. On a full disk, a read-only disk or a denied folder nothing of the old
/// file changes, the hidden file is removed, and the error says why (Error::systemError).
/// (QSaveFile in Qt 6.4 reports success when the last flush of its buffer fails, and a
/// stdio stream reports a full disk only at fclose, after truncating the target.)
///
/// A target that exists and is not a regular file — /dev/null, /dev/stdout, a pipe — is
/// written in place: it cannot be replaced, and there is no old content to keep.

#include "core/base/expected.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace granota {

class FileReplacement {
public:
    /// Creates the hidden file beside `path` (a path in the local 8-bit encoding); the
    /// error names `path` and, in systemError, the errno (EACCES for a folder that cannot
    /// be written, ENOENT for one that does not exist, EISDIR when `path` is a folder).
    static Expected<FileReplacement> open(const std::string& path);

    FileReplacement(FileReplacement&& other) noexcept;
    FileReplacement& operator=(FileReplacement&& other) noexcept;
    FileReplacement(const FileReplacement&) = delete;
    FileReplacement& operator=(const FileReplacement&) = delete;
    /// Without a successful commit(), the hidden file is removed and the target kept.
    ~FileReplacement();

    /// Appends `bytes` (kept in a buffer of 64 KiB, then written with write(2)). After an
    /// error every further call fails with the same error.
    Expected<void> write(std::string_view bytes);
    /// Writes what is buffered, syncs, checks the file holds every byte written, and
    /// renames it over the target, which keeps its permissions.
    Expected<void> commit();

    const std::string& path() const { return m_target; }

private:
    FileReplacement() = default;
    Expected<void> flushBuffer();
    Expected<void> fail(int errnoValue);
    void discard();

    std::string m_target;
    std::string m_hidden; ///< empty when the target is written in place
    int m_fd = -1;
    std::uint64_t m_written = 0;
    std::string m_buffer;
    int m_failed = 0; ///< the errno of the first failure, or 0
};

/// Replaces the file at `path` with `bytes` through a FileReplacement: all or nothing.
Expected<void> replaceFile(const std::string& path, std::string_view bytes);

/// "cannot write NAME: REASON", REASON from `errnoValue` (0: the reason is unknown), with
/// the errno kept in Error::systemError for a translated text.
Error fileWriteError(const std::string& path, int errnoValue);

} // namespace granota
