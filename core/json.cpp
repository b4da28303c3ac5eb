#include "core/json.h"

#include "core/polynomial_text.h"

#include <cassert>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace granota {

std::optional<bool> Json::asBool() const
{
    if (auto b = std::get_if<bool>(&m_v))
        return *b;
    return std::nullopt;
}

std::optional<double> Json::asNumber() const
{
    if (auto d = std::get_if<double>(&m_v))
        return *d;
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
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
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

class Parser {
public:
    explicit Parser(std::string_view text) : m_s(text) {}

    Expected<Json> document()
    {
        auto v = value(0);
        if (!v)
            return v;
        skip();
        if (m_pos != m_s.size())
            return fail("unexpected text after the end");
        return v;
    }

private:
    static constexpr int kMaxDepth = 200; // deeper nesting is an error, not a stack overflow

    Error fail(const std::string& what) const
    {
        int line = 1, column = 1;
        for (std::size_t i = 0; i < m_pos && i < m_s.size(); ++i) {
            if (m_s[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return makeError(ErrorCode::InvalidInput,
                         "JSON: " + what + " at line " + std::to_string(line) + ", column " + std::to_string(column));
    }

    void skip()
    {
        while (m_pos < m_s.size() && (m_s[m_pos] == ' ' || m_s[m_pos] == '\n' || m_s[m_pos] == '\t' || m_s[m_pos] == '\r'))
            ++m_pos;
    }

    bool literal(std::string_view word)
    {
        if (m_s.substr(m_pos, word.size()) == word) {
            m_pos += word.size();
            return true;
        }
        return false;
    }

    Expected<Json> value(int depth)
    {
        if (depth > kMaxDepth)
            return fail("nesting too deep");
        skip();
        if (m_pos >= m_s.size())
            return fail("unexpected end");
        const char c = m_s[m_pos];
        if (c == '{')
            return object(depth);
        if (c == '[')
            return array(depth);
        if (c == '"') {
            auto s = string();
            if (!s)
                return s.error();
            return Json(*s);
        }
        if (literal("true"))
            return Json(true);
        if (literal("false"))
            return Json(false);
        if (literal("null"))
            return Json();
        return number();
    }

    Expected<Json> number()
    {
        const std::size_t begin = m_pos;
        if (m_pos < m_s.size() && m_s[m_pos] == '-')
            ++m_pos;
        while (m_pos < m_s.size() && (std::isdigit(static_cast<unsigned char>(m_s[m_pos])) || m_s[m_pos] == '.' ||
                                      m_s[m_pos] == 'e' || m_s[m_pos] == 'E' || m_s[m_pos] == '+' || m_s[m_pos] == '-'))
            ++m_pos;
        const std::string text(m_s.substr(begin, m_pos - begin));
        if (text.empty() || text == "-")
            return fail("expected a value");
        double d = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), d);
        if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(d)) {
            m_pos = begin;
            return fail("'" + text + "' is not a finite number");
        }
        return Json(d);
    }

    Expected<std::string> string()
    {
        ++m_pos; // opening quote
        std::string out;
        while (m_pos < m_s.size()) {
            const char c = m_s[m_pos++];
            if (c == '"')
                return out;
            if (static_cast<unsigned char>(c) < 0x20)
                return fail("control character in a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (m_pos >= m_s.size())
                break;
            const char e = m_s[m_pos++];
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                if (m_pos + 4 > m_s.size())
                    return fail("bad \\u escape");
                const unsigned code = static_cast<unsigned>(std::strtoul(std::string(m_s.substr(m_pos, 4)).c_str(), nullptr, 16));
                m_pos += 4;
                // UTF-8 of a BMP code point (surrogate pairs are not needed in Granota's files).
                if (code < 0x80) {
                    out += static_cast<char>(code);
                } else if (code < 0x800) {
                    out += static_cast<char>(0xC0 | (code >> 6));
                    out += static_cast<char>(0x80 | (code & 0x3F));
                } else {
                    out += static_cast<char>(0xE0 | (code >> 12));
                    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
                    out += static_cast<char>(0x80 | (code & 0x3F));
                }
                break;
            }
            default: return fail("bad escape");
            }
        }
        return fail("unterminated string");
    }

    Expected<Json> array(int depth)
    {
        ++m_pos;
        Json a = Json::array();
        skip();
        if (m_pos < m_s.size() && m_s[m_pos] == ']') {
            ++m_pos;
            return a;
        }
        while (true) {
            auto v = value(depth + 1);
            if (!v)
                return v;
            a.push(std::move(v).value());
            skip();
            if (m_pos < m_s.size() && m_s[m_pos] == ',') {
                ++m_pos;
                continue;
            }
            if (m_pos < m_s.size() && m_s[m_pos] == ']') {
                ++m_pos;
                return a;
            }
            return fail("expected ',' or ']'");
        }
    }

    Expected<Json> object(int depth)
    {
        ++m_pos;
        Json o = Json::object();
        skip();
        if (m_pos < m_s.size() && m_s[m_pos] == '}') {
            ++m_pos;
            return o;
        }
        while (true) {
            skip();
            if (m_pos >= m_s.size() || m_s[m_pos] != '"')
                return fail("expected a key in quotes");
            auto key = string();
            if (!key)
                return key.error();
            skip();
            if (m_pos >= m_s.size() || m_s[m_pos] != ':')
                return fail("expected ':'");
            ++m_pos;
            auto v = value(depth + 1);
            if (!v)
                return v;
            o.set(*key, std::move(v).value());
            skip();
            if (m_pos < m_s.size() && m_s[m_pos] == ',') {
                ++m_pos;
                continue;
            }
            if (m_pos < m_s.size() && m_s[m_pos] == '}') {
                ++m_pos;
                return o;
            }
            return fail("expected ',' or '}'");
        }
    }

    std::string_view m_s;
    std::size_t m_pos = 0;
};

} // namespace

Expected<Json> Json::parse(std::string_view text) { return Parser(text).document(); }

void Json::write(std::string& out, int indent, int depth) const
{
    if (isNull()) {
        out += "null";
    } else if (const bool* b = std::get_if<bool>(&m_v)) {
        out += *b ? "true" : "false";
    } else if (const double* d = std::get_if<double>(&m_v)) {
        // JSON has no NaN or infinity; nothing of Granota's produces them, and if one
        // slipped through it must not yield invalid JSON.
        out += std::isfinite(*d) ? formatDouble(*d) : "null";
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
