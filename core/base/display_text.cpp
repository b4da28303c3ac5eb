#include "core/base/display_text.h"

#include <string.h> // strerrordesc_np (glibc): the untranslated text of strerror

namespace granota {

namespace {

void appendHex(std::string& out, unsigned char byte)
{
    static const char kDigits[] = "0123456789abcdef";
    out += "\\x";
    out += kDigits[byte >> 4];
    out += kDigits[byte & 0xf];
}

/// The length of the well-formed UTF-8 sequence at the start of `s`, or 0.
std::size_t utf8Length(std::string_view s)
{
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char lead = b(0);
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xbf;
    if (lead >= 0xc2 && lead <= 0xdf)
        n = 2;
    else if (lead >= 0xe0 && lead <= 0xef) {
        n = 3;
        if (lead == 0xe0)
            lo = 0xa0;
        if (lead == 0xed)
            hi = 0x9f; // no surrogates
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        n = 4;
        if (lead == 0xf0)
            lo = 0x90;
        if (lead == 0xf4)
            hi = 0x8f;
    } else
        return 0;
    if (s.size() < n || b(1) < lo || b(1) > hi)
        return 0;
    for (std::size_t i = 2; i < n; ++i)
        if (b(i) < 0x80 || b(i) > 0xbf)
            return 0;
    return n;
}

} // namespace

std::string quotedForDisplay(std::string_view text, std::size_t maxChars)
{
    return "'" + escapedForDisplay(text, maxChars) + "'";
}

std::string escapedForDisplay(std::string_view text, std::size_t maxChars)
{
    std::string out;
    std::size_t chars = 0;
    std::size_t i = 0;
    while (i < text.size() && chars < maxChars) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else if (c == '\r')
            out += "\\r";
        else if (c < 0x20 || c == 0x7f)
            appendHex(out, c);
        else if (c < 0x80)
            out += static_cast<char>(c);
        else if (const std::size_t n = utf8Length(text.substr(i)); n == 0)
            appendHex(out, c);
        else if (n == 2 && c == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0) {
            appendHex(out, c); // a C1 control character, U+0080 to U+009F
            appendHex(out, static_cast<unsigned char>(text[i + 1]));
            i += 2;
            ++chars;
            continue;
        } else {
            out.append(text.substr(i, n));
            i += n;
            ++chars;
            continue;
        }
        ++i;
        ++chars;
    }
    if (i < text.size())
        out += "…";
    return out;
}

std::string systemErrorText(int errnum)
{
    if (const char* text = ::strerrordesc_np(errnum))
        return text;
    return "system error " + std::to_string(errnum);
}

} // namespace granota
