#include "app/cli/json.h"

#include "core/polynomial_text.h"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace granota::cli {

Json& Json::push(Json v)
{
    assert(std::holds_alternative<Array>(m_v));
    std::get<Array>(m_v).push_back(std::move(v));
    return *this;
}

Json& Json::set(const std::string& key, Json v)
{
    assert(std::holds_alternative<Object>(m_v));
    std::get<Object>(m_v).emplace_back(key, std::move(v));
    return *this;
}

std::string Json::dump() const
{
    std::string out;
    write(out);
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
} // namespace

void Json::write(std::string& out) const
{
    if (std::holds_alternative<std::nullptr_t>(m_v)) {
        out += "null";
    } else if (const bool* b = std::get_if<bool>(&m_v)) {
        out += *b ? "true" : "false";
    } else if (const double* d = std::get_if<double>(&m_v)) {
        // JSON has no NaN or infinity; the commands never produce them, and if one slipped
        // through it must not yield invalid JSON.
        out += std::isfinite(*d) ? formatDouble(*d) : "null";
    } else if (const std::string* s = std::get_if<std::string>(&m_v)) {
        writeString(out, *s);
    } else if (const Array* a = std::get_if<Array>(&m_v)) {
        out += '[';
        for (std::size_t i = 0; i < a->size(); ++i) {
            if (i)
                out += ',';
            (*a)[i].write(out);
        }
        out += ']';
    } else {
        const Object& o = std::get<Object>(m_v);
        out += '{';
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (i)
                out += ',';
            writeString(out, o[i].first);
            out += ':';
            o[i].second.write(out);
        }
        out += '}';
    }
}

} // namespace granota::cli
