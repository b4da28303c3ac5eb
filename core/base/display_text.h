#pragma once
/// \file display_text.h
/// Untrusted text (a cell of a CSV, a file name, an argument) shown inside a message.
/// A message goes to a terminal or a dialog, so the text is quoted with every control
/// character escaped: an ESC or BEL in a file cannot clear a terminal or retitle it.

#include <cstddef>
#include <string>
#include <string_view>

namespace granota {

/// `text` between single quotes, at most `maxChars` characters of it followed by "…".
/// Control characters (C0, DEL, C1) become \n, \t, \r or \xNN; bytes that are not
/// UTF-8 become \xNN; printable UTF-8 (accents, "·", "é") is kept as it is.
std::string quotedForDisplay(std::string_view text, std::size_t maxChars = 60);

/// `text` escaped as quotedForDisplay does, without the quotes: for text from a file shown
/// where a name is expected (a scene's title in `simulate --replay`'s answer).
std::string escapedForDisplay(std::string_view text, std::size_t maxChars = 60);

/// The reason for a system error `errnum` (errno) in English whatever the locale, as the
/// rest of a command-line message is: "No space left on device", not "No resta espai…".
std::string systemErrorText(int errnum);

} // namespace granota
