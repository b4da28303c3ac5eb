#pragma once
/// \file output_file.h
/// Writing what granota-cli produces — its answer on stdout, a --trace, a report's files —
/// so that a failed write (a full disk, a closed pipe, a folder that cannot be written) is
/// an error that says what could not be written and why, never a silent success. A file is
/// replaced only once the new one is whole (core/base/file_replacement.h).

#include "core/base/expected.h"

#include <string>
#include <string_view>

namespace granota::cli {

/// "cannot write WHAT: REASON", REASON from `errnoValue` (0: the reason is unknown).
Error writeError(const std::string& what, int errnoValue);

/// Replaces the file at `path` with `bytes`, all or nothing (replaceFile): on any failure
/// the old file is kept byte for byte, and the error names the file and the reason.
Expected<void> writeFile(const std::string& path, std::string_view bytes);

} // namespace granota::cli
