#pragma once
/// \file enum_names.h
/// The names of an enum's values, written once: a constexpr table of {value, name} pairs
/// that both directions read, so a name printed (CLI output, a saved document, a trace)
/// is always one the parser reads back. How typed text is matched is the caller's
/// choice, kept as each parser has always had it (NameMatch).

#include "core/base/text.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace granota {

/// One value of an enum and its name (lower case, as written to files and the CLI).
template <class E> struct EnumName {
    E value;
    std::string_view name;
};

/// How parseName() compares typed text with the names of the table.
enum class NameMatch {
    Exact,          ///< byte for byte: "rk4", not "RK4" nor " rk4"
    IgnoreCase,     ///< "QR" and "qr" (std::tolower), but not " qr"
    IgnoreCaseTrim, ///< as IgnoreCase, after removing surrounding blanks (trim())
};

/// The name of `value` in `table`, or `fallback` for a value the table does not hold.
template <class E, std::size_t N>
constexpr std::string_view nameOf(const std::array<EnumName<E>, N>& table, E value, std::string_view fallback = {})
{
    for (const EnumName<E>& entry : table)
        if (entry.value == value)
            return entry.name;
    return fallback;
}

/// The value whose name is `text` (compared as `match` says), or nullopt. The names of the
/// table are lower case, so IgnoreCase compares them with the lower-cased text.
template <class E, std::size_t N>
std::optional<E> parseName(const std::array<EnumName<E>, N>& table, std::string_view text, NameMatch match = NameMatch::Exact)
{
    std::string folded;
    if (match != NameMatch::Exact) {
        folded = lowerCase(match == NameMatch::IgnoreCaseTrim ? trim(text) : text);
        text = folded;
    }
    for (const EnumName<E>& entry : table)
        if (entry.name == text)
            return entry.value;
    return std::nullopt;
}

} // namespace granota
