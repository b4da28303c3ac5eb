#include "core/softbody/seed/seed_trace.h"

#include "core/base/display_text.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace granota {

namespace {

template <class T> std::string shortest(T value)
{
    if (std::isnan(value))
        return "NaN";
    if (std::isinf(value))
        return value > 0 ? "Infinity" : "-Infinity";
    char buf[64];
    // std::to_chars without a format: the shortest representation that round-trips.
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    std::string s(buf, res.ptr);
    // Java writes "640.0" and "1.0E-5"; keep integral values recognisably real.
    const auto e = s.find('e');
    const std::string mantissa = s.substr(0, e);
    std::string exponent = e == std::string::npos ? std::string() : s.substr(e + 1);
    std::string out = mantissa;
    if (mantissa.find('.') == std::string::npos)
        out += ".0";
    if (!exponent.empty()) {
        std::string sign;
        if (exponent[0] == '+' || exponent[0] == '-') {
            if (exponent[0] == '-')
                sign = "-";
            exponent.erase(0, 1);
        }
        while (exponent.size() > 1 && exponent[0] == '0')
            exponent.erase(0, 1);
        out += "E" + sign + exponent;
    }
    return out;
}

void appendPair(std::string& out, const Vec2<float>& p)
{
    out += ',';
    out += shortest(p.x);
    out += ',';
    out += shortest(p.y);
}
void appendPair(std::string& out, const Vec2<double>& p)
{
    out += ',';
    out += shortest(p.x);
    out += ',';
    out += shortest(p.y);
}

bool parseNumber(std::string_view s, double& out)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    if (s == "NaN") {
        out = std::nan("");
        return true;
    }
    if (s == "Infinity") {
        out = HUGE_VAL;
        return true;
    }
    if (s == "-Infinity") {
        out = -HUGE_VAL;
        return true;
    }
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    const char* first = s.data();
    const char* last = s.data() + s.size();
    const auto res = std::from_chars(first, last, out);
    return res.ec == std::errc() && res.ptr == last && first != last;
}

std::vector<std::string_view> splitComma(std::string_view line)
{
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        if (comma == std::string_view::npos) {
            parts.push_back(line.substr(start));
            return parts;
        }
        parts.push_back(line.substr(start, comma - start));
        start = comma + 1;
    }
}

} // namespace

std::string seedTraceNumber(float value) { return shortest(value); }
std::string seedTraceNumber(double value) { return shortest(value); }

std::string seedTraceHeader(int sides, bool legs)
{
    std::string h = "step";
    for (int i = 0; i < sides; ++i)
        h += ",v" + std::to_string(i) + "x,v" + std::to_string(i) + "y";
    if (legs)
        for (const char* l : {"front_right", "front_left", "back_right", "back_left"})
            for (const char* j : {"_elbow_x", "_elbow_y", "_wrist_x", "_wrist_y"})
                h += std::string(",") + l + j;
    return h;
}

template <class R> std::string seedTraceRow(int step, const SeedFrog<R>& frog)
{
    std::string row = std::to_string(step);
    const auto& v = frog.body().seedVertices();
    for (int i = 0; i < frog.body().sides(); ++i)
        appendPair(row, v[std::size_t(i)].pos);
    for (const auto& leg : frog.legs()) { // front right, front left, back right, back left
        appendPair(row, leg.elbow());
        appendPair(row, leg.wrist());
    }
    return row;
}

Expected<SeedTrace> parseSeedTrace(std::string_view text)
{
    SeedTrace trace;
    std::size_t pos = 0;
    int lineNo = 0;
    bool haveHeader = false;
    while (pos <= text.size()) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos)
            nl = text.size();
        std::string_view line = text.substr(pos, nl - pos);
        pos = nl + 1;
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        if (line.find_first_not_of(" \t") == std::string_view::npos)
            continue;
        const auto parts = splitComma(line);
        if (!haveHeader) {
            for (auto p : parts)
                trace.columns.emplace_back(p);
            haveHeader = true;
            continue;
        }
        if (parts.size() != trace.columns.size())
            return makeError(ErrorCode::InvalidInput, "line " + std::to_string(lineNo) + ": " + std::to_string(parts.size()) +
                                                          " fields, the header has " + std::to_string(trace.columns.size()));
        std::vector<double> row(parts.size());
        for (std::size_t k = 0; k < parts.size(); ++k)
            if (!parseNumber(parts[k], row[k]))
                return makeError(ErrorCode::InvalidInput, "line " + std::to_string(lineNo) + ", column " + trace.columns[k] +
                                                              ": not a number: " + quotedForDisplay(parts[k]));
        trace.rows.push_back(std::move(row));
    }
    if (!haveHeader)
        return makeError(ErrorCode::InvalidInput, "empty trace: no header line");
    return trace;
}

Expected<SeedTrace> readSeedTrace(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return makeError(ErrorCode::InvalidInput, "cannot open the trace file " + path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return parseSeedTrace(ss.str());
}

template std::string seedTraceRow<float>(int, const SeedFrog<float>&);
template std::string seedTraceRow<double>(int, const SeedFrog<double>&);

} // namespace granota
