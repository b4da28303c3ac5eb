#include "core/io/json.h"

#include "core/base/number_format.h"
#include "core/base/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <system_error>

namespace granota {

std::optional<bool> Json::asBool() const
{
    if (auto b = std::get_if<bool>(&m_v))
        return *b;
    return std::nullopt;
}

std::optional<double> Json::asNumber() const
{
    if (auto n = std::get_if<Number>(&m_v))
        return n->value;
    return std::nullopt;
}

std::optional<std::string_view> Json::numberText() const
{
    if (auto n = std::get_if<Number>(&m_v); n && !n->text.empty())
        return std::string_view(n->text);
    return std::nullopt;
}

std::optional<std::string> Json::asString() const
{
    if (auto s = std::get_if<std::string>(&m_v))
        return *s;
    return std::nullopt;
}

const Json* Json::find(const std::string& key) const
{
    if (const Object* o = asObject())
        for (const auto& [k, v] : *o)
            if (k == key)
                return &v;
    return nullptr;
}

Json& Json::push(Json v)
{
    assert(isArray());
    std::get<Array>(m_v).push_back(std::move(v));
    return *this;
}

Json& Json::set(const std::string& key, Json v)
{
    assert(isObject());
    for (auto& [k, old] : std::get<Object>(m_v))
        if (k == key) {
            old = std::move(v);
            return *this;
        }
    std::get<Object>(m_v).emplace_back(key, std::move(v));
    return *this;
}

std::string Json::dump(int indent) const
{
    std::string out;
    write(out, indent, 0);
    return out;
}

namespace {

void writeString(std::string& out, const std::string& s)
{
    constexpr char kHex[] = "0123456789abcdef";
    out += '"';
    for (unsigned char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (c < 0x20) {
                out += "\\u00";
                out += kHex[c >> 4];
                out += kHex[c & 0xF];
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    out += '"';
}

void newline(std::string& out, int indent, int depth)
{
    if (indent > 0) {
        out += '\n';
        out.append(static_cast<std::size_t>(indent * depth), ' ');
    }
}

/// " at line L, column C" for the byte at `index` of `text` (both from 1, columns in bytes).
std::string where(std::string_view text, std::size_t index)
{
    index = std::min(index, text.size());
    std::size_t line = 1, lineStart = 0;
    for (std::size_t i = 0; i < index; ++i)
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    return " at line " + std::to_string(line) + ", column " + std::to_string(index - lineStart + 1);
}

/// nlohmann's words for a syntax error, without its own position (where() gives ours) and
/// without its echo of the text last read, which can be a whole unterminated string.
std::string describe(const nlohmann::json::exception& e)
{
    std::string s = e.what();
    if (const auto column = s.find(", column "); column != std::string::npos) {
        if (const auto colon = s.find(": ", column); colon != std::string::npos)
            s.erase(0, colon + 2);
    } else if (const auto bracket = s.find("] "); bracket != std::string::npos) {
        s.erase(0, bracket + 2);
    }
    constexpr std::string_view kEcho = "; last read: '";
    if (const auto echo = s.find(kEcho); echo != std::string::npos) {
        const auto close = s.find("'; expected ", echo + kEcho.size());
        s.erase(echo, close == std::string::npos ? std::string::npos : close + 1 - echo);
    }
    return s;
}

/// The byte offset of a syntax error. nlohmann counts the bytes read up to the offending
/// one, itself included; when a whole token is out of place, its first byte is the place.
std::size_t errorOffset(std::size_t position, const std::string& lastToken, const std::string& what)
{
    // One byte: a structural character, the end of the text, or a malformed token's bad byte.
    std::size_t length = 1;
    const auto says = [&](const char* words) { return what.find(words) != std::string::npos; };
    if (says("unexpected string literal") || says("unexpected number literal"))
        length = lastToken.size(); // the lexer keeps those two kinds' bytes
    else if (says("unexpected true literal") || says("unexpected null literal"))
        length = 4;
    else if (says("unexpected false literal"))
        length = 5;
    return position >= length ? position - length : 0;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNumberByte(char c) { return isDigit(c) || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E'; }

/// Whether a number no double can hold is too large rather than too small: the power of
/// ten of its first significant digit, plus its exponent, is positive.
bool beyondLargestDouble(std::string_view number)
{
    if (!number.empty() && number.front() == '-')
        number.remove_prefix(1);
    const std::size_t e = number.find_first_of("eE");
    long long exponent = 0;
    if (e != std::string_view::npos) {
        std::string_view digits = number.substr(e + 1);
        const bool negative = !digits.empty() && digits.front() == '-';
        if (!digits.empty() && (digits.front() == '-' || digits.front() == '+'))
            digits.remove_prefix(1);
        const auto read = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
        if (read.ec != std::errc())
            exponent = std::numeric_limits<long long>::max() / 4; // more digits than fit: huge
        if (negative)
            exponent = -exponent;
    }
    const std::string_view mantissa = number.substr(0, e);
    const std::size_t first = mantissa.find_first_not_of("0.");
    if (first == std::string_view::npos)
        return false; // zero
    const std::size_t dot = std::min(mantissa.find('.'), mantissa.size());
    const long long power = first < dot ? static_cast<long long>(dot - first) - 1 : -static_cast<long long>(first - dot);
    return power + exponent > 0;
}

/// A pointer into the text for nlohmann's lexer that counts the bytes the lexer takes, so
/// that a value the reader refuses can be placed at its line and column.
class CountingChars {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingChars(const char* p, std::size_t* taken) : m_p(p), m_taken(taken) {}
    reference operator*() const { return *m_p; }
    CountingChars& operator++()
    {
        ++m_p;
        ++*m_taken;
        return *this;
    }
    CountingChars operator++(int)
    {
        CountingChars before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingChars& other) const { return m_p == other.m_p; }
    bool operator!=(const CountingChars& other) const { return m_p != other.m_p; }

private:
    const char* m_p;
    std::size_t* m_taken;
};

} // namespace

/// Builds Json values from nlohmann's parsing events; refuses too deep nesting and numbers
/// beyond a double, and turns every error into one of ours.
struct Json::Reader final : nlohmann::json_sax<nlohmann::json> {
    Reader(std::string_view text, const std::size_t& taken, const ElementSink* sink = nullptr)
        : m_text(text), m_taken(taken), m_sink(sink)
    {
    }

    bool null() override { return add(Json()); }
    bool boolean(bool b) override { return add(Json(b)); }
    // Every number is read again from its text: nlohmann's strtod is locale-dependent.
    bool number_integer(number_integer_t) override { return number(); }
    bool number_unsigned(number_unsigned_t) override { return number(); }
    bool number_float(number_float_t, const string_t&) override { return number(); }
    bool string(string_t& s) override { return add(Json(std::move(s))); }
    bool binary(binary_t&) override { return refuse(m_taken, "binary data"); } // never from text
    bool start_object(std::size_t) override
    {
        if (!deeper())
            return false;
        m_open.push_back(Json::object());
        m_keys.emplace_back();
        return true;
    }
    bool key(string_t& k) override
    {
        m_keys.back() = std::move(k);
        return true;
    }
    bool end_object() override
    {
        m_keys.pop_back();
        return close();
    }
    bool start_array(std::size_t) override
    {
        if (!deeper())
            return false;
        // The sink's array: the member sink->key of the top-level object.
        if (m_sink && m_open.size() == 1 && m_open.front().isObject() && m_keys.back() == m_sink->key) {
            m_streaming = true;
            m_streamed = 0;
        }
        m_open.push_back(Json::array());
        return true;
    }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::json::exception& e) override
    {
        if (e.id == 406) // out_of_range.406: a number too large for a double
            return tooLarge(lastNumber());
        // The text ends before its value does: a file cut short (a full disk, a copy stopped
        // half-way). Said in plain words, with the byte where it stops, not the parser's
        // ("unexpected end of input; expected ']'").
        const std::string what = e.what();
        const bool atTheEnd = position > m_text.size(); // nlohmann counts the end it read as a byte
        if (what.find("unexpected end of input") != std::string::npos ||
            (atTheEnd && (what.find("invalid literal") != std::string::npos || what.find("invalid string") != std::string::npos ||
                          what.find("invalid number") != std::string::npos)))
            return cutOff();
        return refuse(errorOffset(position, lastToken, e.what()), describe(e));
    }

    Json root;
    std::optional<Error> error;
    std::size_t errorAt = 0; ///< byte offset of the error

private:
    /// The number just read, as written. The lexer may have taken one byte past it: a number
    /// ends with a digit and that byte is none (but after a lone 0, and then parsing fails).
    std::string_view lastNumber() const
    {
        std::size_t end = std::min(m_taken, m_text.size());
        if (end > 0 && !isDigit(m_text[end - 1]))
            --end;
        std::size_t begin = end;
        while (begin > 0 && isNumberByte(m_text[begin - 1]))
            --begin;
        return m_text.substr(begin, end - begin);
    }

    bool number()
    {
        const std::string_view text = lastNumber();
        double value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc::result_out_of_range) {
            if (beyondLargestDouble(text))
                return tooLarge(text);
            value = text.front() == '-' ? -0.0 : 0.0; // below the smallest double: zero is nearest
        } else if (ec != std::errc() || end != text.data() + text.size()) {
            // Not expected: nlohmann has checked the form already.
            return refuse(offset(text), "'" + std::string(text) + "' is not a number");
        }
        Json v;
        v.m_v = Number{value, std::string(text)};
        return add(std::move(v));
    }

    bool cutOff()
    {
        const std::size_t end = m_text.size();
        if (trim(m_text.substr(0, end)).empty()) {
            error = makeError(ErrorCode::InvalidInput, end == 0 ? "JSON: the file is empty" : "JSON: the file holds only blanks");
            errorAt = end;
            return false;
        }
        const std::size_t line = 1 + static_cast<std::size_t>(std::count(m_text.begin(), m_text.begin() + end, '\n'));
        error = makeError(ErrorCode::CutOff,
                          "JSON: the file is cut off at byte " + std::to_string(end) + " (line " + std::to_string(line) + ")");
        errorAt = end;
        return false;
    }

    bool tooLarge(std::string_view number)
    {
        return refuse(offset(number), "the number " + std::string(number) + " is too large for a double (at most about 1.8e308)");
    }

    bool deeper()
    {
        if (m_open.size() < static_cast<std::size_t>(kMaxDepth))
            return true;
        // The '[' or '{' just read is the last byte taken.
        return refuse(m_taken > 0 ? m_taken - 1 : 0,
                      "arrays and objects nested deeper than " + std::to_string(kMaxDepth) + " levels");
    }

    bool close()
    {
        Json done = std::move(m_open.back());
        m_open.pop_back();
        if (m_streaming && m_open.size() == 1)
            m_streaming = false; // the sink's array itself, left empty
        return add(std::move(done));
    }

    bool add(Json v)
    {
        if (m_streaming && m_open.size() == 2) {
            m_sink->take(m_streamed++, std::move(v)); // an element of the sink's array
            return true;
        }
        if (m_open.empty())
            root = std::move(v);
        else if (m_open.back().isArray())
            m_open.back().push(std::move(v));
        else
            m_open.back().set(m_keys.back(), std::move(v)); // a repeated key: the last value wins
        return true;
    }

    std::size_t offset(std::string_view part) const { return static_cast<std::size_t>(part.data() - m_text.data()); }

    bool refuse(std::size_t at, const std::string& what)
    {
        error = makeError(ErrorCode::InvalidInput, "JSON: " + what + where(m_text, at));
        errorAt = at;
        return false;
    }

    std::string_view m_text;
    const std::size_t& m_taken;      ///< bytes nlohmann's lexer has taken so far
    const ElementSink* m_sink;       ///< where the elements of one array go, or nullptr
    bool m_streaming = false;        ///< inside the sink's array (m_open[1])
    std::size_t m_streamed = 0;      ///< its elements handed over so far
    std::vector<Json> m_open;        ///< the arrays and objects not yet closed, outermost first
    std::vector<std::string> m_keys; ///< for each open object, the key whose value comes next
};

Expected<Json> Json::parse(std::string_view text) { return parse(text, ElementSink{}); }

Expected<Json> Json::parse(std::string_view text, const ElementSink& sink)
{
    std::size_t taken = 0;
    Reader reader(text, taken, sink.take ? &sink : nullptr);
    const CountingChars begin(text.data(), &taken), end(text.data() + text.size(), &taken);
    const bool ok = nlohmann::json::sax_parse(begin, end, &reader);
    // nlohmann's lexer takes a NUL byte for the end of the text, so what follows one would
    // go unread; JSON has no place for a raw NUL anyway.
    const std::size_t nul = text.find('\0');
    if (nul != std::string_view::npos && (ok || reader.errorAt >= nul))
        return makeError(ErrorCode::InvalidInput, "JSON: a NUL byte" + where(text, nul));
    if (!ok) {
        assert(reader.error);
        return reader.error ? *reader.error : makeError(ErrorCode::InvalidInput, "JSON: unreadable text");
    }
    return std::move(reader.root);
}

void Json::write(std::string& out, int indent, int depth) const
{
    if (isNull()) {
        out += "null";
    } else if (const bool* b = std::get_if<bool>(&m_v)) {
        out += *b ? "true" : "false";
    } else if (const Number* n = std::get_if<Number>(&m_v)) {
        // JSON has no NaN or infinity; nothing of Granota's produces them, and if one
        // slipped through it must not yield invalid JSON.
        out += std::isfinite(n->value) ? formatDouble(n->value) : "null";
    } else if (const std::string* s = std::get_if<std::string>(&m_v)) {
        writeString(out, *s);
    } else if (const Array* a = std::get_if<Array>(&m_v)) {
        out += '[';
        for (std::size_t i = 0; i < a->size(); ++i) {
            if (i)
                out += ',';
            (*a)[i].write(out, 0, 0); // arrays stay on one line: points, rows
        }
        out += ']';
    } else {
        const Object& o = std::get<Object>(m_v);
        out += '{';
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (i)
                out += ',';
            newline(out, indent, depth + 1);
            writeString(out, o[i].first);
            out += indent > 0 ? ": " : ":";
            o[i].second.write(out, indent, depth + 1);
        }
        if (!o.empty())
            newline(out, indent, depth);
        out += '}';
    }
}

} // namespace granota
