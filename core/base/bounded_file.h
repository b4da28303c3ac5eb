#pragma once
/// \file bounded_file.h
/// Reading a whole file with a bound on the bytes read. The size a file reports cannot
/// be trusted: devices (/dev/zero, /dev/urandom), pipes and /proc files say 0 and never
/// end, so the bound is applied to what is read, not to what the file claims.

#include "core/base/expected.h"

#include <cstddef>
#include <string>

namespace granota {

/// The bytes of the file at `path` (a path in the local 8-bit encoding), or an error
/// that names it: it does not exist or cannot be read (ErrorCode::SystemRefused, with the
/// errno), it is a folder, a pipe or a socket (ErrorCode::NotAFile: refused at once, never
/// waited on), or it holds more than `maxBytes` bytes (ErrorCode::OutOfRange; reading stops
/// after maxBytes + 1 bytes).
Expected<std::string> readBoundedFile(const std::string& path, std::size_t maxBytes);

/// "64 MB": a byte count as a user reads it in a message.
std::string byteSizeText(std::size_t bytes);

} // namespace granota
