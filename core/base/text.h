#pragma once
/// \file text.h
/// The small operations on text that every reader of typed or loaded text needs: the
/// blanks around a number, a name or a line are not part of it. Blanks are the C
/// library's std::isspace (space, tab, newline, carriage return, form feed, vertical tab).

#include <string>
#include <string_view>

namespace granota {

/// `text` without the blanks at its start and end (a view into `text`).
std::string_view trim(std::string_view text);

/// `text` with every letter made lower case by std::tolower, byte by byte.
std::string lowerCase(std::string_view text);

} // namespace granota
